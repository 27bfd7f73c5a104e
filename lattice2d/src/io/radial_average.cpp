#include "hm/lattice2d/io/radial_average.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace hm::lattice2d {

std::vector<double> uniform_shell_edges(double r_min, double r_max, int n_shells) {
  assert(n_shells >= 1 && 0.0 <= r_min && r_min < r_max && "uniform_shell_edges: bad range");
  std::vector<double> edges(static_cast<std::size_t>(n_shells) + 1);
  for (int k = 0; k <= n_shells; ++k) edges[static_cast<std::size_t>(k)] = r_min + (r_max - r_min) * k / n_shells;
  edges.back() = r_max;  // exact, so that r = r_max falls in the last (closed) shell
  return edges;
}

RadialProfile radial_average(const Eigen::Matrix2Xd& centroid, const Eigen::VectorXd& area,
                             const Eigen::VectorXd& values, const std::vector<double>& edges,
                             const Eigen::Vector2d& centre) {
  assert(edges.size() >= 2 && edges.front() >= 0.0 && "at least one shell, radii >= 0");
  assert(std::is_sorted(edges.begin(), edges.end()) && std::adjacent_find(edges.begin(), edges.end()) == edges.end() &&
         "edges strictly increasing");
  assert(area.size() == centroid.cols() && values.size() >= centroid.cols() && "one value per triangle");
  const std::size_t n_shells = edges.size() - 1;
  RadialProfile profile;
  profile.shells.resize(n_shells);
  std::vector<double> weighted_r(n_shells, 0.0), weighted_value(n_shells, 0.0);
  for (Eigen::Index s = 0; s < centroid.cols(); ++s) {
    const double r = (centroid.col(s) - centre).norm();
    if (r < edges.front() || r > edges.back()) {
      ++profile.n_outside;
      continue;
    }
    // upper_bound gives the first edge > r, so shell k holds edges[k] <= r < edges[k+1]; r equal to
    // the last edge goes into the last shell.
    const auto k = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(edges.begin(), edges.end(), r) - edges.begin()) - 1, n_shells - 1);
    RadialShell& shell = profile.shells[k];
    shell.area += area[s];
    ++shell.n_triangles;
    weighted_r[k] += area[s] * r;
    weighted_value[k] += area[s] * values[s];
  }
  for (std::size_t k = 0; k < n_shells; ++k) {
    RadialShell& shell = profile.shells[k];
    shell.r_inner = edges[k];
    shell.r_outer = edges[k + 1];
    const double nan = std::numeric_limits<double>::quiet_NaN();
    shell.r_mean = shell.n_triangles > 0 ? weighted_r[k] / shell.area : nan;
    shell.mean = shell.n_triangles > 0 ? weighted_value[k] / shell.area : nan;
  }
  return profile;
}

RadialProfile radial_average(const DualGraph& dual, const Eigen::VectorXd& values, const std::vector<double>& edges,
                             const Eigen::Vector2d& centre) {
  return radial_average(dual.centroid, dual.triangle_area, values, edges, centre);
}

}  // namespace hm::lattice2d
