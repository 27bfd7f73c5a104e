// Lame's thick-walled cylinder in plane strain, with a free (pressurised) and a fixed outer surface:
// boundary conditions, equilibrium, Hooke consistency and hand-checked values.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "approx.hpp"
#include "hm/analytic/lame.hpp"

using hm::analytic::LameCylinder;
using hm::analytic::LameCylinderFixedOuter;
using hm::analytic::RadialState;
using hm::test::roundoff;

namespace {

// Sixth-order central differences with h = r/200: for the fields' 1/r^n terms the relative
// truncation error is ~(h/r)^6 * 40 = 6e-13 and the round-off ~3 eps (r/h)^2 = 1e-11 (f'') or less.
double d1(const std::function<double(double)>& f, double r) {
  const double h = r / 200.0;
  return (-f(r - 3 * h) + 9 * f(r - 2 * h) - 45 * f(r - h) + 45 * f(r + h) - 9 * f(r + 2 * h) + f(r + 3 * h)) /
         (60 * h);
}

// Plane-strain Hooke (E = 1), written out independently of the library.
double hooke_r(double nu, double du, double u_over_r) {
  return ((1.0 - nu) * du + nu * u_over_r) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}
double hooke_theta(double nu, double du, double u_over_r) {
  return (nu * du + (1.0 - nu) * u_over_r) / ((1.0 + nu) * (1.0 - 2.0 * nu));
}

// Equilibrium, Hooke and sigma_z = nu (sigma_r + sigma_theta) at radii across [R_i, R_o].
// Tolerances: FD error above relative to the largest stress magnitude `scale`.
void check_field_equations(const std::function<RadialState(double)>& state, double R_i, double R_o, double nu,
                           double scale) {
  const auto sr = [&](double r) { return state(r).sigma_r; };
  const auto u = [&](double r) { return state(r).u_r; };
  for (int i = 0; i <= 10; ++i) {
    const double r = R_i + (R_o - R_i) * i / 10.0;
    CAPTURE(r);
    const auto s = state(r);
    CHECK(s.p == 0.0);
    // d sigma_r/dr + (sigma_r - sigma_theta)/r = 0 (no body force).
    CHECK(std::abs(d1(sr, r) + (s.sigma_r - s.sigma_theta) / r) * r <= 1e-9 * scale);
    CHECK(std::abs(s.sigma_r - hooke_r(nu, d1(u, r), s.u_r / r)) <= 1e-9 * scale);
    CHECK(std::abs(s.sigma_theta - hooke_theta(nu, d1(u, r), s.u_r / r)) <= 1e-9 * scale);
    CHECK(s.sigma_z == Approx(nu * (s.sigma_r + s.sigma_theta)).margin(1e-14 * scale));  // round-off
  }
}

}  // namespace

TEST_CASE("Lame cylinder with inner and outer pressure", "[analytic]") {
  SECTION("hand-checked values: p_i = 1e-3, p_o = 0, R_i = 0.5, R_o = 1, nu = 0.25") {
    // A = p_i R_i^2/(R_o^2 - R_i^2) = 1e-3 * 0.25/0.75 = 3.3333e-4; B = A R_o^2 = 3.3333e-4.
    // r = 0.5: sigma_r = A - 4B = -1e-3, sigma_theta = A + 4B = 1.6667e-3,
    //          u = 1.25 (0.5 * A * 0.5 + B/0.5) = 1.25 * 7.5e-4 = 9.375e-4.
    // r = 1:   sigma_r = 0, sigma_theta = 2A = 6.6667e-4, sigma_z = 2 nu A = 1.6667e-4,
    //          u = 1.25 (0.5 A + B) = 6.25e-4.
    const LameCylinder lame(1e-3, 0.0, 0.5, 1.0, 0.25);
    const auto in = lame.state(0.5), out = lame.state(1.0);
    CHECK(in.sigma_r == roundoff(-1e-3));
    CHECK(in.sigma_theta == roundoff(5e-3 / 3.0));
    CHECK(in.u_r == roundoff(9.375e-4));
    CHECK(out.sigma_r == Approx(0.0).margin(1e-18));
    CHECK(out.sigma_theta == roundoff(2e-3 / 3.0));
    CHECK(out.sigma_z == roundoff(0.5e-3 / 3.0));
    CHECK(out.u_r == roundoff(6.25e-4));
  }
  SECTION("boundary conditions sigma_r(R_i) = -p_i, sigma_r(R_o) = -p_o, and the field equations") {
    const double p_i = 2e-3, p_o = 5e-4, R_i = 0.138, R_o = 1.0, nu = 0.3;
    const LameCylinder lame(p_i, p_o, R_i, R_o, nu);
    CHECK(lame.state(R_i).sigma_r == roundoff(-p_i));
    CHECK(lame.state(R_o).sigma_r == roundoff(-p_o));
    check_field_equations([&](double r) { return lame.state(r); }, R_i, R_o, nu, p_i);
  }
  SECTION("equal pressures give a uniform hydrostatic state") {
    const LameCylinder lame(1e-3, 1e-3, 0.2, 1.0, 0.25);
    for (double r : {0.2, 0.5, 1.0}) {
      CHECK(lame.state(r).sigma_r == roundoff(-1e-3));
      CHECK(lame.state(r).sigma_theta == roundoff(-1e-3));
      CHECK(lame.state(r).u_r / r == roundoff(-(1.0 + 0.25) * (1.0 - 0.5) * 1e-3));  // eps = -lambda p
    }
  }
}

TEST_CASE("Lame cylinder with a fixed outer surface", "[analytic]") {
  SECTION("hand-checked values: p_i = 1e-3, R_i = 0.5, R_o = 1, nu = 0.25") {
    // u = C r + D/r, sigma_r = C/lambda - D/((1+nu) r^2), lambda = 0.625: 1/lambda = 1.6, 1/(1+nu) = 0.8.
    // u(1) = 0: D = -C. sigma_r(0.5) = C (1.6 + 0.8 * 4) = -1e-3: C = -2.0833e-4, D = 2.0833e-4.
    // r = 0.5: u = -1.0417e-4 + 4.1667e-4 = 3.125e-4; sigma_theta = 1.6 C + 3.2 D = 3.3333e-4.
    // r = 1:   sigma_r = 1.6 C - 0.8 D = -5e-4; sigma_theta = 1.6 C + 0.8 D = -1.6667e-4.
    const LameCylinderFixedOuter lame(1e-3, 0.5, 1.0, 0.25);
    const auto in = lame.state(0.5), out = lame.state(1.0);
    CHECK(in.sigma_r == roundoff(-1e-3));
    CHECK(in.u_r == roundoff(3.125e-4));
    CHECK(in.sigma_theta == roundoff(1e-3 / 3.0));
    CHECK(out.u_r == Approx(0.0).margin(1e-18));
    CHECK(out.sigma_r == roundoff(-5e-4));
    CHECK(out.sigma_theta == roundoff(-0.5e-3 / 3.0));
  }
  SECTION("boundary conditions u(R_o) = 0, sigma_r(R_i) = -p_i, and the field equations") {
    const double p_i = 2e-3, R_i = 0.138, R_o = 1.0, nu = 0.3;
    const LameCylinderFixedOuter lame(p_i, R_i, R_o, nu);
    CHECK(lame.state(R_i).sigma_r == roundoff(-p_i));
    CHECK(lame.state(R_o).u_r == Approx(0.0).margin(1e-16 * p_i));
    check_field_equations([&](double r) { return lame.state(r); }, R_i, R_o, nu, p_i);
  }
  SECTION("the fixed outer surface is stiffer than the free one") {
    const LameCylinder free_outer(1e-3, 0.0, 0.138, 1.0, 0.25);
    const LameCylinderFixedOuter fixed_outer(1e-3, 0.138, 1.0, 0.25);
    CHECK(fixed_outer.state(0.138).u_r < free_outer.state(0.138).u_r);
    CHECK(fixed_outer.state(0.138).u_r > 0.0);
  }
}
