#include "hm/fdm1d/wall_failure.hpp"

#include <numbers>

namespace hm::fdm1d {

namespace an = hm::analytic;

an::FailureCheck wall_failure_check(const BoreholeSample& wall, const an::DimensionlessParameters& params) {
  const an::MajorMinor mm = an::major_minor({wall.sigma_r, wall.sigma_theta, wall.sigma_z});
  return an::check_failure(mm.sigma_1, mm.sigma_3, params.tensile_strength, params.compressive_strength,
                           params.friction);
}

WallFailure first_wall_failure(const Fdm1dResult& result, const an::DimensionlessParameters& params) {
  WallFailure f;
  const auto& s = result.borehole;
  double before = 0.0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const an::FailureCheck c = wall_failure_check(s[k], params);
    if (c.ratio >= 1.0) {
      const double w = k == 0 ? 1.0 : (1.0 - before) / (c.ratio - before);
      const BoreholeSample& a = s[k == 0 ? 0 : k - 1];
      f.failed = true;
      f.t = a.t + w * (s[k].t - a.t);
      f.p_h = a.p_h + w * (s[k].p_h - a.p_h);
      f.mode = c.mode;
      return f;
    }
    before = c.ratio;
  }
  return f;
}

Fdm1dResult run_to_wall_failure(const an::DimensionlessParameters& params, const Fdm1dNumerics& numerics) {
  bool failed = false;
  return run_fdm1d(
      params, numerics, {},
      [&](const Fdm1dResult& so_far) { failed = wall_failure_check(so_far.borehole.back(), params).ratio >= 1.0; },
      [&] { return failed; });
}

double half_space_time_to_pressure(const an::DimensionlessParameters& params, double p) {
  const double q = params.Q / (2.0 * std::numbers::pi * params.R_i);
  const double half = p / (2.0 * q);
  return std::numbers::pi * an::storage_coefficient(params.material) * half * half;
}

}  // namespace hm::fdm1d
