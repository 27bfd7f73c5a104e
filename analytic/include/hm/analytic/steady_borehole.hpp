#pragma once
/// \file
/// Steady state of continuous injection into a borehole (paper Appendix B), with the paper's
/// misprints corrected (docs/errata.md lists each with its evidence).
#include "hm/analytic/radial_state.hpp"

namespace hm::analytic {

/// Annulus R_i <= r <= 1 in plane strain; injection Q into the borehole, p = 0 at r = 1;
/// effective radial stress -(1-b) p_h at r = R_i (total radial stress -p_h: the fluid pushes on
/// the wall; Appendix B's text prints +(1-b) p_h) and 0 at r = 1. With lambda = (1+nu)(1-2nu),
/// a = R_i^2/(1-R_i^2):
///   p = -(Q/2pi) ln r                                                          (B3)
///   u = (b p_h/2) [lambda r (ln r/(1-nu) - 1)/ln R_i
///                  - a (1-2nu)/(1-nu) ((1+nu)/r + lambda r)] + p_h a ((1+nu)/r + lambda r)
///                                                      (B6 corrected; prints (1-nu) ln r - 1)
///   sigma_r, sigma_theta: plane-strain Hooke of u                          (B7, B8 as printed)
///   sigma_z = nu (sigma_r + sigma_theta)      (B9 corrected; prints ln r - 1 + 2nu for ln r - 1/2 + nu)
/// Stresses are effective (sigma_m); total = effective - b p. Dimensionless (E = 1); tension positive.
/// Limits: steady state only (t* >~ 1 for Table 1 values), unfractured, linear poroelastic,
/// 0 < R_i < 1; with b = 0 it reduces to Lame's cylinder under inner pressure p_h.
/// Outside R_i <= r <= 1 the expressions are evaluated as written (smooth for r > 0) but mean nothing.
class SteadyBorehole {
 public:
  /// Q >= 0 injection rate (Eq. 14), 0 <= b <= 1, 0 < nu < 0.5, 0 < R_i < 1 (asserted).
  SteadyBorehole(double Q, double b, double nu, double R_i);

  /// p_h = -(Q/2pi) ln R_i, Eq. 23 (independent of b and nu).
  double borehole_pressure() const;
  /// p, u_r and effective stresses at radius r.
  RadialState state(double r) const;

 private:
  double Q_, b_, nu_, R_i_;
};

}  // namespace hm::analytic
