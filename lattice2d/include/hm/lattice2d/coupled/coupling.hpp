#pragma once
/// \file
/// The hydromechanical coupling terms of Section 2.3 on the lattice's Voronoi dual: the pore-pressure
/// forces on particles (Eq. 17) and the undrained split's normal spring (Eqs. 18-20). Dimensionless
/// (forces and pressures over E, lengths over R). Derivations and boundary rules: docs/coupling.md.
///
/// Geometry: like the beam mechanics (mechanics.hpp), the terms are linearised about the undeformed
/// lattice: d_st, n_ij and L_ij are those of build_dual_graph(lattice) and Lattice. The flow network
/// is the part that sees the deformed geometry (V^{n+1} - V^n).
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/flow/flow_network.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/rank_one_stiffness.hpp"

namespace hm::lattice2d {

/// The modelling choices of the coupling terms (the material's b and E/M come with the flow
/// parameters, FlowParameters). Every default is set here; CouplingOptions::terms carries them.
/// Plausibility bounds of CouplingTerms: xi is 1 by the divergence theorem, and the paper's Psi study
/// (Fig. 8) ends at 10; a thousand and a million times these are still allowed, 1e12 makes the
/// mechanical factor lose its digits.
inline constexpr double kMaxPressureForceScale = 1e3;
inline constexpr double kMaxSplitFeedback = 1e6;

/// Whether the borehole fluid answers its wall's motion inside the mechanics (BoreholeSpring::undrained:
/// a rank-1 stiffness, borehole_spring()). Without it the borehole's pressure is fixed for a
/// whole mechanical solve, a break cascade included, and its compliance acts only at the next flow
/// solve, after the beams are broken for good.
enum class BoreholeSpring {
  none,       ///< the paper's split: the borehole pressure is the pass's guess; default
  undrained,  ///< the hole's undrained stiffness (beta_h / s_h) g g^T, relaxed at the pass iterate
};
constexpr auto enum_names(BoreholeSpring) {
  return core::enum_table<BoreholeSpring>({{BoreholeSpring::none, "none"}, {BoreholeSpring::undrained, "undrained"}});
}

struct CouplingTerms {
  /// xi, scaling of the pressure force (Eq. 17). Our choice 1: by the divergence theorem xi = 1
  /// reproduces the continuum body force -b grad p (docs/coupling.md, tested). Allowed: 0 < xi <= 1e3.
  double xi = 1.0;
  /// Psi, feedback of the undrained split (Eq. 20); 0 is the drained split. Our choice 1.3, the
  /// paper's near-optimum (Section 3.1, Fig. 8). Allowed: 0 <= psi <= 1e6.
  double psi = 1.3;
  /// The borehole wall (annulus) carries the full borehole pressure p_h as a normal traction (the
  /// total-stress boundary condition), lumped half to each end of a wall beam, besides the b-weighted
  /// Voronoi-segment forces. Our choice true; see docs/coupling.md. No effect without a borehole.
  bool borehole_wall_traction = true;
  /// The Psi spring of a beam that breaks: kept (default: the fluid in the segment is still there) or
  /// dropped with the beam. Psi is a convergence parameter of the split; with "keep" and fracture
  /// checks at every pass it also stiffens cracks while they form (docs/coupling.md).
  BrokenBeamSpring broken_beam_spring = BrokenBeamSpring::keep;
  /// The borehole's undrained spring (BoreholeSpring). Default none (the paper's split). Needs a
  /// borehole whose volume change enters its pressure (FlowParameters::borehole_storage and
  /// borehole_deformation not "none"); checked by CoupledModel.
  BoreholeSpring borehole_spring = BoreholeSpring::none;

  /// Throws hm::InputError "coupling.field = value, allowed: rule".
  void validate() const;
};

/// Nodal forces (3 n_particles, dof = 3 i + component; rotations 0) of the pore pressure, Eq. 17:
/// for the Voronoi segment of beam ij (n_ij from i to j), p_st = (p_s + p_t)/2 and
///   F_i = -xi b d_st p_st n_ij,  F_j = -F_i.
/// `pressure` holds one value per triangle, optionally followed by the borehole pressure p_h (the
/// FlowNetwork layout); p_h = 0 if absent. Boundary segments (d_su, from the dual point to the
/// boundary beam): p_t is the surface pressure, 0 on the outer boundary, p_h on the borehole wall.
/// With borehole_wall_traction, each wall beam also gets -p_h L/2 m on each end (m the outward normal
/// of the solid), as BoundaryConditions::inner_pressure would.
/// Properties (tested): a uniform pressure gives zero force on every interior particle; a linear
/// pressure sampled at the dual points gives -xi b V_i grad p on interior particles to round-off.
/// Limits: pressures are cell constants; the signed dual lengths are used as they are (a slightly
/// negative d_st of a nearly co-circular pair keeps the cells closed).
/// b is the Biot coefficient (FlowParameters::b, 0 <= b <= 1). With `crack_weight` (empty, or one per
/// beam: FlowNetwork::crack_weights with CrackCoupling::full) a beam's facet takes
/// face_pressure_share(b, w) instead of b: a crack's faces carry the whole fluid pressure.
Eigen::VectorXd pressure_forces(const Lattice& lattice, const DualGraph& dual, const Eigen::VectorXd& pressure,
                                double b, const CouplingTerms& terms, const Eigen::VectorXd& crack_weight = {});

/// The share of the fluid pressure on a facet that is a fraction w of crack (0 rock, 1 broken): the
/// rock's b on the rest, the crack's 1 on w, b + (1 - b) w; exactly b and 1 at the ends.
inline double face_pressure_share(double b, double w) { return w == 0.0 ? b : w == 1.0 ? 1.0 : b + (1.0 - b) * w; }

/// The fluid volume of the cracks per triangle (n_triangles): for each beam e with crack weight w_e > 0
/// (one per beam, FlowNetwork::crack_weights), w_e times its opening times its facet,
/// w_e d_e (u_j - u_i).n_e, half to each of its two triangles (undeformed d_e and n_e, as
/// pressure_forces). Its change is work-conjugate to the crack's share of the pressure on the facets
/// (pressure_forces with b = 0, xi = 1: sum_s p_s dV_s = f . du, tested), so that the flow charges the
/// crack the volume the mechanics opens. A triangle's area would not be: an opening w of one beam changes the two
/// triangles' areas by w (h_k + h_l) / 2, 1.5 w d_e on an equilateral lattice.
Eigen::VectorXd crack_opening_volumes(const Lattice& lattice, const DualGraph& dual,
                                      const Eigen::VectorXd& crack_weight, const Eigen::VectorXd& u);

/// The unit normal of the crack through beam `beam`'s facet, on the side of the beam's direction n: the
/// normal of the chord through the facet (its Voronoi segment in `reference`, the undeformed dual graph)
/// and the facets with crack weight > 0 that share its ends, each end continued by every such facet (a
/// chain's chord; a branch adds both arms). n itself for a boundary beam, a facet with no cracked
/// neighbour, or a chord shorter than 1e-9 of the beam (a crack that turns back on itself).
Eigen::Vector2d local_crack_normal(const Lattice& lattice, const DualGraph& reference,
                                   const Eigen::VectorXd& crack_weight, int beam);

/// The openings the cubic law's apertures come from (FlowNetwork::set_crack_openings), one per beam, 0
/// where the crack weight is 0: the axial opening (u_j - u_i).n, the one crack_opening_volumes charges;
/// with CrackAperture::jump, where that is > 0, the length of the facet's displacement jump (with
/// facet_slide); with CrackAperture::crack_normal, the larger of the axial opening and the jump's
/// component along local_crack_normal. Rotations move the facet's ends by -s (theta_j - theta_i) along
/// it, s from the beam's axis: second order for a crack much longer than a beam, and left out.
/// `reference` is read only for crack_normal.
Eigen::VectorXd crack_facet_openings(const Lattice& lattice, const DualGraph& reference,
                                     const Eigen::VectorXd& crack_weight, const Eigen::VectorXd& u,
                                     CrackAperture aperture);

/// The borehole's volume gradient dV_h/du (3 n_particles; zero off the wall): for each wall beam, half
/// its length times the normal into the solid on each end, the wall traction of pressure_forces per
/// unit p_h (and exactly the gradient of the wall polygon's area). Undeformed geometry, as the rest.
Eigen::VectorXd borehole_volume_gradient(const Lattice& lattice);

/// The undrained borehole's stiffness on the wall, BoreholeSpring::undrained: a wall motion du
/// changes V_h by g.du, and with no time for flow the borehole's balance (Eq. 16) s_h dp_h +
/// beta_h dV_h = 0 gives dp_h = -(beta_h / s_h) g.du, whose wall traction is dp_h g: a stiffness
/// k g g^T with k = beta_h / s_h (FlowNetwork's borehole coefficients). Relaxed at the pass iterate
/// like the Psi springs (RankOneStiffness's reference), so the converged step is unchanged.
/// Throws hm::InputError when s_h or beta_h is 0 (the hole's volume then does not set its pressure).
RankOneStiffness borehole_spring(const Lattice& lattice, double storage_coefficient, double deformation_coefficient);

/// Stiffness per beam of the undrained split's normal spring (Eq. 20 linearised, docs/coupling.md):
///   k_ij = Psi xi b^2 (M/E) max(d_st, 0) / L_ij,
/// all zero for Psi = 0 (the drained split). Feed it to BeamMechanics::set_normal_springs.
/// b and E/M are the material's (FlowParameters::b, FlowParameters::E_over_M > 0).
Eigen::VectorXd undrained_spring_stiffness(const Lattice& lattice, const DualGraph& dual, double b, double E_over_M,
                                           const CouplingTerms& terms);

/// The spring's right-hand side K_psi u_ref (3 n_particles): the springs are relaxed at the reference
/// displacement u_ref (the previous coupling iterate), so that (K + K_psi) u = f + K_psi u_ref has the
/// drained solution K u = f as its fixed point. For each beam: -k (u_j - u_i).n n on i, +... on j.
Eigen::VectorXd spring_preload(const Lattice& lattice, const Eigen::VectorXd& stiffness,
                               const Eigen::VectorXd& u_reference);

}  // namespace hm::lattice2d
