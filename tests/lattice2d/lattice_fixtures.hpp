#pragma once
// Lattices the lattice2d tests build over and over: a spec or a generated lattice of a given
// domain, size and seed, everything else at LatticeSpec's defaults.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/geometry/lattice.hpp"

namespace hm::test {

inline hm::lattice2d::LatticeSpec spec_of(hm::lattice2d::DomainShape shape, long long n, std::uint64_t seed = 1) {
  hm::lattice2d::LatticeSpec spec;
  spec.domain = shape;
  spec.n_particles = n;
  spec.seed = seed;
  return spec;
}

/// Lower bound of d_su / L for a boundary beam: the boundary spacing is <= 1.01 h, h = factor r_min,
/// and the third vertex is >= r_min from both ends, so the angle opposite the beam is
/// <= a = 2 asin(1.01 factor / 2) and d_su = (L/2) cot(a') >= (L/2) cot(a) (0.28 at factor 1, 0.070 at
/// the default 1.3, 0.035 at 1.35; lattice.hpp).
inline double min_boundary_dual_ratio(double boundary_spacing_factor) {
  return 0.5 / std::tan(2.0 * std::asin(1.01 * boundary_spacing_factor / 2.0));
}

inline hm::lattice2d::Lattice make_lattice(hm::lattice2d::DomainShape shape, long long n, std::uint64_t seed = 1) {
  return hm::lattice2d::generate_lattice(spec_of(shape, n, seed));
}

/// Shoelace area of the polygon through the boundary particles with `tag` (the generator places
/// them counter-clockwise along each curve, so the area is positive).
inline double ring_area(const hm::lattice2d::Lattice& lattice, hm::lattice2d::BoundaryTag tag) {
  std::vector<int> ring;
  for (int i = 0; i < lattice.n_particles(); ++i)
    if (lattice.boundary[static_cast<std::size_t>(i)] == tag) ring.push_back(i);
  double twice = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const Eigen::Vector2d a = lattice.points.col(ring[k]), b = lattice.points.col(ring[(k + 1) % ring.size()]);
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

/// The lines of a text file (e.g. a CSV the code under test wrote).
inline std::vector<std::string> lines_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A regular triangular lattice on a 60-degree rhombus of n x n particles, spacing l, centred at the
// origin: every triangle equilateral, every interior particle a centre of inversion symmetry.
inline hm::lattice2d::Lattice regular_triangular_lattice(int n, double l) {
  using namespace hm::lattice2d;
  Lattice lat;
  lat.spec.domain = DomainShape::rectangle;
  lat.spec.n_particles = static_cast<long long>(n) * n;
  const double h = l * std::sqrt(3.0) / 2.0;
  // The rhombus's inscribed circle has radius (n - 1) h / 2; the measurement's region is a fraction of
  // min(width, height) / 2, so width = height = (n - 1) h keeps it inside.
  lat.spec.width = lat.spec.height = (n - 1) * h;
  lat.min_spacing = l;
  auto id = [n](int i, int j) { return j * n + i; };
  lat.points.resize(2, n * n);
  lat.boundary.assign(static_cast<std::size_t>(n) * n, BoundaryTag::interior);
  const Eigen::Vector2d centre((n - 1) * l * 0.75, (n - 1) * h * 0.5);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      lat.points.col(id(i, j)) = Eigen::Vector2d(i * l + j * l / 2.0, j * h) - centre;
      if (i == 0 || j == 0 || i == n - 1 || j == n - 1) lat.boundary[id(i, j)] = BoundaryTag::outer;
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      lat.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});          // counter-clockwise
      lat.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});  // counter-clockwise
    }
  std::map<std::pair<int, int>, int> beam_of;
  for (int t = 0; t < lat.n_triangles(); ++t) {
    std::array<int, 3> tb{};
    for (int k = 0; k < 3; ++k) {
      int a = lat.triangles[t][(k + 1) % 3], b = lat.triangles[t][(k + 2) % 3];
      if (a > b) std::swap(a, b);
      auto [it, added] = beam_of.try_emplace({a, b}, lat.n_beams());
      if (added) {
        lat.beams.push_back({a, b});
        lat.beam_triangles.push_back({t, -1});
      } else {
        lat.beam_triangles[it->second][1] = t;
      }
      tb[k] = it->second;
    }
    lat.triangle_beams.push_back(tb);
  }
  const int nb = lat.n_beams();
  lat.length.resize(nb);
  lat.direction.resize(2, nb);
  lat.angle.resize(nb);
  for (int e = 0; e < nb; ++e) {
    const Eigen::Vector2d d = lat.points.col(lat.beams[e][1]) - lat.points.col(lat.beams[e][0]);
    lat.length[e] = d.norm();
    lat.direction.col(e) = d / d.norm();
    lat.angle[e] = std::atan2(d.y(), d.x());
    lat.beam_boundary.push_back(lat.beam_triangles[e][1] < 0 ? BoundaryTag::outer : BoundaryTag::interior);
  }
  return lat;
}

}  // namespace hm::test
