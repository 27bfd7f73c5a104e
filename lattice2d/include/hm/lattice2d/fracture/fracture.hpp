#pragma once
/// \file
/// Brittle fracture of the dry lattice (Section 2.1, Eq. 11, Figs. 2-3): the break loop ("break the one
/// beam most over its threshold, re-solve, repeat until none fails"), a quasi-static load-stepping
/// driver around it, and the crack-face pressure of a crack made of broken beams (Appendix C).
/// Dimensionless (lengths over R, stresses and pressures over E). Tension positive.
///
/// Load factor (docs/lattice.md, "Fracture"): the BeamMechanics holds one *reference* load (its
/// boundary pressures, prescribed displacements and external forces, all at load factor 1). Without
/// initial gaps the compression-only contacts of Eqs. 8-10 make the problem positively homogeneous of
/// degree one, so the solution at load factor lambda > 0 is exactly lambda times the reference solution
/// for the same broken set, and so are the stresses and both failure measures of Eq. 11. The loop
/// therefore solves at the reference load and judges failure on lambda x stress: no refactorisation
/// and no change of BeamMechanics when the load grows. Limits: proportional loading only (no fixed
/// load plus a growing one, e.g. a confinement plus an increasing pressure); detached fragments
/// (mechanics.hpp) are frozen at their reference-scale rigid motion, which only their drawing sees.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hm/core/enum_names.hpp"
#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/fracture/sawtooth_law.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"

namespace hm::lattice2d {

// ---------------------------------------------------------------------------------------------------
// Break loop

/// Options of break_until_stable.
struct BreakLoopOptions {
  /// Crack-tip factor (L/2L_m)^(1/2) of Fig. 2 and its L_m (particle_stress.hpp). Validated with these.
  CrackTipOptions crack_tip;
  /// Cap on the beams broken (and, under the saw-tooth law, teeth given way) by one call; reaching it
  /// is reported (status break_cap), never thrown. Our choice 1e6 (more than the beams of the paper's
  /// largest lattice). Allowed: >= 1.
  int max_breaks = 1000000;
  /// Asked before each solve (empty: never): when it returns true the loop ends at once with status
  /// interrupted, so that a user's Ctrl-C does not wait for thousands of breaks. The caller undoes them.
  std::function<bool()> interrupted;

  /// Throws hm::InputError "break_loop.field = value, allowed: rule".
  void validate() const;
};

/// How a break loop or a loading run ended.
enum class BreakLoopStatus {
  stable,        ///< no intact beam has failure ratio >= 1 at the final solve
  break_cap,     ///< max_breaks beams broken, the last solve may still have failing beams
  solve_failed,  ///< a mechanical solve did not converge (linear solver or contact set); see message
  interrupted,   ///< BreakLoopOptions::interrupted said so: the loop stopped between two solves
};
constexpr auto enum_names(BreakLoopStatus) {
  return core::enum_table<BreakLoopStatus>({{BreakLoopStatus::stable, "stable"},
                                            {BreakLoopStatus::break_cap, "break_cap"},
                                            {BreakLoopStatus::solve_failed, "solve_failed"},
                                            {BreakLoopStatus::interrupted, "interrupted"}});
}

/// What one break loop did (Ceres' Summary in small).
struct BreakLoopSummary {
  BreakLoopStatus status = BreakLoopStatus::stable;
  int n_breaks = 0;          ///< beams broken by this call
  int n_teeth = 0;           ///< teeth given way by this call (saw-tooth law; a beam's last is also a break)
  double first_ratio = 0.0;  ///< failure ratio of the call's first break or tooth (0 if none)
  int n_solves = 0;          ///< BeamMechanics::solve() calls (n_breaks + 1 when stable)
  /// Largest failure ratio max(sigma_1/T_u, sigma_CC/C_u) over intact beams at the last solve, at
  /// the judged stress (stress_scale x reference): < 1 when stable.
  double max_ratio = 0.0;
  /// The same at the reference load (stress_scale = 1): the load factor of the next break is
  /// 1 / max_reference_ratio (homogeneity; see the file comment). 0 if no intact beam is stressed.
  double max_reference_ratio = 0.0;
  int n_contact_iterations = 0;  ///< summed over the solves
  int n_contact_changes = 0;     ///< open <-> contact switches, summed over the solves
  double seconds = 0.0;          ///< wall time of the call, of which:
  double solve_seconds = 0.0;    ///< BeamMechanics::solve (back-substitutions, contact iterations)
  double stress_seconds = 0.0;   ///< beam stresses and the failure check
  double break_seconds = 0.0;    ///< BeamMechanics::break_beam (factor downdates, detachment)
  std::string message;           ///< why, when not stable
  bool near_mechanism = false;   ///< solve_failed with the lattice nearly cut through (MechanicsSummary's)
  bool is_stable() const { return status == BreakLoopStatus::stable; }
};

/// Particle stresses of `mechanics`' current solution as the failure check sees them: the beam forces
/// of the whole displacement (the rest state under an in-situ field plus the increment since) ->
/// compute_particle_stress with V_i from `dual`. Precondition: dual built from mechanics.lattice().
ParticleStress current_particle_stress(const BeamMechanics& mechanics, const DualGraph& dual);

/// Beam stresses (with the crack-tip factor) of `mechanics`' current solution, times stress_scale:
/// mechanics.beam_forces() (bit for bit compute_beam_forces' forces) -> compute_particle_stress (V_i from
/// `dual`) -> compute_beam_stress: the functions the break loop's failure check uses.
/// Only beam forces enter the particle stress (as in Section 2.1): external forces (crack-face or
/// pore pressure) are loads, not stresses. Precondition: dual built from mechanics.lattice().
BeamStress current_beam_stress(const BeamMechanics& mechanics, const DualGraph& dual,
                               const CrackTipOptions& crack_tip = {}, double stress_scale = 1.0);

/// Every beam's failure ratio under the break loop's check of `mechanics`' current solution (a beam
/// fails at >= 1), 0 for broken beams: max(sigma_1 / T_u, sigma_CC / C_u) with the crack-tip factor
/// (brittle, `law` null), or, under the saw-tooth `law`, max(axial stress / its tooth's strength,
/// sigma_CC / C_u) without it.
Eigen::VectorXd failure_ratios(const BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                               const CrackTipOptions& crack_tip, const SawtoothLaw* law = nullptr);

/// The break loop of Section 2.1: solve; judge every intact beam on stress_scale x (its beam stress)
/// against its own strengths (Eq. 11 and the tensile criterion, evaluate_failure); if any ratio >= 1
/// break the single beam most over its threshold (select_beam_to_break; ties to the lowest index) with
/// BeamMechanics::break_beam (a downdate of the kept factor), append a BreakEvent (stresses at the
/// judged scale, `load` as its load/time) to `log`, re-solve, and repeat until none fails, the cap
/// is reached or a solve fails. Deterministic: equal inputs give an identical sequence.
/// Cost per iteration (re-solve + check): the re-solves use BeamMechanics::solve(false) (no
/// equilibrium residual; nothing here reads it), and the check is select_beam_to_break(
/// current_beam_stress(...)) computed bit for bit the same in one pass over buffers kept for the loop,
/// with the crack-tip set updated around each broken beam (tests/lattice2d/test_fast_path.cpp checks it
/// against the public path at every break, in the Release build).
/// Use stress_scale = 1 when the mechanics holds the actual load (time-driven runs), = lambda under
/// the load-factor convention of run_load_stepping. Throws hm::InputError for invalid options, a
/// negative or non-finite stress_scale, or strengths not sized one per beam.
BreakLoopSummary break_until_stable(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                    const BreakLoopOptions& options, double load, std::vector<BreakEvent>& log,
                                    double stress_scale = 1.0);

/// The same loop under the saw-tooth law (sawtooth_law.hpp; `law` built for this mechanics' lattice and
/// its current softening): an intact beam fails in tension when its axial stress reaches its current
/// tooth's strength (ratio = stress_scale x axial stress / strength), in shear by Eq. 11 on the particle
/// stresses without the crack-tip factor (options.crack_tip is not used). The beam most over its
/// threshold gives way: a tensile failure is a ToothEvent in `teeth` and steps the beam down to the next
/// tooth (BeamMechanics::soften_beam) or, on the last tooth, breaks it; a beam that breaks (last tooth,
/// or shear) is a BreakEvent in `log`, with its particle stresses, ratio and crack-tip factor 1.
BreakLoopSummary break_until_stable(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                    SawtoothLaw& law, const BreakLoopOptions& options, double load,
                                    std::vector<BreakEvent>& log, std::vector<ToothEvent>& teeth,
                                    double stress_scale = 1.0);

// ---------------------------------------------------------------------------------------------------
// Quasi-static loading

/// Options of run_load_stepping. The load factor lambda multiplies the mechanics' reference load.
struct LoadSteppingOptions {
  /// lambda of the first step (the break loop runs there too). Allowed: >= 0, finite.
  double initial_load = 0.0;
  /// Delta lambda between steps. Allowed: > 0, finite.
  double load_increment = 0.1;
  /// Last load factor; the run ends after the step that reaches it. Allowed: >= initial_load, finite.
  double max_load = 1.0;
  /// true: a step that would pass the next break's load factor 1/max_reference_ratio stops exactly
  /// there (times 1 + 1e-9, so the beam's ratio is >= 1 despite round-off): breaks are found at their
  /// exact load, not up to Delta lambda late. Steps without a due break skip the solve (the reference
  /// solution has not changed). Our choice true; false gives plain fixed steps.
  bool snap_to_breaks = true;
  /// Cap on the number of steps (reported, not thrown). Allowed: >= 1.
  int max_steps = 100000;
  /// Cap on the total beams broken (reported as break_cap). Allowed: >= 1.
  int max_breaks = 1000000;
  /// The break loop's options (crack tip; its max_breaks is lowered to what the total cap leaves).
  BreakLoopOptions break_loop;

  /// Throws hm::InputError "load_stepping.field = value, allowed: rule" (break_loop.* for the nested).
  void validate() const;
};

/// One load step, after its break loop.
struct LoadStep {
  int step = 0;                  ///< 0, 1, ...
  double load = 0.0;             ///< load factor lambda
  int n_breaks = 0;              ///< beams broken at this load (and teeth given way, under the saw-tooth law)
  int n_breaks_total = 0;        ///< beams broken so far (and teeth given way, under the saw-tooth law)
  double max_ratio = 0.0;        ///< largest failure ratio of the intact beams at lambda (< 1 when stable)
  double next_break_load = 0.0;  ///< 1 / max_reference_ratio: lambda at which the next beam breaks (inf if none)
  BreakLoopStatus status = BreakLoopStatus::stable;
};

/// Called after every step with the step and the mechanics (holding the *reference* solution: the
/// physical displacement, force or reaction at this step is step.load times mechanics'). Return
/// false to stop the run (e.g. once the specimen has lost its load-bearing capacity).
using LoadStepObserver = std::function<bool(const LoadStep&, const BeamMechanics&)>;

/// How run_load_stepping ended.
enum class LoadingStatus {
  reached_max_load,  ///< the step at max_load completed stably
  stopped,           ///< the observer returned false
  step_cap,          ///< max_steps steps without reaching max_load
  break_cap,         ///< max_breaks beams broken
  solve_failed,      ///< a solve did not converge; see message
};
constexpr auto enum_names(LoadingStatus) {
  return core::enum_table<LoadingStatus>({{LoadingStatus::reached_max_load, "reached_max_load"},
                                          {LoadingStatus::stopped, "stopped"},
                                          {LoadingStatus::step_cap, "step_cap"},
                                          {LoadingStatus::break_cap, "break_cap"},
                                          {LoadingStatus::solve_failed, "solve_failed"}});
}

/// Result of run_load_stepping.
struct LoadingResult {
  LoadingStatus status = LoadingStatus::reached_max_load;
  std::vector<LoadStep> steps;     ///< one per step, in order
  std::vector<BreakEvent> breaks;  ///< every break in order; BreakEvent::load = lambda (non-decreasing)
  std::vector<ToothEvent> teeth;   ///< under the saw-tooth law, every tooth that gave way, in order
  int n_solves = 0;
  double seconds = 0.0;
  std::string message;  ///< why, when not reached_max_load
};

/// Quasi-static loading: lambda = initial_load, then + load_increment per step (snapped to the next
/// break when snap_to_breaks) up to max_load; at each load the break loop runs until stable.
/// Broken beams stay broken (BeamMechanics never heals one). `mechanics` keeps the final state.
/// Throws hm::InputError for invalid options or strengths; numerical trouble is in the status.
LoadingResult run_load_stepping(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                const LoadSteppingOptions& options, const LoadStepObserver& observer = {});
/// The same under the saw-tooth `law` (break_until_stable's saw-tooth overload at every step); a step's
/// n_breaks and the cap count teeth and breaks. A softened beam is linear in the load factor like an
/// intact one, so the homogeneity (and snap_to_breaks) holds.
LoadingResult run_load_stepping(BeamMechanics& mechanics, const DualGraph& dual, const BeamStrengths& strengths,
                                SawtoothLaw& law, const LoadSteppingOptions& options,
                                const LoadStepObserver& observer = {});

// ---------------------------------------------------------------------------------------------------
// Cracks made of broken beams, pressurised on their faces (Appendix C)

/// Beams whose segment crosses the segment a-b (proper intersection; a beam touching it at an end
/// point counts when that end lies strictly on one side). In beam order. Use: break these to make a
/// straight crack a-b (the crack faces are then the Voronoi segments of these beams).
std::vector<int> beams_crossing_segment(const Lattice& lattice, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

/// Nodal forces (3 n_particles, rotations 0) of a pressure p acting inside a crack whose faces are the
/// Voronoi segments of `crack_beams`: on each beam (i, j), p d_st pushes i by -p d_st n_ij and j by
/// +p d_st n_ij (Eq. 17's form with b = xi = 1; d_st = dual.dual_length). Zero net force and moment
/// (each pair acts along its own beam). Pass to BeamMechanics::set_external_forces. Preconditions of
/// meaning (not checked): the beams are broken (a pressure inside an intact bond is not a crack).
/// Throws hm::InputError for a beam index out of range or a non-finite pressure.
Eigen::VectorXd crack_face_forces(const Lattice& lattice, const DualGraph& dual, const std::vector<int>& crack_beams,
                                  double pressure);
/// The same with beam crack_beams[k]'s pressure times weights[k] (one weight per beam, finite).
Eigen::VectorXd crack_face_forces(const Lattice& lattice, const DualGraph& dual, const std::vector<int>& crack_beams,
                                  double pressure, const std::vector<double>& weights);

/// Opening across one broken beam.
struct CrackOpening {
  int beam = -1;
  Eigen::Vector2d midpoint = Eigen::Vector2d::Zero();  ///< beam midpoint, undeformed (over R)
  Eigen::Vector2d jump = Eigen::Vector2d::Zero();      ///< u_j - u_i (over R)
  /// (u_j - u_i).n_ij: opening normal to the beam's own Voronoi segment (its crack-face facet),
  /// > 0 when the faces separate. On a zig-zag facet of a straight crack this is the crack-normal
  /// opening times cos(facet tilt); project `jump` on the mean crack normal for Sneddon's 2w.
  double normal_opening = 0.0;
};

/// Openings across `beams` for displacements u (3 n_particles). Throws hm::InputError for a beam
/// index out of range; asserts u's size.
std::vector<CrackOpening> crack_opening(const Lattice& lattice, const Eigen::VectorXd& displacement,
                                        const std::vector<int>& beams);

}  // namespace hm::lattice2d
