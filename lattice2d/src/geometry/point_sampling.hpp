#pragma once
// Private: seeded point generation for generate_lattice (boundary particles + Bridson Poisson disk).
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/geometry/lattice.hpp"

namespace hm::lattice2d::detail {

struct PointSet {
  std::vector<Eigen::Vector2d> points;
  std::vector<BoundaryTag> tags;
};

/// Boundary particles (evenly spaced, spacing in [h, ~1.01 h], h = spec.boundary_spacing_factor r) followed by Bridson
/// interior particles at least r from every particle, drawn from std::mt19937_64(stream_seed). Deterministic in (spec,
/// r, stream_seed); spec.seed is not used here.
PointSet sample_points(const LatticeSpec& spec, double r, std::uint64_t stream_seed);

/// Estimate of r giving `spec.n_particles` points (saturated Poisson-disk density ~0.7 / r^2).
double initial_spacing_guess(const LatticeSpec& spec);

}  // namespace hm::lattice2d::detail
