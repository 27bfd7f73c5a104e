#include "hm/lattice2d/fracture/fracture.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "hm/core/input_error.hpp"

#include "fracture/failure_scan.hpp"

namespace hm::lattice2d {

namespace {

std::string num(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

BeamStress scaled(BeamStress s, double scale) {
  s.stress *= scale;
  s.sigma_1 *= scale;
  s.sigma_3 *= scale;
  return s;
}

void check_beam_index(const Lattice& lattice, int beam, const std::string& field) {
  if (beam < 0 || beam >= lattice.n_beams())
    throw hm::InputError(field + " = " + std::to_string(beam) + ", allowed: 0 <= beam < " +
                         std::to_string(lattice.n_beams()));
}

// Sign of the cross product (b - a) x (c - a): which side of line a-b the point c lies on.
double side(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, v = c - a;
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace

// --- options -----------------------------------------------------------------------------------------

void BreakLoopOptions::validate() const {
  try {
    crack_tip.validate();
  } catch (const hm::InputError& e) {
    throw hm::InputError(std::string("break_loop.crack_tip.") + e.what());
  }
  if (max_breaks < 1) throw hm::InputError("break_loop.max_breaks = " + std::to_string(max_breaks) + ", allowed: >= 1");
}

void LoadSteppingOptions::validate() const {
  const std::string p = "load_stepping.";
  if (!(std::isfinite(initial_load) && initial_load >= 0.0))
    throw hm::InputError(p + "initial_load = " + num(initial_load) + ", allowed: >= 0, finite");
  if (!(std::isfinite(load_increment) && load_increment > 0.0))
    throw hm::InputError(p + "load_increment = " + num(load_increment) + ", allowed: > 0, finite");
  if (!(std::isfinite(max_load) && max_load >= initial_load))
    throw hm::InputError(p + "max_load = " + num(max_load) + ", allowed: >= initial_load (" + num(initial_load) +
                         "), finite");
  if (max_steps < 1) throw hm::InputError(p + "max_steps = " + std::to_string(max_steps) + ", allowed: >= 1");
  if (max_breaks < 1) throw hm::InputError(p + "max_breaks = " + std::to_string(max_breaks) + ", allowed: >= 1");
  try {
    break_loop.validate();
  } catch (const hm::InputError& e) {
    throw hm::InputError(p + e.what());
  }
}

// --- break loop --------------------------------------------------------------------------------------

ParticleStress current_particle_stress(const BeamMechanics& mechanics, const DualGraph& dual) {
  assert(dual.particle_area.size() == mechanics.lattice().n_particles() && "dual graph of another lattice");
  // The break loop's own path (FailureScan): connection forces, then the particle stresses of them.
  ParticleStress particle;
  compute_particle_stress(mechanics.lattice(), dual, mechanics.beam_forces(), particle);
  return particle;
}

BeamStress current_beam_stress(const BeamMechanics& mechanics, const DualGraph& dual, const CrackTipOptions& crack_tip,
                               double stress_scale) {
  BeamStress stress =
      compute_beam_stress(mechanics.lattice(), current_particle_stress(mechanics, dual), mechanics.states(), crack_tip);
  return stress_scale == 1.0 ? stress : scaled(std::move(stress), stress_scale);
}

Eigen::VectorXd failure_ratios(const BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                               const CrackTipOptions& crack_tip, const SawtoothLaw* law) {
  if (!law)
    return evaluate_failure(current_beam_stress(mechanics, dual, crack_tip), strengths, mechanics.states()).ratio;
  const BeamStress stress = current_beam_stress(mechanics, dual, CrackTipOptions{false});
  const std::vector<BeamForce> forces = mechanics.beam_forces();
  const FailureCriterion criterion(strengths.friction);
  Eigen::VectorXd ratio = Eigen::VectorXd::Zero(mechanics.lattice().n_beams());
  for (int e = 0; e < ratio.size(); ++e) {
    if (mechanics.states()[static_cast<std::size_t>(e)] != BeamState::intact) continue;
    const double tensile = law->axial_stress(e, forces[static_cast<std::size_t>(e)].normal) / law->strength(e);
    ratio[e] = FailureCriterion::combine(
                   tensile, criterion.shear_ratio(stress.sigma_1[e], stress.sigma_3[e], strengths.compressive[e]))
                   .ratio;
  }
  return ratio;
}

namespace {

// The saw-tooth law's tooth of the judged beam gives way, its energy booked: the beam softens to the
// next tooth's stiffness, or (last) is left for the caller to break.
void give_way(SawtoothLaw& law, BeamMechanics& mechanics, const FailureScan::Result& checked, double load, bool last,
              std::vector<ToothEvent>& teeth) {
  const int e = checked.judged.beam;
  ToothEvent tooth;
  tooth.sequence = static_cast<int>(teeth.size());
  tooth.beam = e;
  tooth.load = load;
  tooth.tooth = law.tooth(e);
  tooth.stiffness_factor = last ? 0.0 : law.next_stiffness_factor(e);
  tooth.axial_stress = checked.axial_stress;
  tooth.ratio = checked.judged.ratio;
  tooth.energy = law.give_way(e);
  if (!last) mechanics.soften_beam(e, tooth.stiffness_factor);
  teeth.push_back(tooth);
}

// The break loop of both laws (law null: brittle, teeth unused).
BreakLoopSummary run_break_loop(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                SawtoothLaw* law, const BreakLoopOptions& options, double load,
                                std::vector<BreakEvent>& log, std::vector<ToothEvent>* teeth, double stress_scale) {
  const auto start = std::chrono::steady_clock::now();
  options.validate();
  if (!(std::isfinite(stress_scale) && stress_scale >= 0.0))
    throw hm::InputError("stress_scale = " + num(stress_scale) + ", allowed: >= 0, finite");
  if (strengths.n_beams() != mechanics.lattice().n_beams() || strengths.compressive.size() != strengths.tensile.size())
    throw hm::InputError("strengths: " + std::to_string(strengths.n_beams()) + " beams, allowed: one per beam (" +
                         std::to_string(mechanics.lattice().n_beams()) + ")");

  BreakLoopSummary summary;
  FailureScan scan(mechanics.lattice(), dual, options.crack_tip, mechanics.states(), law);
  std::vector<BeamForce> forces;  // the connection forces of each solve, storage reused
  while (true) {
    if (options.interrupted && options.interrupted()) {
      summary.status = BreakLoopStatus::interrupted;
      summary.message = "interrupted after " + std::to_string(summary.n_breaks) + " breaks";
      break;
    }
    const MechanicsSummary solved = mechanics.solve(false);  // no equilibrium residual: not read here
    summary.solve_seconds += solved.solve_seconds;
    ++summary.n_solves;
    summary.n_contact_iterations += solved.contact_iterations;
    summary.n_contact_changes += solved.n_contact_changes;
    if (!solved.is_converged()) {
      summary.status = BreakLoopStatus::solve_failed;
      summary.near_mechanism = solved.near_mechanism;
      summary.message = "mechanical solve " + std::to_string(summary.n_solves) + " after " +
                        std::to_string(summary.n_breaks) + " breaks: " + solved.message;
      break;
    }
    const auto stress_start = std::chrono::steady_clock::now();
    // = select_beam_to_break(current_beam_stress(mechanics, dual, crack_tip, stress_scale), ...), faster.
    mechanics.beam_forces(forces);
    const FailureScan::Result checked = scan.run(forces, strengths, mechanics.states(), stress_scale);
    const BreakCandidate& candidate = checked.judged;
    summary.max_reference_ratio = std::max(0.0, checked.max_reference_ratio);
    summary.max_ratio = std::max(0.0, candidate.max_ratio);
    summary.stress_seconds += seconds_since(stress_start);
    if (!candidate.found()) break;  // stable
    if (summary.n_breaks + summary.n_teeth >= options.max_breaks) {
      summary.status = BreakLoopStatus::break_cap;
      summary.message = "break cap reached (break_loop.max_breaks = " + std::to_string(options.max_breaks) +
                        "); beams still fail at load " + num(load);
      break;
    }
    const int e = candidate.beam;
    if (summary.n_breaks + summary.n_teeth == 0) summary.first_ratio = candidate.ratio;
    const auto break_start = std::chrono::steady_clock::now();
    const bool tensile = candidate.mode == FailureMode::tensile;
    // A tensile failure under the saw-tooth law: the tooth gives way (its energy booked), to the next
    // tooth's stiffness or, after the last, to 0 (the beam breaks below).
    const bool tooth_gives_way = law && tensile;
    const bool last = !tooth_gives_way || law->on_last_tooth(e);
    if (tooth_gives_way) {
      give_way(*law, mechanics, checked, load, last, *teeth);
      ++summary.n_teeth;
    }
    if (last) {
      log.push_back(make_break_event(mechanics.lattice(), candidate, checked.sigma_1, checked.sigma_3,
                                     checked.crack_tip_factor, load, static_cast<int>(log.size())));
      mechanics.break_beam(e);
      // Only break_beam turns an intact beam into a broken one (detachment and contacts switch broken
      // beams between contact and open).
      scan.beam_broken(e);
      ++summary.n_breaks;
    }
    summary.break_seconds += seconds_since(break_start);
  }
  summary.seconds = seconds_since(start);
  return summary;
}

}  // namespace

BreakLoopSummary break_until_stable(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                    const BreakLoopOptions& options, double load, std::vector<BreakEvent>& log,
                                    double stress_scale) {
  return run_break_loop(mechanics, dual, strengths, nullptr, options, load, log, nullptr, stress_scale);
}

BreakLoopSummary break_until_stable(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                    SawtoothLaw& law, const BreakLoopOptions& options, double load,
                                    std::vector<BreakEvent>& log, std::vector<ToothEvent>& teeth, double stress_scale) {
  return run_break_loop(mechanics, dual, strengths, &law, options, load, log, &teeth, stress_scale);
}

// --- load stepping -----------------------------------------------------------------------------------

namespace {

LoadingResult run_loading(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                          SawtoothLaw* law, const LoadSteppingOptions& options, const LoadStepObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  options.validate();
  LoadingResult result;
  const double inf = std::numeric_limits<double>::infinity();
  double load = options.initial_load;
  double reference_ratio = -1.0;  // unknown until the first solve
  for (int step = 0;; ++step) {
    if (step >= options.max_steps) {
      result.status = LoadingStatus::step_cap;
      result.message =
          "step cap reached (load_stepping.max_steps = " + std::to_string(options.max_steps) + ") at load " + num(load);
      break;
    }
    LoadStep record;
    record.step = step;
    record.load = load;
    // With an unchanged broken set the reference solution is unchanged: a step whose load is below the
    // next break's needs no solve (homogeneity, file comment of fracture.hpp).
    const bool due = reference_ratio < 0.0 || load * reference_ratio >= 1.0 || !options.snap_to_breaks;
    if (due) {
      BreakLoopOptions loop = options.break_loop;
      const int events = static_cast<int>(result.breaks.size() + result.teeth.size());
      loop.max_breaks = std::min(loop.max_breaks, options.max_breaks - events);
      const BreakLoopSummary s =
          law ? run_break_loop(mechanics, dual, strengths, law, loop, load, result.breaks, &result.teeth, load)
              : run_break_loop(mechanics, dual, strengths, nullptr, loop, load, result.breaks, nullptr, load);
      result.n_solves += s.n_solves;
      record.n_breaks = s.n_breaks + s.n_teeth;
      record.status = s.status;
      reference_ratio = s.max_reference_ratio;
      if (!s.is_stable()) result.message = s.message;
    }
    record.n_breaks_total = static_cast<int>(result.breaks.size() + result.teeth.size());
    record.max_ratio = load * reference_ratio;
    record.next_break_load = reference_ratio > 0.0 ? 1.0 / reference_ratio : inf;
    result.steps.push_back(record);
    const bool keep_going = !observer || observer(record, mechanics);
    if (record.status == BreakLoopStatus::solve_failed) {
      result.status = LoadingStatus::solve_failed;
      break;
    }
    if (record.status == BreakLoopStatus::break_cap || record.n_breaks_total >= options.max_breaks) {
      result.status = LoadingStatus::break_cap;
      if (result.message.empty())
        result.message = "break cap reached (load_stepping.max_breaks = " + std::to_string(options.max_breaks) + ")";
      break;
    }
    if (!keep_going) {
      result.status = LoadingStatus::stopped;
      result.message = "stopped by the observer at load " + num(load);
      break;
    }
    if (load >= options.max_load) {
      result.status = LoadingStatus::reached_max_load;
      break;
    }
    double next = std::min(load + options.load_increment, options.max_load);
    if (options.snap_to_breaks && reference_ratio > 0.0) {
      // 1 + 1e-9: the snapped beam's judged ratio lands at >= 1 although 1/r * r may round below 1.
      const double at_break = (1.0 / reference_ratio) * (1.0 + 1e-9);
      if (at_break <= next) next = std::max(at_break, load);
    }
    load = next;
  }
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace

LoadingResult run_load_stepping(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                const LoadSteppingOptions& options, const LoadStepObserver& observer) {
  return run_loading(mechanics, dual, strengths, nullptr, options, observer);
}

LoadingResult run_load_stepping(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                SawtoothLaw& law, const LoadSteppingOptions& options,
                                const LoadStepObserver& observer) {
  return run_loading(mechanics, dual, strengths, &law, options, observer);
}

// --- crack faces -------------------------------------------------------------------------------------

std::vector<int> beams_crossing_segment(const Lattice& lattice, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  std::vector<int> out;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const Eigen::Vector2d p = lattice.points.col(i), q = lattice.points.col(j);
    const double s1 = side(a, b, p), s2 = side(a, b, q), s3 = side(p, q, a), s4 = side(p, q, b);
    if (((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0)) && ((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0))) out.push_back(e);
  }
  return out;
}

Eigen::VectorXd crack_face_forces(const Lattice& lattice, const DualGraph& dual, const std::vector<int>& crack_beams,
                                  double pressure) {
  return crack_face_forces(lattice, dual, crack_beams, pressure, std::vector<double>(crack_beams.size(), 1.0));
}

Eigen::VectorXd crack_face_forces(const Lattice& lattice, const DualGraph& dual, const std::vector<int>& crack_beams,
                                  double pressure, const std::vector<double>& weights) {
  if (!std::isfinite(pressure)) throw hm::InputError("pressure = " + num(pressure) + ", allowed: finite");
  if (weights.size() != crack_beams.size())
    throw hm::InputError("weights: " + std::to_string(weights.size()) + " values, allowed: one per crack beam (" +
                         std::to_string(crack_beams.size()) + ")");
  assert(dual.dual_length.size() == lattice.n_beams() && "dual graph of another lattice");
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  for (std::size_t k = 0; k < crack_beams.size(); ++k) {
    const int e = crack_beams[k];
    check_beam_index(lattice, e, "crack_beams[" + std::to_string(k) + "]");
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    if (!std::isfinite(weights[k]))
      throw hm::InputError("weights[" + std::to_string(k) + "] = " + num(weights[k]) + ", allowed: finite");
    const Eigen::Vector2d push = (weights[k] * pressure) * dual.dual_length[e] * lattice.direction.col(e);
    f.segment<2>(dof_index(i, 0)) -= push;
    f.segment<2>(dof_index(j, 0)) += push;
  }
  return f;
}

std::vector<CrackOpening> crack_opening(const Lattice& lattice, const Eigen::VectorXd& displacement,
                                        const std::vector<int>& beams) {
  assert(displacement.size() == 3 * lattice.n_particles() && "3 entries per particle");
  std::vector<CrackOpening> out;
  out.reserve(beams.size());
  for (std::size_t k = 0; k < beams.size(); ++k) {
    const int e = beams[k];
    check_beam_index(lattice, e, "beams[" + std::to_string(k) + "]");
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    CrackOpening o;
    o.beam = e;
    o.midpoint = 0.5 * (lattice.points.col(i) + lattice.points.col(j));
    o.jump = displacement.segment<2>(dof_index(j, 0)) - displacement.segment<2>(dof_index(i, 0));
    o.normal_opening = o.jump.dot(lattice.direction.col(e));
    out.push_back(o);
  }
  return out;
}

}  // namespace hm::lattice2d
