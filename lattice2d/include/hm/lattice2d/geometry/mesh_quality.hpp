#pragma once
/// \file
/// Mesh-quality report of a lattice and its dual graph: counts, triangle angles and the ranges of
/// every geometric quantity the mechanics (L) and the flow network (d_st, d_su, A/d, V) divide by.
#include <iosfwd>
#include <string>

#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"

namespace hm::lattice2d {

/// A [min, max] range with the mean.
struct Range {
  double min = 0.0;
  double max = 0.0;
  double mean = 0.0;
};

/// What mesh_quality() measures. Angles in degrees, everything else dimensionless.
struct MeshQuality {
  int n_particles = 0;
  int n_boundary_particles = 0;
  int n_beams = 0;
  int n_boundary_beams = 0;
  int n_triangles = 0;
  double min_spacing = 0.0;        ///< r_min of the sampling
  Range triangle_angle_deg;        ///< all three angles of every triangle
  Range beam_length;               ///< L_ij
  Range dual_length;               ///< d_st, interior beams (exact Voronoi segment)
  Range surface_distance;          ///< d_su, boundary beams
  Range dual_ratio;                ///< d_st / L, interior beams (>= 0 on a Delaunay triangulation)
  Range surface_ratio;             ///< d_su / L, boundary beams (> 0.28 by the boundary spacing)
  Range conductance;               ///< A/d_flow = L/max(d, min_dual_ratio L), all beams
  int n_floored = 0;               ///< beams whose flow distance was raised to the floor
  Range particle_area;             ///< V_i
  Range triangle_area;             ///< V_s
  double sum_particle_area = 0.0;  ///< sum V_i
  double sum_triangle_area = 0.0;  ///< sum V_s = area of the polygonal domain
  double domain_area = 0.0;        ///< exact area of the curved domain
};

/// Measures `lattice` with its `dual` (built from the same lattice).
MeshQuality mesh_quality(const Lattice& lattice, const DualGraph& dual);

/// Multi-line human-readable report.
std::string to_string(const MeshQuality& quality);
std::ostream& operator<<(std::ostream& out, const MeshQuality& quality);

}  // namespace hm::lattice2d
