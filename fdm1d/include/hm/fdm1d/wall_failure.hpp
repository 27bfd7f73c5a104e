#pragma once
/// \file
/// Where the unfractured 1D model stops being valid (Appendix A): the first time its borehole wall
/// meets the failure criteria of Section 2.1 (check_failure: sigma_1 reaching T_u, or the Coulomb stress
/// of Eq. 11 reaching C_u), and the borehole pressure then, the 1D model's breakdown pressure.
/// Dimensionless; tension positive.
#include <limits>

#include "hm/analytic/failure_criteria.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace hm::fdm1d {

/// check_failure of the wall's effective principal stresses (sigma_r, sigma_theta, sigma_z) with the
/// strengths and friction of `params`.
hm::analytic::FailureCheck wall_failure_check(const BoreholeSample& wall,
                                              const hm::analytic::DimensionlessParameters& params);

struct WallFailure {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  bool failed = false;  ///< false: the wall stayed below the criteria over the whole run
  double t = none;      ///< when the failure ratio reached 1, linear between the two steps around it
  double p_h = none;    ///< p_h at that time, linear between the same two steps
  hm::analytic::FailureMode mode = hm::analytic::FailureMode::none;  ///< of the later of the two steps
};

/// The first step whose wall ratio is >= 1, interpolated back to ratio 1 (at t = 0 if the very first
/// sample fails). Linear interpolation between implicit-Euler steps adds an error of second order in dt
/// to t and p_h; the steps' own error is first order (fdm1d.hpp).
WallFailure first_wall_failure(const Fdm1dResult& result, const hm::analytic::DimensionlessParameters& params);

}  // namespace hm::fdm1d
