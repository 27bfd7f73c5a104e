// Lattice runs to the first break: see first_break_runs.hpp.
#include "first_break_runs.hpp"

#include <chrono>
#include <optional>

#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/progress.hpp"
#include "hm/case/provenance.hpp"
#include "hm/case/run_output.hpp"
#include "hm/core/file_output.hpp"

namespace hm::verification::breakdown {

namespace fs = std::filesystem;
namespace lt = hm::lattice2d;

FirstBreakRuns::FirstBreakRuns(fs::path root, fs::path runs_dir, std::ostream* progress)
    : root_(std::move(root)), runs_dir_(std::move(runs_dir)), progress_(progress) {}

borehole_fracture::RunOutcome FirstBreakRuns::run(const cases::RunCase& c, const std::string& label,
                                                  const fdm1d::Fdm1dResult& ref) {
  std::error_code ec;
  if (!runs_dir_.empty() && fs::exists(runs_dir_ / label, ec)) {
    read_.push_back(label);
    return borehole_fracture::read_run(c, label, runs_dir_ / label, ref);
  }
  // As `hmlattice run` does with stop_at_first_break: the step that breaks the first beam is recorded
  // as an output time's and is the last; a run that never breaks ends at t_end. Both are complete.
  const auto start = std::chrono::steady_clock::now();
  const auto model = cases::make_coupled_model(c);
  const fs::path dir = root_ / label;
  fs::create_directories(dir);
  cases::RunRecorder recorder(dir, c);
  const auto broken = [&](const lt::CoupledModel& m) { return c.stop_at_first_break && m.n_broken() > 0; };
  std::optional<cases::ProgressReporter> reporter;
  if (progress_) reporter.emplace(*progress_, label, 60.0);
  const auto run = model->run(
      c.stepping,
      [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
        recorder.record(m, s, out || broken(m));
        if (reporter) reporter->update(m.time(), c.stepping.t_end);
      },
      [&] { return broken(*model); });
  const bool complete = run.is_ok() || broken(*model);
  if (reporter) reporter->finish(complete ? std::to_string(run.n_steps) + " steps, broken " + std::to_string(model->n_broken())
                                          : "failed: " + run.message);
  if (!complete) {  // the folder stays, with the series up to the failure, for a look
    borehole_fracture::RunOutcome o;
    o.label = label;
    o.b = c.physics.parameters.material.b;
    o.n_particles = c.lattice.n_particles;
    o.seed = c.lattice.seed;
    o.R_i = c.physics.parameters.R_i;
    o.message = run.message;
    return o;
  }
  recorder.finish();
  core::write_file_atomically(dir / "config.toml", [&](std::ostream& out) {
    out << cases::run_case_to_toml(c, cases::to_toml(cases::make_provenance("hmlattice verify (lattice2d.fig18), run " + label)));
  });
  borehole_fracture::RunOutcome o = borehole_fracture::read_run(c, label, dir, ref);
  o.n_halvings = run.n_step_halvings;
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return o;
}

std::string FirstBreakRuns::note() const {
  if (runs_dir_.empty()) return "";
  std::string labels;
  for (const auto& l : read_) labels += (labels.empty() ? "" : ", ") + l;
  return "Runs read from `--runs " + runs_dir_.string() + "` (made by `hmlattice run`, checked to be complete and of "
         "the benchmark's case): " + (labels.empty() ? "none" : labels) + "; the others were run here (wall time nan "
         "for a read run).";
}

}  // namespace hm::verification::breakdown
