#pragma once
/// \file
/// Lame's thick-walled cylinder in plane strain (a standard elasticity result; used to verify the
/// dry lattice and the first break of a pressurised borehole).
#include "hm/analytic/radial_state.hpp"

namespace hm::analytic {

/// Cylinder R_i <= r <= R_o under inner pressure p_i and outer pressure p_o (pressures positive in
/// compression), plane strain, E = 1, no pore fluid (state.p is 0):
///   sigma_r = A - B/r^2, sigma_theta = A + B/r^2, sigma_z = 2 nu A,
///   A = (p_i R_i^2 - p_o R_o^2)/(R_o^2 - R_i^2), B = (p_i - p_o) R_i^2 R_o^2/(R_o^2 - R_i^2),
///   u_r = (1+nu)((1-2nu) A r + B/r).
/// Limits: 0 < R_i < R_o; linear elastic, isotropic.
class LameCylinder {
 public:
  LameCylinder(double p_i, double p_o, double R_i, double R_o, double nu);
  RadialState state(double r) const;

 private:
  double p_i_, p_o_, R_i_, R_o_, nu_;
};

/// Same cylinder with the outer surface fixed (u_r(R_o) = 0) under inner pressure p_i: the paper's
/// other mechanical boundary condition.
class LameCylinderFixedOuter {
 public:
  LameCylinderFixedOuter(double p_i, double R_i, double R_o, double nu);
  RadialState state(double r) const;

 private:
  double p_i_, R_i_, R_o_, nu_;
};

}  // namespace hm::analytic
