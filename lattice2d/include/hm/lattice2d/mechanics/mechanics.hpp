#pragma once
/// \file
/// The quasi-static mechanical solve of the dry lattice (Section 2.1): particles with (x, y, rotation)
/// displacements, intact beams (Eqs. 3-7), broken beams as compression-only contacts (Eqs. 8-10) with
/// an active-set loop, boundary conditions (free, fixed, pressure, prescribed displacement or
/// homogeneous boundary strain), and a fast re-solve after each broken beam through a rank-<=3
/// modification of the kept factor (spd_solver.hpp). Dimensionless: lengths over R, forces and
/// pressures over E (per unit thickness). Displacements are small (geometrically linear, about the
/// undeformed lattice). Rules and reasons: docs/lattice.md, "Mechanical solve".
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "hm/core/enum_names.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/linalg/spd_solver.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/rank_one_stiffness.hpp"

namespace hm::lattice2d {

/// Support of a whole boundary curve (Section 2.1, last paragraph but one).
enum class BoundarySupport {
  free,   ///< no constraint (the paper's default: "mechanically free unless confinement is included")
  fixed,  ///< x and y of the boundary particles held at 0; rotation free (the paper fixes "x- and y-coordinates")
};
constexpr auto enum_names(BoundarySupport) {
  return core::enum_table<BoundarySupport>({{BoundarySupport::free, "free"}, {BoundarySupport::fixed, "fixed"}});
}

/// One prescribed displacement component of one particle.
struct PrescribedDisplacement {
  int particle = 0;    ///< particle index. Allowed: 0 <= particle < n_particles.
  int component = 0;   ///< 0 = x, 1 = y, 2 = rotation. Allowed: 0, 1, 2.
  double value = 0.0;  ///< displacement (over R) or rotation (radians). Allowed: finite.
};

/// Boundary conditions of the mechanical problem. Order of application: supports, boundary strain,
/// then `prescribed` (a later entry overrides an earlier value of the same degree of freedom).
/// Without any held degree of freedom (pure traction) the solve pins the rigid-body modes itself
/// (see BeamMechanics); held degrees of freedom that leave a rigid-body mode free are rejected.
struct BoundaryConditions {
  /// Support of the outer boundary (r = 1, or all four sides of a rectangle). Default free.
  BoundarySupport outer = BoundarySupport::free;
  /// Support of the borehole wall r = R_i (annulus only). Default free.
  BoundarySupport inner = BoundarySupport::free;
  /// Normal pressure on the borehole wall (Fig. 1; Lamé); positive pushes into the solid (radially
  /// outward). Over E; a deviation from p0, so any finite value. Annulus only (else must be 0).
  double inner_pressure = 0.0;
  /// Normal pressure on the outer boundary; positive pushes into the solid (inward). Any finite value.
  /// On a fixed boundary a pressure only adds to the reactions (loads at held DOFs do nothing).
  double outer_pressure = 0.0;
  /// A stress tensor whose traction outer_stress . m (m the outward normal) loads the outer boundary
  /// besides outer_pressure: the in-situ far field (the effective one in a coupled run, see
  /// docs/insitu.md). Tension positive, over E. Any constant tensor's traction is self-equilibrated
  /// on the closed boundary polygon, so a free lattice needs no support. Allowed: finite, symmetric;
  /// zero unless outer = free (loads at held DOFs would do nothing).
  Eigen::Matrix2d outer_stress = Eigen::Matrix2d::Zero();
  /// Hold x, y of every boundary particle (inner and outer) at u = boundary_strain * x (homogeneous
  /// strain, for calibration and patch tests); rotations stay free. Needs both supports free.
  bool prescribe_boundary_strain = false;
  /// The homogeneous strain (symmetric; tension positive). Allowed: finite, symmetric.
  Eigen::Matrix2d boundary_strain = Eigen::Matrix2d::Zero();
  /// Further prescribed components (tests, calibration), applied last.
  std::vector<PrescribedDisplacement> prescribed;

  /// Throws hm::InputError "boundary_conditions.field = value, allowed: rule".
  void validate(const Lattice& lattice) const;
  /// No boundary pressure, outer stress, boundary strain or non-zero prescribed value: u = 0 is the
  /// equilibrium of the unloaded lattice.
  bool is_unloaded() const;
};

/// Numerical options of the mechanical solve.
struct MechanicsOptions {
  /// Linear solver (spd_solver.hpp). Default: CHOLMOD with low-rank modifications.
  SpdSolverKind solver = SpdSolverKind::cholmod;
  /// Options of that solver (ordering, refactorisation triggers, CG tolerance); validated with these.
  SpdSolverOptions solver_options;
  /// Cap on the contact active-set iterations of one solve() (Eqs. 8-10). Allowed: >= 1.
  int max_contact_iterations = 50;
  /// Active-set iterations in which every violated beam switches at once; after them one beam switches
  /// per iteration, the most violated, because the full switches can cycle (measured: six beams at a
  /// fluid-filled crack's tip, N = 1.5e4, in a 4-cycle until the cap). Our choice 10: the runs so far
  /// settle within it, bit for bit as before. Allowed: >= 0.
  int contact_switches_at_once = 10;
  /// A broken beam closes when its elongation (u_j - u_i).n < -contact_tolerance * max|u| and opens
  /// when > +contact_tolerance * max|u| (a round-off hysteresis against flip-flopping). Our choice
  /// 1e-10. Allowed: 0 <= contact_tolerance < 1.
  double contact_tolerance = 1e-10;

  /// Throws hm::InputError "mechanics_options.field = value, allowed: rule".
  void validate() const;
};

/// The translational normal springs of BeamMechanics::set_normal_springs, given to its constructor so
/// that the matrix is factorised once, with them (a factorisation is a minute at N = 1e6).
struct NormalSprings {
  Eigen::VectorXd stiffness;  ///< one per beam, or empty: none
  BrokenBeamSpring broken = BrokenBeamSpring::keep;
};

/// Forces of every beam for displacements u (3 n_particles, dof = 3 i + component) and the given beam
/// states: beam_force (BeamOperator's internal force) of each, i.e. intact beams by Eqs. 3-4
/// (linearised), contacts by Eq. 9-10's normal spring, open beams zero; equal to -K_e u_e to round-off
/// (tests/lattice2d/test_fast_path.cpp), so the particle sums are -K u. particle_stress.hpp's
/// compute_beam_forces(lattice, parameters, u, states) gives the same F_ij and moments, bit for bit, in
/// its BeamForces layout; this one adds the normal and shear components. Limits: like the stiffness,
/// geometrically linear.
std::vector<BeamForce> connection_forces(const Lattice& lattice, const BeamParameters& parameters,
                                         const std::vector<BeamState>& states, const Eigen::VectorXd& u);

/// The largest displacement (over R; rotations in rad) the small-strain lattice stands for: 1e3 times a
/// rock's strain at failure. Beyond it a state means nothing, whatever its residuals.
inline constexpr double kMaxSmallStrainDisplacement = 0.1;

/// What one BeamMechanics::solve did (Ceres' Summary in small).
struct MechanicsSummary {
  Eigen::ComputationInfo info = Eigen::Success;  ///< linear solver status (Success, NumericalIssue, ...)
  bool contact_converged = false;                ///< the contact set was stable at the last iteration
  int contact_iterations = 0;                    ///< linear solves in the active-set loop
  int n_contact_changes = 0;                     ///< open <-> contact switches in this solve
  int n_contacts = 0;                            ///< broken beams in contact after the solve
  int n_open = 0;                                ///< broken beams open after the solve
  int n_detached_particles = 0;                  ///< particles held because they lost their anchoring (all so far)
  double solver_residual = 0.0;                  ///< ||A x - b|| / ||b|| of the last linear solve
  /// max |K u - f| over free degrees of freedom, over max |f| (f the loads incl. held-DOF terms).
  /// NaN after solve(false), which skips it.
  double equilibrium_residual = 0.0;
  double solve_seconds = 0.0;  ///< wall time of this solve()
  std::string message;         ///< why, when not converged
  /// A failed solve whose displacements pass kMaxSmallStrainDisplacement: parts of the lattice held by
  /// a few beams move almost freely (the lattice nearly cut through), and the matrix is near-singular.
  bool near_mechanism = false;
  bool is_converged() const { return info == Eigen::Success && contact_converged; }
};

/// u (3 entries per particle) minus the least-squares rigid motion of all the particles'
/// translations: the gauge in which BeamMechanics reports a pure-traction solve, for putting a closed
/// form in the same gauge.
Eigen::VectorXd without_rigid_motion(const Lattice& lattice, Eigen::VectorXd u);

/// The dry lattice's mechanics: assembles and factorises once, then solve() / break_beam() / solve().
///
/// Rules (docs/lattice.md):
///  - Prescribed degrees of freedom are eliminated (not penalised): the solver sees K_ff, the rhs
///    f_f - K_fh u_h, so the system stays SPD and as well-conditioned as the lattice.
///  - Pure traction (no held degree of freedom): x, y, rotation of the particle nearest the lattice's
///    centroid are pinned at 0 and, after each solve, the least-squares rigid motion of all particles
///    is subtracted from the reported displacement (the gauge: zero mean translation and rotation).
///    Exact when the loads are self-equilibrated, as boundary pressures are; pin_reaction reports
///    what the pin carries otherwise. When break_beam leaves the pinned particle without an intact
///    beam (springs and contacts carry no moment: the body could turn about it), the pin moves, at
///    its current displacement, to the particle nearest the centroid with all beams intact in the
///    largest intact-connected part; pinned_particle() is then that particle.
///  - Detachment: a particle or cluster whose intact (or sprung, set_normal_springs) beams no longer connect it to held
///  degrees of
///    freedom that stop all three rigid motions (a particle with only contacts left has a free
///    rotation) is frozen at the least-squares rigid motion of its last displacement (so it carries no
///    force), all its broken beams are forced open, and the system is re-assembled and refactorised.
///  - break_beam: intact -> contact if the beam is currently shortened, else open; the factor is
///    downdated with columns of beam_element_factor (rank 2 or 3). solve() then runs the active set.
/// Limits: linear, small displacements; contacts are frictionless normal springs with the intact
/// beam's k_n (Eq. 9-10); loads are fixed nodal forces on the undeformed geometry.
class BeamMechanics {
 public:
  /// Validates everything (throws hm::InputError), assembles and factorises, with `springs` in the
  /// matrix (set_normal_springs). Does not solve.
  BeamMechanics(Lattice lattice, const BeamParameters& parameters, const BoundaryConditions& conditions,
                const MechanicsOptions& options = {}, const NormalSprings& springs = {});

  /// Solve for the current loads and beam states, with the contact active-set loop.
  MechanicsSummary solve();
  /// The same; equilibrium_check = false skips the O(n_beams) re-evaluation of every beam behind
  /// summary.equilibrium_residual (then NaN), for callers that do not read it (the break loop, which
  /// re-solves after every broken beam; the linear solver still checks its own residual). The
  /// displacement and everything else are the same as solve()'s.
  MechanicsSummary solve(bool equilibrium_check);
  /// Break an intact beam (no-op for a broken one); returns its new state. Throws hm::InputError
  /// "beam = b, allowed: 0 <= beam < n_beams" for a bad index.
  BeamState break_beam(int beam);
  /// Soften an intact beam (the saw-tooth law, sawtooth.hpp): all of its stiffness (k_n and with it
  /// the bending k_omega, Eq. 4) becomes stiffness_factor times the unsoftened one, by a rank-3
  /// downdate of the kept factor. Allowed: 0 < stiffness_factor < the current factor (a beam only
  /// softens); throws hm::InputError otherwise, for a bad index or a broken beam. When the beam
  /// later breaks, its contact has the unsoftened k_n (Eqs. 9-10). While a softened beam is shortened
  /// (its crack closed: the contact active set of solve() decides, as for broken beams), its normal
  /// stiffness is the unsoftened k_n and only its bending stays softened.
  void soften_beam(int beam, double stiffness_factor);
  /// True while softened beam `beam` is closed (normal stiffness unsoftened; see soften_beam).
  bool is_closed(int beam) const { return closed_[static_cast<std::size_t>(beam)]; }
  /// The stiffness of intact beam `beam` over its unsoftened stiffness (1 unless softened; 1 for a
  /// broken beam, whose contact is unsoftened).
  double stiffness_factor(int beam) const { return softening_[static_cast<std::size_t>(beam)]; }
  /// Additional nodal forces (3 n_particles; e.g. pore-pressure forces, crack-face pressure), added
  /// to the boundary pressures. Components at held degrees of freedom are ignored.
  void set_external_forces(const Eigen::VectorXd& forces);
  /// Extra translational normal springs, one stiffness per beam (size n_beams, each >= 0 and finite):
  /// beam e adds k_e n n^T (u_j - u_i) between its particles' x, y, whatever the beam's state. Used by
  /// the undrained split of the coupling (Eq. 20, coupling.hpp); empty or all zero: none. Part of the
  /// matrix (re-assembled and refactorised once here), of reactions() and of the equilibrium residual;
  /// not part of beam_forces() (the springs are a numerical device, not a bond). Throws hm::InputError.
  /// With BrokenBeamSpring::drop, a beam's spring goes with the beam when it breaks (break_beam).
  void set_normal_springs(const Eigen::VectorXd& stiffness, BrokenBeamSpring broken = BrokenBeamSpring::keep);
  /// The springs of set_normal_springs (empty if none), zero where a dropped spring's beam broke.
  const Eigen::VectorXd& normal_springs() const { return springs_; }
  /// A stiffness k g g^T over all degrees of freedom on top of the beams and springs (g of size
  /// 3 n_particles), relaxed at set_rank_one_reference's displacement and applied in every solve by
  /// Sherman-Morrison, not put into the factor (RankOneStiffness): the coupling's borehole fluid
  /// answering its wall's motion, which couples the whole wall. Part of solve(), linear_response()
  /// (without the reference) and reactions(); not of beam_forces(). A default-constructed term
  /// removes it. Throws hm::InputError for a vector of the wrong size.
  void set_rank_one_stiffness(RankOneStiffness term);
  /// The displacement at which the rank-1 term is relaxed (its force k g g.(u - u_ref)).
  void set_rank_one_reference(const Eigen::VectorXd& u_reference);
  const RankOneStiffness& rank_one_stiffness() const { return rank_one_; }

  /// The displacement (3 n_particles; 0 at held dofs) that `forces` (3 n_particles) add under the
  /// current matrix (beam states, contacts, springs) with the kept factor: one solve, no state
  /// changed. The coupling's linearised response of the lattice to a pressure. Throws hm::InputError.
  Eigen::VectorXd linear_response(const Eigen::VectorXd& forces) const;
  /// Displacements (3 n_particles, dof = 3 i + component) of the last solve (0 before).
  const Eigen::VectorXd& displacement() const { return displacement_; }
  /// Forces of every beam at the current displacement (connection_forces). For particle stresses use
  /// compute_beam_forces(lattice(), parameters(), displacement(), states()) of particle_stress.hpp.
  std::vector<BeamForce> beam_forces() const;
  /// The same into `forces` (resized to n_beams), reusing its storage across calls.
  void beam_forces(std::vector<BeamForce>& forces) const;
  /// Nodal loads: boundary pressures plus set_external_forces (3 n_particles).
  Eigen::VectorXd loads() const { return pressure_loads_ + extra_loads_; }
  /// K u - loads (3 n_particles): ~0 at free degrees of freedom, the reactions at held ones.
  Eigen::VectorXd reactions() const;

  const Lattice& lattice() const { return lattice_; }
  const BeamParameters& parameters() const { return parameters_; }
  const std::vector<BeamState>& states() const { return states_; }
  const std::vector<bool>& held_dofs() const { return held_; }
  const std::vector<bool>& detached_particles() const { return detached_; }
  int n_detached_particles() const { return n_detached_; }
  int n_free_dofs() const { return static_cast<int>(free_dofs_.size()); }
  /// True when the rigid-body modes were pinned automatically (pure traction).
  bool is_pinned() const { return pinned_particle_ >= 0; }
  int pinned_particle() const { return pinned_particle_; }
  const SpdSolver& solver() const { return *solver_; }

  /// The state after a solve (beam states, held and detached degrees of freedom, the pin, loads,
  /// displacement, the solver's factor), for checkpoints (whole): a BeamMechanics built with the same
  /// arguments that restores it continues bitwise; or the start of a coupled step (step_start, after
  /// begin_step()), for this BeamMechanics to return to, without a copy of the factor.
  void save_state(core::StateWriter& w, StateScope scope = StateScope::whole) const;
  /// Marks a coupled step's start (SpdSolver::begin_step).
  void begin_step() { solver_->begin_step(); }
  /// Throws hm::InputError for a state of another lattice or written by other code.
  void restore_state(core::StateReader& r);

 private:
  // The constructor's parts, in order: the held degrees of freedom, the rigid-body modes (pinned or
  // checked), the boundary tractions lumped to the particles, the particle -> beam adjacency.
  void hold(int dof, double value);
  void hold_boundary_dofs();
  void remove_rigid_body_modes();
  void lump_boundary_loads();
  void build_adjacency();
  // set_normal_springs' checks and assignment, without the re-assembly (the constructor assembles once).
  void adopt_normal_springs(const Eigen::VectorXd& stiffness, BrokenBeamSpring broken);
  void setup_system();                             // free-DOF map, reduced matrix, held-term vector, factorisation
  BeamParameters beam_parameters(int beam) const;  // = beam_parameters_for(lattice_, parameters_, beam), cached k_n
  void change_state(int beam, BeamState to);
  double elongation(int beam) const;  // (u_j - u_i).n of the last solve: the contact active set's measure
  // sigma scale V_c V_c^T for columns c of the unsoftened intact element factor (rank <= 3).
  void modify_beam(int beam, const std::vector<int>& columns, double scale, int sigma);
  void check_detachment(int i, int j);
  // From `start`, the particles joined through intact (or sprung) beams, marked in `seen`: true at once
  // if `target` is among them (`out` then partial).
  bool connected_part(int start, int target, std::vector<char>& seen, std::vector<int>& out) const;
  bool is_anchored(const std::vector<int>& part) const;  // its held dofs stop its three rigid motions
  void freeze_part(const std::vector<int>& part);        // held at its nearest rigid motion, its contacts open
  bool has_intact_beam(int particle) const;
  void move_pin();  // pure traction: re-pin on the intact body (check_detachment)
  // One change of the contact active set: a broken beam between open and contact, or a softened one
  // between open and closed; violation is |elongation|.
  struct ContactSwitch {
    int beam;
    bool softened;
    double violation;
  };
  std::vector<ContactSwitch> contact_switches(double tol, int iteration) const;
  void apply(const std::vector<ContactSwitch>& switches, double tol);
  void remove_rigid_motion();           // displacement_ = raw_ less its least-squares rigid motion (the gauge)
  double equilibrium_residual() const;  // from every beam's state, independent of the factor
  Eigen::VectorXd full_vector(const Eigen::VectorXd& x_free) const;

  Lattice lattice_;
  BeamParameters parameters_;
  BoundaryConditions conditions_;
  MechanicsOptions options_;
  std::vector<BeamState> states_;
  std::vector<double> normal_stiffness_;  // per beam: beam_parameters_for(...).normal_stiffness (facet scaling)
  std::vector<double> softening_;         // per beam: stiffness over the unsoftened one (soften_beam)
  std::vector<bool> closed_;              // per beam: softened, intact and shortened (normal unsoftened)
  std::vector<int> softened_;             // the intact softened beams, in index order (the closure loop's)
  std::vector<bool> held_;                // per dof
  Eigen::VectorXd held_value_;            // per dof (0 where free)
  std::vector<bool> detached_;            // per particle
  int n_detached_ = 0;
  int pinned_particle_ = -1;
  std::vector<int> free_index_;  // per dof: index in the reduced system or -1
  std::vector<int> free_dofs_;
  std::vector<int> adjacency_start_, adjacency_beam_;  // CSR particle -> beams
  Eigen::VectorXd pressure_loads_, extra_loads_;
  Eigen::VectorXd held_term_;  // K u_h (3 n), kept current under state changes
  Eigen::VectorXd raw_;        // last solution incl. held values, before the gauge shift
  Eigen::VectorXd displacement_;
  std::vector<int> broken_;            // beams not intact
  Eigen::VectorXd springs_;            // set_normal_springs, per beam (empty: none)
  mutable RankOneStiffness rank_one_;  // mutable: it keeps K^-1 g of the current matrix for linear_response
  BrokenBeamSpring broken_spring_ = BrokenBeamSpring::keep;
  void remove_normal_spring(int beam);  // a rank-1 downdate of k n n^T
  std::unique_ptr<SpdSolver> solver_;
};

}  // namespace hm::lattice2d
