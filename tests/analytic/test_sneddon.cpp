// Sneddon's pressurised crack (paper Appendix C, Eq. C1): hand values, the ellipse, the crack volume
// by quadrature, and agreement with linear elastic fracture mechanics (docs/errata.md, "Checked and right").
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "approx.hpp"
#include "hm/analytic/sneddon.hpp"

using hm::analytic::SneddonCrack;
using hm::test::roundoff;

namespace {
constexpr double pi = std::numbers::pi;
// p = 1e-3 (p/E), half length c = 0.1, nu = 0.25.
constexpr SneddonCrack crack{1e-3, 0.1, 0.25};
}  // namespace

TEST_CASE("Sneddon half aperture: hand-checked values", "[analytic]") {
  // eps = 2 (1 - nu^2) p c = 2 * 0.9375 * 1e-3 * 0.1 = 1.875e-4.
  CHECK(crack.max_half_aperture() == roundoff(1.875e-4));
  CHECK(crack.half_aperture(0.0) == roundoff(1.875e-4));
  // x = 0.06: sqrt(1 - 0.36) = 0.8, w = 1.5e-4.
  CHECK(crack.half_aperture(0.06) == roundoff(1.5e-4));
  CHECK(crack.half_aperture(-0.06) == roundoff(1.5e-4));
  // Closed at and beyond the tips.
  CHECK(crack.half_aperture(0.1) == 0.0);
  CHECK(crack.half_aperture(-0.1) == 0.0);
  CHECK(crack.half_aperture(0.3) == 0.0);
  // Linear in p and in c at fixed x/c: doubling c doubles w(x = 0.6 c).
  const SneddonCrack longer{1e-3, 0.2, 0.25};
  CHECK(longer.half_aperture(0.12) == roundoff(2.0 * crack.half_aperture(0.06)));
}

TEST_CASE("Sneddon crack faces lie on the ellipse of Eq. C1", "[analytic]") {
  for (double t = -0.99; t <= 0.99; t += 0.09) {
    const double x = t * crack.c;
    const double w = crack.half_aperture(x);
    CHECK((x / crack.c) * (x / crack.c) + (w / crack.max_half_aperture()) * (w / crack.max_half_aperture()) ==
          roundoff(1.0));
  }
}

TEST_CASE("Sneddon crack volume equals the integral of the full aperture 2w", "[analytic]") {
  // tanh-sinh quadrature copes with the square-root end points; its error estimate is checked too.
  boost::math::quadrature::tanh_sinh<double> quad;
  double error = 0.0;
  const double integral =
      quad.integrate([](double x) { return 2.0 * crack.half_aperture(x); }, -crack.c, crack.c, 1e-14, &error);
  CHECK(error <= 1e-12 * integral);
  // Tolerance: the quadrature's own error estimate (<= 1e-12 relative, asserted above), with margin.
  CHECK(crack.crack_volume() == Approx(integral).epsilon(1e-10));
  // Hand value: pi c eps = pi * 0.1 * 1.875e-4 = 5.8904862e-5.
  CHECK(crack.crack_volume() == Approx(5.8904862e-5).epsilon(1e-8));  // 8 digits written
}

TEST_CASE("Sneddon's C1 agrees with LEFM in plane strain (K_I = p sqrt(pi c), E' = E/(1-nu^2))", "[analytic]") {
  const double K_I = crack.p * std::sqrt(pi * crack.c);
  const double E_prime = 1.0 / (1.0 - crack.nu * crack.nu);
  SECTION("near-tip opening 2w = (8 K_I/E') sqrt(rho/(2 pi)), rho the distance to the tip") {
    // The exact ratio is sqrt(1 - rho/(2c)); at rho = 1e-8 c it is 1 - 2.5e-9.
    for (double rho_over_c : {1e-8, 1e-6, 1e-3}) {
      const double rho = rho_over_c * crack.c;
      const double lefm = 8.0 * K_I / E_prime * std::sqrt(rho / (2.0 * pi));
      // Round-off: x = c - rho and 1 - (x/c)^2 lose digits in proportion to c/rho (eps c/rho each).
      CHECK(2.0 * crack.half_aperture(crack.c - rho) / lefm ==
            Approx(std::sqrt(1.0 - rho_over_c / 2.0)).epsilon(5e-16 / rho_over_c + 1e-12));
    }
  }
  SECTION("energy release rate from the crack volume equals K_I^2/E' (Irwin)") {
    // Fixed pressure: potential energy -p V/2; both tips advance with c, so G = (p/4) dV/dc.
    // V is quadratic in c, so the central difference is exact up to round-off (~eps V/h).
    const double h = 1e-4 * crack.c;
    const double dV_dc = (SneddonCrack{crack.p, crack.c + h, crack.nu}.crack_volume() -
                          SneddonCrack{crack.p, crack.c - h, crack.nu}.crack_volume()) /
                         (2.0 * h);
    CHECK(crack.p / 4.0 * dV_dc == Approx(K_I * K_I / E_prime).epsilon(1e-10));
  }
  SECTION("plane stress (E' = E) would give a different aperture: C1 is the plane-strain one") {
    CHECK(crack.max_half_aperture() != Approx(2.0 * crack.p * crack.c).epsilon(1e-3));
  }
}
