// Principal stresses and the paper's failure criteria (Section 2.1, Eq. 11). Tension positive.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <numbers>

#include "approx.hpp"
#include "hm/analytic/failure_criteria.hpp"

using namespace hm::analytic;
using hm::test::roundoff;

namespace {
constexpr double pi = std::numbers::pi;
// K = [(1 + mu_i^2)^(1/2) + mu_i]^2 for mu_i = 0.9: (sqrt(1.81) + 0.9)^2 = 2.2453624047^2 = 5.0416523285.
constexpr double K_table1 = 5.0416523285;
}  // namespace

TEST_CASE("Principal stresses of known 2D states", "[analytic]") {
  SECTION("uniaxial along x") {
    const auto p = principal_stresses(1e-3, 0.0, 0.0);
    CHECK(p.sigma_1 == roundoff(1e-3));
    CHECK(p.sigma_2 == Approx(0.0).margin(1e-18));
    CHECK(p.angle == Approx(0.0).margin(1e-15));
  }
  SECTION("uniaxial along y: sigma_1 points along y") {
    const auto p = principal_stresses(0.0, 1e-3, 0.0);
    CHECK(p.sigma_1 == roundoff(1e-3));
    CHECK(std::abs(std::cos(p.angle)) == Approx(0.0).margin(1e-15));
  }
  SECTION("pure shear tau: +-tau at 45 degrees") {
    const auto p = principal_stresses(0.0, 0.0, 2e-4);
    CHECK(p.sigma_1 == roundoff(2e-4));
    CHECK(p.sigma_2 == roundoff(-2e-4));
    CHECK(p.angle == roundoff(pi / 4.0));
  }
  SECTION("compressive state: sigma_1 is the less compressive one") {
    const auto p = principal_stresses(-1e-3, -3e-3, 0.0);
    CHECK(p.sigma_1 == roundoff(-1e-3));
    CHECK(p.sigma_2 == roundoff(-3e-3));
  }
}

TEST_CASE("Principal stresses are invariant under rotation and recover the rotation angle", "[analytic]") {
  const double s1 = 3e-4, s2 = -1e-3;
  for (double theta = -1.5; theta <= 1.5; theta += 0.25) {
    CAPTURE(theta);
    const double c = std::cos(theta), s = std::sin(theta);
    const double sxx = s1 * c * c + s2 * s * s, syy = s1 * s * s + s2 * c * c, sxy = (s1 - s2) * s * c;
    const auto p = principal_stresses(sxx, syy, sxy);
    // Round-off on the O(1e-3) entries (absolute floor 1e-16 for the rotated sums).
    CHECK(p.sigma_1 == Approx(s1).epsilon(1e-12).margin(1e-16));
    CHECK(p.sigma_2 == Approx(s2).epsilon(1e-12).margin(1e-16));
    // The direction is defined modulo pi: compare the doubled angle.
    CHECK(std::cos(2.0 * p.angle) == Approx(std::cos(2.0 * theta)).margin(1e-12));
    CHECK(std::sin(2.0 * p.angle) == Approx(std::sin(2.0 * theta)).margin(1e-12));
    // Invariants: trace and determinant.
    CHECK(p.sigma_1 + p.sigma_2 == Approx(sxx + syy).margin(1e-16));
    CHECK(p.sigma_1 * p.sigma_2 == Approx(sxx * syy - sxy * sxy).margin(1e-19));
  }
}

TEST_CASE("major_minor picks the largest and smallest of three principal stresses", "[analytic]") {
  for (const auto& triple : {std::array<double, 3>{-1.0, 2.0, 0.5}, std::array<double, 3>{2.0, 0.5, -1.0},
                             std::array<double, 3>{0.5, -1.0, 2.0}}) {
    const auto mm = major_minor(triple);
    CHECK(mm.sigma_1 == 2.0);
    CHECK(mm.sigma_3 == -1.0);
  }
}

TEST_CASE("Coulomb stress of Eq. 11", "[analytic]") {
  SECTION("hand-checked with mu_i = 0.9") {
    CHECK(std::pow(std::sqrt(1.0 + 0.81) + 0.9, 2) == Approx(K_table1).epsilon(1e-10));  // 11 digits above
    // sigma_1 = 2e-4, sigma_3 = -1e-3: 5.0416523285 * 2e-4 + 1e-3 = 2.0083304657e-3.
    CHECK(coulomb_stress(2e-4, -1e-3, 0.9) == Approx(2.0083304657e-3).epsilon(1e-10));
  }
  SECTION("K equals the Mohr-Coulomb (1 + sin phi)/(1 - sin phi) with tan phi = mu_i") {
    for (double mu : {0.0, 0.3, 0.6, 0.9, 1.5}) {
      const double sin_phi = std::sin(std::atan(mu));
      CHECK(coulomb_stress(1.0, 0.0, mu) == roundoff((1.0 + sin_phi) / (1.0 - sin_phi)));
    }
  }
  SECTION("without friction it is sigma_1 - sigma_3 (Tresca: twice the maximum shear)") {
    CHECK(coulomb_stress(1e-4, -5e-4, 0.0) == roundoff(6e-4));
  }
  SECTION("the compression-positive line sigma_1' = C_u + K sigma_3' is exactly sigma_CC = C_u") {
    const double C_u = 3.33e-3;
    CHECK(coulomb_stress(0.0, -C_u, 0.9) == roundoff(C_u));  // uniaxial compression at strength
    for (double confinement : {1e-4, 1e-3, 5e-3}) {
      // sigma_3' = confinement (compression positive) -> sigma_1' = C_u + K confinement.
      const double s1 = -confinement, s3 = -(C_u + K_table1 * confinement);
      CHECK(coulomb_stress(s1, s3, 0.9) == Approx(C_u).epsilon(1e-9));  // K known to 11 digits
    }
  }
}

TEST_CASE("check_failure reports the mode with the larger strength ratio", "[analytic]") {
  const double T_u = 2e-4, C_u = 3.33e-3, mu = 0.9;
  SECTION("no failure below both criteria") {
    const auto c = check_failure(1e-4, -1e-4, T_u, C_u, mu);
    CHECK(c.mode == FailureMode::none);
    // ratio = max(0.5, (5.0417e-4 + 1e-4)/3.33e-3 = 0.1814) = 0.5
    CHECK(c.ratio == roundoff(0.5));
  }
  SECTION("tensile failure when sigma_1 exceeds T_u") {
    const auto c = check_failure(3e-4, 0.0, T_u, C_u, mu);
    CHECK(c.mode == FailureMode::tensile);
    CHECK(c.ratio == roundoff(1.5));
  }
  SECTION("shear failure under strong compression") {
    // Uniaxial compression 4e-3 > C_u: sigma_CC/C_u = 1.2012, sigma_1/T_u = 0.
    const auto c = check_failure(0.0, -4e-3, T_u, C_u, mu);
    CHECK(c.mode == FailureMode::shear);
    CHECK(c.ratio == roundoff(4e-3 / C_u));
  }
  SECTION("both exceeded: the larger ratio decides") {
    // sigma_1 = 2.2e-4 (1.1 T_u); sigma_CC = 5.0417 * 2.2e-4 + 4e-3 = 5.109e-3 (1.534 C_u): shear.
    const auto c = check_failure(2.2e-4, -4e-3, T_u, C_u, mu);
    CHECK(c.mode == FailureMode::shear);
    CHECK(c.ratio == Approx((K_table1 * 2.2e-4 + 4e-3) / C_u).epsilon(1e-10));  // K_table1 has 11 digits
    // sigma_1 = 4e-4 (2 T_u); sigma_CC = 2.017e-3 + 1e-4 (0.636 C_u): tensile.
    CHECK(check_failure(4e-4, -1e-4, T_u, C_u, mu).mode == FailureMode::tensile);
  }
  SECTION("exactly at the tensile strength counts as failure (ratio >= 1)") {
    const auto c = check_failure(T_u, 0.0, T_u, C_u, mu);
    CHECK(c.ratio == 1.0);
    CHECK(c.mode == FailureMode::tensile);
  }
}
