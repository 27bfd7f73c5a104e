#pragma once
/// \file
/// Breakdown pressure of a borehole under an in-situ horizontal stress: the wall pressure at which
/// the effective hoop stress on the wall reaches the tensile strength. Effective stress as in Eq. 1,
/// sigma_m = sigma + b p (tension positive), so the criterion is sigma_theta + b p = T_u at the wall.
/// Dimensionless (over E). Derivations and references: docs/insitu.md.
#include "hm/analytic/insitu_annulus.hpp"

namespace hm::analytic {

/// Rock and pore fluid for the breakdown criteria.
struct BreakdownParameters {
  /// T_u/E, tensile strength (Table 1: 2e-4). Allowed: T_u > 0.
  double T_u = 2e-4;
  /// p0/E, in-situ pore pressure, compression positive like S_H. Allowed: p0 >= 0.
  double p0 = 0.0;
  /// b, Biot coefficient in the effective stress (1: Terzaghi's, the textbook forms). Allowed: 0 <= b <= 1.
  double b = 1.0;
  /// nu, Poisson ratio. Allowed: 0 < nu < 0.5.
  double nu = 0.25;

  /// Throws hm::InputError "field = value, allowed: rule".
  void validate() const;
};

/// eta = b (1 - 2nu)/(2 (1 - nu)), the poroelastic stress coefficient: a pore-pressure rise dp
/// confined to the rock near a hole in an infinite plane adds -2 eta dp to the wall's hoop stress.
double poroelastic_stress_coefficient(double b, double nu);

/// The wall pressure and the angle (from S_H) at which the largest effective hoop stress on a wall
/// first reaches T_u.
struct WallBreakdown {
  double p_w;    ///< breakdown pressure p_b/E
  double theta;  ///< angle from S_H [rad]; 0 (and pi) for S_H > S_h; every angle ties for S_H = S_h, 0 given
};

/// Hubbert & Willis (1957): Kirsch's wall with a non-penetrating fluid (the pore pressure at the wall
/// stays p0): p_b = 3 S_h - S_H + T_u - b p0 (the textbook form at b = 1), reached at theta = 0 from
/// S_H. Throws hm::InputError for invalid input. A negative p_b means the wall fails in tension
/// before any pressure is applied.
WallBreakdown hubbert_willis_breakdown(const FarFieldStress& far, const BreakdownParameters& m);

/// Haimson & Fairhurst (1967): Kirsch's wall with a penetrating fluid (pore pressure p_w at the wall,
/// p0 far away): p_b = (3 S_h - S_H + T_u - 2 eta p0)/(1 + b - 2 eta) (the textbook
/// (...)/(2 - 2 eta) at b = 1), reached at theta = 0 from S_H. Throws hm::InputError for invalid input.
/// Limits: the poroelastic term assumes the pressure disturbance decays within the infinite plane.
WallBreakdown haimson_fairhurst_breakdown(const FarFieldStress& far, const BreakdownParameters& m);

/// The Hubbert-Willis (jacketed, non-penetrating) criterion on the finite InSituAnnulus of radius
/// ratio R_i: the wall hoop stress is linear in p_w and largest on the S_H axis (its cos 2psi
/// coefficient 4 q (1 + 2 R_i^2)/(1 - R_i^2)^2 is positive), so
/// p_b = (T_u - b p0 - sigma_theta(R_i, 0; p_w = 0))/(d sigma_theta(R_i, 0)/d p_w).
/// Tends to hubbert_willis_breakdown like R_i^2 as R_i -> 0. Throws hm::InputError for invalid input.
WallBreakdown annulus_jacketed_breakdown(const FarFieldStress& far, const BreakdownParameters& m, double R_i);

}  // namespace hm::analytic
