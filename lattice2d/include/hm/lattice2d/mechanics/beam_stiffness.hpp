#pragma once
/// \file
/// Linear 2D beams between particles (Section 2.1, Eqs. 3-7, 9-10): 3 degrees of freedom per particle
/// (x, y displacement and rotation omega, in that order: dof = 3 i + component), one symmetric 6 x 6
/// element matrix per beam, assembled into a sparse stiffness K so that the internal force is -K u.
/// Dimensionless (stresses over E).
///
/// Energy form: with the chord rotation phi = (u_j - u_i).s / L and the end deflections
/// theta_i = omega_i - phi, theta_j = omega_j - phi (Fig. 2), the beam stores
///   W = 1/2 k_n ((u_j - u_i).n)^2 + 1/2 [theta_i theta_j] D [theta_i theta_j]^T,
///   D = 2 k_omega L^2 [[gamma + 1/3, 1/6 - gamma], [1/6 - gamma, gamma + 1/3]],
/// whose derivatives are Eq. 3's force (shear k_omega L (theta_i + theta_j)) and Eq. 4's moment.
/// Its Hessian reproduces every coefficient of Eqs. 5-7 except that Eq. 7 prints 2 k_omega L (not
/// L^2) on the rotation terms; the L^2 of Eq. 4 is the consistent one (docs/lattice.md).
/// Limits: small displacements and rotations (geometrically linear); no pressure terms (Eq. 17-20).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/core/enum_names.hpp"

namespace hm::lattice2d {

/// How k_n (and with it k_omega, which Eq. 4 makes proportional to k_n) varies from beam to beam.
/// The toolkit's calibrated default is voronoi_facet (calibrated_beam_parameters(), docs/lattice.md).
enum class StiffnessScaling : std::uint8_t {
  /// The paper's: every beam has the same k_n.
  uniform,
  /// Our option (not in the paper): k_n,ij = k_n sqrt(3) max(d_ij / L_ij, facet_floor), d_ij the exact
  /// Voronoi facet (dual) length (d_st, or d_su on the boundary). Each beam then stands for the
  /// "diamond" of area d L / 2; the diamonds tile the domain, so an affine strain stores the energy of a
  /// uniform continuum (central springs: nu = 1/4 in plane strain for the affine field). sqrt(3)
  /// normalises to the regular triangular lattice (d/L = 1/sqrt(3) -> factor 1).
  voronoi_facet,
};
constexpr auto enum_names(StiffnessScaling) {
  return core::enum_table<StiffnessScaling>({
      {StiffnessScaling::uniform, "uniform"}, {StiffnessScaling::voronoi_facet, "voronoi_facet"}});
}


/// Beam constants of Eqs. 3-4. The defaults are generic unit values; the calibrated constants
/// (E = 1, nu = 0.2236 measured on the lattice, docs/lattice.md "Calibration") come from
/// calibrated_beam_parameters() in calibration.hpp, which every model should use.
struct BeamParameters {
  /// k_n, normal spring constant (Eq. 3), the same for every beam. Allowed: > 0.
  double normal_stiffness = 1.0;
  /// a = d / L_eq, beam width over length (Eq. 4: gamma = a^2 (1 + nu0) / 6,
  /// k_omega = k_n (2/a^2 + 4 (1 + nu0))^-1). Allowed: > 0.
  double aspect = 1.0;
  /// nu0, Poisson ratio of the beam material (Eq. 4). Allowed: -1 < nu0 < 0.5.
  double beam_poisson = 0.25;
  /// Per-beam variation of k_n (and k_omega). Default uniform (the paper's); docs/lattice.md
  /// "Stiffness scaling and boundary spacing" has the measurements. Allowed: uniform, voronoi_facet.
  StiffnessScaling stiffness_scaling = StiffnessScaling::uniform;
  /// voronoi_facet only: floor on d/L in the factor, so that the beams of nearly co-circular
  /// quadrilaterals (d -> 0) keep a little stiffness. Allowed: 0 <= facet_floor <= 1/sqrt(3).
  double facet_floor = 0.0;

  void validate() const;
  /// k_omega = k_n (2/a^2 + 4 (1 + nu0))^-1 (text after Eq. 4).
  double rotational_stiffness() const;
  /// gamma = a^2 (1 + nu0) / 6 (text after Eq. 4).
  double gamma() const;
};

/// State of the connection between two particles.
enum class BeamState : std::uint8_t {
  intact,   ///< full beam, Eqs. 5-7
  contact,  ///< broken, particles overlapping: normal spring only, Eqs. 9-10
  open,     ///< broken, particles apart: no force (Eq. 8 with H = 0)
};

/// What happens to the undrained split's normal spring of a beam (Eq. 20, BeamMechanics::
/// set_normal_springs) when the beam breaks. The spring stands for the pore fluid's resistance to the
/// Voronoi segment's change of volume, a convergence device of the operator split, not a bond.
enum class BrokenBeamSpring {
  keep,  ///< the spring stays (the fluid is still there); default, as the model has always run
  drop,  ///< the spring goes with the beam, so the split's Psi cannot hold a crack closed
};
constexpr auto enum_names(BrokenBeamSpring) {
  return core::enum_table<BrokenBeamSpring>({{BrokenBeamSpring::keep, "keep"}, {BrokenBeamSpring::drop, "drop"}});
}

/// Broken flags from beam states: true where state != BeamState::intact (the flow network's view of
/// the beams: a broken beam, open or in contact, is a fracture channel).
std::vector<bool> broken_flags(const std::vector<BeamState>& states);

/// d/L of every beam of the undeformed lattice, d the exact Voronoi facet: (L/2)(cot a_s + cot a_t)
/// with a_s, a_t the angles opposite the beam in its triangles (one triangle on the boundary). The
/// same number as DualGraph::dual_length / length, computed from the lattice alone.
Eigen::VectorXd facet_ratios(const Lattice& lattice);

/// k_n,beam / k_n: 1 for uniform, sqrt(3) max(d/L, facet_floor) for voronoi_facet.
double beam_stiffness_factor(const Lattice& lattice, const BeamParameters& parameters, int beam);

/// `parameters` with normal_stiffness multiplied by beam_stiffness_factor (the constants that beam
/// `beam` uses in every element matrix and force).
BeamParameters beam_parameters_for(const Lattice& lattice, const BeamParameters& parameters, int beam);

using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// Element stiffness of one connection of length L at angle theta (Fig. 2) in global components,
/// ordered (x_i, y_i, omega_i, x_j, y_j, omega_j). Symmetric, positive semi-definite with the three
/// rigid-body motions in its null space (intact), or rank one (contact), or zero (open).
Matrix6d beam_element_stiffness(double length, double angle, const BeamParameters& parameters,
                                BeamState state = BeamState::intact);

using Matrix63d = Eigen::Matrix<double, 6, 3>;

/// A factor V of the element stiffness, K_e = V V^T (beam_element_stiffness(length, angle, parameters,
/// state)), used for rank-<=3 updates/downdates of a factorised global matrix when a beam changes state.
/// Column 0 is the normal spring, sqrt(k_n) b with b.u_e = (u_j - u_i).n_ij the elongation (zero when
/// open); columns 1 and 2 are the bending part B^T C with D = C C^T (Cholesky of the 2 x 2 bending
/// matrix, SPD: eigenvalues k_w L^2 and 2 k_w L^2 (2 gamma + 1/6)), zero unless intact.
/// So intact -> contact removes columns 1-2 (rank 2), contact -> open column 0 (rank 1).
Matrix63d beam_element_factor(double length, double angle, const BeamParameters& parameters,
                              BeamState state = BeamState::intact);

/// Degree of freedom of a particle's component (0 = x, 1 = y, 2 = rotation).
constexpr int dof_index(int particle, int component) { return 3 * particle + component; }

/// K (3 n x 3 n, both triangles stored) for the lattice's undeformed beam geometry, each beam with
/// beam_parameters_for(lattice, parameters, e); `states` is
/// empty (all intact) or one per beam. Validates `parameters` (throws hm::InputError).
/// Singular until displacements are prescribed somewhere (three rigid-body modes per connected part).
Eigen::SparseMatrix<double> assemble_stiffness(const Lattice& lattice, const BeamParameters& parameters,
                                               const std::vector<BeamState>& states = {});

}  // namespace hm::lattice2d
