#pragma once
// The 1D model's breakdown pressure (Appendix A, no fracture, flux-boundary borehole: p_h when its wall
// first meets the failure criteria, hm/fdm1d/wall_failure.hpp) at one (b, Q), with its grid study: the
// wall's pressure layer sqrt(t/S) thins as Q grows (docs/breakdown.md section 4), so the grid that
// resolves it depends on Q and is found by refining n_r by 4 until p_b settles. For the Fig. 18
// benchmark (benchmarks_breakdown.cpp).
#include <limits>
#include <vector>

#include "hm/analytic/physical_parameters.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace hm::verification::breakdown {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// One grid's run.
struct GridRun {
  int n_r = 0;
  bool failed = false;  // the wall met the criteria before t_end
  double p_b = kNaN;    // p_h then (first_wall_failure)
  double t_b = kNaN;
  bool tensile = false;         // it failed in tension (the criterion of the lattice's beams)
  double max_wall_ratio = 0.0;  // largest failure ratio of the wall over the run (1 at failure)
  long steps = 0;
  double seconds = 0.0;
};

/// How far to refine.
struct GridStudyPlan {
  std::vector<int> start = {400, 1600, 6400};  // always run: three levels give an observed order
  int n_r_max = 102400;                        // refine by 4 up to this while p_b still moves
  double settled = 1e-3;  // stop when the last refinement moved p_b by less than this (relative), or
                          // when the wall failed on neither of the last two grids
};

/// A grid study of p_b at one (b, Q).
struct GridStudy {
  std::vector<GridRun> levels;  // n_r increasing by 4
  /// log4 of the ratio of the last two changes of p_b (NaN: fewer than three failing levels, or no change).
  double observed_order = kNaN;
  /// The finest level extrapolated with the scheme's order 2 (second order in dr, docs/breakdown.md 6(c)).
  double richardson = kNaN;
  /// |finest / previous - 1|: what the last refinement moved p_b.
  double last_change = kNaN;
  const GridRun& finest() const { return levels.back(); }
};

/// The 1D time steps of a breakdown run at rate d.Q (as studies/breakdown_limits.cpp): from a thousandth
/// of the half-space failure time at p_b_fast (capped at 1e-4), growing by 5% to dt = 1, to t = 1e3 such
/// times (capped at 300, where every transient is gone and a wall that has not failed never will).
fdm1d::Fdm1dNumerics breakdown_numerics(const analytic::DimensionlessParameters& d, int n_r);

/// One run to the wall's first failure (or t_end) on n_r intervals.
GridRun run_grid(const analytic::DimensionlessParameters& d, int n_r);

/// The grid study of `plan` at d (d.Q the rate).
GridStudy run_grid_study(const analytic::DimensionlessParameters& d, const GridStudyPlan& plan);

}  // namespace hm::verification::breakdown
