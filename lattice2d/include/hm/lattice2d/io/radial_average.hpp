#pragma once
/// \file
/// Radial averages of per-triangle fields (pressure, strain, ...) over circular shells around a
/// centre: the 2D lattice's counterpart of a radially symmetric profile (Figs. 7, 13, 15 and the
/// comparisons with the 1D model and the analytic solutions). Dimensionless.
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/geometry/dual_graph.hpp"

namespace hm::lattice2d {

/// One shell edges[k] <= r < edges[k+1] of a RadialProfile.
struct RadialShell {
  double r_inner = 0.0;  ///< edges[k]
  double r_outer = 0.0;  ///< edges[k+1]
  /// Area-weighted mean centroid radius of the triangles in the shell (NaN if empty). For a field
  /// that is affine in r at the centroids, mean = f(r_mean) exactly; prefer it to the midpoint.
  double r_mean = 0.0;
  double mean = 0.0;    ///< area-weighted mean of the values (NaN if empty)
  double area = 0.0;    ///< total area of the triangles in the shell
  int n_triangles = 0;  ///< triangles whose centroid lies in the shell
};

/// The shells of radial_average, innermost first.
struct RadialProfile {
  std::vector<RadialShell> shells;
  /// Triangles whose centroid radius lies outside [edges.front(), edges.back()].
  int n_outside = 0;
};

/// n_shells + 1 equally spaced edges from r_min to r_max. Preconditions (asserted): n_shells >= 1,
/// 0 <= r_min < r_max.
std::vector<double> uniform_shell_edges(double r_min, double r_max, int n_shells);

/// Bins triangle s by the radius of its centroid about `centre` (half-open shells
/// [edges[k], edges[k+1]), the last one closed) and averages `values[s]` weighted by `area[s]`.
/// Each triangle counts in exactly one shell, so the shells partition the triangles inside the edges.
/// Preconditions (asserted): edges strictly increasing with >= 2 entries, edges[0] >= 0; sizes of
/// centroid (2 x n), area (n, > 0) and values (n) agree.
/// Limits: a triangle is attributed whole to the shell of its centroid (no area splitting), so a
/// shell narrower than ~2 spacings holds few triangles and its mean is noisy; r_mean is the
/// triangles' mean radius, not the shell's midpoint.
RadialProfile radial_average(const Eigen::Matrix2Xd& centroid, const Eigen::VectorXd& area,
                             const Eigen::VectorXd& values, const std::vector<double>& edges,
                             const Eigen::Vector2d& centre = Eigen::Vector2d::Zero());

/// The same with the dual graph's triangle centroids and areas; `values` has one entry per triangle
/// (extra trailing entries, such as the borehole node of a FlowNetwork pressure, are ignored).
RadialProfile radial_average(const DualGraph& dual, const Eigen::VectorXd& values, const std::vector<double>& edges,
                             const Eigen::Vector2d& centre = Eigen::Vector2d::Zero());

}  // namespace hm::lattice2d
