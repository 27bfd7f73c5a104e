#include "hm/lattice2d/coupled/coupled_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>

#include "hm/core/input_error.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

double default_psi(CouplingSplit split) { return split == CouplingSplit::drained ? 0.0 : CouplingTerms{}.psi; }

void CouplingOptions::validate() const {
  using namespace hm::core;
  terms.validate();
  if (split == CouplingSplit::drained && terms.psi != 0.0)
    throw hm::FieldError("psi", "", format_value(terms.psi), "0 for split = drained");
  // A pass's relative change stalls at round-off (~1e-11 for the pressure of the Fig. 12 quick case):
  // a tolerance below kMinCouplingTolerance could never be met.
  for (const auto& [value, name] : {std::pair{pressure_tolerance, "pressure_tolerance"},
                                    std::pair{displacement_tolerance, "displacement_tolerance"}})
    if (!(value >= kMinCouplingTolerance && value < 1.0))
      throw hm::FieldError(name, "", format_value(value), format_value(kMinCouplingTolerance) + " <= {} < 1");
  if (!(balance_tolerance >= kMinCouplingTolerance && balance_tolerance <= 1.0))
    throw hm::FieldError("balance_tolerance", "", format_value(balance_tolerance),
                         format_value(kMinCouplingTolerance) + " <= {} <= 1");
  require_at_least(max_iterations, "max_iterations", 1);
  if (events_per_check < 0 || events_per_check > kMaxEventsPerCheck)
    throw hm::FieldError("events_per_check", "", std::to_string(events_per_check),
                         "0 ... " + std::to_string(kMaxEventsPerCheck));
  if (anderson_depth < 1 || anderson_depth > 50)
    throw hm::FieldError("anderson_depth", "", std::to_string(anderson_depth), "1 ... 50");
  if (!(initial_relaxation > 0.0 && initial_relaxation <= 1.0))
    throw hm::FieldError("initial_relaxation", "", format_value(initial_relaxation), "0 < {} <= 1");
}

void TimeStepping::validate() const {
  using namespace hm::core;
  require_finite(t_end, "t_end");
  require_positive(t_end, "t_end");
  require_finite(dt_initial, "dt_initial");
  require_positive(dt_initial, "dt_initial");
  if (dt_initial > t_end)
    throw hm::FieldError("dt_initial", "", format_value(dt_initial), "<= t_end = " + format_value(t_end));
  require_finite(dt_growth, "dt_growth");
  if (!(dt_growth >= 1.0)) throw hm::FieldError("dt_growth", "", format_value(dt_growth), ">= 1");
  if (max_step_halvings < 0 || max_step_halvings > 50)
    throw hm::FieldError("max_step_halvings", "", std::to_string(max_step_halvings), "0 ... 50");
  if (!(dt_max >= dt_initial))
    throw hm::FieldError("dt_max", "", format_value(dt_max), ">= dt_initial = " + format_value(dt_initial));
  if (!(overshoot_tolerance >= 0.0 && overshoot_tolerance < 1.0))
    throw hm::FieldError("overshoot_tolerance", "", format_value(overshoot_tolerance), "0 <= value < 1");
  require_feasible_stepping(dt_initial, dt_growth, dt_max, t_end);
  for (std::size_t k = 0; k < output_times.size(); ++k) {
    const double t = output_times[k];
    const std::string element = element_of(k);
    if (!(t > 0.0 && t <= t_end))
      throw hm::FieldError("output_times", element, format_value(t), "0 < t <= t_end = " + format_value(t_end));
    if (k > 0 && !(t > output_times[k - 1]))
      throw hm::FieldError("output_times", element, format_value(t), "strictly increasing");
  }
}

namespace {

// The largest |p| over E the small-strain model stands for (the displacements': kMaxSmallStrainDisplacement).
constexpr double kMaxSmallStrainPressure = 1.0;

// max|a - b| / max|a| (0 when both vanish), over entries selected by `stride` pattern (all for 0).
double relative_change(const Eigen::VectorXd& a, const Eigen::VectorXd& b, bool translations_only) {
  double num = 0.0, den = 0.0;
  for (Eigen::Index k = 0; k < a.size(); ++k) {
    if (translations_only && k % 3 == 2) continue;
    num = std::max(num, std::abs(a[k] - b[k]));
    den = std::max(den, std::abs(a[k]));
  }
  return den > 0.0 ? num / den : (num > 0.0 ? 1.0 : 0.0);
}

}  // namespace

CoupledModel::CoupledModel(Lattice lattice, const BeamParameters& beams, const BoundaryConditions& conditions,
                           const MechanicsOptions& mechanics_options, const FlowParameters& flow,
                           const CouplingOptions& options)
    : options_(options) {
  options_.validate();
  flow.validate();
  reference_dual_ = build_dual_graph(lattice);
  current_dual_ = reference_dual_;
  flow_ = std::make_unique<FlowNetwork>(lattice, reference_dual_, flow);
  springs_ = undrained_spring_stiffness(lattice, reference_dual_, flow.b, flow.E_over_M, options_.terms);
  // The springs are in the matrix from its first factorisation; Psi = 0 leaves the dry matrix as it is.
  NormalSprings springs;
  if (options_.terms.psi > 0.0) springs = {springs_, options_.terms.broken_beam_spring};
  mechanics_ = std::make_unique<BeamMechanics>(std::move(lattice), beams, conditions, mechanics_options, springs);
  if (options_.terms.borehole_spring == BoreholeSpring::undrained) {
    if (!flow_->has_borehole())
      throw hm::InputError(
          "coupling.borehole_spring = \"undrained\", allowed: only with a borehole (lattice.domain = annulus)");
    // At the undeformed hole's storage: V_h changes by the strains (~1e-4), and the spring only sets
    // the passes' path.
    mechanics_->set_rank_one_stiffness(borehole_spring(mechanics_->lattice(), flow_->borehole_storage_coefficient(),
                                                       flow_->borehole_deformation_coefficient()));
  }
  displacement_ = Eigen::VectorXd::Zero(3 * mechanics_->lattice().n_particles());
  volume_ = unknown_volumes(reference_dual_.triangle_area);
  unloaded_ = conditions.is_unloaded();
  relaxation_ = make_pass_relaxation(options_.relaxation, options_.initial_relaxation, options_.anderson_depth);
}

CoupledModel::~CoupledModel() = default;

void CoupledModel::enable_fracture(BeamStrengths strengths, const BreakLoopOptions& options) {
  options.validate();
  const int n = lattice().n_beams();
  if (strengths.n_beams() != n || strengths.compressive.size() != n)
    throw hm::InputError("fracture.strengths: " + std::to_string(strengths.n_beams()) +
                         " values, allowed: one per beam (" + std::to_string(n) + ")");
  fracture_ = std::make_unique<FractureSetup>(FractureSetup{std::move(strengths), options, nullptr});
}

void CoupledModel::use_sawtooth_law(const SawtoothLawOptions& options) {
  if (!fracture_) throw hm::InputError("law = sawtooth: allowed only with fracture enabled");
  if (at_rest_ || cursor_.started) throw hm::InputError("law = sawtooth: allowed only before the first step");
  fracture_->sawtooth = std::make_unique<SawtoothLaw>(lattice(), reference_dual_, mechanics_->parameters(),
                                                      fracture_->strengths, options);
}

void CoupledModel::cut_beams(const std::vector<int>& beams, double slot_width) {
  if (!fracture_) throw hm::InputError("notch: allowed only with fracture enabled");
  if (at_rest_ || cursor_.started) throw hm::InputError("notch: allowed only before the first step");
  if (!(std::isfinite(slot_width) && slot_width >= 0.0))
    throw hm::InputError("notch slot width = " + hm::core::format_value(slot_width) + ", allowed: >= 0, finite");
  if (slot_width != 0.0 && flow_->parameters().fracture_flow.law != FractureFlow::cubic)
    throw hm::InputError("notch slot width = " + hm::core::format_value(slot_width) +
                         ", allowed: 0 unless the fracture flow is the cubic law");
  const Lattice& l = lattice();
  for (int e : beams) {
    if (e < 0 || e >= l.n_beams())
      throw hm::InputError("notch beam = " + std::to_string(e) + ", allowed: 0 <= beam < " +
                           std::to_string(l.n_beams()));
    if (mechanics_->states()[static_cast<std::size_t>(e)] != BeamState::intact)
      throw hm::InputError("notch beam = " + std::to_string(e) + ", allowed: an intact beam (each beam once)");
    const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
    BreakEvent cut;
    cut.sequence = static_cast<int>(break_log_.size());
    cut.beam = e;
    cut.particle_i = i;
    cut.particle_j = j;
    cut.position = 0.5 * (l.points.col(i) + l.points.col(j));
    cut.load = 0.0;  // before the first step; mode none, ratio 0: cut, not failed
    mechanics_->break_beam(e);
    break_log_.push_back(cut);
    ++n_cut_;
  }
  if (!beams.empty()) flow_->set_crack_weights(crack_weights());
  if (slot_width != 0.0) flow_->set_slot_width(beams, slot_width);
}

int CoupledModel::n_broken() const {
  return static_cast<int>(std::count_if(mechanics_->states().begin(), mechanics_->states().end(),
                                        [](BeamState s) { return s != BeamState::intact; }));
}

ParticleStress CoupledModel::particle_stress() const { return current_particle_stress(*mechanics_, reference_dual_); }

Eigen::VectorXd CoupledModel::failure_ratio() const {
  if (!fracture_) return {};
  return failure_ratios(*mechanics_, reference_dual_, fracture_->strengths, fracture_->options.crack_tip,
                        fracture_->sawtooth.get());
}

Eigen::Matrix2Xd CoupledModel::positions(const Eigen::VectorXd& u) const {
  Eigen::Matrix2Xd x = lattice().points;
  for (Eigen::Index i = 0; i < x.cols(); ++i) {
    x(0, i) += u[3 * i];
    x(1, i) += u[3 * i + 1];
  }
  return x;
}

Eigen::VectorXd CoupledModel::unknown_volumes(const Eigen::VectorXd& triangle_area) const {
  Eigen::VectorXd v(flow_->n_unknowns());
  v.head(triangle_area.size()) = triangle_area;
  if (flow_->has_borehole()) v[flow_->borehole_index()] = flow_->borehole_volume();
  return v;
}

Eigen::VectorXd CoupledModel::charged_volumes(Eigen::VectorXd volumes, const Eigen::VectorXd& triangle_area,
                                              const Eigen::VectorXd& u) const {
  if (flow_->parameters().crack_coupling != CrackCoupling::full) return volumes;
  // A crack triangle holds b of its area (the rock's pores) and 1 - b of its beams' openings, each
  // weighted by its crack weight: the volume whose change is conjugate to the crack's share of the
  // pressure on those faces (pressure_load).
  // The flow charges a crack triangle's change at weight 1 (FlowNetwork::deformation).
  const Eigen::VectorXd& crack = flow_->crack_weights();
  const double b = flow_->parameters().b;
  const Eigen::VectorXd opening = crack_opening_volumes(lattice(), reference_dual_, crack, u);
  for (int e = 0; e < lattice().n_beams(); ++e)
    if (crack[e] > 0.0)
      for (const int t : lattice().beam_triangles[static_cast<std::size_t>(e)])
        if (t >= 0) volumes[t] = b * triangle_area[t] + (1.0 - b) * opening[t];
  return volumes;
}

CoupledStepSummary CoupledModel::settle() {
  CoupledStepSummary summary;
  summary.time = time();
  if (at_rest_) return summary;
  at_rest_ = true;
  if (unloaded_) return summary;
  const auto start = std::chrono::steady_clock::now();
  // Drained: before injection the pore pressure has long equalised at p0 (p = 0 here). The Eq. 20
  // springs belong to the split, not to the rock: they are out of the matrix for this solve.
  const bool sprung = options_.terms.psi > 0.0;
  if (sprung) mechanics_->set_normal_springs(Eigen::VectorXd());
  RankOneStiffness borehole = mechanics_->rank_one_stiffness();  // the split's too: out at rest
  mechanics_->set_rank_one_stiffness({});
  mechanics_->set_external_forces(Eigen::VectorXd::Zero(3 * lattice().n_particles()));
  bool ok = true;
  if (fracture_) {
    int n_breaks = 0;
    ok = break_beams(0, n_breaks, summary);
  } else {
    const MechanicsSummary ms = mechanics_->solve();
    summary.mechanics_seconds += ms.solve_seconds;
    ++summary.n_mechanics_solves;
    summary.n_contact_changes += ms.n_contact_changes;
    if (!ms.is_converged()) {
      ok = false;
      summary.status = CoupledStatus::solver_failure;
      summary.message = "mechanics at rest (t = 0): " + ms.message;
    }
  }
  if (sprung) mechanics_->set_normal_springs(springs_, options_.terms.broken_beam_spring);
  mechanics_->set_rank_one_stiffness(std::move(borehole));
  if (ok) {
    displacement_ = mechanics_->displacement();
    const Eigen::Matrix2Xd x = positions(displacement_);
    current_dual_ = build_dual_graph(lattice(), x, reference_dual_.options);
    flow_->update_geometry(current_dual_, x);
    update_crack_openings(displacement_);
    volume_ = unknown_volumes(current_dual_.triangle_area);
  }
  summary.n_broken = n_broken();
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

// One time step (Fig. 5): predict the guess, then passes of mechanics (with the break loop) and flow
// until the guess stops changing, then accept the step or restore t^n.
CoupledStepSummary CoupledModel::step(double dt, double overshoot_tolerance) {
  if (!(dt > 0.0 && std::isfinite(dt)))
    throw hm::InputError("dt = " + hm::core::format_value(dt) + ", allowed: > 0, finite");
  if (!at_rest_) {
    CoupledStepSummary rest = settle();
    if (!rest.is_ok()) return rest;
  }
  const auto start = std::chrono::steady_clock::now();
  CoupledStepSummary summary;
  summary.dt = dt;
  summary.time = time() + dt;
  const int factorizations_before = mechanics_->solver().report().n_factorizations;
  const int update_failures_before = mechanics_->solver().report().n_update_failures;
  // A failed attempt must leave no trace: the beams it broke, the contacts it changed, the factor's
  // updates and the strengths it used are undone from this snapshot, so that a retry with a shorter
  // step starts from t^n exactly as a run that took the shorter step in the first place.
  // The first snapshot is measured first, so that its buffer is made once at its size (growing it would
  // hold two copies of the state at once); later ones reuse it.
  // The mechanics' factor is not copied: its changes from here are logged and undone (FactorUndoLog).
  mechanics_->begin_step();
  if (first_snapshot_) {
    step_start_.reserve(
        core::StateWriter::measure([this](core::StateWriter& w) { save_model_state(w, StateScope::step_start); }));
    first_snapshot_ = false;
  }
  step_start_.clear();
  save_model_state(step_start_, StateScope::step_start);
  PassGuess guess = predict(dt);
  DualGraph dual;
  const bool converged = iterate(dt, overshoot_tolerance, guess, dual, summary);
  finish_step(dt, converged, std::move(dual), summary);
  if (!summary.is_ok()) {
    core::StateReader snapshot =
        core::StateReader::of_snapshot(step_start_, "the state at t = " + hm::core::format_value(time()));
    restore_model_state(snapshot);
  }
  summary.n_broken = n_broken();
  summary.n_mechanics_factorizations = mechanics_->solver().report().n_factorizations - factorizations_before;
  summary.n_mechanics_update_failures = mechanics_->solver().report().n_update_failures - update_failures_before;
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

CoupledModel::PassGuess CoupledModel::predict(double dt) const {
  // p^n: the drained split's frozen pressure; u^n: where the springs are relaxed at the first pass.
  PassGuess guess{flow_->pressure(), displacement_};
  if (options_.predictor == CouplingPredictor::linear && previous_dt_ > 0.0) {
    const double ratio = dt / previous_dt_;
    guess.pressure += ratio * (flow_->pressure() - previous_pressure_);
    guess.displacement += ratio * (displacement_ - previous_displacement_);
  }
  return guess;
}

bool CoupledModel::iterate(double dt, double overshoot_tolerance, PassGuess& guess, DualGraph& dual,
                           CoupledStepSummary& summary) {
  // The step is retried whatever its later passes do once its first event overshoots: stop there.
  const auto overshot = [&] {
    if (!(overshoot_tolerance > 0.0 && summary.first_event_ratio > 1.0 + overshoot_tolerance)) return false;
    summary.status = CoupledStatus::overshoot;
    summary.message = std::string("first ") + (summary.n_teeth > 0 ? "event" : "break") +
                      " at t = " + hm::core::format_value(summary.time) + " at failure ratio " +
                      hm::core::format_value(summary.first_event_ratio) + ", above 1 + overshoot_tolerance (" +
                      hm::core::format_value(overshoot_tolerance) + ")";
    return true;
  };
  const bool check_every_pass = fracture_ && options_.fracture_check == FractureCheck::every_pass;
  relaxation_->start_step();
  // The crack stabiliser is linearised at the step's first state (every crack: so that a resumed or
  // retried step starts as the uninterrupted one) and after breaks (the cracks they changed).
  bool stabiliser_stale = true;
  bool first_update = true;
  int last_break_pass = 0;  // at_convergence: max_iterations counts from here
  for (int k = 1; k - last_break_pass <= options_.max_iterations; ++k) {
    if (interrupt_ && interrupt_()) {
      summary.status = CoupledStatus::interrupted;
      summary.message = "interrupted in the step to t = " + hm::core::format_value(summary.time) + " at pass " +
                        std::to_string(k) + " (the step is undone)";
      return false;
    }
    summary.iterations = k;
    int breaks_this_pass = 0;
    if (!solve_mechanics(k, guess, check_every_pass, breaks_this_pass, summary) || overshot()) return false;
    if (stabiliser_stale || breaks_this_pass > 0) update_crack_stabiliser(!first_update);
    stabiliser_stale = first_update = false;
    const Eigen::VectorXd& u = mechanics_->displacement();
    if (!solve_flow(dt, k, u, guess.pressure, dual, summary)) return false;
    const Eigen::VectorXd& p = flow_->trial_pressure();
    summary.pressure_residual = relative_change(p, guess.pressure, false);
    summary.displacement_residual = relative_change(u, guess.displacement, true);
    summary.pressure_history.push_back(summary.pressure_residual);
    if (pass_observer_) pass_observer_(k, p, u);
    relaxation_->next_guess(guess.pressure, guess.displacement, p, u, breaks_this_pass > 0);
    const bool unchanged = summary.pressure_residual <= options_.pressure_tolerance &&
                           summary.displacement_residual <= options_.displacement_tolerance &&
                           summary.flow.balance_error <= options_.balance_tolerance;
    if (breaks_this_pass > 0 || !unchanged) continue;
    if (fracture_ && !check_every_pass) {
      // A coupled equilibrium: break what fails under its forces, then converge again from the
      // broken state (springs relaxed there, a fresh relaxation history: the map changed).
      int n_breaks = 0;
      if (!break_beams(k, n_breaks, summary) || overshot()) return false;
      if (n_breaks > 0) {
        guess.displacement = mechanics_->displacement();
        stabiliser_stale = true;
        relaxation_->restart();
        last_break_pass = k;
        continue;
      }
    }
    return true;
  }
  return false;
}

bool CoupledModel::solve_mechanics(int pass, const PassGuess& guess, bool check_every_pass, int& n_breaks,
                                   CoupledStepSummary& summary) {
  // The pressure force of the guess (Eq. 17) and the undrained predictor's springs (Eq. 20).
  Eigen::VectorXd f = pressure_load(guess.pressure);
  if (options_.terms.psi > 0.0) f += spring_preload(lattice(), mechanics_->normal_springs(), guess.displacement);
  // The borehole's undrained spring, relaxed at the same iterate.
  if (mechanics_->rank_one_stiffness().is_active()) mechanics_->set_rank_one_reference(guess.displacement);
  mechanics_->set_external_forces(f);
  // Solve, then break one beam at a time until none fails (the stresses of the effective, i.e. beam,
  // forces; V_i of the undeformed dual like the rest of the linear mechanics).
  if (check_every_pass) return break_beams(pass, n_breaks, summary);
  // No equilibrium residual: nothing here reads it, and it costs a pass over every beam.
  const MechanicsSummary ms = mechanics_->solve(false);
  summary.mechanics_seconds += ms.solve_seconds;
  ++summary.n_mechanics_solves;
  summary.n_contact_changes += ms.n_contact_changes;
  if (ms.is_converged()) return true;
  summary.status = CoupledStatus::solver_failure;
  summary.message =
      "mechanics at t = " + hm::core::format_value(summary.time) + ", pass " + std::to_string(pass) + ": " + ms.message;
  return false;
}

bool CoupledModel::break_beams(int pass, int& n_breaks, CoupledStepSummary& summary) {
  BreakLoopOptions loop = fracture_->options;
  if (pass > 0) loop.interrupted = interrupt_;  // a step can be undone; the settling at t = 0 (pass 0) is not
  // The settling at t = 0 takes all: no fluid moves before the first step.
  const bool capped = options_.events_per_check > 0 && pass > 0;
  if (capped) loop.max_breaks = options_.events_per_check;
  const BreakLoopSummary bs =
      fracture_->sawtooth
          ? break_until_stable(*mechanics_, reference_dual_, fracture_->strengths, *fracture_->sawtooth, loop,
                               summary.time, break_log_, tooth_log_)
          : break_until_stable(*mechanics_, reference_dual_, fracture_->strengths, loop, summary.time, break_log_);
  summary.mechanics_seconds += bs.solve_seconds;
  summary.stress_seconds += bs.stress_seconds;
  summary.break_seconds += bs.break_seconds;
  summary.n_mechanics_solves += bs.n_solves;
  summary.n_contact_changes += bs.n_contact_changes;
  // A tooth changes the system as a break does: the coupling must pass again.
  n_breaks = bs.n_breaks + bs.n_teeth;
  if (summary.first_event_ratio == 0.0) summary.first_event_ratio = bs.first_ratio;
  summary.n_breaks += bs.n_breaks;
  summary.n_teeth += bs.n_teeth;
  if (bs.status == BreakLoopStatus::interrupted) {
    summary.status = CoupledStatus::interrupted;
    summary.message = "interrupted in the step to t = " + hm::core::format_value(summary.time) + " at pass " +
                      std::to_string(pass) + ", " + bs.message + " (the step is undone)";
    return false;
  }
  if (!bs.is_stable() && !(capped && bs.status == BreakLoopStatus::break_cap)) {
    summary.status = CoupledStatus::solver_failure;
    // The breaks of one check all see the pass's pressures: a crack fed by a fluid volume is then loaded
    // as if its pressure could not drop as it grows, and runs through a free body. (With pressures
    // outside the small-strain range the pass itself went astray, and the breaks followed.)
    const Eigen::VectorXd& p = flow_->trial_pressure();
    summary.near_mechanism =
        bs.near_mechanism && bs.n_breaks > 1 && (p.size() == 0 || p.cwiseAbs().maxCoeff() <= kMaxSmallStrainPressure);
    const std::string cause = summary.near_mechanism ? std::string("breaks judged at the pass's pressures, ")
                                                     : core::name_of(bs.status) + " ";
    summary.message = "break loop at t = " + hm::core::format_value(summary.time) + ", pass " + std::to_string(pass) +
                      ": " + cause + bs.message;
    return false;
  }
  if (bs.n_breaks + bs.n_teeth > 0) flow_->set_crack_weights(crack_weights());
  return true;
}

Eigen::VectorXd CoupledModel::crack_weights() const {
  const std::vector<BeamState>& states = mechanics_->states();
  // With fluid-filled cracks the saw-tooth law's process zone is crack in proportion to its damage
  // 1 - s: it takes fluid and is pushed by it continuously from the first tooth to the break, as the
  // cohesive zone of a crack without fluid lag (no dry zone ahead of the fluid).
  const bool wet_process_zone =
      fracture_ && fracture_->sawtooth && flow_->parameters().crack_coupling == CrackCoupling::full;
  Eigen::VectorXd w(lattice().n_beams());
  for (int e = 0; e < lattice().n_beams(); ++e)
    w[e] = states[static_cast<std::size_t>(e)] != BeamState::intact ? 1.0
           : wet_process_zone                                       ? 1.0 - mechanics_->stiffness_factor(e)
                                                                    : 0.0;
  if (!wet_process_zone) return w;
  // The fluid reaches a softened facet only along a crack: softened beams not joined to a broken one
  // through cracked facets stay dry (a closed pocket would hold no fluid, only suction).
  std::vector<char> fed(static_cast<std::size_t>(flow_->n_unknowns()), 0);
  for (const std::vector<int>& mode : flow_->crack_modes(w)) {
    bool has_crack = false;
    for (int u : mode)
      if (u < lattice().n_triangles())
        for (int e : lattice().triangle_beams[static_cast<std::size_t>(u)])
          if (states[static_cast<std::size_t>(e)] != BeamState::intact) has_crack = true;
    if (has_crack)
      for (int u : mode) fed[static_cast<std::size_t>(u)] = 1;
  }
  for (int e = 0; e < lattice().n_beams(); ++e) {
    if (!(w[e] > 0.0 && w[e] < 1.0)) continue;
    const int s = lattice().beam_triangles[static_cast<std::size_t>(e)][0];
    if (s < 0 || !fed[static_cast<std::size_t>(s)]) w[e] = 0.0;
  }
  return w;
}

Eigen::VectorXd CoupledModel::pressure_load(const Eigen::VectorXd& pressure) const {
  const bool full_crack_pressure = flow_->parameters().crack_coupling == CrackCoupling::full;
  return pressure_forces(lattice(), reference_dual_, pressure, flow_->parameters().b, options_.terms,
                         full_crack_pressure ? flow_->crack_weights() : Eigen::VectorXd{});
}

void CoupledModel::update_crack_stabiliser(bool keep_unchanged_modes) {
  FlowStabiliser previous = std::move(crack_stabiliser_);
  crack_stabiliser_ = FlowStabiliser{};
  if (flow_->parameters().crack_coupling != CrackCoupling::full || options_.crack_stabiliser == CrackStabiliser::none)
    return;
  const std::vector<std::vector<int>> cracks = flow_->crack_modes();
  const bool per_unknown = options_.crack_stabiliser == CrackStabiliser::crack_unknowns;
  crack_stabiliser_.modes = cracks;
  if (per_unknown) {
    std::vector<std::vector<int>> unknowns;
    for (const std::vector<int>& crack : cracks)
      for (const int v : crack) unknowns.push_back({v});
    crack_stabiliser_.modes = std::move(unknowns);
  }
  const auto k = static_cast<Eigen::Index>(crack_stabiliser_.modes.size());
  const Eigen::VectorXd& weights = flow_->crack_weights();
  // The stabiliser only sets the passes' path, not their fixed point: a crack whose unknowns and
  // weights are those of the last update keeps its response (the lattice around it changed by a
  // tooth elsewhere at most), so an event costs solves for the crack it changed, not for every crack.
  std::map<std::vector<int>, Eigen::Index> kept;
  if (keep_unchanged_modes && stabiliser_weights_.size() == weights.size()) {
    std::vector<char> changed(static_cast<std::size_t>(flow_->n_unknowns()), 0);
    for (int e = 0; e < lattice().n_beams(); ++e)
      if (weights[e] != stabiliser_weights_[e])
        for (const int t : lattice().beam_triangles[static_cast<std::size_t>(e)])
          if (t >= 0) changed[static_cast<std::size_t>(t)] = 1;
    // An event changes the response of every unknown of its crack, not only of those beside it.
    if (per_unknown)
      for (const std::vector<int>& crack : cracks)
        if (std::any_of(crack.begin(), crack.end(), [&](int v) { return changed[static_cast<std::size_t>(v)]; }))
          for (const int v : crack) changed[static_cast<std::size_t>(v)] = 1;
    for (std::size_t c = 0; c < previous.modes.size(); ++c)
      if (std::none_of(previous.modes[c].begin(), previous.modes[c].end(),
                       [&](int v) { return changed[static_cast<std::size_t>(v)]; }))
        kept.emplace(previous.modes[c], static_cast<Eigen::Index>(c));
  }
  stabiliser_weights_ = weights;
  const Eigen::VectorXd& u = mechanics_->displacement();
  // A kept crack keeps its flow solve A^-1 V too, which the flow solves again if the event changed
  // the cracks' conductances (FlowStabiliser).
  FlowStabiliser& next = crack_stabiliser_;
  next.volume_response = Eigen::MatrixXd::Zero(flow_->n_unknowns(), k);
  next.solved_response = Eigen::MatrixXd::Zero(flow_->n_unknowns(), k);
  next.solved.assign(static_cast<std::size_t>(k), 0);
  next.solved_dt = previous.solved_dt;
  next.solved_conductances = previous.solved_conductances;
  for (Eigen::Index c = 0; c < k; ++c) {
    const std::vector<int>& mode = next.modes[static_cast<std::size_t>(c)];
    if (const auto old = kept.find(mode); old != kept.end()) {
      next.volume_response.col(c) = previous.volume_response.col(old->second);
      const auto o = static_cast<std::size_t>(old->second);
      if (o < previous.solved.size() && previous.solved[o]) {
        next.solved_response.col(c) = previous.solved_response.col(old->second);
        next.solved[static_cast<std::size_t>(c)] = 1;
      }
      continue;
    }
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(flow_->n_unknowns());
    for (int v : mode) unit[v] = 1.0;
    const Eigen::VectorXd du = mechanics_->linear_response(pressure_load(unit));
    const double largest = du.cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) continue;
    // Areas are quadratic in the displacements: the central difference is their exact derivative
    // (a step of 1e-6 R keeps the round-off of the areas far below the difference).
    const double h = 1e-6 / largest;
    const auto volumes = [&](double step) {
      const Eigen::VectorXd moved = u + step * du;
      const Eigen::VectorXd areas = triangle_areas(lattice(), positions(moved));
      return charged_volumes(unknown_volumes(areas), areas, moved);
    };
    next.volume_response.col(c) = flow_->deformation((volumes(h) - volumes(-h)) / (2 * h));
  }
}

void CoupledModel::update_crack_openings(const Eigen::VectorXd& u) {
  const FractureFlowSpec& law = flow_->parameters().fracture_flow;
  if (law.law != FractureFlow::cubic) return;
  flow_->set_crack_openings(crack_facet_openings(lattice(), reference_dual_, flow_->crack_weights(), u, law.aperture));
}

bool CoupledModel::solve_flow(double dt, int pass, const Eigen::VectorXd& u, const Eigen::VectorXd& pressure_guess,
                              DualGraph& dual, CoupledStepSummary& summary) {
  // The deformed flow geometry, then the flow step with b (V^{n+1} - V^n).
  const auto tick = std::chrono::steady_clock::now();
  const Eigen::Matrix2Xd x = positions(u);
  dual = build_dual_graph(lattice(), x, reference_dual_.options);
  flow_->update_geometry(dual, x);
  update_crack_openings(u);
  const auto tock = std::chrono::steady_clock::now();
  summary.geometry_seconds += std::chrono::duration<double>(tock - tick).count();
  const bool stabilised = !crack_stabiliser_.modes.empty();
  if (stabilised) crack_stabiliser_.reference_pressure = pressure_guess;
  // V^n with the cracks of now: a beam broken in this step is charged its opening since t^n.
  const Eigen::VectorXd volume_change = charged_volumes(unknown_volumes(dual.triangle_area), dual.triangle_area, u) -
                                        charged_volumes(volume_, current_dual_.triangle_area, displacement_);
  summary.flow = flow_->solve(dt, volume_change, stabilised ? &crack_stabiliser_ : nullptr);
  summary.flow_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - tock).count();
  if (summary.flow.is_ok()) return true;
  summary.status = CoupledStatus::solver_failure;
  summary.message = "flow at t = " + hm::core::format_value(summary.time) + ", pass " + std::to_string(pass) + ": " +
                    summary.flow.message;
  return false;
}

bool CoupledModel::within_small_strain(CoupledStepSummary& summary) const {
  // The model is linear elasticity on the undeformed lattice with pressures over E: a pass map can
  // have fixed points far outside that range (a fluid-filled crack whose stabiliser misses most of its
  // compliance: pressures ~100 E, displacements ~1e3 R, the deformed areas' storage balancing the
  // books). No rock reaches them: such a step is refused like one that did not converge, and retried.
  const double u_max = mechanics_->displacement().cwiseAbs().maxCoeff();
  const double p_max = flow_->trial_pressure().cwiseAbs().maxCoeff();
  if (u_max <= kMaxSmallStrainDisplacement && p_max <= kMaxSmallStrainPressure) return true;
  summary.message = "coupling at t = " + hm::core::format_value(summary.time) +
                    ": converged to a state outside the small-strain model (largest displacement " +
                    hm::core::format_value(u_max) + " R or rad, largest |p| = " + hm::core::format_value(p_max) +
                    " E; limits " + hm::core::format_value(kMaxSmallStrainDisplacement) + " and " +
                    hm::core::format_value(kMaxSmallStrainPressure) + " E)";
  return false;
}

void CoupledModel::finish_step(double dt, bool converged, DualGraph dual, CoupledStepSummary& summary) {
  if (summary.status != CoupledStatus::solver_failure && summary.status != CoupledStatus::overshoot &&
      summary.status != CoupledStatus::interrupted) {
    if (converged && !within_small_strain(summary)) {
      summary.status = CoupledStatus::not_converged;
    } else if (converged) {
      summary.status = CoupledStatus::converged;
    } else if (options_.accept_unconverged) {
      summary.status = CoupledStatus::accepted_unconverged;
    } else {
      summary.status = CoupledStatus::not_converged;
      summary.message = "coupling at t = " + hm::core::format_value(summary.time) + ": not converged after " +
                        std::to_string(options_.max_iterations) + " passes (max_iterations); pressure residual " +
                        hm::core::format_value(summary.pressure_residual) + ", displacement residual " +
                        hm::core::format_value(summary.displacement_residual) + ", volume balance error " +
                        hm::core::format_value(summary.flow.balance_error);
    }
  }
  if (summary.is_ok()) {
    if (options_.predictor == CouplingPredictor::linear) {
      previous_pressure_ = flow_->pressure();
      previous_displacement_ = displacement_;
      previous_dt_ = summary.n_breaks + summary.n_teeth == 0 ? dt : 0.0;
    }
    flow_->accept();
    displacement_ = mechanics_->displacement();  // the last pass's u, which the accepted flow saw
    current_dual_ = std::move(dual);
    volume_ = unknown_volumes(current_dual_.triangle_area);
  }
}

void CoupledRunSummary::add_accepted_step(const CoupledStepSummary& s) {
  step_seconds += s.seconds;
  mechanics_seconds += s.mechanics_seconds;
  stress_seconds += s.stress_seconds;
  break_seconds += s.break_seconds;
  geometry_seconds += s.geometry_seconds;
  flow_seconds += s.flow_seconds;
  n_mechanics_solves += s.n_mechanics_solves;
  n_contact_changes += s.n_contact_changes;
  n_mechanics_factorizations += s.n_mechanics_factorizations;
  n_mechanics_update_failures += s.n_mechanics_update_failures;
}

bool CoupledModel::begin_run(const TimeStepping& stepping, std::size_t n_outputs, const Observer& observer) {
  RunCursor& c = cursor_;
  if (!c.started) {  // initial step: the lattice at rest at t = 0
    const CoupledStepSummary rest = settle();
    if (!rest.is_ok()) {
      c.totals.status = rest.status;
      c.totals.message = rest.message;
      return false;
    }
    c.started = true;
    c.next_output = 0;
    c.dt_nominal = stepping.dt_initial;
    if (observer) observer(*this, CoupledStepSummary{}, true);
  }
  // A restored cursor must fit this case's stepping (a damaged checkpoint would step backwards or
  // read past the output times).
  if (c.next_output >= n_outputs || !(c.dt_nominal > 0.0) || !(time() >= 0.0) || time() > stepping.t_end)
    throw InputError("run: the restored state (t = " + hm::core::format_value(time()) +
                     ", dt = " + hm::core::format_value(c.dt_nominal) + ", output " + std::to_string(c.next_output) +
                     " of " + std::to_string(n_outputs) + ") does not fit the case's stepping: a damaged checkpoint");
  return true;
}

CoupledStepSummary CoupledModel::step_with_retries(double& dt, const TimeStepping& stepping) {
  // A coupling loop that did not converge is retried with half the step (fewer breaks per step,
  // a milder change of the contact set), up to max_step_halvings times; so is a step whose first
  // break went past its threshold by more than overshoot_tolerance, whose last try is accepted.
  const auto tolerance = [&](int halvings) {
    return halvings < stepping.max_step_halvings ? stepping.overshoot_tolerance : 0.0;
  };
  CoupledRunSummary& run = cursor_.totals;
  CoupledStepSummary s = step(dt, tolerance(0));
  run.total_iterations += s.iterations;
  for (int h = 0; (s.status == CoupledStatus::not_converged || s.status == CoupledStatus::overshoot) &&
                  h < stepping.max_step_halvings;
       ++h) {
    dt *= 0.5;
    cursor_.dt_nominal = dt;
    ++run.n_step_halvings;
    s = step(dt, tolerance(h + 1));
    run.total_iterations += s.iterations;
  }
  return s;
}

CoupledRunSummary CoupledModel::run(const TimeStepping& stepping, const Observer& observer,
                                    const std::function<bool()>& stop) {
  stepping.validate();
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> outputs = stepping.output_times;
  if (outputs.empty() || outputs.back() < stepping.t_end) outputs.push_back(stepping.t_end);
  // Times closer than this to an output are snapped onto it (no sliver steps).
  const double snap = 1e-9 * stepping.t_end;

  RunCursor& c = cursor_;
  CoupledRunSummary& run = c.totals;
  const double seconds_before = run.seconds;
  if (!begin_run(stepping, outputs.size(), observer)) return run;
  run.status = CoupledStatus::converged;
  run.message.clear();
  while (time() < stepping.t_end - snap) {
    const double t_out = outputs[c.next_output];
    double dt = std::min(c.dt_nominal, t_out - time());
    if (t_out - (time() + dt) < snap) dt = t_out - time();
    // An interrupted step leaves no trace, not even in the counters: a resumed run redoes it whole.
    const RunCursor before = c;
    const CoupledStepSummary s = step_with_retries(dt, stepping);
    if (s.status == CoupledStatus::interrupted) {
      c = before;
      run.status = s.status;
      run.message = s.message;
      break;
    }
    run.status = s.status;
    if (!s.is_ok()) {
      run.message = s.message;
      run.near_mechanism = s.near_mechanism;
      break;
    }
    ++run.n_steps;
    run.max_balance_error = std::max(run.max_balance_error, s.flow.balance_error);
    run.add_accepted_step(s);
    const bool is_output = std::abs(time() - t_out) <= snap;
    if (is_output) ++c.next_output;
    // Geometric growth of the nominal step; a step shortened to hit an output does not reset it.
    if (dt >= c.dt_nominal * (1.0 - 1e-12)) c.dt_nominal = std::min(c.dt_nominal * stepping.dt_growth, stepping.dt_max);
    if (observer) observer(*this, s, is_output);
    if (stop && stop() && time() < stepping.t_end - snap) {
      run.status = CoupledStatus::interrupted;
      run.message = "stopped on request at t = " + hm::core::format_value(time());
      break;
    }
  }
  run.time = time();
  run.seconds = seconds_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

namespace {

void save_break_log(core::StateWriter& w, const std::vector<BreakEvent>& log) {
  std::vector<int> ints;
  std::vector<double> reals;
  for (const BreakEvent& e : log) {
    ints.insert(ints.end(), {e.sequence, e.beam, e.particle_i, e.particle_j, static_cast<int>(e.mode)});
    reals.insert(reals.end(),
                 {e.position.x(), e.position.y(), e.load, e.sigma_1, e.sigma_3, e.ratio, e.crack_tip_factor});
  }
  w.put("breaks.ints", ints);
  w.put("breaks.reals", reals);
}

std::vector<BreakEvent> restore_break_log(core::StateReader& r) {
  std::vector<int> ints;
  std::vector<double> reals;
  r.get("breaks.ints", ints);
  r.get("breaks.reals", reals);
  if (ints.size() % 5 != 0 || reals.size() / 7 != ints.size() / 5 || reals.size() % 7 != 0)
    throw InputError(r.source() + ": at 'breaks': inconsistent sizes");
  std::vector<BreakEvent> log(ints.size() / 5);
  for (std::size_t k = 0; k < log.size(); ++k) {
    const int* i = &ints[5 * k];
    const double* x = &reals[7 * k];
    log[k] = {i[0], i[1], i[2], i[3], Eigen::Vector2d(x[0], x[1]),   x[2],
              x[3], x[4], x[5], x[6], static_cast<FailureMode>(i[4])};
  }
  return log;
}

void save_tooth_log(core::StateWriter& w, const std::vector<ToothEvent>& log) {
  std::vector<int> ints;
  std::vector<double> reals;
  for (const ToothEvent& e : log) {
    ints.insert(ints.end(), {e.sequence, e.beam, e.tooth});
    reals.insert(reals.end(), {e.load, e.stiffness_factor, e.axial_stress, e.ratio, e.energy});
  }
  w.put("teeth.ints", ints);
  w.put("teeth.reals", reals);
}

std::vector<ToothEvent> restore_tooth_log(core::StateReader& r) {
  std::vector<int> ints;
  std::vector<double> reals;
  r.get("teeth.ints", ints);
  r.get("teeth.reals", reals);
  if (ints.size() % 3 != 0 || reals.size() % 5 != 0 || reals.size() / 5 != ints.size() / 3)
    throw InputError(r.source() + ": at 'teeth': inconsistent sizes");
  std::vector<ToothEvent> log(ints.size() / 3);
  for (std::size_t k = 0; k < log.size(); ++k) {
    const int* i = &ints[3 * k];
    const double* x = &reals[5 * k];
    log[k] = {i[0], i[1], x[0], i[2], x[1], x[2], x[3], x[4]};
  }
  return log;
}

// The run's counters, saved or restored (Archive: core::StateWriter with const totals, or StateReader).
template <class Archive, class Totals>
void transfer_totals(Archive& a, Totals& t) {
  a.io("run.n_steps", t.n_steps);
  a.io("run.total_iterations", t.total_iterations);
  a.io("run.n_step_halvings", t.n_step_halvings);
  a.io("run.time", t.time);
  a.io("run.seconds", t.seconds);
  a.io("run.max_balance_error", t.max_balance_error);
  a.io("run.step_seconds", t.step_seconds);
  a.io("run.mechanics_seconds", t.mechanics_seconds);
  a.io("run.stress_seconds", t.stress_seconds);
  a.io("run.break_seconds", t.break_seconds);
  a.io("run.geometry_seconds", t.geometry_seconds);
  a.io("run.flow_seconds", t.flow_seconds);
  a.io("run.n_mechanics_solves", t.n_mechanics_solves);
  a.io("run.n_contact_changes", t.n_contact_changes);
  a.io("run.n_mechanics_factorizations", t.n_mechanics_factorizations);
  a.io("run.n_mechanics_update_failures", t.n_mechanics_update_failures);
}

// Where run() is (Archive and Cursor as above).
template <class Archive, class Cursor>
void transfer_cursor(Archive& a, Cursor& c) {
  a.io("cursor.started", c.started);
  a.io("cursor.next_output", c.next_output);
  a.io("cursor.dt_nominal", c.dt_nominal);
  transfer_totals(a, c.totals);
}

}  // namespace

template <class Archive, class Self>
void CoupledModel::transfer_history(Archive& a, Self& m) {
  a.io("model.displacement", m.displacement_);
  a.io("model.previous_pressure", m.previous_pressure_);
  a.io("model.previous_displacement", m.previous_displacement_);
  a.io("model.previous_dt", m.previous_dt_);
}

void CoupledModel::save_state(core::StateWriter& w) const {
  save_model_state(w, StateScope::whole);
  transfer_cursor(w, cursor_);
}

void CoupledModel::restore_state(core::StateReader& r) {
  restore_model_state(r);
  transfer_cursor(r, cursor_);
  // The accepted geometry is a function of the accepted displacement (finish_step's dual graph).
  current_dual_ = cursor_.totals.n_steps == 0 && (unloaded_ || !at_rest_)
                      ? reference_dual_
                      : build_dual_graph(lattice(), positions(displacement_), reference_dual_.options);
  volume_ = unknown_volumes(current_dual_.triangle_area);
}

void CoupledModel::save_model_state(core::StateWriter& w, StateScope scope) const {
  w.put("model.particles", lattice().n_particles());
  w.put("model.beams", lattice().n_beams());
  mechanics_->save_state(w, scope);
  flow_->save_state(w);
  transfer_history(w, *this);
  w.put("model.at_rest", at_rest_);
  w.put("model.fracture", fracture_enabled());
  if (fracture_) {
    w.put("strengths.tensile", fracture_->strengths.tensile);
    w.put("strengths.compressive", fracture_->strengths.compressive);
  }
  save_break_log(w, break_log_);
  if (sawtooth_law()) {
    fracture_->sawtooth->save_state(w);
    save_tooth_log(w, tooth_log_);
  }
}

void CoupledModel::restore_model_state(core::StateReader& r) {
  int particles = 0, beams = 0;
  r.get("model.particles", particles);
  r.get("model.beams", beams);
  if (particles != lattice().n_particles() || beams != lattice().n_beams())
    throw InputError(r.source() + ": a state of another lattice (" + std::to_string(particles) + " particles, " +
                     std::to_string(beams) + " beams; this one has " + std::to_string(lattice().n_particles()) + ", " +
                     std::to_string(lattice().n_beams()) + ")");
  // Sizes and indices are checked against this lattice before anything indexes with them: a damaged
  // checkpoint whose checksum still matches is refused, not followed out of an array.
  const auto check = [&](bool ok, const char* tag) {
    if (!ok)
      throw InputError(r.source() + ": at '" + tag + "': not a state of this lattice (damaged or of another case)");
  };
  const Eigen::Index n_dofs = 3 * lattice().n_particles();
  mechanics_->restore_state(r);
  flow_->restore_state(r);
  transfer_history(r, *this);
  check(displacement_.size() == n_dofs, "model.displacement");
  check(previous_displacement_.size() == 0 || previous_displacement_.size() == n_dofs, "model.previous_displacement");
  check(previous_pressure_.size() == 0 || previous_pressure_.size() == flow_->pressure().size(),
        "model.previous_pressure");
  r.get("model.at_rest", at_rest_);
  bool fracture = false;
  r.get("model.fracture", fracture);
  if (fracture != fracture_enabled())
    throw InputError(r.source() + ": a state of a model with fracture " + (fracture ? "on" : "off"));
  if (fracture_) {
    r.get("strengths.tensile", fracture_->strengths.tensile);
    r.get("strengths.compressive", fracture_->strengths.compressive);
    check(fracture_->strengths.tensile.size() == beams, "strengths.tensile");
    check(fracture_->strengths.compressive.size() == beams, "strengths.compressive");
  }
  break_log_ = restore_break_log(r);
  // Each logged break names a broken beam of this lattice and its particles.
  for (const BreakEvent& e : break_log_)
    check(e.beam >= 0 && e.beam < beams &&
              mechanics_->states()[static_cast<std::size_t>(e.beam)] != BeamState::intact &&
              lattice().beams[static_cast<std::size_t>(e.beam)] == std::array<int, 2>{e.particle_i, e.particle_j},
          "breaks.ints");
  if (sawtooth_law()) {
    fracture_->sawtooth->restore_state(r);
    tooth_log_ = restore_tooth_log(r);
    for (const ToothEvent& e : tooth_log_) check(e.beam >= 0 && e.beam < beams, "teeth.ints");
  }
}

}  // namespace hm::lattice2d
