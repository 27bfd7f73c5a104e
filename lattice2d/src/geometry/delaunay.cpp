#include "geometry/delaunay.hpp"

#include <cassert>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace hm::lattice2d::detail {
namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, DataStructure>;
}  // namespace

std::vector<std::array<int, 3>> delaunay_triangles(const std::vector<Eigen::Vector2d>& points) {
  std::vector<std::pair<Kernel::Point_2, int>> input;
  input.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k)
    input.emplace_back(Kernel::Point_2(points[k].x(), points[k].y()), static_cast<int>(k));
  // The range insert spatially sorts first (deterministically), which makes it fast.
  Delaunay dt(input.begin(), input.end());
  assert(dt.number_of_vertices() == points.size() && "duplicate points in the Delaunay input");

  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(static_cast<std::size_t>(dt.number_of_faces()));
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return triangles;
}

}  // namespace hm::lattice2d::detail
