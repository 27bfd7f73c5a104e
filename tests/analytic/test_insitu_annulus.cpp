// The annulus under a far-field stress and Kirsch's hole: field equations by finite differences, the
// four traction conditions, the Kirsch and Lame limits, the textbook wall stresses, bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include "approx.hpp"
#include "hm/analytic/insitu_annulus.hpp"
#include "hm/analytic/lame.hpp"
#include "hm/core/input_error.hpp"

using namespace hm::analytic;
using hm::test::roundoff;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double inf = std::numeric_limits<double>::infinity();

// Sixth-order central difference with step h. For the fields' r^-4 terms (the stiffest) the relative
// truncation error is ~1080 (h/r)^6; for cos 2theta it is ~0.5 h^6 (theta in rad).
double d1(const std::function<double(double)>& f, double x, double h) {
  return (-f(x - 3 * h) + 9 * f(x - 2 * h) - 45 * f(x - h) + 45 * f(x + h) - 9 * f(x + 2 * h) + f(x + 3 * h)) /
         (60 * h);
}

// A loaded case away from every special value: S_H > S_h, S_H rotated, wall pressure between them.
const FarFieldStress far{3e-3, 1e-3, 0.3};
constexpr double p_w = 2e-3, R_i = 0.138, nu = 0.3, scale = 3e-3;  // scale: the largest load

// Interior points: every finite-difference stencil below (3 steps of r/200) stays inside [R_i, 1].
const double radii[] = {0.16, 0.25, 0.5, 0.8, 0.98};
const double angles[] = {0.0, 0.3, 1.0, 2.2, 4.0, 5.9};

}  // namespace

TEST_CASE("The in-situ annulus satisfies equilibrium in polar coordinates", "[analytic]") {
  const InSituAnnulus sol(far, p_w, R_i, nu);
  for (double r : radii)
    for (double th : angles) {
      CAPTURE(r, th);
      const auto s = sol.state(r, th);
      const double hr = r / 200.0, ht = 1e-2;
      const double dsr_dr = d1([&](double x) { return sol.state(x, th).sigma_r; }, r, hr);
      const double dtau_dr = d1([&](double x) { return sol.state(x, th).sigma_rtheta; }, r, hr);
      const double dtau_dt = d1([&](double t) { return sol.state(r, t).sigma_rtheta; }, th, ht);
      const double dst_dt = d1([&](double t) { return sol.state(r, t).sigma_theta; }, th, ht);
      // d sigma_r/dr + (1/r) d tau/d theta + (sigma_r - sigma_theta)/r = 0 and
      // d tau/dr + (1/r) d sigma_theta/d theta + 2 tau/r = 0, times r. The FD error is
      // 1080 (1/200)^6 = 2e-11 and 0.5e-12 relative (round-off eps 200 = 4e-14): 1e-9 leaves 50x.
      CHECK(std::abs(r * dsr_dr + dtau_dt + s.sigma_r - s.sigma_theta) <= 1e-9 * scale);
      CHECK(std::abs(r * dtau_dr + dst_dt + 2.0 * s.sigma_rtheta) <= 1e-9 * scale);
    }
}

TEST_CASE("The in-situ annulus meets its four traction conditions to round-off", "[analytic]") {
  const InSituAnnulus sol(far, p_w, R_i, nu);
  const double P = 0.5 * (far.S_H + far.S_h), q = 0.5 * (far.S_H - far.S_h);
  for (double th : angles) {
    CAPTURE(th);
    const double psi = th - far.theta_H;
    const auto wall = sol.state(R_i, th), outer = sol.state(1.0, th);
    CHECK(wall.sigma_r == roundoff(-p_w));
    CHECK(wall.sigma_rtheta == Approx(0.0).margin(1e-14 * scale));  // round-off of O(scale) terms
    CHECK(outer.sigma_r == roundoff(-P - q * std::cos(2.0 * psi)));
    CHECK(outer.sigma_rtheta == roundoff(q * std::sin(2.0 * psi)));
  }
  SECTION("the outer traction is the far-field tensor: -S_H along S_H, -S_h across it") {
    CHECK(sol.state(1.0, far.theta_H).sigma_r == roundoff(-far.S_H));
    CHECK(sol.state(1.0, far.theta_H + 0.5 * pi).sigma_r == roundoff(-far.S_h));
    CHECK(sol.state(1.0, far.theta_H + pi).sigma_r == roundoff(-far.S_H));
  }
}

TEST_CASE("The in-situ annulus stresses are plane-strain Hooke of its displacements", "[analytic]") {
  const InSituAnnulus sol(far, p_w, R_i, nu);
  const double lambda = (1.0 + nu) * (1.0 - 2.0 * nu);
  for (double r : radii)
    for (double th : angles) {
      CAPTURE(r, th);
      const auto s = sol.state(r, th);
      const double hr = r / 200.0, ht = 1e-2;
      const auto ur = [&](double x, double t) { return sol.state(x, t).u_r; };
      const auto ut = [&](double x, double t) { return sol.state(x, t).u_theta; };
      const double eps_r = d1([&](double x) { return ur(x, th); }, r, hr);
      const double eps_t = (s.u_r + d1([&](double t) { return ut(r, t); }, th, ht)) / r;
      const double gamma = d1([&](double x) { return ut(x, th); }, r, hr) - s.u_theta / r +
                           d1([&](double t) { return ur(r, t); }, th, ht) / r;
      // Written out independently of the library (E = 1). FD error as in the equilibrium test.
      CHECK(std::abs(s.sigma_r - ((1.0 - nu) * eps_r + nu * eps_t) / lambda) <= 1e-9 * scale);
      CHECK(std::abs(s.sigma_theta - (nu * eps_r + (1.0 - nu) * eps_t) / lambda) <= 1e-9 * scale);
      CHECK(std::abs(s.sigma_rtheta - gamma / (2.0 * (1.0 + nu))) <= 1e-9 * scale);
    }
  SECTION("the rigid-body choice: the principal axes do not rotate") {
    for (double r : radii) {
      CHECK(sol.state(r, far.theta_H).u_theta == Approx(0.0).margin(1e-14 * scale));
      CHECK(sol.state(r, far.theta_H + 0.5 * pi).u_theta == Approx(0.0).margin(1e-14 * scale));
    }
  }
}

TEST_CASE("An isotropic far field reduces the in-situ annulus to Lame's cylinder", "[analytic]") {
  const FarFieldStress iso{2e-3, 2e-3, 0.7};
  const InSituAnnulus sol(iso, p_w, R_i, nu);
  const LameCylinder lame(p_w, 2e-3, R_i, 1.0, nu);
  for (double r : {R_i, 0.3, 0.7, 1.0})
    for (double th : angles) {
      CAPTURE(r, th);
      const auto s = sol.state(r, th);
      const auto l = lame.state(r);
      CHECK(s.u_r == roundoff(l.u_r));
      CHECK(s.sigma_r == roundoff(l.sigma_r));
      CHECK(s.sigma_theta == roundoff(l.sigma_theta));
      CHECK(s.u_theta == 0.0);  // q = 0 makes every deviatoric term exactly zero
      CHECK(s.sigma_rtheta == 0.0);
    }
}

TEST_CASE("Kirsch's hole gives the textbook wall and far-field stresses", "[analytic]") {
  const double a = 0.1;
  const KirschHole k(far, p_w, a, nu);
  // Tension positive: S_H - 3 S_h + p_w on the S_H axis (compression-positive 3 S_h - S_H - p_w),
  // S_h - 3 S_H + p_w across it (compression-positive 3 S_H - S_h - p_w).
  CHECK(k.state(a, far.theta_H).sigma_theta == roundoff(far.S_H - 3.0 * far.S_h + p_w));
  CHECK(k.state(a, far.theta_H + 0.5 * pi).sigma_theta == roundoff(far.S_h - 3.0 * far.S_H + p_w));
  for (double th : angles) {
    CHECK(k.state(a, th).sigma_r == roundoff(-p_w));
    CHECK(k.state(a, th).sigma_rtheta == Approx(0.0).margin(1e-14 * scale));
  }
  // Far away the field is the far-field tensor; the disturbance decays like (a/r)^2 = 1e-8 here.
  const double r_far = 1e4 * a;
  CHECK(k.state(r_far, far.theta_H).sigma_r == Approx(-far.S_H).epsilon(1e-7));
  CHECK(k.state(r_far, far.theta_H).sigma_theta == Approx(-far.S_h).epsilon(1e-7));
  CHECK(k.state(r_far, far.theta_H + 0.25 * pi).sigma_rtheta == Approx(0.5 * (far.S_H - far.S_h)).epsilon(1e-7));
  SECTION("with S_H = 3 S_h and no wall pressure the wall hoop stress vanishes on the S_H axis") {
    const KirschHole k3({3e-3, 1e-3, 0.0}, 0.0, a, nu);
    CHECK(k3.state(a, 0.0).sigma_theta == Approx(0.0).margin(1e-14 * scale));
    CHECK(k3.state(a, 0.5 * pi).sigma_theta == roundoff(-8e-3));
  }
}

TEST_CASE("The in-situ annulus tends to Kirsch's hole like R_i^2", "[analytic]") {
  // Largest stress difference over r = a, 2a, 5a and the angles, relative to S_H.
  const auto difference = [](double a) {
    const InSituAnnulus ann(far, p_w, a, nu);
    const KirschHole kirsch(far, p_w, a, nu);
    double worst = 0.0;
    for (double k : {1.0, 2.0, 5.0})
      for (double th : angles) {
        const auto s = ann.state(k * a, th), t = kirsch.state(k * a, th);
        worst = std::max({worst, std::abs(s.sigma_r - t.sigma_r), std::abs(s.sigma_theta - t.sigma_theta),
                          std::abs(s.sigma_rtheta - t.sigma_rtheta)});
      }
    return worst / far.S_H;
  };
  const double e1 = difference(1e-3), e2 = difference(2e-3), e4 = difference(4e-3);
  CAPTURE(e1, e2, e4);
  CHECK(e1 > 0.0);
  CHECK(e1 < 1e-4);  // the difference is O(R_i^2) = 1e-6 times an O(1) coefficient
  // Observed order: the next term is O(R_i^4), a relative 1.6e-5 at R_i = 4e-3, and round-off in a
  // difference of 1e-6 S_H is 1e-10 of it: 2 +- 1e-3 is generous and still sharp.
  CHECK(std::log2(e2 / e1) == Approx(2.0).margin(1e-3));
  CHECK(std::log2(e4 / e2) == Approx(2.0).margin(1e-3));
}

TEST_CASE("In-situ annulus and Kirsch input is refused with one line naming value and rule", "[analytic]") {
  const auto refused = [](const std::function<void()>& f, const std::string& message) {
    CHECK_THROWS_AS(f(), hm::InputError);
    CHECK_THROWS_WITH(f(), message);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  refused([] { InSituAnnulus({1.0, 2.0, 0.0}, 0.0, R_i, nu); }, "S_h = 2, allowed: 0 <= S_h <= S_H (1)");
  refused([] { InSituAnnulus({-1.0, 0.0, 0.0}, 0.0, R_i, nu); }, "S_H = -1, allowed: S_H >= 0");
  refused([] { InSituAnnulus({1.0, -0.5, 0.0}, 0.0, R_i, nu); }, "S_h = -0.5, allowed: 0 <= S_h <= S_H (1)");
  refused([&] { InSituAnnulus({1.0, 0.5, nan}, 0.0, R_i, nu); }, "theta_H = nan, allowed: a finite number");
  refused([] { InSituAnnulus(far, inf, R_i, nu); }, "p_w = inf, allowed: a finite number");
  refused([] { InSituAnnulus(far, p_w, 1.0, nu); }, "R_i = 1, allowed: 0 < R_i < 1");
  refused([] { InSituAnnulus(far, p_w, 0.0, nu); }, "R_i = 0, allowed: 0 < R_i < 1");
  refused([] { InSituAnnulus(far, p_w, R_i, 0.5); }, "nu = 0.5, allowed: 0 < nu < 0.5");
  refused([] { InSituAnnulus(far, p_w, R_i, -0.1); }, "nu = -0.1, allowed: 0 < nu < 0.5");
  const InSituAnnulus sol(far, p_w, R_i, nu);
  refused([&] { sol.state(0.1, 0.0); }, "r = 0.1, allowed: 0.138 <= r <= 1");
  refused([&] { sol.state(1.5, 0.0); }, "r = 1.5, allowed: 0.138 <= r <= 1");
  refused([&] { sol.state(0.5, nan); }, "theta = nan, allowed: a finite number");
  refused([] { KirschHole(far, p_w, 0.0, nu); }, "a = 0, allowed: a > 0");
  const KirschHole k(far, p_w, 0.1, nu);
  refused([&] { k.state(0.05, 0.0); }, "r = 0.05, allowed: a <= r < inf (a = 0.1)");
  CHECK_NOTHROW(FarFieldStress{}.validate());  // the defaults (no load) are valid
}
