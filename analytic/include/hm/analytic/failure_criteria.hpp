#pragma once
/// \file
/// Principal stresses and the paper's failure criteria (Section 2.1, Eq. 11, Fig. 3). Tension positive.
#include <array>
#include <cmath>

#include "hm/core/enum_names.hpp"

namespace hm::analytic {

/// In-plane principal stresses of (s_xx, s_yy, s_xy), sigma_1 >= sigma_3, without the angle (an atan2
/// per call): the form for loops over every beam. principal_stresses gives the same two values.
struct PrincipalPair {
  double sigma_1;
  double sigma_3;
};
inline PrincipalPair principal_pair(double s_xx, double s_yy, double s_xy) {
  const double mean = 0.5 * (s_xx + s_yy);
  const double radius = std::hypot(0.5 * (s_xx - s_yy), s_xy);
  return {mean + radius, mean - radius};
}

/// Principal values of a symmetric 2D tensor, sigma_1 >= sigma_2, and the angle (rad) of sigma_1's
/// direction from the x axis.
struct Principal2D {
  double sigma_1;
  double sigma_2;
  double angle;
};
Principal2D principal_stresses(double s_xx, double s_yy, double s_xy);

/// Largest and smallest of three principal stresses (e.g. sigma_r, sigma_theta, sigma_z).
struct MajorMinor {
  double sigma_1;  ///< major (most tensile)
  double sigma_3;  ///< minor (most compressive)
};
MajorMinor major_minor(const std::array<double, 3>& principal);

/// Eq. 11's factor K = [(1 + mu_i^2)^(1/2) + mu_i]^2 on sigma_1 (formed once for loops over every beam).
inline double coulomb_factor(double friction) {
  const double k = std::sqrt(1.0 + friction * friction) + friction;
  return k * k;
}

/// Coulomb stress of Eq. 11: [(1 + mu_i^2)^(1/2) + mu_i]^2 sigma_1 - sigma_3 (tension positive;
/// shear failure when it exceeds C_u). Equivalent to the compression-positive Coulomb line
/// sigma_1' = C_u + K sigma_3' with K = [(1+mu^2)^(1/2)+mu]^2.
double coulomb_stress(double sigma_1, double sigma_3, double friction);

/// Failure mode of a stress state against T_u and C_u; `none` if neither criterion is met.
enum class FailureMode { none, tensile, shear };
constexpr auto enum_names(FailureMode) {
  return core::enum_table<FailureMode>(
      {{FailureMode::none, "none"}, {FailureMode::tensile, "tensile"}, {FailureMode::shear, "shear"}});
}

/// Which criterion a stress state exceeds, and by how much relative to its strength
/// (max(sigma_1/T_u, sigma_CC/C_u)); the mode is the one with the larger ratio.
struct FailureCheck {
  FailureMode mode;
  double ratio;  ///< >= 1 means failure
};
FailureCheck check_failure(double sigma_1, double sigma_3, double tensile_strength, double compressive_strength,
                           double friction);

}  // namespace hm::analytic
