#pragma once
/// \file
/// Steady state of continuous injection into a borehole (paper Appendix B), with the paper's
/// misprints corrected (docs/errata.md lists each with its evidence).
#include "hm/analytic/radial_state.hpp"

namespace hm::analytic {

/// Annulus R_i <= r <= 1 in plane strain; injection Q into the borehole, p = 0 at r = 1;
/// effective radial stress -(1-b) p_h at r = R_i (fluid pushing on the wall) and 0 at r = 1.
///   p = -(Q/2pi) ln r (B3);  u solves B2 with those stress conditions (corrected B6);
///   effective stresses from u by plane-strain Hooke's law (corrected B7-B9).
/// Dimensionless (E = 1); tension positive. Limits: steady state only, unfractured, 0 < R_i < 1.
class SteadyBorehole {
 public:
  SteadyBorehole(double Q, double b, double nu, double R_i);

  /// p_h = -(Q/2pi) ln R_i, Eq. 23.
  double borehole_pressure() const;
  RadialState state(double r) const;

 private:
  double Q_, b_, nu_, R_i_;
};

}  // namespace hm::analytic
