#include "hm/lattice2d/geometry/dual_graph.hpp"

#include <algorithm>
#include <cassert>

#include "hm/core/validation.hpp"

namespace hm::lattice2d {

void DualGraphOptions::validate() const { hm::core::require_open(min_dual_ratio, "min_dual_ratio", 0.0, 1.0); }

Eigen::VectorXd triangle_areas(const Lattice& lattice, const Eigen::Matrix2Xd& x) {
  assert(x.cols() == lattice.n_particles() && "one position per particle");
  Eigen::VectorXd area(lattice.n_triangles());
  for (int s = 0; s < lattice.n_triangles(); ++s) {
    const auto [a, b, c] = lattice.triangles[static_cast<std::size_t>(s)];
    const Eigen::Vector2d u = x.col(b) - x.col(a), v = x.col(c) - x.col(a);
    area[s] = 0.5 * (u.x() * v.y() - u.y() * v.x());
  }
  return area;
}

DualGraph build_dual_graph(const Lattice& lattice, const DualGraphOptions& options) {
  return build_dual_graph(lattice, lattice.points, options);
}

DualGraph build_dual_graph(const Lattice& lattice, const Eigen::Matrix2Xd& x, const DualGraphOptions& options) {
  options.validate();
  assert(x.cols() == lattice.n_particles() && "one position per particle");
  DualGraph dual;
  dual.options = options;
  const int n_tri = lattice.n_triangles();
  const int n_beams = lattice.n_beams();

  dual.triangle_area = triangle_areas(lattice, x);
  dual.dual_point.resize(2, n_tri);
  dual.centroid.resize(2, n_tri);
  for (int s = 0; s < n_tri; ++s) {
    const auto [a, b, c] = lattice.triangles[static_cast<std::size_t>(s)];
    // Relative to vertex a: the circumcentre formula then loses no digits to the absolute position.
    const Eigen::Vector2d u = x.col(b) - x.col(a), v = x.col(c) - x.col(a);
    const double cross = 2.0 * dual.triangle_area[s];  // exact: the area is half the cross product
    assert(cross > 0.0 && "triangle not counter-clockwise");
    const double uu = u.squaredNorm(), vv = v.squaredNorm();
    dual.dual_point.col(s) =
        x.col(a) + Eigen::Vector2d(v.y() * uu - u.y() * vv, u.x() * vv - v.x() * uu) / (2.0 * cross);
    dual.centroid.col(s) = (x.col(a) + x.col(b) + x.col(c)) / 3.0;
  }

  dual.dual_length.resize(n_beams);
  dual.flow_distance.resize(n_beams);
  dual.conductance.resize(n_beams);
  dual.is_floored.assign(static_cast<std::size_t>(n_beams), false);
  dual.particle_area = Eigen::VectorXd::Zero(lattice.n_particles());
  for (int e = 0; e < n_beams; ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const auto [s, t] = lattice.beam_triangles[static_cast<std::size_t>(e)];
    const Eigen::Vector2d xi = x.col(i), d = x.col(j) - xi;
    const double length = d.norm();
    // Unit normal m of the beam pointing out of triangle s (away from its third vertex).
    Eigen::Vector2d m(-d.y() / length, d.x() / length);
    const auto& ts = lattice.triangles[static_cast<std::size_t>(s)];
    const int opposite = ts[0] != i && ts[0] != j ? ts[0] : (ts[1] != i && ts[1] != j ? ts[1] : ts[2]);
    if ((x.col(opposite) - xi).dot(m) > 0.0) m = -m;
    // Signed distances from each circumcentre to the beam line, positive on the triangle's own side;
    // their sum is the Voronoi segment c_s c_t, which is parallel to m.
    double dual_length = (xi - dual.dual_point.col(s)).dot(m);
    if (t >= 0) dual_length += (dual.dual_point.col(t) - xi).dot(m);
    dual.dual_length[e] = dual_length;
    const double floor = options.min_dual_ratio * length;
    dual.is_floored[static_cast<std::size_t>(e)] = dual_length < floor;
    dual.flow_distance[e] = std::max(dual_length, floor);
    dual.conductance[e] = length / dual.flow_distance[e];
    // Voronoi cell pieces: the triangles (x_i, c_s, c_t) and (x_j, c_s, c_t) have area L d / 4 each.
    dual.particle_area[i] += 0.25 * length * dual_length;
    dual.particle_area[j] += 0.25 * length * dual_length;
  }
  return dual;
}

}  // namespace hm::lattice2d
