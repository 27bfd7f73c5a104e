#include "hm/analytic/steady_borehole.hpp"

#include <cassert>
#include <cmath>
#include <numbers>

namespace hm::analytic {

// Derivation (docs/errata.md, "Appendix B"). With lambda = (1+nu)(1-2nu), eta = b lambda/(1-nu) and
// dp/dr = -Q/(2 pi r) = p_h/(r ln R_i), B2 reads ((r u)'/r)' = eta p_h/(r ln R_i), so
//   u = A r ln r + C_1/r + C_2 r,  A = eta p_h/(2 ln R_i)          (B5 corrected: B5 prints -A).
// Hooke gives lambda sigma_r = A ln r + (1-nu) A + C_2 - (1-2nu) C_1/r^2; the two stress conditions
// fix (1-2nu) C_1 = lambda p_h a [(1-b) + b/(2(1-nu))] with a = R_i^2/(1-R_i^2), and
// C_2 = (1-2nu) C_1 - (1-nu) A. Written out, these are the expressions below.

SteadyBorehole::SteadyBorehole(double Q, double b, double nu, double R_i) : Q_(Q), b_(b), nu_(nu), R_i_(R_i) {
  assert(R_i > 0.0 && R_i < 1.0 && "SteadyBorehole: need 0 < R_i < 1");
  assert(nu > 0.0 && nu < 0.5 && "SteadyBorehole: need 0 < nu < 0.5");
  assert(b >= 0.0 && b <= 1.0 && "SteadyBorehole: need 0 <= b <= 1");
}

double SteadyBorehole::borehole_pressure() const { return -Q_ / (2.0 * std::numbers::pi) * std::log(R_i_); }

RadialState SteadyBorehole::state(double r) const {
  assert(r > 0.0 && "SteadyBorehole::state: need r > 0");
  const double nu = nu_, b = b_;
  const double p_h = borehole_pressure();
  const double lambda = (1.0 + nu) * (1.0 - 2.0 * nu);
  const double ln_Ri = std::log(R_i_), ln_r = std::log(r);
  const double a = R_i_ * R_i_ / (1.0 - R_i_ * R_i_);
  const double c = (1.0 - 2.0 * nu) / (1.0 - nu);
  const double inv_r2 = 1.0 / (r * r);

  RadialState s;
  // B3.
  s.p = -Q_ / (2.0 * std::numbers::pi) * ln_r;
  // B6 (corrected): the paper prints ((1-nu) ln r - 1) where ln r/(1-nu) - 1 is right.
  s.u_r = 0.5 * b * p_h * (lambda * r / ln_Ri * (ln_r / (1.0 - nu) - 1.0) - a * c * ((1.0 + nu) / r + lambda * r)) +
          p_h * a * ((1.0 + nu) / r + lambda * r);
  // B7 (as printed; it is the Hooke radial stress of the corrected B6).
  s.sigma_r = 0.5 * b * p_h * (ln_r / ((1.0 - nu) * ln_Ri) + a * c * (inv_r2 - 1.0)) + p_h * a * (1.0 - inv_r2);
  // B8 (as printed; the Hooke hoop stress of the corrected B6).
  s.sigma_theta = 0.5 * b * p_h * ((ln_r - 1.0 + 2.0 * nu) / ((1.0 - nu) * ln_Ri) - a * c * (inv_r2 + 1.0)) +
                  p_h * a * (inv_r2 + 1.0);
  // B9 (corrected) = nu (B7 + B8): the paper prints (ln r - 1 + 2nu) where (ln r - 1/2 + nu) is right.
  s.sigma_z = b * p_h * nu * ((ln_r - 0.5 + nu) / ((1.0 - nu) * ln_Ri) - a * c) + 2.0 * p_h * nu * a;
  return s;
}

}  // namespace hm::analytic
