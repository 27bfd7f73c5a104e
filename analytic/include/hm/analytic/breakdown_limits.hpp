#pragma once
/// \file
/// Limits of the breakdown pressure of the paper's borehole under constant-rate injection (Fig. 18,
/// Section 3.5), from the unfractured 1D model of Appendix A: the annulus R_i <= r <= 1 in plane strain
/// with a free outer surface, p = 0 at r = 1 and total radial stress -p_h at the wall. Dimensionless
/// (over E), tension positive, effective stress of Eq. 1 (sigma_m = sigma + b p).
/// Breakdown is the tensile criterion of failure_criteria.hpp at the wall: the effective hoop stress,
/// the wall's largest principal stress, reaches T_u. Everything is linear in p_h, so each limit is
/// T_u over a stress per unit p_h (no root-finding). Derivations and references: docs/breakdown.md.
/// Limits: no in-situ stress, p0 = 0 (breakdown_insitu.hpp has those for the textbook wall); the
/// Coulomb criterion of Eq. 11 is not checked (docs/breakdown.md shows it is far from met at Table 1
/// strengths).
#include "hm/analytic/physical_parameters.hpp"

namespace hm::analytic {

/// Effective hoop stress on the wall of the 1D model's annulus for any radial pore pressure p(r) with
/// p(R_i) = p_h, p(1) = 0 and area mean p_mean = (2/(1 - R_i^2)) int_{R_i}^1 p r dr:
///   sigma_theta(R_i) = (L + b - 2 eta) p_h + 2 eta p_mean,
/// L = (1 + R_i^2)/(1 - R_i^2) (Lame's wall hoop stress per unit inner pressure),
/// eta = poroelastic_stress_coefficient(b, nu). Exact in quasi-static radial poroelasticity (the
/// thermoelastic analogy); time enters only through p_h and p_mean, whatever the fluid equation.
/// Preconditions: 0 < R_i < 1 (asserted), 0 <= b <= 1, 0 < nu < 0.5.
double annulus_wall_hoop_stress(double p_h, double p_mean, double b, double nu, double R_i);

/// p_mean/p_h of the Q -> infinity limit: the pressurised layer at the wall vanishes, and the rock
/// behind it, stretched by the wall load at no fluid exchange (undrained: E/M p + f b eps_v = 0,
/// f = vol_strain_factor), carries a uniform pressure
///   p_u/p_h = -f b A/((lambda + G) E/M + f b^2),  A = R_i^2/(1 - R_i^2),  lambda + G = 1/(2 (1+nu)(1-2nu)),
/// A being Lame's mean in-plane stress per unit p_h. Negative (a suction); 0 for b = 0 and as R_i -> 0.
/// Validates `m`; 0 < R_i < 1 asserted.
double undrained_bulk_pressure_ratio(const PoroelasticParameters& m, double R_i);

/// p_b_slow: the drained steady state (Appendix B, corrected; SteadyBorehole): T_u over the wall's
/// steady sigma_theta per unit p_h. Reached as Q decreases to minimum_breakdown_rate.
double slow_breakdown_pressure(const DimensionlessParameters& d);

/// p_b_fast: the Q -> infinity limit: T_u/(L + b - 2 eta + 2 eta p_u/p_h) with
/// p_u/p_h = undrained_bulk_pressure_ratio. Limits: the layer sqrt(t/S) must be thin against R_i
/// when the wall fails; docs/breakdown.md gives the 1D model's approach to it.
double fast_breakdown_pressure(const DimensionlessParameters& d);

/// p_b_jacketed: the pressure confined to the hole, p = 0 in the rock (Hubbert-Willis on the finite
/// annulus, annulus_jacketed_breakdown with no far-field stress): T_u/L, independent of b.
double jacketed_breakdown_pressure(const DimensionlessParameters& d);

/// q_min: the smallest Q at which the unfractured 1D model's wall ever fails. The wall stress grows
/// monotonically to its steady value (docs/breakdown.md; tests/fdm1d/test_breakdown_limits.cpp), so
/// q_min is the Q whose steady p_h (Eq. 23) is slow_breakdown_pressure:
///   q_min = 2 pi p_b_slow/ln(1/R_i). At q_min itself the wall reaches T_u only as t -> infinity.
double minimum_breakdown_rate(const DimensionlessParameters& d);

/// The four values of one borehole (the columns of `hmlattice analytic breakdown`).
struct BreakdownLimits {
  double q_min = 0.0;         ///< minimum_breakdown_rate
  double p_b_slow = 0.0;      ///< slow_breakdown_pressure
  double p_b_fast = 0.0;      ///< fast_breakdown_pressure
  double p_b_jacketed = 0.0;  ///< jacketed_breakdown_pressure
};

/// All four; validates `d` (hm::InputError "field = value, allowed: rule"), requires R_i > 0 (a
/// borehole) and ignores d.Q, the iota and the compressive strength.
BreakdownLimits breakdown_limits(const DimensionlessParameters& d);

}  // namespace hm::analytic
