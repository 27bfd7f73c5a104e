#pragma once
/// \file
/// The random particle lattice of Section 2.1 (Fig. 1): seeded Poisson-disk points in a disk, an
/// annulus or a rectangle, their Delaunay triangulation (edges = beams, triangles = fluid cells of
/// Section 2.2) and the per-beam geometry L_ij, n_ij, theta. Dimensionless lengths (over R).
/// The Voronoi dual lives in dual_graph.hpp, the quality report in mesh_quality.hpp.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "hm/core/enum_names.hpp"

namespace hm::lattice2d {

/// The three domains of the toolkit.
enum class DomainShape {
  disk,       ///< r <= 1, point injection at the centre (Section 3.1)
  annulus,    ///< R_i <= r <= 1, the borehole geometry (Fig. 1, dashed)
  rectangle,  ///< [-width/2, width/2] x [-height/2, height/2], for calibration and unit tests
};
constexpr auto enum_names(DomainShape) {
  return core::enum_table<DomainShape>(
      {{DomainShape::disk, "disk"}, {DomainShape::annulus, "annulus"}, {DomainShape::rectangle, "rectangle"}});
}

/// Which boundary a particle or a boundary beam lies on.
enum class BoundaryTag : std::uint8_t {
  interior = 0,  ///< not on the domain boundary
  outer = 1,     ///< the outer circle r = 1, or any side of the rectangle
  inner = 2,     ///< the borehole wall r = R_i (annulus only)
};

/// Input of generate_lattice. Defaults give the paper's borehole-free disk at a test resolution.
struct LatticeSpec {
  /// Domain shape (Fig. 1). Allowed: disk, annulus, rectangle.
  DomainShape domain = DomainShape::disk;
  /// Target number of particles in the final domain, boundary particles included (Section 2.1:
  /// 1e3 to 2.5e5, 1e5 for the paper's results). Allowed: 500 <= n_particles <= 5e6.
  /// The generated count is within about 1% of the target (see docs/lattice.md).
  long long n_particles = 2000;
  /// Seed of the std::mt19937_64 stream; equal seeds give bitwise equal lattices. Any value.
  std::uint64_t seed = 1;
  /// R_i/R, borehole radius (Table 1: 0.138); annulus only. Allowed: 0 < R_i < 1.
  double inner_radius = 0.138;
  /// Rectangle width (x extent); rectangle only. Allowed: > 0.
  double width = 1.0;
  /// Rectangle height (y extent); rectangle only. Allowed: > 0, 1/20 <= height/width <= 20.
  double height = 1.0;
  /// Bridson's number of candidate darts per active point. Larger packs closer to maximal
  /// (higher minimum angle), smaller is more irregular. Our choice 30 (Bridson 2007).
  /// Allowed: 5 <= bridson_attempts <= 1000.
  int bridson_attempts = 30;
  /// Spacing of the evenly spaced boundary particles over r_min: h = factor * r_min (chord spacing in
  /// [h, ~1.01 h]). Our default 1.3 spaces the boundary row like the Poisson-disk interior (mean beam
  /// ~1.3 r_min); 1 makes it denser, a stiff skin along every boundary (worse wall stresses and Lame
  /// error with facet-scaled beams; docs/lattice.md "Stiffness scaling and boundary spacing").
  /// Allowed: 1 <= factor <= 1.35 (the angle opposite a boundary beam stays <= 2 asin(1.35 * 1.01 / 2)
  /// = 86 deg, so d_su > 0: every boundary circumcentre stays inside the domain).
  double boundary_spacing_factor = 1.3;

  /// Throws hm::InputError "field = value, allowed: rule" on the first violated rule.
  void validate() const;
};

/// Exact area of the (curved) domain: pi, pi (1 - R_i^2) or width * height.
double domain_area(const LatticeSpec& spec);

/// The generated lattice: particles, beams (Delaunay edges) and triangles (Delaunay faces), as
/// plain arrays indexed by particle, beam and triangle number. Ordering is canonical (beams and
/// triangles sorted by vertex indices), so two lattices from the same spec compare equal.
///
/// Limits: the domain boundary is the polygon through the boundary particles (chords of the circles),
/// so areas differ from domain_area() by O(h^2); geometry is of the undeformed configuration.
struct Lattice {
  LatticeSpec spec;  ///< the validated input
  /// Minimum particle spacing r_min of the Poisson-disk sampling: every pair is at least this far apart.
  double min_spacing = 0.0;

  // --- particles ---------------------------------------------------------------------------------
  Eigen::Matrix2Xd points;            ///< column i = position of particle i
  std::vector<BoundaryTag> boundary;  ///< boundary tag of particle i

  // --- triangles (fluid cells, Section 2.2) ------------------------------------------------------
  std::vector<std::array<int, 3>> triangles;       ///< particle indices, counter-clockwise
  std::vector<std::array<int, 3>> triangle_beams;  ///< beam k is opposite vertex k of the triangle

  // --- beams (Delaunay edges, Section 2.1) -------------------------------------------------------
  std::vector<std::array<int, 2>> beams;  ///< particle indices (i, j) with i < j
  /// The one or two triangles sharing the beam; [1] = -1 for a boundary beam.
  std::vector<std::array<int, 2>> beam_triangles;
  std::vector<BoundaryTag> beam_boundary;  ///< interior, or the boundary a one-triangle beam lies on
  Eigen::VectorXd length;                  ///< L_ij = |x_j - x_i| (Eqs. 3-7 use it as L_ij,eq)
  Eigen::Matrix2Xd direction;              ///< n_ij, unit vector from i to j (Fig. 2)
  Eigen::VectorXd angle;                   ///< theta = atan2(n_y, n_x) in (-pi, pi] (Fig. 2)

  int n_particles() const { return static_cast<int>(points.cols()); }
  int n_beams() const { return static_cast<int>(beams.size()); }
  int n_triangles() const { return static_cast<int>(triangles.size()); }
  bool is_boundary_beam(int beam) const { return beam_triangles[beam][1] < 0; }
  /// The unit normal of boundary beam `beam` pointing out of the solid (away from its triangle's third
  /// vertex): a boundary traction t acts as -p m for a pressure p, lumped half to each end.
  Eigen::Vector2d outward_normal(int beam) const;
  /// The force a pressure p on boundary beam `beam`'s face puts on each of its two ends, -p L m / 2
  /// (positive p pushes into the solid): half to each end is exact for a constant traction (the
  /// segment's force and moment). With p = 1, the wall's area gradient per end.
  Eigen::Vector2d lumped_pressure_force(int beam, double p) const {
    return -0.5 * p * length[beam] * outward_normal(beam);
  }
};

/// Generates the lattice of `spec` (validated first; throws hm::InputError).
/// 1. Boundary particles evenly spaced on each boundary curve, spacing in [r_min, ~1.01 r_min].
/// 2. Interior particles by Bridson's Poisson-disk sampling, at least r_min from every particle;
///    r_min is tuned (a few re-runs with the same seed) so that the total count meets the target.
/// 3. CGAL Delaunay triangulation; for the annulus the triangles inside the hole (all three vertices
///    on the borehole wall) are dropped, and with them the edges that belong to no kept triangle.
/// Deterministic: uses std::mt19937_64 and its own uniform mapping, no std distributions.
/// Takes well under a second at n_particles = 1e5.
Lattice generate_lattice(const LatticeSpec& spec);

}  // namespace hm::lattice2d
