#include "hm/analytic/failure_criteria.hpp"

#include <algorithm>
#include <cmath>

namespace hm::analytic {

Principal2D principal_stresses(double s_xx, double s_yy, double s_xy) {
  const PrincipalPair p = principal_pair(s_xx, s_yy, s_xy);
  return {p.sigma_1, p.sigma_3, 0.5 * std::atan2(2.0 * s_xy, s_xx - s_yy)};
}

MajorMinor major_minor(const std::array<double, 3>& principal) {
  const auto [lo, hi] = std::minmax_element(principal.begin(), principal.end());
  return {*hi, *lo};
}

double coulomb_stress(double sigma_1, double sigma_3, double friction) {
  return coulomb_factor(friction) * sigma_1 - sigma_3;
}

FailureCheck check_failure(double sigma_1, double sigma_3, double tensile_strength, double compressive_strength,
                           double friction) {
  const double tensile = sigma_1 / tensile_strength;
  const double shear = coulomb_stress(sigma_1, sigma_3, friction) / compressive_strength;
  const double ratio = std::max(tensile, shear);
  if (ratio < 1.0) return {FailureMode::none, ratio};
  return {tensile >= shear ? FailureMode::tensile : FailureMode::shear, ratio};
}

}  // namespace hm::analytic
