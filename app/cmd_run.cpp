// hmlattice run <case.toml> [--set table.key=value ...] [--out DIR] [--overwrite] [--checkpoint-every SECONDS]
//               [--stop-after-steps N]
// hmlattice run --resume DIR
//
// Runs the two-way coupled 2D lattice model of Sections 2.1-2.3 (beam mechanics + dual-graph flow,
// drained or undrained operator split iterated to convergence in every time step, Fig. 5) on a case
// file (model = "lattice2d", format in hm/case/run_case.hpp) and writes, into DIR (default
// out/<case name>) the files hm/case/run_output.hpp lists (series, radial, VTK; with fracture the break
// log and the fracture tables), and:
//   config.toml  the resolved case + provenance; rerunnable as a case
//   checkpoint.bin  while the run is not complete: the state --resume continues from (checkpoint.hpp)
// With [fracture] stop_at_first_break = true the run ends, complete, with the step that breaks the
// first beam, and that step is written as an output time (radial.csv, VTK, fracture tables).
// DIR must be new or empty, or an earlier result folder with --overwrite (hm/core/result_folder.hpp).
// Examples:
//   hmlattice run cases/fig07_rudnicki_free_quick.toml --out out/fig07_quick
//   hmlattice run cases/fig07_rudnicki_free.toml
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "hm/case/checkpoint.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/progress.hpp"
#include "hm/case/provenance.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/run_files.hpp"
#include "hm/case/run_output.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/interrupt.hpp"
#include "hm/core/peak_memory.hpp"
#include "hm/core/result_folder.hpp"
#include "hm/core/toml_text.hpp"
#include "hm/core/validation.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"

namespace hm::app {

namespace {

// Steps left after time t with the last step dt, if dt keeps growing geometrically up to dt_max
// (output times ignored): for the ETA of the progress line only.
int remaining_steps(double t, double dt, const lattice2d::TimeStepping& s) {
  int n = 0;
  for (dt = std::max(dt, s.dt_initial); t < s.t_end * (1.0 - 1e-12) && n < 10000000; ++n) {
    dt = std::min(dt * s.dt_growth, s.dt_max);
    t += dt;
  }
  return n;
}

struct RunArgs {
  std::string case_file, out, resume;
  std::vector<std::string> set;  // --set table.key=value
  bool overwrite = false;
  double checkpoint_seconds = 300.0;
  int stop_after_steps = -1;
};

// What usually cures a step that does not converge or a solve that fails (docs/coupling.md), as
// "; to try: ..." (empty: nothing to suggest).
std::string what_to_try_after(const cases::RunCase& c, const lattice2d::CoupledRunSummary& run) {
  // A lattice nearly cut through by one pass's breaks: only letting the fluid answer each break helps.
  if (run.near_mechanism)
    return c.coupling.events_per_check == 1 ? std::string() : std::string("; to try: [coupling] events_per_check = 1");
  std::string remedies = "; to try: ";
  if (c.coupling.relaxation != lattice2d::CouplingRelaxation::anderson)
    remedies += "[coupling] relaxation = \"anderson\", ";
  // A fluid-filled crack whose pressure is far from uniform (docs/coupling.md).
  if (c.flow.crack_coupling == lattice2d::CrackCoupling::full &&
      c.coupling.crack_stabiliser == lattice2d::CrackStabiliser::uniform_pressure &&
      (c.flow.fracture_flow.law != lattice2d::FractureFlow::permeability || c.physics.parameters.iota < 1e6))
    remedies += "[coupling] crack_stabiliser = \"crack_unknowns\", ";
  return remedies + "a smaller [numerics] dt_initial or dt_max";
}

// The case's defining numbers, one line before anything is computed.
void print_case(const cases::RunCase& c) {
  const auto& p = c.physics.parameters;
  std::cout << "run: Q = " << p.Q << ", b = " << p.material.b << ", E/M = " << p.material.E_over_M
            << ", iota = " << p.iota << "; " << core::name_of(c.lattice.domain) << ", N = " << c.lattice.n_particles
            << ", seed = " << c.lattice.seed << ", outer " << core::name_of(c.boundary.outer);
  if (!c.insitu.is_zero())
    std::cout << " (S_H = " << c.insitu.S_H << ", S_h = " << c.insitu.S_h << " at " << c.insitu.theta_H_deg
              << " deg, p0 = " << c.insitu.p0 << ")";
  std::cout << "; split " << core::name_of(c.coupling.split) << ", Psi = " << c.coupling.terms.psi
            << ", xi = " << c.coupling.terms.xi << "; t_end = " << c.stepping.t_end << "\n";
}

// The lattice built, and the saw-tooth law's teeth where it is on.
void print_model(const lattice2d::CoupledModel& model) {
  std::cout << "lattice: " << model.lattice().n_particles() << " particles, " << model.lattice().n_beams() << " beams, "
            << model.lattice().n_triangles() << " triangles\n";
  if (const lattice2d::SawtoothLaw* law = model.sawtooth_law())
    std::cout << "saw-tooth law: G_f/(E R) = " << core::format_value(law->options().fracture_energy) << ", "
              << law->options().teeth.n_teeth << " teeth of ratio "
              << core::format_value(law->options().teeth.reduction) << "; " << law->n_brittle_beams() << " of "
              << model.lattice().n_beams()
              << " beams are too long for their G_f and have one tooth at the strength that dissipates it\n";
}

// The run's counters and its time split, for the progress line's last word.
std::string summary_line(const lattice2d::CoupledRunSummary& run, const lattice2d::CoupledModel& model,
                         double setup_seconds) {
  char summary[500];
  std::snprintf(summary, sizeof summary,
                "%d steps (%d halved), %d coupling iterations (= flow factorisations and solves), %d beams broken "
                "(= factor downdates), %lld mechanical solves, %lld contact switches, %lld mechanical "
                "refactorisations (%lld after failed updates), max volume-balance error %.2e; set-up %.1f s, "
                "mechanics solves %.1f s, stresses and failure checks %.1f s, downdates %.1f s, geometry %.1f s, "
                "flow %.1f s; peak memory %.0f MB",
                run.n_steps, run.n_step_halvings, run.total_iterations, model.n_broken(), run.n_mechanics_solves,
                run.n_contact_changes, run.n_mechanics_factorizations, run.n_mechanics_update_failures,
                run.max_balance_error, setup_seconds, run.mechanics_seconds, run.stress_seconds, run.break_seconds,
                run.geometry_seconds, run.flow_seconds, core::peak_memory_bytes() / 1e6);
  return summary;
}

// A run that stopped early: its folder kept with status.toml saying why and where, and one line on
// stderr with what to try; returns the exit code (1 numerical failure, the signal's, 0 on request).
int keep_incomplete(core::ResultFolder& out, const std::filesystem::path& kept, const cases::RunCase& c,
                    const lattice2d::CoupledRunSummary& run, const lattice2d::CoupledModel& model,
                    const core::InterruptRequest& interrupt, int step, const core::StoppedCheckpoint& checkpoint) {
  const bool interrupted = run.status == lattice2d::CoupledStatus::interrupted;
  const std::string why = !interrupted ? "numerical failure: " + run.message
                          : interrupt.signal() != 0
                              ? std::string("interrupted by ") + interrupt.signal_name()
                              : "stopped after step " + std::to_string(step) + " (--stop-after-steps)";
  core::write_stopped_status(out.path() / "status.toml", "run", why, step, model.time(), c.stepping.t_end, kept,
                             checkpoint);
  out.commit(why);
  const std::string what_to_try = interrupted ? std::string() : what_to_try_after(c, run);
  std::cerr << "hmlattice run: " << core::one_line(why, 300) << what_to_try << "; the " << step
            << " steps done (t = " << model.time() << " of " << c.stepping.t_end << ") are in " << kept.string()
            << ", marked incomplete (status.toml)"
            << (checkpoint.step >= 0 ? "; continue with hmlattice run --resume " + kept.string() : std::string())
            << "\n";
  return !interrupted ? 1 : interrupt.signal() != 0 ? interrupt.exit_code() : 0;
}

// The progress line's words after a step.
std::string step_progress(const lattice2d::CoupledModel& m, const lattice2d::CoupledStepSummary& s, int step,
                          double eta_seconds) {
  return "step " + std::to_string(step) + ", broken " + std::to_string(m.n_broken()) + ", iterations " +
         std::to_string(s.iterations) + ", contact switches " + std::to_string(s.n_contact_changes) +
         ", refactorisations " + std::to_string(s.n_mechanics_factorizations) + " (" +
         std::to_string(s.n_mechanics_update_failures) + " after failed updates), ETA " +
         std::to_string(static_cast<int>(eta_seconds)) + " s" +
         (s.n_mechanics_update_failures > 0
              ? "; last failed update: " + m.mechanics().solver().report().last_update_failure
              : std::string());
}

// A run that reached its end (t_end, or its first break when asked to stop there): the folder
// committed without status.toml or checkpoint, and where the results are.
void keep_complete(core::ResultFolder& out, const cases::RunCase& c, const cases::Breakdown& breakdown,
                   bool stopped_at_first_break, int step) {
  std::error_code ec;
  std::filesystem::remove(out.path() / "status.toml", ec);  // a resumed run is complete now
  std::filesystem::remove(out.path() / cases::checkpoint_file_name, ec);
  out.commit();
  if (stopped_at_first_break)
    std::cout << "Stopped at the first break: t* = " << core::format_value(breakdown.t_first)
              << ", p_h = " << core::format_value(breakdown.p_first) << " (step " << step << ")\n";
  else if (c.stop_at_first_break)
    std::cout << "No beam broke by t_end = " << core::format_value(c.stepping.t_end) << "\n";
  std::cout << "Results: " << cases::results_line(out.target(), c) << "\n";
}

// A run read, built and ready to step: its folder, case, model and recorder.
struct PreparedRun {
  std::unique_ptr<core::ResultFolder> out;
  cases::RunCase c;
  std::string case_text;  // the resolved case, which a checkpoint must match
  std::unique_ptr<lattice2d::CoupledModel> model;
  std::unique_ptr<cases::RunRecorder> recorder;
  double setup_seconds = 0.0;
};

PreparedRun prepare_run(const RunArgs& a, const std::string& command_line) {
  // 1. Read and validate everything, the output folder and a checkpoint to resume included, before
  //    computing. A resumed run reads its folder's config.toml and continues in that folder.
  PreparedRun r;
  const bool resuming = !a.resume.empty();
  r.out =
      resuming
          ? std::make_unique<core::ResultFolder>(core::ResultFolder::Resume{}, a.resume, "--resume", command_line)
          : std::make_unique<core::ResultFolder>(output_folder(a.out, a.case_file), "--out", a.overwrite, command_line);
  r.c = resuming ? cases::read_run_case(cases::run_file_path(r.out->path(), cases::RunFileId::config))
                 : cases::read_run_case(a.case_file, a.set);
  r.case_text = cases::run_case_to_toml(r.c, "");
  print_case(r.c);

  // 2. Build the lattice and the coupled model (mechanics factorised once, with the Eq. 20 springs).
  //    The beams are the toolkit's calibrated constants (E = 1; the lattice's nu is
  //    calibrated_continuum().poisson_ratio, docs/lattice.md), whatever [physics] nu says: nu there
  //    enters E/M (Eq. 22) only. A resumed model then takes the checkpoint's state.
  const auto setup_start = std::chrono::steady_clock::now();
  r.model = cases::make_coupled_model(r.c);
  if (resuming) {
    core::StateReader state = cases::read_checkpoint(r.out->path(), r.case_text, *r.model);
    r.recorder = std::make_unique<cases::RunRecorder>(r.out->path(), r.c, *r.model, state);
  } else {
    r.recorder = std::make_unique<cases::RunRecorder>(r.out->path(), r.c);
    // The resolved configuration first: a run killed at any point leaves it beside its steps.
    core::write_file_atomically(cases::run_file_path(r.out->path(), cases::RunFileId::config), [&](std::ostream& f) {
      f << cases::run_case_to_toml(r.c, cases::to_toml(cases::make_provenance(command_line)));
    });
  }
  r.setup_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
  return r;
}

void run_case(const RunArgs& a, int& exit_code, const std::string& command_line) {
  PreparedRun prepared = prepare_run(a, command_line);
  const bool resuming = !a.resume.empty();
  const std::unique_ptr<core::ResultFolder>& out = prepared.out;
  const cases::RunCase& c = prepared.c;
  const std::string& case_text = prepared.case_text;
  const std::unique_ptr<lattice2d::CoupledModel>& model = prepared.model;
  const std::unique_ptr<cases::RunRecorder>& recorder = prepared.recorder;
  const double setup_seconds = prepared.setup_seconds;
  print_model(*model);
  const int first_step = model->run_cursor().totals.n_steps;
  if (resuming)
    std::cout << "resumed at step " << first_step << ", t = " << model->time() << ", from "
              << (out->path() / cases::checkpoint_file_name).string() << "\n";

  // 3. Run: the initial state, then while time remains a coupled step; each step is recorded, and a
  //    checkpoint written at the output times and every checkpoint_seconds of wall time. With
  //    stop_at_first_break, the step that breaks the first beam is recorded as an output and is the last.
  cases::ProgressReporter progress(std::cout, "run");
  // Ctrl-C or SIGTERM: stop, keep the results. A step in progress is undone at its next coupling pass
  // or break-loop solve, so the answer does not wait for the step; the checkpoint is the last step's.
  const core::InterruptRequest interrupt;
  model->set_interrupt([&] { return interrupt.signal() != 0; });
  int step = first_step;
  // A long step (thousands of breaks at N = 1e5) reports its passes on the same throttled line.
  model->set_pass_observer([&](int pass, const Eigen::VectorXd&, const Eigen::VectorXd&) {
    progress.update(model->time(), c.stepping.t_end,
                    "step " + std::to_string(step + 1) + " in progress: pass " + std::to_string(pass) + ", broken " +
                        std::to_string(model->n_broken()));
  });
  int checkpoint_step = resuming ? first_step : -1;
  double checkpoint_t = model->time();
  auto last_checkpoint = std::chrono::steady_clock::now();
  const auto checkpoint = [&](const lattice2d::CoupledModel& m) {
    cases::write_checkpoint(out->path(), case_text, m, *recorder);
    checkpoint_step = step;
    checkpoint_t = m.time();
    last_checkpoint = std::chrono::steady_clock::now();
  };
  double step_seconds = 0.0;  // for the ETA of the progress line
  bool stopped_at_first_break = false;
  const auto run = model->run(
      c.stepping,
      [&](const lattice2d::CoupledModel& m, const lattice2d::CoupledStepSummary& s, bool is_output) {
        recorder->record(m, s, is_output || c.reached_first_break(m));
        step = m.run_cursor().totals.n_steps;  // accepted steps so far (0 at the initial state)
        const double since = std::chrono::duration<double>(std::chrono::steady_clock::now() - last_checkpoint).count();
        if (step > 0 && (is_output || since >= a.checkpoint_seconds || step == a.stop_after_steps)) checkpoint(m);
        step_seconds += s.seconds;
        const int remaining = remaining_steps(m.time(), s.dt, c.stepping);
        const int done = step - first_step;
        progress.update(m.time(), c.stepping.t_end,
                        step_progress(m, s, step, done > 0 ? step_seconds / done * remaining : 0.0));
      },
      [&] {
        stopped_at_first_break = c.reached_first_break(*model);
        return stopped_at_first_break || interrupt.signal() != 0 || step == a.stop_after_steps;
      });
  // Ending at the first break is the run's end, not an interruption (whatever else came with that step).
  const bool complete = run.is_ok() || stopped_at_first_break;
  progress.finish(summary_line(run, *model, setup_seconds));
  if (run.n_mechanics_update_failures >
      0)  // each cost a refactorisation: say what CHOLMOD reported (docs/borehole_fracture.md)
    std::cout << "last failed update: " << model->mechanics().solver().report().last_update_failure << "\n";

  // 4. Everything appears at once. A run that stopped early keeps every step it finished, marked
  //    incomplete, with status.toml saying why and where it stopped; an interrupted one has a
  //    checkpoint of its last step (a numerical failure keeps the last one before: the failed
  //    attempts' breaks stay in the model, so its state is not a step's).
  if (!complete && run.status == lattice2d::CoupledStatus::interrupted && checkpoint_step != step) checkpoint(*model);
  recorder->finish();
  if (!complete) {
    // A resumed folder stays where it is when it stops again (a killed run's staging folder included).
    const std::filesystem::path kept = resuming ? std::filesystem::path(a.resume) : out->target();
    exit_code = keep_incomplete(*out, kept, c, run, *model, interrupt, step, {checkpoint_step, checkpoint_t});
    return;
  }
  keep_complete(*out, c, recorder->breakdown(), stopped_at_first_break, step);
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code, const std::string& command_line) {
  auto a = std::make_shared<RunArgs>();
  auto* cmd = app.add_subcommand("run", "Run the coupled 2D lattice model (Sections 2.1-2.3) on a case");
  auto* file = cmd->add_option("case", a->case_file, "case file (TOML), e.g. cases/fig07_rudnicki_free.toml");
  add_output_options(*cmd, a->out, a->overwrite);
  auto* resume = cmd->add_option("--resume", a->resume,
                                 "continue the run in this folder (one that stopped before t_end) from its checkpoint");
  add_set_option(*cmd, a->set);
  resume->excludes(file)->excludes("--out")->excludes("--overwrite")->excludes("--set");
  cmd->add_option(
         "--checkpoint-every", a->checkpoint_seconds,
         "write a checkpoint at least every this many seconds of wall time (and at each output time; 0: every step)")
      ->check(finite_between(0.0, 1e9))
      ->capture_default_str();
  cmd->add_option("--stop-after-steps", a->stop_after_steps,
                  "stop after this many steps, as an interrupt would (checkpoint, incomplete folder, exit 0)")
      ->check(integer_between(1, 100000000));
  cmd->footer(cases::run_files_help());
  cmd->callback([a, &exit_code, command_line, file, resume] {
    if (file->count() == 0 && resume->count() == 0) throw InputError("run: a case file or --resume DIR is required");
    run_case(*a, exit_code, command_line);
  });
}

}  // namespace hm::app
