#pragma once
/// \file
/// The two-way coupled lattice model of Section 2.3 (Fig. 5): beam mechanics (mechanics.hpp) and the
/// dual-graph flow network (flow_network.hpp) advanced together in time by the drained or undrained
/// operator split, iterated inside each time step until the pressure and the displacement both stop
/// changing. Dimensionless. Choices the paper leaves open: docs/coupling.md.
#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "hm/core/enum_names.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/lattice2d/coupled/coupling.hpp"
#include "hm/lattice2d/coupled/relaxation.hpp"
#include "hm/lattice2d/flow/flow_network.hpp"
#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"

namespace hm::lattice2d {

/// The two splits of Section 2.3.
enum class CouplingSplit {
  undrained,  ///< the mechanical step sees the undrained pressure predictor (Eq. 20, Psi > 0 allowed)
  drained,    ///< the mechanical step sees the last pressure only (Psi = 0)
};
constexpr auto enum_names(CouplingSplit) {
  return core::enum_table<CouplingSplit>(
      {{CouplingSplit::undrained, "undrained"}, {CouplingSplit::drained, "drained"}});
}

/// When the coupling loop looks for failing beams (with fracture enabled).
enum class FractureCheck {
  /// After every pass's mechanical solve (the paper's Fig. 5): beams can break on an unconverged
  /// iterate, so the pattern depends a little on the iteration's path (docs/coupling.md, section 6).
  every_pass,
  /// Only once the passes have converged without breaking; after breaks the loop converges again
  /// and checks again, until a converged state breaks nothing. Our addition: breaks are decided on
  /// coupled equilibria only.
  at_convergence,
};
constexpr auto enum_names(FractureCheck) {
  return core::enum_table<FractureCheck>(
      {{FractureCheck::every_pass, "every_pass"}, {FractureCheck::at_convergence, "at_convergence"}});
}

/// Where the first pass of a step starts.
enum class CouplingPredictor {
  /// From the last accepted state, p^n and u^n (the paper's loop).
  previous,
  /// From the straight line through the last two accepted states, p^n + (dt / dt_prev)(p^n - p^{n-1})
  /// and likewise u, when the last step broke no beam (a crack's jump is not a trend); otherwise as
  /// previous. Our addition: fewer passes on the smooth part of a run; same fixed point.
  linear,
};
constexpr auto enum_names(CouplingPredictor) {
  return core::enum_table<CouplingPredictor>(
      {{CouplingPredictor::previous, "previous"}, {CouplingPredictor::linear, "linear"}});
}

/// What the flow solve of a pass knows of the cracks' compliance (FlowStabiliser, flow_network.hpp).
enum class CrackStabiliser {
  /// Nothing: the split as the paper iterates it. With fluid-filled cracks (CrackCoupling::full) at
  /// small b the passes then stall or diverge: a crack's compliance is thousands of times its fluid's
  /// storage (docs/coupling.md).
  none,
  /// Each connected crack's volume response to a uniform pressure on it, from the lattice's factor at
  /// the step's state (one solve per crack, refreshed after breaks): the fixed point is unchanged, a
  /// well-connected crack converges in a few passes. Used only with CrackCoupling::full.
  uniform_pressure,
  /// Every crack unknown's own volume response (one solve per crack triangle): the cracks' whole
  /// compliance as the flow sees it, for a crack whose pressure is far from uniform (a viscous fluid,
  /// the cubic law). Costs a solve per crack unknown at each update instead of one per crack.
  crack_unknowns,
};
constexpr auto enum_names(CrackStabiliser) {
  return core::enum_table<CrackStabiliser>({{CrackStabiliser::none, "none"},
                                            {CrackStabiliser::uniform_pressure, "uniform_pressure"},
                                            {CrackStabiliser::crack_unknowns, "crack_unknowns"}});
}

/// The smallest coupling tolerance: a pass's relative change stalls at round-off (measured ~1e-11 for
/// the pressure of the Fig. 12 quick case, whose passes then never converge).
inline constexpr double kMinCouplingTolerance = 1e-10;

/// Options of the coupling iteration (Fig. 5). Every default is set here.
struct CouplingOptions {
  /// The split. Default undrained (the paper's primary scheme).
  CouplingSplit split = CouplingSplit::undrained;
  /// xi, Psi and the borehole wall traction (coupling.hpp). Psi must be 0 for the drained split, the
  /// split without the Eq. 20 feedback (default_psi gives a case reader the default of each split).
  CouplingTerms terms;
  /// Iterations stop when max|p^k - p^{k-1}| <= pressure_tolerance * max|p^k| ... Our choice 1e-6.
  /// Allowed: kMinCouplingTolerance = 1e-10 <= pressure_tolerance < 1 (below, round-off stalls the passes).
  double pressure_tolerance = 1e-6;
  /// ... and max|u^k - u^{k-1}| <= displacement_tolerance * max|u^k| (x, y components). Our choice 1e-6.
  /// Allowed: 1e-10 <= displacement_tolerance < 1.
  double displacement_tolerance = 1e-6;
  /// ... and the run's volume balance error after the step (FlowStepSummary::balance_error) is at most
  /// this. It is round-off (< 1e-10) unless the flow solve carries the crack stabiliser, whose term
  /// V W^T (p - p_ref) is fluid charged to a crack ahead of its opening (FlowStepSummary::charged_ahead,
  /// supplied again at the next step): the tolerance bounds that outstanding fluid as a fraction of all
  /// the run has moved, not of the step's own volumes, which vanish with dt (a step cut short to land an
  /// event would need its pressures to round-off). Our choice 1e-3; 1: off.
  /// Allowed: 1e-10 <= balance_tolerance <= 1.
  double balance_tolerance = 1e-3;
  /// Cap on the mechanics -> flow iterations of one step (with fracture_check = at_convergence: since
  /// the last breaks). Allowed: >= 1.
  int max_iterations = 100;
  /// When beams are checked for failure. Default every_pass (the paper's Fig. 5).
  FractureCheck fracture_check = FractureCheck::every_pass;
  /// Events (breaks or teeth) taken at one check before the coupling solves again; 0: every beam
  /// that fails under the check's loads, one after the other at fixed pressure (the paper's Fig. 5).
  /// With 1 the fluid responds to each event before the next is judged: the events of a crack whose
  /// compliance dwarfs its fluid's storage then come at the injected volume, not at a pressure the
  /// opening has already relieved. Allowed: 0 ... kMaxEventsPerCheck.
  int events_per_check = 0;
  static constexpr int kMaxEventsPerCheck = 1000000;
  /// The first pass's guess. Default previous (the paper's loop).
  CouplingPredictor predictor = CouplingPredictor::previous;
  /// The flow solve's knowledge of fluid-filled cracks (CrackCoupling::full only). Default uniform_pressure.
  CrackStabiliser crack_stabiliser = CrackStabiliser::uniform_pressure;
  /// Relaxation of the pressure guess between passes. Default none (the paper's loop). Our addition for
  /// the borehole, whose stiff feedback makes the plain loop diverge (docs/coupling.md, section 3).
  CouplingRelaxation relaxation = CouplingRelaxation::none;
  /// First relaxation factor of the aitken variant, mixing factor of the anderson one. Our choice 0.5.
  /// Allowed: 0 < initial_relaxation <= 1.
  double initial_relaxation = 0.5;
  /// Number of past residual differences the anderson variant combines. Our choice 5. Allowed: 1 ... 50.
  int anderson_depth = 5;
  /// Accept a step that hit max_iterations (the paper's "one iteration of both systems" with
  /// max_iterations = 1). Default false: such a step is a numerical failure (status not_converged).
  bool accept_unconverged = false;

  /// Throws hm::InputError "coupling.field = value, allowed: rule".
  void validate() const;
};

/// Psi's default for `split`: CouplingTerms{}.psi for the undrained split, 0 for the drained one.
double default_psi(CouplingSplit split);

/// Time stepping of CoupledModel::run. Every default is set here.
struct TimeStepping {
  /// First time step. Allowed: > 0, finite, <= t_end.
  double dt_initial = 1e-6;
  /// Factor between consecutive steps (1 = fixed dt). Allowed: >= 1, finite.
  double dt_growth = 1.0;
  /// Largest time step. Allowed: >= dt_initial, finite.
  double dt_max = std::numeric_limits<double>::max();
  /// End time t*. Allowed: > 0, finite.
  double t_end = 1e-4;
  /// A step whose coupling loop does not converge (status not_converged) is retried with half the
  /// step, at most this many times, before run() stops; the nominal dt then grows again from there.
  /// Our choice 8 (dt / 256). A failed attempt leaves no trace: its breaks are undone with the rest
  /// of its state (CoupledModel::step), so the retry breaks what the shorter step breaks.
  /// Allowed: 0 ... 50.
  int max_step_halvings = 8;
  /// > 0: a step whose first break has failure ratio above 1 + this (the time-driven load went past
  /// the beam's threshold within the step) is retried with half the step, like one that does not
  /// converge, up to max_step_halvings times; the last try is accepted. Breakdown then happens within
  /// this of the critical load whatever dt_max is. 0: off (every first break accepted, as the
  /// paper's steps). Allowed: 0 <= value < 1.
  double overshoot_tolerance = 0.0;
  /// Times at which run() calls its observer besides t = 0 (steps are shortened to land on them).
  /// Allowed: strictly increasing, in (0, t_end]; t_end is always an output.
  std::vector<double> output_times;

  /// Throws hm::InputError "numerics.field = value, allowed: rule".
  void validate() const;
};

/// How a step or a run ended.
enum class CoupledStatus {
  converged,             ///< both residuals below tolerance
  accepted_unconverged,  ///< max_iterations hit and accept_unconverged set
  not_converged,         ///< max_iterations hit: the step was not taken
  solver_failure,        ///< the mechanics or the flow solve failed: the step was not taken
  interrupted,           ///< run() stopped: between steps (its stop request) or within one, undone (set_interrupt)
  overshoot,             ///< its first break was above 1 + overshoot_tolerance: the step was not taken
};
constexpr auto enum_names(CoupledStatus) {
  return core::enum_table<CoupledStatus>({{CoupledStatus::converged, "converged"},
                                          {CoupledStatus::accepted_unconverged, "accepted unconverged"},
                                          {CoupledStatus::not_converged, "not converged"},
                                          {CoupledStatus::solver_failure, "solver failure"},
                                          {CoupledStatus::overshoot, "overshoot"},
                                          {CoupledStatus::interrupted, "interrupted"}});
}

/// What one coupled time step did (Ceres' Summary in small).
struct CoupledStepSummary {
  CoupledStatus status = CoupledStatus::converged;
  double time = 0.0;  ///< t^{n+1}
  double dt = 0.0;
  int iterations = 0;                  ///< mechanics -> flow passes
  double pressure_residual = 0.0;      ///< max|p^k - p^{k-1}| / max|p^k| at the last pass
  double displacement_residual = 0.0;  ///< max|u^k - u^{k-1}| / max|u^k| at the last pass
  /// The pressure residual after each pass (for the Psi study, Fig. 8).
  std::vector<double> pressure_history;
  FlowStepSummary flow;                 ///< the last flow solve (volumes of this step, balance)
  int n_breaks = 0;                     ///< beams broken in this step (all passes)
  int n_teeth = 0;                      ///< saw-tooth law: teeth given way in this step (breaks not included)
  double first_event_ratio = 0.0;       ///< failure ratio of the step's first break or tooth (0 if none)
  int n_broken = 0;                     ///< beams broken since t = 0, after this step
  double seconds = 0.0;                 ///< wall time of the step, of which:
  double mechanics_seconds = 0.0;       ///< BeamMechanics::solve (back-substitutions), also inside break loops
  double stress_seconds = 0.0;          ///< break loops: beam stresses and failure checks
  double break_seconds = 0.0;           ///< break loops: BeamMechanics::break_beam (factor downdates)
  int n_mechanics_solves = 0;           ///< mechanical solves (one per pass plus one per break)
  int n_contact_changes = 0;            ///< open <-> contact switches of broken beams (each a factor modification)
  int n_mechanics_factorizations = 0;   ///< full refactorisations of the mechanical factor (after
                                        ///< max_modifications modifications, or a failed update)
  int n_mechanics_update_failures = 0;  ///< of which after a failed low-rank update (cholmod_updown)
  double geometry_seconds = 0.0;        ///< deformed dual graph and FlowNetwork::update_geometry
  double flow_seconds = 0.0;            ///< FlowNetwork::solve (refactorisation and solve)
  std::string message;                  ///< empty when converged
  /// A solver_failure with the lattice nearly cut through by the breaks of one pass at physical pressures
  /// (BreakLoopSummary's): one event per check lets the fluid answer each break.
  bool near_mechanism = false;
  bool is_ok() const { return status == CoupledStatus::converged || status == CoupledStatus::accepted_unconverged; }
};

/// What run() did.
struct CoupledRunSummary {
  CoupledStatus status = CoupledStatus::converged;  ///< of the last step
  int n_steps = 0;
  int total_iterations = 0;
  int n_step_halvings = 0;  ///< retries with half the step after a coupling loop did not converge
  double time = 0.0;
  double seconds = 0.0;
  double max_balance_error = 0.0;
  std::string message;
  bool near_mechanism = false;  ///< the last step's (CoupledStepSummary's)
  /// The accepted steps' time split and counters (CoupledStepSummary's), summed.
  double step_seconds = 0.0, mechanics_seconds = 0.0, stress_seconds = 0.0, break_seconds = 0.0, geometry_seconds = 0.0,
         flow_seconds = 0.0;
  long long n_mechanics_solves = 0, n_contact_changes = 0, n_mechanics_factorizations = 0,
            n_mechanics_update_failures = 0;
  bool is_ok() const { return status == CoupledStatus::converged || status == CoupledStatus::accepted_unconverged; }
  /// Adds one accepted step to the sums above.
  void add_accepted_step(const CoupledStepSummary& s);
};

/// The coupled lattice (Fig. 5): per time step
///   1. mechanics with the current pressure guess: forces of Eq. 17 plus, for the undrained split,
///      the springs of Eq. 20 relaxed at the previous iterate;
///   2. the deformed geometry (triangle areas, conductances) from the new displacement;
///   3. the flow step of Eqs. 15-16 with b (V^{n+1} - V^n);
///   4. repeat until both residuals are below tolerance (or max_iterations).
/// At convergence the spring term vanishes, so every Psi converges to the drained split's fixed point.
/// With fracture enabled (enable_fracture), step 1 is the break loop of Section 2.1 (fracture.hpp):
/// solve, break the one beam most over its strength, re-solve, until none fails; the broken beams' flow
/// segments get iota before step 3, and a pass that broke a beam never ends the iteration (Fig. 5: "if
/// the system is changed during the solver steps, a new iteration is necessary"). Broken beams stay
/// broken, also when a later pass or a failed step would not have broken them.
/// Limits: geometrically linear mechanics, no re-meshing.
class CoupledModel {
 public:
  /// Validates everything (hm::InputError), builds mechanics and flow. b and E/M are the flow's.
  CoupledModel(Lattice lattice, const BeamParameters& beams, const BoundaryConditions& conditions,
               const MechanicsOptions& mechanics_options, const FlowParameters& flow, const CouplingOptions& options);
  ~CoupledModel();

  /// Turns fracture on (Fig. 5's grey boxes) with one strength per beam and the break loop's options
  /// (crack-tip factor, cap per call). Throws hm::InputError for strengths not sized n_beams or invalid
  /// options. Call before the first step.
  void enable_fracture(BeamStrengths strengths, const BreakLoopOptions& options = {});
  bool fracture_enabled() const { return fracture_ != nullptr; }
  /// Replaces the brittle beam by the saw-tooth law (sawtooth_law.hpp): tension on each beam's axial
  /// stress against its current tooth, a beam stepped down tooth by tooth (logged in tooth_log()) and
  /// broken after its last; the break loop's crack-tip factor is then not used. Call after
  /// enable_fracture (its tensile strengths are the f_t) and before the first step; throws
  /// hm::InputError otherwise or for invalid options.
  void use_sawtooth_law(const SawtoothLawOptions& options);
  /// The saw-tooth law's state (null under the brittle law).
  const SawtoothLaw* sawtooth_law() const { return fracture_ ? fracture_->sawtooth.get() : nullptr; }
  /// Every tooth given way so far (saw-tooth law), in order; ToothEvent::load is the time of its step.
  const std::vector<ToothEvent>& tooth_log() const { return tooth_log_; }
  /// Breaks `beams` before the first step: pre-cut cracks ([fracture] notch, notch.hpp). Each becomes
  /// open (or contact) as a break makes it, is logged at t = 0 with mode none and ratio 0 (it did not
  /// fail), and the flow sees it as broken; the rest state (settle) is then that of the notched rock.
  /// With the cubic law the cut facets are a slot `slot_width` wide (FlowNetwork::set_slot_width).
  /// Throws hm::InputError without fracture enabled, after the first step, for a beam out of range or
  /// broken already, or a slot width < 0 or one > 0 without the cubic law.
  void cut_beams(const std::vector<int>& beams, double slot_width = 0.0);
  /// Beams broken by cut_beams (the first entries of break_log()).
  int n_cut() const { return n_cut_; }
  /// Every break so far, in order; BreakEvent::load is the time t^{n+1} of the step that broke it.
  const std::vector<BreakEvent>& break_log() const { return break_log_; }

  /// One coupled step of length dt > 0. On failure (status not_converged or solver_failure) the state
  /// is restored to t^n bit for bit, breaks of the failed attempt included; the summary says why.
  /// The first call (or run()) first brings the model to rest (settle).
  CoupledStepSummary step(double dt, double overshoot_tolerance = 0.0);

  /// The state at rest before injection: the drained equilibrium (p = 0, the deviation from p0, and
  /// no Eq. 20 springs) under the constant boundary loads, e.g. the in-situ far field, with the break
  /// loop when fracture is enabled (breaks logged at t = 0); injection starts from it, and failure
  /// sees the rest stress plus the increment. With no boundary load (is_unloaded) u = 0 is that state
  /// and nothing is solved. Called by the first step() or run(); later calls do nothing. The summary
  /// says what the solve did (status solver_failure and a message when it failed).
  CoupledStepSummary settle();
  bool is_at_rest() const { return at_rest_; }

  /// Observer of run(): called after every accepted step, with `is_output` true at t = 0, at each
  /// output time and at t_end.
  using Observer = std::function<void(const CoupledModel&, const CoupledStepSummary&, bool is_output)>;
  /// Initial state (observer at t = 0), then while time remains, a step. Stops at the first failed step,
  /// or (status interrupted) after an accepted step and its observer when `stop` returns true. A second
  /// call, or one after restore_state, continues from run_cursor(); the summary counts the whole run.
  CoupledRunSummary run(const TimeStepping& stepping, const Observer& observer = {},
                        const std::function<bool()>& stop = {});

  /// Where run() is between two steps: what it needs, besides the model's state, to go on.
  struct RunCursor {
    bool started = false;         ///< the initial state was observed (t = 0)
    std::size_t next_output = 0;  ///< index of the next output time
    double dt_nominal = 0.0;      ///< the step the next one starts from (before output snapping)
    CoupledRunSummary totals;     ///< counters of the accepted steps so far
  };
  /// The cursor after the last accepted step and its observer call (valid inside the observer).
  const RunCursor& run_cursor() const { return cursor_; }

  /// Everything the run depends on between two steps (mechanics with its factor, flow, coupling history,
  /// break log, strengths, run() cursor), for checkpoints. A model built from the same case that
  /// restores it continues (run()) bitwise as this one would have.
  void save_state(core::StateWriter& w) const;
  /// Throws hm::InputError for a state of another model or written by other code. After it, run()
  /// continues from the restored cursor without observing t = 0 again.
  void restore_state(core::StateReader& r);

  /// Called after every pass of step() with the pass number (1-based), that pass's flow pressure
  /// (trial, size n_unknowns) and displacement: for studies of the iteration itself (Fig. 8).
  using PassObserver =
      std::function<void(int pass, const Eigen::VectorXd& pressure, const Eigen::VectorXd& displacement)>;
  void set_pass_observer(PassObserver observer) { pass_observer_ = std::move(observer); }
  /// Asked between coupling passes and between the break loop's solves (empty: never): when it returns
  /// true, the step in progress is undone (as a failed attempt is) and run() ends as interrupted at
  /// the last accepted step, so a Ctrl-C need not wait for a long step; the state is a step's, and a
  /// checkpoint of it continues bitwise. The settling at t = 0 is not interrupted.
  void set_interrupt(std::function<bool()> requested) { interrupt_ = std::move(requested); }

  double time() const { return flow_->time(); }
  const Lattice& lattice() const { return mechanics_->lattice(); }
  /// Displacement u^n (3 n_particles) of the last accepted step.
  const Eigen::VectorXd& displacement() const { return displacement_; }
  /// Pressures p^n (triangles, then the borehole node).
  const Eigen::VectorXd& pressure() const { return flow_->pressure(); }
  /// Dual graph of the deformed configuration at t^n (triangle areas and centroids for averages).
  const DualGraph& current_dual() const { return current_dual_; }
  /// Dual graph of the undeformed lattice (the coupling terms' geometry).
  const DualGraph& reference_dual() const { return reference_dual_; }
  const FlowNetwork& flow() const { return *flow_; }
  const BeamMechanics& mechanics() const { return *mechanics_; }
  const CouplingOptions& options() const { return options_; }
  /// Per-beam spring stiffness of Eq. 20 on the intact lattice (zero for the drained split); the
  /// current ones, without dropped springs of broken beams, are mechanics().normal_springs().
  const Eigen::VectorXd& spring_stiffness() const { return springs_; }
  int n_broken() const;
  /// Particle stresses (sigma_xx, sigma_yy, sigma_xy per column) of the last mechanical solution as the
  /// failure check sees them: the beams' forces from the whole displacement (the rest state under an
  /// in-situ field plus the increment since), V_i of the undeformed dual like the break loop's.
  ParticleStress particle_stress() const;
  /// Every beam's failure ratio under the break loop's check (failure_ratios of fracture.hpp: with the
  /// crack-tip factor, or the saw-tooth law's; a beam gives way at >= 1), 0 for broken beams. Empty
  /// when fracture is off.
  Eigen::VectorXd failure_ratio() const;

 private:
  // run()'s start: the lattice settled at rest on a first call, a restored cursor checked against
  // the case's `n_outputs` output times. false: settling failed (recorded in the run's totals).
  bool begin_run(const TimeStepping& stepping, std::size_t n_outputs, const Observer& observer);
  // One step of nominal length dt, retried with half the step as TimeStepping says; dt ends as the
  // length of the last try.
  CoupledStepSummary step_with_retries(double& dt, const TimeStepping& stepping);
  // The guess a pass's mechanics sees: the pressure p_g (Eq. 17) and the springs' rest state u_g (Eq. 20).
  struct PassGuess {
    Eigen::VectorXd pressure, displacement;
  };
  // The sub-steps of step(); each returns false after recording a solver failure in the summary.
  PassGuess predict(double dt) const;
  // true: converged. A first event above 1 + overshoot_tolerance (> 0) ends the step at once.
  bool iterate(double dt, double overshoot_tolerance, PassGuess& guess, DualGraph& dual, CoupledStepSummary& summary);
  bool solve_mechanics(int pass, const PassGuess& guess, bool check_every_pass, int& n_breaks,
                       CoupledStepSummary& summary);
  bool break_beams(int pass, int& n_breaks, CoupledStepSummary& summary);
  bool solve_flow(double dt, int pass, const Eigen::VectorXd& u, const Eigen::VectorXd& pressure_guess, DualGraph& dual,
                  CoupledStepSummary& summary);
  // Fluid-filled cracks (CrackCoupling::full): each crack's volume response to a uniform pressure at
  // the current state, for the flow solve (FlowStabiliser); empty without cracks. keep_unchanged_modes:
  // a crack with the unknowns and weights of the last update keeps its response.
  void update_crack_stabiliser(bool keep_unchanged_modes);
  // With the cubic law: the cracked beams' openings at displacement u, whose apertures set the cracks'
  // conductances (the flow of a pass sees the pass's mechanics, so the converged step is implicit).
  void update_crack_openings(const Eigen::VectorXd& u);
  Eigen::VectorXd pressure_load(const Eigen::VectorXd& pressure) const;  // Eq. 17's forces of a pressure
  FlowStabiliser crack_stabiliser_;
  Eigen::VectorXd stabiliser_weights_;  // the crack weights crack_stabiliser_ was computed with
  void finish_step(double dt, bool converged, DualGraph dual, CoupledStepSummary& summary);  // accept or restore t^n
  // A converged pass state inside the model's range (every displacement <= 0.1 R, rotation <= 0.1 rad,
  // |p| <= 1 E); else says why in summary.
  bool within_small_strain(CoupledStepSummary& summary) const;
  Eigen::Matrix2Xd positions(const Eigen::VectorXd& u) const;
  Eigen::VectorXd unknown_volumes(const Eigen::VectorXd& triangle_area) const;  // V_s (areas), then V_h
  // How much of each beam's facet is crack (FlowNetwork::set_crack_weights): 1 broken; with
  // CrackCoupling::full and the saw-tooth law, the damage 1 - s of a softened beam; 0 otherwise.
  Eigen::VectorXd crack_weights() const;
  // The volumes the flow charges: with CrackCoupling::full a crack triangle's is b of its area and 1 - b
  // of its cracked beams' weighted openings at u (crack_opening_volumes); otherwise `volumes` as they are.
  Eigen::VectorXd charged_volumes(Eigen::VectorXd volumes, const Eigen::VectorXd& triangle_area,
                                  const Eigen::VectorXd& u) const;
  // save_state without the run cursor: what step() restores after a failed attempt. The accepted
  // geometry (current_dual_, volume_) is not in it: only an accepted step changes it.
  void save_model_state(core::StateWriter& w, StateScope scope) const;
  void restore_model_state(core::StateReader& r);
  // The accepted u and the linear predictor's history, saved (const Self) or restored (save_state).
  template <class Archive, class Self>
  static void transfer_history(Archive& a, Self& m);

  CouplingOptions options_;
  std::unique_ptr<BeamMechanics> mechanics_;
  std::unique_ptr<FlowNetwork> flow_;
  DualGraph reference_dual_;
  DualGraph current_dual_;
  Eigen::VectorXd springs_;
  Eigen::VectorXd displacement_;
  Eigen::VectorXd volume_;  // V^n per unknown
  // p^{n-1}, u^{n-1} and t^n - t^{n-1} for the linear predictor; previous_dt_ = 0 when the last step
  // broke beams (or there is none).
  Eigen::VectorXd previous_pressure_;
  Eigen::VectorXd previous_displacement_;
  double previous_dt_ = 0.0;
  PassObserver pass_observer_;
  std::function<bool()> interrupt_;
  std::unique_ptr<PassRelaxation> relaxation_;
  struct FractureSetup {
    BeamStrengths strengths;
    BreakLoopOptions options;
    std::unique_ptr<SawtoothLaw> sawtooth;  // null: the brittle beam
  };
  std::unique_ptr<FractureSetup> fracture_;
  std::vector<BreakEvent> break_log_;
  std::vector<ToothEvent> tooth_log_;
  bool unloaded_ = true;  // BoundaryConditions::is_unloaded: the rest state is u = 0
  bool at_rest_ = false;  // settle() has run
  int n_cut_ = 0;         // pre-cut beams (cut_beams), the head of break_log_
  RunCursor cursor_;
  // The state at the start of the step being taken, restored if the attempt fails; one buffer for
  // every step (its memory kept: a snapshot holds the factors, 44 MB at N = 1e4).
  core::StateWriter step_start_;
  bool first_snapshot_ = true;
};

}  // namespace hm::lattice2d
