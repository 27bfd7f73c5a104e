#include "hm/analytic/breakdown_limits.hpp"

#include <cassert>

#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/analytic/lame.hpp"
#include "hm/analytic/steady_borehole.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::analytic {

namespace {

void require_borehole(const DimensionlessParameters& d) {
  d.validate();
  if (!(d.R_i > 0.0))
    throw InputError("R_i = " + core::format_value(d.R_i) + ", allowed: 0 < R_i < 1 (the limits are of a borehole)");
}

// Lame's cylinder R_i..1 under unit inner pressure and a free outer surface: the 1D model's
// mechanics with no pore pressure.
RadialState unit_lame_wall(double nu, double R_i) { return LameCylinder(1.0, 0.0, R_i, 1.0, nu).state(R_i); }

// The drained steady state at unit borehole pressure (SteadyBorehole is linear in Q).
double steady_wall_hoop_per_pressure(const DimensionlessParameters& d) {
  const SteadyBorehole steady(1.0, d.material.b, d.material.nu, d.R_i);
  return steady.state(d.R_i).sigma_theta / steady.borehole_pressure();
}

}  // namespace

double annulus_wall_hoop_stress(double p_h, double p_mean, double b, double nu, double R_i) {
  assert(R_i > 0.0 && R_i < 1.0 && "annulus_wall_hoop_stress: need 0 < R_i < 1");
  const double eta = poroelastic_stress_coefficient(b, nu);
  return (unit_lame_wall(nu, R_i).sigma_theta + b - 2.0 * eta) * p_h + 2.0 * eta * p_mean;
}

double undrained_bulk_pressure_ratio(const PoroelasticParameters& m, double R_i) {
  m.validate();
  assert(R_i > 0.0 && R_i < 1.0 && "undrained_bulk_pressure_ratio: need 0 < R_i < 1");
  // Lame's total stress does not depend on the moduli, so the undrained rock carries it too; its
  // mean in-plane part A = (sigma_r + sigma_theta)/2 is the same at every r.
  const RadialState lame = unit_lame_wall(m.nu, R_i);
  const double A = 0.5 * (lame.sigma_r + lame.sigma_theta);
  const double lambda_plus_G = 0.5 / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu));
  const double f_b = vol_strain_factor(m.vol_strain) * m.b;
  return -f_b * A / (lambda_plus_G * m.E_over_M + f_b * m.b);
}

double slow_breakdown_pressure(const DimensionlessParameters& d) {
  require_borehole(d);
  return d.tensile_strength / steady_wall_hoop_per_pressure(d);
}

double fast_breakdown_pressure(const DimensionlessParameters& d) {
  require_borehole(d);
  const double p_u = undrained_bulk_pressure_ratio(d.material, d.R_i);
  return d.tensile_strength / annulus_wall_hoop_stress(1.0, p_u, d.material.b, d.material.nu, d.R_i);
}

double jacketed_breakdown_pressure(const DimensionlessParameters& d) {
  require_borehole(d);
  BreakdownParameters m;
  m.T_u = d.tensile_strength;
  m.p0 = 0.0;
  m.b = d.material.b;
  m.nu = d.material.nu;
  return annulus_jacketed_breakdown(FarFieldStress{}, m, d.R_i).p_w;
}

double minimum_breakdown_rate(const DimensionlessParameters& d) {
  // slow_breakdown_pressure validates; Eq. 23's p_h is linear in Q.
  const double p_b = slow_breakdown_pressure(d);
  return p_b / SteadyBorehole(1.0, d.material.b, d.material.nu, d.R_i).borehole_pressure();
}

BreakdownLimits breakdown_limits(const DimensionlessParameters& d) {
  return {minimum_breakdown_rate(d), slow_breakdown_pressure(d), fast_breakdown_pressure(d),
          jacketed_breakdown_pressure(d)};
}

}  // namespace hm::analytic
