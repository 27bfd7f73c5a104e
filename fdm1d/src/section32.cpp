#include "hm/fdm1d/section32.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "hm/analytic/failure_criteria.hpp"
#include "hm/analytic/steady_borehole.hpp"

namespace hm::fdm1d {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// Time at which a linear segment from (t0, v0) to (t1, v1) crosses `level`.
double crossing(double t0, double v0, double t1, double v1, double level) {
  return v1 == v0 ? t1 : t0 + (level - v0) * (t1 - t0) / (v1 - v0);
}
}  // namespace

double steady_borehole_pressure(double Q, double R_i) { return -Q / (2.0 * std::numbers::pi) * std::log(R_i); }

double time_to_fraction(const Fdm1dResult& result, double p_h_steady, double fraction) {
  if (!(p_h_steady > 0.0)) return nan;
  const double level = fraction * p_h_steady;
  const auto& b = result.borehole;
  for (std::size_t k = 1; k < b.size(); ++k)
    if (b[k].p_h >= level) return crossing(b[k - 1].t, b[k - 1].p_h, b[k].t, b[k].p_h, level);
  return nan;
}

double wall_coulomb_ratio(const BoreholeSample& w) {
  const double sigma_1 = std::max({w.sigma_r, w.sigma_theta, w.sigma_z});
  return sigma_1 > 0.0 ? w.coulomb / sigma_1 : nan;
}

Section32Diagnostics section32_diagnostics(const Fdm1dResult& result,
                                           const hm::analytic::DimensionlessParameters& params) {
  Section32Diagnostics d;
  d.p_h_steady = steady_borehole_pressure(params.Q, params.R_i);
  d.t_99 = time_to_fraction(result, d.p_h_steady, 0.99);
  d.min_pressure = result.min_pressure;

  const auto& b = result.borehole;
  for (std::size_t j = 0; j < result.probe_radii.size(); ++j) {
    ProbeNegativePressure pr;
    pr.r = result.probe_radii[j];
    for (std::size_t k = 1; k < b.size(); ++k) {
      const double p0 = result.probe_p[k - 1][j], p1 = result.probe_p[k][j];
      const double t0 = b[k - 1].t, t1 = b[k].t;
      if (p1 < pr.p_min) {
        pr.p_min = p1;
        pr.t_min = t1;
      }
      // The part of [t0, t1] with p < 0 under linear interpolation.
      if (p0 < 0.0 && p1 < 0.0) {
        pr.time_negative += t1 - t0;
        pr.last_negative_t = t1;
      } else if (p0 < 0.0) {
        const double tc = crossing(t0, p0, t1, p1, 0.0);
        pr.time_negative += tc - t0;
        pr.last_negative_t = tc;
      } else if (p1 < 0.0) {
        pr.time_negative += t1 - crossing(t0, p0, t1, p1, 0.0);
        pr.last_negative_t = t1;
      }
    }
    d.probes.push_back(pr);
  }

  {
    const auto wall =
        hm::analytic::SteadyBorehole(params.Q, params.material.b, params.material.nu, params.R_i).state(params.R_i);
    BoreholeSample w;
    w.sigma_r = wall.sigma_r;
    w.sigma_theta = wall.sigma_theta;
    w.sigma_z = wall.sigma_z;
    const auto mm = hm::analytic::major_minor({wall.sigma_r, wall.sigma_theta, wall.sigma_z});
    w.coulomb = hm::analytic::coulomb_stress(mm.sigma_1, mm.sigma_3, params.friction);
    d.wall_ratio_steady = wall_coulomb_ratio(w);
  }
  d.wall_ratio_final = b.empty() ? nan : wall_coulomb_ratio(b.back());
  d.wall_ratio_min = d.wall_ratio_max = nan;
  for (const auto& w : b) {
    const double ratio = wall_coulomb_ratio(w);
    if (std::isnan(ratio)) continue;
    if (std::isnan(d.wall_ratio_min) || ratio < d.wall_ratio_min) {
      d.wall_ratio_min = ratio;
      d.t_wall_ratio_min = w.t;
    }
    if (std::isnan(d.wall_ratio_max) || ratio > d.wall_ratio_max) {
      d.wall_ratio_max = ratio;
      d.t_wall_ratio_max = w.t;
    }
  }
  return d;
}

}  // namespace hm::fdm1d
