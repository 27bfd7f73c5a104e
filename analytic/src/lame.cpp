#include "hm/analytic/lame.hpp"

#include <cassert>

namespace hm::analytic {

LameCylinder::LameCylinder(double p_i, double p_o, double R_i, double R_o, double nu)
    : p_i_(p_i), p_o_(p_o), R_i_(R_i), R_o_(R_o), nu_(nu) {
  assert(R_i > 0.0 && R_o > R_i && "LameCylinder: need 0 < R_i < R_o");
}

RadialState LameCylinder::state(double r) const {
  const double a2 = R_i_ * R_i_, b2 = R_o_ * R_o_;
  const double A = (p_i_ * a2 - p_o_ * b2) / (b2 - a2);
  const double B = (p_i_ - p_o_) * a2 * b2 / (b2 - a2);
  RadialState s;
  s.u_r = (1.0 + nu_) * ((1.0 - 2.0 * nu_) * A * r + B / r);
  s.sigma_r = A - B / (r * r);
  s.sigma_theta = A + B / (r * r);
  s.sigma_z = 2.0 * nu_ * A;
  return s;
}

LameCylinderFixedOuter::LameCylinderFixedOuter(double p_i, double R_i, double R_o, double nu)
    : p_i_(p_i), R_i_(R_i), R_o_(R_o), nu_(nu) {
  assert(R_i > 0.0 && R_o > R_i && "LameCylinderFixedOuter: need 0 < R_i < R_o");
}

RadialState LameCylinderFixedOuter::state(double r) const {
  // u = C r + D/r; u(R_o) = 0 and sigma_r(R_i) = -p_i, with
  // sigma_r = C/((1+nu)(1-2nu)) - D/((1+nu) r^2) for E = 1 in plane strain.
  const double a2 = R_i_ * R_i_, b2 = R_o_ * R_o_;
  const double k1 = 1.0 / ((1.0 + nu_) * (1.0 - 2.0 * nu_)), k2 = 1.0 / (1.0 + nu_);
  // D = -C b2, so sigma_r(R_i) = C (k1 + k2 b2/a2) = -p_i.
  const double C = -p_i_ / (k1 + k2 * b2 / a2);
  const double D = -C * b2;
  RadialState s;
  s.u_r = C * r + D / r;
  set_plane_strain_stresses(s, nu_, C - D / (r * r), C + D / (r * r));
  return s;
}

}  // namespace hm::analytic
