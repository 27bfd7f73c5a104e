#pragma once
#include <cmath>
// Lattices the lattice2d tests build over and over: a spec or a generated lattice of a given
// domain, size and seed, everything else at LatticeSpec's defaults.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/lattice.hpp"

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

}  // namespace hm::test
