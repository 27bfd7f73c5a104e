#include "hm/analytic/insitu_annulus.hpp"

#include <cmath>
#include <string>

#include "hm/analytic/lame.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::analytic {

using namespace hm::core;  // require_* and format_value

namespace {

// The deviatoric part of the load, phi = (A r^2 + B r^4 + C r^-2 + D) cos 2psi, with the plane-strain
// displacements of each term (kappa = 3 - 4 nu, 2 mu = 1/(1 + nu) for E = 1; Barber, Elasticity,
// Ch. 9). These displacements carry no rigid-body part: u_theta vanishes on the principal axes.
struct MichellCos2 {
  double A, B, C, D;
};

PolarState michell_cos2(const MichellCos2& m, double nu, double r, double psi) {
  const double c = std::cos(2.0 * psi), s = std::sin(2.0 * psi);
  const double r2 = r * r, ir2 = 1.0 / r2, ir4 = ir2 * ir2;
  const double kappa = 3.0 - 4.0 * nu, two_mu = 1.0 / (1.0 + nu);
  PolarState st;
  st.sigma_r = -(2.0 * m.A + 6.0 * m.C * ir4 + 4.0 * m.D * ir2) * c;
  st.sigma_theta = (2.0 * m.A + 12.0 * m.B * r2 + 6.0 * m.C * ir4) * c;
  st.sigma_rtheta = (2.0 * m.A + 6.0 * m.B * r2 - 6.0 * m.C * ir4 - 2.0 * m.D * ir2) * s;
  st.u_r = (-2.0 * m.A * r + (kappa - 3.0) * m.B * r2 * r + 2.0 * m.C * ir2 / r + (kappa + 1.0) * m.D / r) * c / two_mu;
  st.u_theta =
      (2.0 * m.A * r + (kappa + 3.0) * m.B * r2 * r + 2.0 * m.C * ir2 / r - (kappa - 1.0) * m.D / r) * s / two_mu;
  return st;
}

// The isotropic part adds a purely radial field.
PolarState plus_radial(PolarState st, double u_r, double sigma_r, double sigma_theta) {
  st.u_r += u_r;
  st.sigma_r += sigma_r;
  st.sigma_theta += sigma_theta;
  return st;
}

double mean_stress(const FarFieldStress& f) { return 0.5 * (f.S_H + f.S_h); }
double deviator(const FarFieldStress& f) { return 0.5 * (f.S_H - f.S_h); }

void validate_common(const FarFieldStress& far, double p_w, double nu) {
  far.validate();
  require_finite(p_w, "p_w");
  require_open(nu, "nu", 0.0, 0.5);
}

}  // namespace

void FarFieldStress::validate() const {
  require_non_negative(S_H, "S_H");
  // S_H names the larger magnitude; a swapped pair is a typo, not a rotated field.
  if (!(S_h >= 0.0 && S_h <= S_H))
    throw InputError("S_h = " + format_value(S_h) + ", allowed: 0 <= S_h <= S_H (" + format_value(S_H) + ")");
  require_finite(theta_H, "theta_H");
}

InSituAnnulus::InSituAnnulus(const FarFieldStress& far, double p_w, double R_i, double nu)
    : far_(far), p_w_(p_w), R_i_(R_i), nu_(nu) {
  validate_common(far, p_w, nu);
  require_open(R_i, "R_i", 0.0, 1.0);
}

PolarState InSituAnnulus::state(double r, double theta) const {
  require_closed(r, "r", R_i_, 1.0);
  require_finite(theta, "theta");
  const double q = deviator(far_);
  const double a2 = R_i_ * R_i_, a4 = a2 * a2, m = 1.0 - a2, m3 = m * m * m;
  // The four traction conditions (docs/insitu.md) solved in closed form.
  const MichellCos2 dev{q * (1.0 + a2 + 4.0 * a4) / (2.0 * m3), -q * a2 / m3, q * a4 * (1.0 + a2) / (2.0 * m3),
                        -q * a2 * (1.0 + a2 + a4) / m3};
  const RadialState iso = LameCylinder(p_w_, mean_stress(far_), R_i_, 1.0, nu_).state(r);
  return plus_radial(michell_cos2(dev, nu_, r, theta - far_.theta_H), iso.u_r, iso.sigma_r, iso.sigma_theta);
}

KirschHole::KirschHole(const FarFieldStress& far, double p_w, double a, double nu)
    : far_(far), p_w_(p_w), a_(a), nu_(nu) {
  validate_common(far, p_w, nu);
  require_positive(a, "a");
}

PolarState KirschHole::state(double r, double theta) const {
  if (!(r >= a_) || !std::isfinite(r))
    throw InputError("r = " + format_value(r) + ", allowed: a <= r < inf (a = " + format_value(a_) + ")");
  require_finite(theta, "theta");
  const double q = deviator(far_), P = mean_stress(far_);
  const double a2 = a_ * a_;
  const MichellCos2 dev{0.5 * q, 0.0, 0.5 * q * a2 * a2, -q * a2};
  // Lame's sigma = A -+ B/r^2, u = (1+nu)((1-2nu) A r + B/r) with R_o -> infinity: A = -P, B = (p_w - P) a^2.
  const double A = -P, B = (p_w_ - P) * a2;
  const double u = (1.0 + nu_) * ((1.0 - 2.0 * nu_) * A * r + B / r);
  return plus_radial(michell_cos2(dev, nu_, r, theta - far_.theta_H), u, A - B / (r * r), A + B / (r * r));
}

}  // namespace hm::analytic
