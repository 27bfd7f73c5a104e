#include "fdm1d_sampling.hpp"

#include <algorithm>
#include <cmath>

namespace hm::verification {

double interpolate(const std::vector<double>& r, const std::vector<double>& f, double x) {
  if (x <= r.front()) return f.front();
  if (x >= r.back()) return f.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(r.begin(), r.end(), x) - r.begin());
  const double w = (x - r[i - 1]) / (r[i] - r[i - 1]);
  return (1.0 - w) * f[i - 1] + w * f[i];
}

double shell_mean(const std::vector<double>& r, const std::vector<double>& f, double r0, double r1) {
  constexpr int m = 400;
  double num = 0.0, den = 0.0;
  for (int k = 0; k <= m; ++k) {
    const double x = r0 + (r1 - r0) * k / m, w = (k == 0 || k == m) ? 0.5 : 1.0;
    num += w * interpolate(r, f, x) * x;
    den += w * x;
  }
  return num / den;
}

double borehole_pressure_at(const fdm1d::Fdm1dResult& result, double t) {
  const auto& h = result.borehole;
  if (t <= h.front().t) return h.front().p_h;
  if (t >= h.back().t) return h.back().p_h;
  const auto it =
      std::lower_bound(h.begin(), h.end(), t, [](const fdm1d::BoreholeSample& s, double x) { return s.t < x; });
  const std::size_t i = static_cast<std::size_t>(it - h.begin());
  if (std::abs(h[i].t - t) <= 1e-12 * t) return h[i].p_h;
  const double w = (t - h[i - 1].t) / (h[i].t - h[i - 1].t);
  return (1.0 - w) * h[i - 1].p_h + w * h[i].p_h;
}

}  // namespace hm::verification
