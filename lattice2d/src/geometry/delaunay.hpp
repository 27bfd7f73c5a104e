#pragma once
// Private: the one place that includes CGAL (it compiles slowly).
#include <array>
#include <vector>

#include <Eigen/Core>

namespace hm::lattice2d::detail {

/// Finite faces of the Delaunay triangulation of `points` as counter-clockwise index triples
/// (CGAL Delaunay_triangulation_2, exact predicates). Precondition: no duplicate points.
std::vector<std::array<int, 3>> delaunay_triangles(const std::vector<Eigen::Vector2d>& points);

}  // namespace hm::lattice2d::detail
