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

#include "hm/core/enum_names.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"

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
  return core::enum_table<StiffnessScaling>(
      {{StiffnessScaling::uniform, "uniform"}, {StiffnessScaling::voronoi_facet, "voronoi_facet"}});
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
  /// k_omega's own factor, on top of k_n's: 1 except for a softened beam whose crack has closed, whose
  /// normal stiffness is the unsoftened k_n again while its bending stays softened (BeamMechanics).
  /// Allowed: 0 < bending_factor <= 1.
  double bending_factor = 1.0;

  void validate() const;
  /// k_omega = bending_factor k_n (2/a^2 + 4 (1 + nu0))^-1 (text after Eq. 4).
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
  keep,  ///< the spring stays: the fluid it stands for is still there after the break; default
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
using Matrix63d = Eigen::Matrix<double, 6, 3>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// The one definition of a connection's linear mechanics (Eqs. 3-10), from which its element
/// stiffness, the factor columns and its internal force all come. With element displacements u_e in
/// global components (x_i, y_i, omega_i, x_j, y_j, omega_j), T = diag(R, R) turns them into local
/// (n, s, omega) components (n = n_ij = (c, s), R the rotation onto it), B maps those onto the
/// generalised strains q = (elongation (u_j - u_i).n, theta_i, theta_j) (theta = omega - chord
/// rotation, Fig. 2) and D = diag(k_n, D_b) onto the resultants (N, m_i, m_j) (axial force, tension
/// positive, and end moments; D_b the bending matrix of the file comment), so that
///   K_e = T^T B^T D B T,   K_e = V V^T with V = T^T B^T C, C C^T = D,   f_int = K_e u_e.
/// The state enters only through D: contact keeps k_n (Eqs. 9-10), open keeps nothing. Eq. 8's
/// Heaviside is not applied here: it chooses the state (contact_state), and a force always belongs
/// to the matrix of its state, so that the particle sums of the forces are exactly the -K u the
/// mechanics solved.
/// The matrix forms are for assembly, factor updates and tests; strains / resultants / nodal_forces
/// apply the same B, D and T^T B^T without forming them (no 6 x 6 products, no trigonometry), the
/// form of the per-solve loops over every beam. Both agree to round-off (tests/lattice2d/
/// test_fast_path.cpp). Limits: geometrically linear, like the file.
class BeamOperator {
 public:
  /// Beam with unit direction (c, s) = n_ij, length L and its own constants `parameters`
  /// (beam_parameters_for: k_n under stiffness_scaling) in state `state`.
  BeamOperator(double c, double s, double length, const BeamParameters& parameters, BeamState state);
  /// Beam `beam` of `lattice` (n_ij = lattice.direction, L = lattice.length).
  BeamOperator(const Lattice& lattice, int beam, const BeamParameters& parameters, BeamState state);

  BeamState state() const { return state_; }

  /// q = B T u_e = (elongation, theta_i, theta_j).
  Eigen::Vector3d strains(const Vector6d& u_e) const {
    const double dx = u_e[3] - u_e[0], dy = u_e[4] - u_e[1];
    const double phi = (-s_ * dx + c_ * dy) / length_;  // chord rotation
    return {c_ * dx + s_ * dy, u_e[2] - phi, u_e[5] - phi};
  }
  /// (N, m_i, m_j) = D q.
  Eigen::Vector3d resultants(const Eigen::Vector3d& q) const {
    return {normal_ * q[0], bending_ * (diagonal_ * q[1] + off_diagonal_ * q[2]),
            bending_ * (off_diagonal_ * q[1] + diagonal_ * q[2])};
  }
  /// T^T B^T r: the nodal forces and moments of resultants r = (N, m_i, m_j).
  Vector6d nodal_forces(const Eigen::Vector3d& r) const {
    const double fn = -r[0], fs = (r[1] + r[2]) / length_;  // local (n, s) force on i; minus on j
    Vector6d f;
    f << c_ * fn - s_ * fs, s_ * fn + c_ * fs, r[1], -(c_ * fn - s_ * fs), -(s_ * fn + c_ * fs), r[2];
    return f;
  }
  /// f_int = K_e u_e (the force the beam exerts on its particles is -f_int).
  Vector6d internal_force(const Vector6d& u_e) const {
    if (state_ == BeamState::open) return Vector6d::Zero();
    return nodal_forces(resultants(strains(u_e)));
  }

  /// T (6 x 6): global (x, y, omega) -> local (n, s, omega) at both ends.
  Matrix6d rotation() const;
  /// B (3 x 6) in local components.
  Eigen::Matrix<double, 3, 6> strain_matrix() const;
  /// D (3 x 3).
  Eigen::Matrix3d constitutive() const;
  /// C with C C^T = D: sqrt(k_n) and the Cholesky factor of D_b (SPD: eigenvalues k_w L^2 and
  /// 2 k_w L^2 (2 gamma + 1/6)), zero where D is.
  Eigen::Matrix3d constitutive_factor() const;
  /// K_e = T^T B^T D B T.
  Matrix6d stiffness() const;
  /// V = T^T B^T C.
  Matrix63d factor() const;

 private:
  double c_, s_, length_;
  double normal_;                   // k_n, 0 when open
  double bending_;                  // 2 k_w L^2, 0 unless intact
  double diagonal_, off_diagonal_;  // D_b / bending_: gamma + 1/3 and 1/6 - gamma
  BeamState state_;
};

/// The state Eq. 8's Heaviside gives a broken connection of elongation (u_j - u_i).n: contact when
/// the particles overlap by more than `tolerance` (elongation < -tolerance), open when they separate
/// by more than it, else `current` (a hysteresis of +-tolerance against round-off flip-flopping; a
/// just-broken beam, current = intact, takes tolerance 0). The one place the contact rule lives:
/// forces follow the state (BeamOperator).
BeamState contact_state(BeamState current, double elongation, double tolerance);

/// u_e of beam `beam`: (x_i, y_i, omega_i, x_j, y_j, omega_j) of u (dof = 3 particle + component).
inline Vector6d element_displacements(const Lattice& lattice, int beam, const Eigen::VectorXd& u) {
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(beam)];
  Vector6d u_e;
  u_e << u.segment<3>(3 * i), u.segment<3>(3 * j);
  return u_e;
}

/// The force a beam or contact exerts on its particle i (Eqs. 3, 4, 8), and its components.
/// On particle j it exerts -force_on_i and moment_j. For the particle stress of Section 2.1,
/// sigma_i = 1/2 V_i^-1 sum_j F_ij (x) L_ij with F_ij = force_on_i and L_ij = x_j - x_i (for particle j
/// use -force_on_i and -L_ij: the same outer product). Tension positive.
struct BeamForce {
  Eigen::Vector2d force_on_i = Eigen::Vector2d::Zero();  ///< F_ij, global components
  double normal = 0.0;    ///< F_ij . n_ij = k_n (u_j - u_i).n_ij: > 0 in tension, <= 0 for a contact
  double shear = 0.0;     ///< F_ij . s_ij, s_ij = n_ij rotated by +90 degrees
  double moment_i = 0.0;  ///< moment on particle i (Eq. 4, counter-clockwise positive)
  double moment_j = 0.0;  ///< moment on particle j
};

/// Beam `beam`'s BeamForce at displacements u: -BeamOperator(...).internal_force(u_e) and its
/// normal and shear components. `parameters` are the beam's own (beam_parameters_for).
BeamForce beam_force(const Lattice& lattice, int beam, const BeamParameters& parameters, BeamState state,
                     const Eigen::VectorXd& u);

/// Element stiffness of one connection of length L at angle theta (Fig. 2) in global components,
/// ordered (x_i, y_i, omega_i, x_j, y_j, omega_j): BeamOperator(cos theta, sin theta, ...).stiffness().
/// Symmetric, positive semi-definite with the three rigid-body motions in its null space (intact),
/// or rank one (contact), or zero (open).
Matrix6d beam_element_stiffness(double length, double angle, const BeamParameters& parameters,
                                BeamState state = BeamState::intact);

/// A factor V of the element stiffness, K_e = V V^T (beam_element_stiffness(length, angle, parameters,
/// state)), used for rank-<=3 updates/downdates of a factorised global matrix when a beam changes state:
/// BeamOperator(...).factor(). Column 0 is the normal spring, sqrt(k_n) b with b.u_e = (u_j - u_i).n_ij
/// the elongation (zero when open); columns 1 and 2 are the bending part, zero unless intact.
/// So intact -> contact removes columns 1-2 (rank 2), contact -> open column 0 (rank 1).
Matrix63d beam_element_factor(double length, double angle, const BeamParameters& parameters,
                              BeamState state = BeamState::intact);

/// Degree of freedom of a particle's component (0 = x, 1 = y, 2 = rotation).
constexpr int dof_index(int particle, int component) { return 3 * particle + component; }

/// The normal elongation (u_j - u_i).n of `beam` in its undeformed direction n (the first of
/// BeamOperator::strains()), from u with 3 degrees of freedom per particle: the contact rule's
/// measure, the Eq. 20 spring's stretch and a crack's opening. The one copy of this arithmetic.
inline double normal_elongation(const Lattice& lattice, const Eigen::VectorXd& u, int beam) {
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(beam)];
  const Eigen::Vector2d du(u[dof_index(j, 0)] - u[dof_index(i, 0)], u[dof_index(j, 1)] - u[dof_index(i, 1)]);
  return du.dot(lattice.direction.col(beam));
}

/// The slide of `beam`'s facet: the tangential component, along s = n rotated by +90 degrees, of the
/// displacement jump at the beam's midpoint (on its facet's line, the perpendicular bisector), where
/// particle i's rotation moves the point by omega_i (L/2) s and particle j's by -omega_j (L/2) s:
/// (u_j - u_i).s - (omega_i + omega_j) L/2. With normal_elongation, the facet's jump.
inline double facet_slide(const Lattice& lattice, const Eigen::VectorXd& u, int beam) {
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(beam)];
  const Eigen::Vector2d n = lattice.direction.col(beam);
  const Eigen::Vector2d du(u[dof_index(j, 0)] - u[dof_index(i, 0)], u[dof_index(j, 1)] - u[dof_index(i, 1)]);
  return -n.y() * du.x() + n.x() * du.y() - 0.5 * (u[dof_index(i, 2)] + u[dof_index(j, 2)]) * lattice.length[beam];
}

/// Eq. 20's normal spring on a beam: k g g^T on its ends' translations (x_i, y_i, x_j, y_j), with
/// g = (-n, n) so that g.u is the normal elongation. Its force is k (g.u) g: -k (g.u) n on i, +k (g.u) n
/// on j. The one copy of this arithmetic for the mechanics' assembly, downdate and reactions and the
/// coupling's preload (each passes the stiffness k it holds).
struct NormalSpring {
  std::array<int, 4> dofs;  ///< global dofs x_i, y_i, x_j, y_j
  std::array<double, 4> g;  ///< d(elongation)/d(dofs) = (-n_x, -n_y, n_x, n_y)

  NormalSpring(const Lattice& lattice, int beam) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(beam)];
    const Eigen::Vector2d n = lattice.direction.col(beam);
    dofs = {dof_index(i, 0), dof_index(i, 1), dof_index(j, 0), dof_index(j, 1)};
    g = {-n.x(), -n.y(), n.x(), n.y()};
  }
  /// g.v over the spring's dofs of a vector with 3 dofs per particle (e.g. the held displacements).
  double stretch(const Eigen::VectorXd& v) const {
    double s = 0.0;
    for (std::size_t a = 0; a < 4; ++a) s += g[a] * v[dofs[a]];
    return s;
  }
  /// Adds the spring's force at elongation `elongation`, k elongation g, to f (3 dofs per particle).
  void add_force(double k, double elongation, Eigen::VectorXd& f) const {
    const double t = k * elongation;
    for (std::size_t a = 0; a < 4; ++a) f[dofs[a]] += t * g[a];
  }
};

/// K (3 n x 3 n, both triangles stored) for the lattice's undeformed beam geometry, each beam with
/// beam_parameters_for(lattice, parameters, e); `states` is
/// empty (all intact) or one per beam. Validates `parameters` (throws hm::InputError).
/// Singular until displacements are prescribed somewhere (three rigid-body modes per connected part).
Eigen::SparseMatrix<double> assemble_stiffness(const Lattice& lattice, const BeamParameters& parameters,
                                               const std::vector<BeamState>& states = {});

}  // namespace hm::lattice2d
