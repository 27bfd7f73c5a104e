// Breakdown-pressure limits of the unfractured borehole (hm/analytic/breakdown_limits.hpp): the wall
// formula against Appendix B's steady state and Lame, the fast limit against a direct construction of
// its state, the failure criterion at the limits, the b = 0 coincidence, and bad input.
// The 1D model's own approach to the limits is tested in tests/fdm1d/test_breakdown_limits.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "approx.hpp"
#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/analytic/breakdown_limits.hpp"
#include "hm/analytic/failure_criteria.hpp"
#include "hm/analytic/lame.hpp"
#include "hm/analytic/radial_state.hpp"
#include "hm/analytic/steady_borehole.hpp"
#include "hm/core/input_error.hpp"

using namespace hm::analytic;
using hm::test::roundoff;

namespace {

// Area mean of the steady pressure p = p_h ln r/ln R_i over the annulus, by hand:
// (2/(1 - R_i^2)) (p_h/ln R_i) int_{R_i}^1 r ln r dr, int r ln r = r^2 ln r/2 - r^2/4.
double steady_mean_pressure(double p_h, double R_i) {
  const double integral = -0.25 - 0.5 * R_i * R_i * std::log(R_i) + 0.25 * R_i * R_i;
  return 2.0 / (1.0 - R_i * R_i) * p_h / std::log(R_i) * integral;
}

// The Q -> infinity state built directly from displacements: u = C2 r + C1/r behind the layer,
// undrained there (E/M p_u + f b 2 C2 = 0), total radial stress -p_h at the wall and 0 at r = 1
// (both carried through the vanishing layer); in the layer p = p_h, u is continuous and Eq. A3's
// eps_v = c p + const (c = b (1+nu)(1-2nu)/(1-nu)) makes eps_v jump by c (p_h - p_u).
RadialState fast_limit_wall(const DimensionlessParameters& d, double p_h) {
  const double nu = d.material.nu, b = d.material.b, R_i = d.R_i;
  const double f_b = vol_strain_factor(d.material.vol_strain) * b;
  const double pu_per_C2 = -2.0 * f_b / d.material.E_over_M;
  // Total radial stress at r of the unit states (C2 = 1, C1 = 0) and (C2 = 0, C1 = 1).
  const auto total_r = [&](double C2, double C1, double r) {
    RadialState s;
    set_plane_strain_stresses(s, nu, C2 - C1 / (r * r), C2 + C1 / (r * r));
    return s.sigma_r - b * pu_per_C2 * C2;
  };
  // [a11 a12; a21 a22] (C2, C1) = (-p_h, 0).
  const double a11 = total_r(1, 0, R_i), a12 = total_r(0, 1, R_i), a21 = total_r(1, 0, 1.0), a22 = total_r(0, 1, 1.0);
  const double det = a11 * a22 - a12 * a21;
  const double C2 = -p_h * a22 / det, C1 = p_h * a21 / det;
  const double p_u = pu_per_C2 * C2;
  const double jump = b * oedometric_compliance(nu) * (p_h - p_u);
  const double eps_theta = C2 + C1 / (R_i * R_i);
  const double eps_v = 2.0 * C2 + jump;
  RadialState wall;
  wall.p = p_h;
  wall.u_r = eps_theta * R_i;
  set_plane_strain_stresses(wall, nu, eps_v - eps_theta, eps_theta);
  return wall;
}

}  // namespace

TEST_CASE("The annulus wall formula gives Appendix B's steady wall hoop stress", "[analytic]") {
  for (const double b : {0.0, 0.2, 0.5, 0.8, 1.0})
    for (const double nu : {0.1, 0.25, 0.4})
      for (const double R_i : {0.05, 0.138, 0.5}) {
        CAPTURE(b, nu, R_i);
        const SteadyBorehole steady(0.01, b, nu, R_i);
        const double p_h = steady.borehole_pressure();
        CHECK(annulus_wall_hoop_stress(p_h, steady_mean_pressure(p_h, R_i), b, nu, R_i) ==
              roundoff(steady.state(R_i).sigma_theta));
      }
}

TEST_CASE("Without pore pressure the annulus wall formula is Lame's wall", "[analytic]") {
  // p_mean = p_h = 0 in the rock is not a state of the formula (p_h is the rock's wall value); with
  // b = 0 the pore pressure does not act on the solid at all, whatever it is.
  for (const double R_i : {0.05, 0.138, 0.5}) {
    CAPTURE(R_i);
    const double lame = LameCylinder(1e-3, 0.0, R_i, 1.0, 0.25).state(R_i).sigma_theta;
    CHECK(annulus_wall_hoop_stress(1e-3, 0.3e-3, 0.0, 0.25, R_i) == roundoff(lame));
    // Lame by hand: sigma_theta(R_i) = p (1 + R_i^2)/(1 - R_i^2).
    CHECK(lame == roundoff(1e-3 * (1.0 + R_i * R_i) / (1.0 - R_i * R_i)));
  }
}

TEST_CASE("The fast limit is the wall of the directly built undrained state with its pressurised layer", "[analytic]") {
  for (const double b : {0.0, 0.2, 0.5, 0.8, 1.0})
    for (const VolStrain v : {VolStrain::plane_strain, VolStrain::appendix_a}) {
      CAPTURE(b, hm::core::name_of(v));
      DimensionlessParameters d = table1_borehole(b, 0.01, v);
      const double p_b = fast_breakdown_pressure(d);
      const RadialState wall = fast_limit_wall(d, p_b);
      // The construction meets the wall condition of Appendix A: effective sigma_r = -(1 - b) p_h.
      CHECK(wall.sigma_r == roundoff(-(1.0 - b) * p_b));
      // At p_b_fast its hoop stress is T_u (the 2x2 solve's round-off).
      CHECK(wall.sigma_theta == Approx(d.tensile_strength).epsilon(1e-12));
    }
}

TEST_CASE("The undrained bulk pressure is a suction that vanishes without coupling", "[analytic]") {
  PoroelasticParameters m = table1_borehole(0.5).material;
  CHECK(undrained_bulk_pressure_ratio(m, 0.138) < 0.0);
  m.b = 0.0;
  CHECK(undrained_bulk_pressure_ratio(m, 0.138) == 0.0);
  // Incompressible constituents (E/M -> 0): the rock cannot change volume, so the pore fluid carries
  // Lame's whole mean stress A = R_i^2/(1 - R_i^2) per unit p_h: -b p_u = A.
  m.b = 1.0;
  m.E_over_M = 1e-14;
  const double A = 0.138 * 0.138 / (1.0 - 0.138 * 0.138);
  CHECK(-undrained_bulk_pressure_ratio(m, 0.138) == Approx(A).epsilon(1e-12));
}

TEST_CASE("At each limit the wall fails in tension with the hoop stress as its largest principal stress",
          "[analytic]") {
  for (const double b : {0.0, 0.2, 0.5, 0.8, 1.0}) {
    CAPTURE(b);
    DimensionlessParameters d = table1_borehole(b);
    const BreakdownLimits l = breakdown_limits(d);
    // Slow: the steady state at q_min, whose p_h (Eq. 23) is p_b_slow.
    const SteadyBorehole steady(l.q_min, b, d.material.nu, d.R_i);
    CHECK(steady.borehole_pressure() == roundoff(l.p_b_slow));
    // By hand: q_min = 2 pi p_b_slow/ln(1/R_i).
    CHECK(l.q_min == roundoff(2.0 * std::numbers::pi * l.p_b_slow / -std::log(d.R_i)));
    const RadialState slow_wall = steady.state(d.R_i);
    const RadialState fast_wall = fast_limit_wall(d, l.p_b_fast);
    const RadialState jacketed_wall = LameCylinder(l.p_b_jacketed, 0.0, d.R_i, 1.0, d.material.nu).state(d.R_i);
    for (const RadialState& s : {slow_wall, fast_wall, jacketed_wall}) {
      const MajorMinor mm = major_minor({s.sigma_r, s.sigma_theta, s.sigma_z});
      CHECK(mm.sigma_1 == s.sigma_theta);
      const FailureCheck c =
          check_failure(mm.sigma_1, mm.sigma_3, d.tensile_strength, d.compressive_strength, d.friction);
      // Ratio 1 to round-off (so the mode may read none at 1 - 1e-16), reached by sigma_1/T_u.
      CHECK(c.ratio == Approx(1.0).epsilon(1e-12));
      CHECK(mm.sigma_1 / d.tensile_strength == Approx(c.ratio).epsilon(1e-15));
      // Eq. 11's Coulomb stress is far below C_u at Table 1's strengths (0.30-0.36 C_u: 5.04 T_u + (1 - b) p_b).
      CHECK(coulomb_stress(mm.sigma_1, mm.sigma_3, d.friction) < 0.5 * d.compressive_strength);
    }
  }
}

TEST_CASE("The three breakdown pressures coincide at b = 0 and are ordered slow < fast < jacketed above it",
          "[analytic]") {
  // b = 0: the pore pressure does not load the solid, so every rate sees Lame's wall.
  const DimensionlessParameters dry = table1_borehole(0.0);
  const BreakdownLimits l0 = breakdown_limits(dry);
  const double lame = dry.tensile_strength * (1.0 - 0.138 * 0.138) / (1.0 + 0.138 * 0.138);
  CHECK(l0.p_b_jacketed == roundoff(lame));
  CHECK(l0.p_b_slow == roundoff(lame));
  CHECK(l0.p_b_fast == roundoff(lame));
  double previous_slow = l0.p_b_slow, previous_fast = l0.p_b_fast;
  for (const double b : {0.2, 0.5, 0.8, 1.0}) {
    CAPTURE(b);
    const BreakdownLimits l = breakdown_limits(table1_borehole(b));
    CHECK(l.p_b_slow < l.p_b_fast);
    CHECK(l.p_b_fast < l.p_b_jacketed);
    CHECK(l.p_b_jacketed == roundoff(lame));  // no fluid in the rock: independent of b
    // Both limits fall with b: the fluid in the rock, or in the layer, adds tension to the wall.
    CHECK(l.p_b_slow < previous_slow);
    CHECK(l.p_b_fast < previous_fast);
    previous_slow = l.p_b_slow;
    previous_fast = l.p_b_fast;
  }
}

TEST_CASE("The jacketed breakdown is Hubbert-Willis on the finite annulus without far-field stress", "[analytic]") {
  const DimensionlessParameters d = table1_borehole(0.5);
  BreakdownParameters m;
  m.T_u = d.tensile_strength;
  m.b = 0.5;
  CHECK(jacketed_breakdown_pressure(d) == roundoff(annulus_jacketed_breakdown(FarFieldStress{}, m, 0.138).p_w));
}

TEST_CASE("Breakdown limits refuse invalid parameters and a point injection", "[analytic]") {
  DimensionlessParameters d = table1_borehole(0.5);
  d.R_i = 0.0;
  CHECK_THROWS_AS(breakdown_limits(d), hm::InputError);
  CHECK_THROWS_WITH(breakdown_limits(d), Catch::StartsWith("R_i = 0, allowed: 0 < R_i < 1"));
  d = table1_borehole(0.5);
  d.material.b = 1.5;
  CHECK_THROWS_WITH(breakdown_limits(d), Catch::StartsWith("b = 1.5, allowed: 0 <= b <= 1"));
  d = table1_borehole(0.5);
  d.tensile_strength = -1.0;
  CHECK_THROWS_WITH(fast_breakdown_pressure(d), Catch::StartsWith("tensile_strength = -1"));
}
