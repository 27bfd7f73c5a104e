// Study (an executable, not a test; it asserts nothing): the breakdown pressure of the unfractured 1D
// model (Appendix A) against the injection rate Q, and how it approaches the limits of
// hm/analytic/breakdown_limits.hpp. Prints, per b of Table 1 (0.2, 0.5, 0.8; E/M by Eq. 22):
//   (a) the premise of q_min: the largest wall hoop stress over a run to steady state over its final
//       value, and the smallest step-to-step change of p_h and of sigma_theta (negative: not monotone);
//   (b) p_b(Q), the 1D model's p_h when its wall first meets the criteria (first_wall_failure), from
//       just above q_min to Q = 10, at n_r = 400 and 4000;
//   (c) the fast limit's convergence in n_r at Q = 1 and 10 (constant dt, t_b/400);
//   (d) its dependence on that dt.
// Run: build/studies/study_breakdown_limits (about a minute). Findings: docs/breakdown.md.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "hm/analytic/breakdown_limits.hpp"
#include "hm/analytic/physical_parameters.hpp"
#include "hm/fdm1d/fdm1d.hpp"
#include "hm/fdm1d/wall_failure.hpp"

namespace {

using hm::analytic::DimensionlessParameters;
using hm::fdm1d::Fdm1dNumerics;

struct Breakdown {
  hm::fdm1d::WallFailure failure;
  long steps = 0;
  double seconds = 0.0;
};

// Runs until the wall fails (or t_end) and interpolates the failure.
Breakdown breakdown_of(const DimensionlessParameters& d, const Fdm1dNumerics& n) {
  const auto start = std::chrono::steady_clock::now();
  const auto res = hm::fdm1d::run_to_wall_failure(d, n);
  return {hm::fdm1d::first_wall_failure(res, d), res.summary.n_steps,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

Fdm1dNumerics growing_steps(int n_r, double dt_initial) {
  Fdm1dNumerics n;
  n.n_r = n_r;
  n.dt_initial = dt_initial;
  n.dt_growth = 1.05;
  n.dt_max = 1.0;
  n.t_end = 300.0;
  n.output_times = {};
  n.probe_radii = {};
  return n;
}

}  // namespace

int main() {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each line as it is measured
  for (const double b : {0.2, 0.5, 0.8}) {
    const DimensionlessParameters base = hm::analytic::table1_borehole(b);
    const auto lim = hm::analytic::breakdown_limits(base);
    std::printf("\n## b = %.1f: q_min = %.6e, p_b_slow = %.6e, p_b_fast = %.6e, p_b_jacketed = %.6e\n", b, lim.q_min,
                lim.p_b_slow, lim.p_b_fast, lim.p_b_jacketed);

    // (a) One run to steady state at Q = q_min (the problem is linear in Q).
    {
      DimensionlessParameters d = base;
      d.Q = lim.q_min;
      Fdm1dNumerics n = growing_steps(400, 1e-6);
      n.dt_max = 10.0;
      n.dt_growth = 1.2;
      const auto res = hm::fdm1d::run_fdm1d(d, n);
      const auto& s = res.borehole;
      double max_hoop = 0.0, min_dp = 0.0, min_dhoop = 0.0, min_ratio = 1e300, max_ratio = 0.0;
      for (std::size_t k = 1; k < s.size(); ++k) {
        max_hoop = std::max(max_hoop, s[k].sigma_theta);
        min_dp = std::min(min_dp, s[k].p_h - s[k - 1].p_h);
        min_dhoop = std::min(min_dhoop, s[k].sigma_theta - s[k - 1].sigma_theta);
        min_ratio = std::min(min_ratio, s[k].sigma_theta / s[k].p_h);
        max_ratio = std::max(max_ratio, s[k].sigma_theta / s[k].p_h);
      }
      std::printf(
          "(a) Q = q_min, n_r = 400, to t = 300 (%ld steps): max sigma_theta / final = %.12f, final / T_u = %.6f,\n"
          "    smallest step change of p_h = %.3e, of sigma_theta = %.3e; sigma_theta/p_h from %.6f to %.6f "
          "(fast limit %.6f, steady %.6f)\n",
          res.summary.n_steps, max_hoop / s.back().sigma_theta, s.back().sigma_theta / d.tensile_strength, min_dp,
          min_dhoop, min_ratio, max_ratio, d.tensile_strength / lim.p_b_fast, d.tensile_strength / lim.p_b_slow);
    }

    // (b) p_b(Q).
    std::printf("(b) %-10s %-12s %-14s %-14s %-9s %-9s\n", "Q", "Q/q_min", "p_b (n_r=400)", "p_b (n_r=4000)", "/slow",
                "/fast");
    for (const double Q :
         {1.01 * lim.q_min, 1.1 * lim.q_min, 2.0 * lim.q_min, 5.0 * lim.q_min, 1e-2, 1e-1, 1.0, 10.0}) {
      DimensionlessParameters d = base;
      d.Q = Q;
      // Steps from a thousandth of the wall-layer time; a fast run fails within a few of them.
      const double t_layer = hm::fdm1d::half_space_time_to_pressure(d, lim.p_b_fast);
      Fdm1dNumerics n = growing_steps(400, std::min(1e-4, 1e-3 * t_layer));
      n.t_end = std::min(300.0, 1e3 * t_layer);
      const Breakdown coarse = breakdown_of(d, n);
      n.n_r = 4000;
      const Breakdown fine = breakdown_of(d, n);
      std::printf("    %-10.4e %-12.4g %-14.6e %-14.6e %-9.5f %-9.5f  (t_b = %.3e, %ld steps, %.1f s)\n", Q,
                  Q / lim.q_min, coarse.failure.p_h, fine.failure.p_h, fine.failure.p_h / lim.p_b_slow,
                  fine.failure.p_h / lim.p_b_fast, fine.failure.t, fine.steps, fine.seconds);
    }

    // (c) The fast limit in n_r: constant dt = t_b/400 (one factorisation).
    for (const double Q : {1.0, 10.0}) {
      DimensionlessParameters d = base;
      d.Q = Q;
      const double t_b = hm::fdm1d::half_space_time_to_pressure(d, lim.p_b_fast);
      std::printf("(c) Q = %g (t_b ~ %.3e, layer sqrt(t_b/S) ~ %.3e):\n", Q, t_b,
                  std::sqrt(t_b / hm::analytic::storage_coefficient(d.material)));
      for (const int n_r : {1000, 3000, 10000, 30000, 100000}) {
        Fdm1dNumerics n = growing_steps(n_r, t_b / 400.0);
        n.dt_growth = 1.0;
        n.dt_max = n.dt_initial;
        n.t_end = 3.0 * t_b;
        const Breakdown r = breakdown_of(d, n);
        std::printf("    n_r = %6d (dr = %.2e): p_b = %.8e, p_b/p_b_fast - 1 = %+.3e (%ld steps, %.1f s)\n", n_r,
                    (1.0 - d.R_i) / n_r, r.failure.p_h, r.failure.p_h / lim.p_b_fast - 1.0, r.steps, r.seconds);
      }
    }

    // (d) The time step at Q = 1, n_r = 30000: constant dt = t_b/400, /800, /1600.
    {
      DimensionlessParameters d = base;
      d.Q = 1.0;
      const double t_b = hm::fdm1d::half_space_time_to_pressure(d, lim.p_b_fast);
      for (const double per : {400.0, 800.0, 1600.0}) {
        Fdm1dNumerics n = growing_steps(30000, t_b / per);
        n.dt_growth = 1.0;
        n.dt_max = n.dt_initial;
        n.t_end = 3.0 * t_b;
        const Breakdown r = breakdown_of(d, n);
        std::printf("(d) Q = 1, n_r = 30000, dt = t_b/%4.0f: p_b = %.8e, p_b/p_b_fast - 1 = %+.3e\n", per,
                    r.failure.p_h, r.failure.p_h / lim.p_b_fast - 1.0);
      }
    }
  }
  return 0;
}
