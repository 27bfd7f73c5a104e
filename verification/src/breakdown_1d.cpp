// The 1D model's breakdown pressure and its grid study: see breakdown_1d.hpp.
#include "breakdown_1d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "hm/analytic/breakdown_limits.hpp"
#include "hm/fdm1d/wall_failure.hpp"

namespace hm::verification::breakdown {

fdm1d::Fdm1dNumerics breakdown_numerics(const analytic::DimensionlessParameters& d, int n_r) {
  const double t_layer = fdm1d::half_space_time_to_pressure(d, analytic::fast_breakdown_pressure(d));
  fdm1d::Fdm1dNumerics n;
  n.n_r = n_r;
  n.dt_initial = std::min(1e-4, 1e-3 * t_layer);
  n.dt_growth = 1.05;
  n.dt_max = 1.0;
  n.t_end = std::min(300.0, 1e3 * t_layer);
  n.output_times = {};
  n.probe_radii = {};
  return n;
}

GridRun run_grid(const analytic::DimensionlessParameters& d, int n_r) {
  const auto start = std::chrono::steady_clock::now();
  const fdm1d::Fdm1dResult res = fdm1d::run_to_wall_failure(d, breakdown_numerics(d, n_r));
  if (!res.summary.is_success() && res.summary.status != fdm1d::Fdm1dSummary::Status::interrupted)
    throw std::runtime_error("fdm1d at n_r = " + std::to_string(n_r) + " failed: " + res.summary.message);
  GridRun g;
  g.n_r = n_r;
  const fdm1d::WallFailure f = fdm1d::first_wall_failure(res, d);
  g.failed = f.failed;
  g.p_b = f.p_h;
  g.t_b = f.t;
  g.tensile = f.mode == analytic::FailureMode::tensile;
  for (const auto& s : res.borehole)
    g.max_wall_ratio = std::max(g.max_wall_ratio, fdm1d::wall_failure_check(s, d).ratio);
  g.steps = res.summary.n_steps;
  g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return g;
}

GridStudy run_grid_study(const analytic::DimensionlessParameters& d, const GridStudyPlan& plan) {
  GridStudy s;
  for (int n_r : plan.start) s.levels.push_back(run_grid(d, n_r));
  const auto change = [&] {
    const std::size_t k = s.levels.size();
    return std::abs(s.levels[k - 1].p_b / s.levels[k - 2].p_b - 1.0);
  };
  // Settled: p_b moved by less than plan.settled, or the wall failed on neither of the last two grids
  // (below q_min: nothing to converge). One failing and one not is unsettled.
  const auto settled = [&] {
    const std::size_t k = s.levels.size();
    return change() < plan.settled || (!s.levels[k - 1].failed && !s.levels[k - 2].failed);
  };
  while (!settled() && s.levels.back().n_r * 4 <= plan.n_r_max)
    s.levels.push_back(run_grid(d, s.levels.back().n_r * 4));
  s.last_change = change();
  const std::size_t k = s.levels.size();
  const double f1 = s.levels[k - 3].p_b, f2 = s.levels[k - 2].p_b, f3 = s.levels[k - 1].p_b;
  if (std::isfinite(f1 - f2) && std::isfinite(f2 - f3) && f2 != f3)
    s.observed_order = std::log(std::abs((f1 - f2) / (f2 - f3))) / std::log(4.0);
  if (std::isfinite(f3 - f2)) s.richardson = f3 + (f3 - f2) / 15.0;  // 4^2 - 1
  return s;
}

}  // namespace hm::verification::breakdown
