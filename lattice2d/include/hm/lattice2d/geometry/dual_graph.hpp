#pragma once
/// \file
/// The Voronoi dual of the lattice (Section 2.2, Fig. 4): one pressure node per Delaunay triangle at
/// its Voronoi connection point (the circumcentre), one Voronoi segment per beam of length d_st (or
/// d_su to the surface for a boundary beam), particle areas V_i (Voronoi cells clipped to the
/// domain) and triangle areas V_s. Dimensionless.
///
/// Dual-geometry rule (docs/lattice.md): the dual points are the true circumcentres, never moved, so
/// every Voronoi segment is perpendicular to its beam and the Voronoi cells close exactly (zero net
/// pressure force in a uniform pressure, Section 2.3; sum of V_i = polygon area). On a Delaunay
/// triangulation d_st = L/2 (cot a_s + cot a_t) >= 0 with a_s, a_t the angles opposite the beam, so it
/// can only fail by being ~0 (nearly co-circular quadrilaterals). The flow conductance therefore uses
/// d_flow = max(d, min_dual_ratio * L), which bounds A/d_flow <= 1/min_dual_ratio; d_su > 0 is
/// guaranteed by the boundary spacing of generate_lattice (angle opposite a boundary beam < 90 deg).
#include <Eigen/Core>

#include "hm/lattice2d/geometry/lattice.hpp"

namespace hm::lattice2d {

/// Options of build_dual_graph.
struct DualGraphOptions {
  /// Floor on the flow distance relative to the beam length, d_flow >= min_dual_ratio * L, so that the
  /// conductance A_st/d_flow (Eq. 15, A_st = L_ij) is at most 1/min_dual_ratio. Our choice; see
  /// docs/lattice.md and docs/flow.md (0.02 biased the conductivity by ~4e-4 and stalled the flow's
  /// second-order convergence; 1e-3 behaves like no floor). Allowed: 0 < min_dual_ratio < 1.
  double min_dual_ratio = 1e-3;

  void validate() const;
};

/// Dual geometry of a lattice in a given configuration (positions).
struct DualGraph {
  // --- per triangle s ----------------------------------------------------------------------------
  Eigen::VectorXd triangle_area;  ///< V_s, > 0 (Eq. 15)
  Eigen::Matrix2Xd dual_point;    ///< Voronoi connection point = circumcentre (may lie outside s)
  Eigen::Matrix2Xd centroid;      ///< triangle centroid (for locating sources, plotting)

  // --- per beam ----------------------------------------------------------------------------------
  /// Signed Voronoi segment length: d_st = (c_t - c_s).m for an interior beam (m the unit normal of
  /// the beam pointing from s to t), d_su = signed distance from c_s to the beam for a boundary beam.
  /// Exact dual, used for cell areas and pressure forces (Eq. 17); >= 0 up to round-off.
  Eigen::VectorXd dual_length;
  /// Flow distance max(dual_length, min_dual_ratio * L) > 0 for the conductance of Eq. 15.
  Eigen::VectorXd flow_distance;
  /// Conductance factor A_st/d_flow = L/flow_distance, in (0, 1/min_dual_ratio] (Eq. 15 without dt).
  Eigen::VectorXd conductance;
  std::vector<bool> is_floored;  ///< true where flow_distance > dual_length (the floor acted)

  // --- per particle i ----------------------------------------------------------------------------
  /// V_i, Voronoi cell of particle i clipped to the polygonal domain (Section 2.1 stress formula).
  /// sum_i V_i = sum_s V_s to round-off.
  Eigen::VectorXd particle_area;

  DualGraphOptions options;  ///< the options used
};

/// The dual graph at the lattice's own (undeformed) particle positions.
DualGraph build_dual_graph(const Lattice& lattice, const DualGraphOptions& options = {});

/// The dual graph at other particle positions (column i = particle i; the paper recomputes the
/// flow network each time step, Fig. 5). Precondition: positions.cols() == n_particles and every
/// triangle keeps a positive orientation; the Delaunay property is not re-checked, so d_st < 0 is
/// possible for a strongly deformed lattice and then only the floor keeps the conductance positive.
DualGraph build_dual_graph(const Lattice& lattice, const Eigen::Matrix2Xd& positions,
                           const DualGraphOptions& options = {});

/// The triangles' areas V_s at these particle positions (DualGraph::triangle_area, bit for bit), without
/// the rest of the dual graph: what a volume needs, at a fraction of build_dual_graph's cost.
Eigen::VectorXd triangle_areas(const Lattice& lattice, const Eigen::Matrix2Xd& positions);

}  // namespace hm::lattice2d
