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

/// Runs the 1D model from rest until its wall first meets the criteria (the step whose ratio is >= 1 is
/// the last; status interrupted), or to numerics.t_end (status success, the wall never failed): the
/// breakdown pressure needs nothing after the failure. Pass the result to first_wall_failure.
Fdm1dResult run_to_wall_failure(const hm::analytic::DimensionlessParameters& params, const Fdm1dNumerics& numerics);

/// The time at which the borehole pressure of a flux-loaded half space, p_h = 2 q sqrt(t/(pi S)) with
/// q = Q/(2 pi R_i) and S = storage_coefficient, reaches p: the time scale of a fast injection's wall
/// failure (docs/breakdown.md section 4); the pressurised layer at the wall is then sqrt(t/S) thick.
double half_space_time_to_pressure(const hm::analytic::DimensionlessParameters& params, double p);

}  // namespace hm::fdm1d
