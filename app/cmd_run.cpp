// hmlattice run <case.toml> [--out DIR] [--overwrite]
//
// Runs the two-way coupled 2D lattice model of Sections 2.1-2.3 (beam mechanics + dual-graph flow,
// drained or undrained operator split iterated to convergence in every time step, Fig. 5) on a case
// file (model = "lattice2d", format in hm/case/run_case.hpp) and writes, into DIR (default
// out/<case name>):
//   series.csv   per step: p_h, injected, stored, coupling, outflow volumes, balance error, iterations
//   radial.csv   radially averaged u_r and p at the output times (Figs. 7, 13, 15)
//   vtk/         lattice.pvd + lattice_NNNN.vtu snapshots for ParaView (pressure per triangle)
//   config.toml  the resolved case + provenance; rerunnable as a case
// DIR must be new or empty, or an earlier result folder with --overwrite (hm/core/result_folder.hpp).
// Examples:
//   hmlattice run cases/fig07_rudnicki_free_quick.toml --out out/fig07_quick
//   hmlattice run cases/fig07_rudnicki_free.toml
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/interrupt.hpp"
#include "hm/core/validation.hpp"
#include "hm/core/result_folder.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/case/progress.hpp"
#include "hm/case/provenance.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/run_output.hpp"

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

}  // namespace

void add_run_command(CLI::App& app, int& exit_code, const std::string& command_line) {
  struct Args {
    std::string case_file, out;
    bool overwrite = false;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("run", "Run the coupled 2D lattice model (Sections 2.1-2.3) on a case");
  cmd->add_option("case", a->case_file, "case file (TOML), e.g. cases/fig07_rudnicki_free.toml")->required();
  add_output_options(*cmd, a->out, a->overwrite);
  cmd->callback([a, &exit_code, command_line] {
    // 1. Read and validate everything, the output folder included, before computing.
    const cases::RunCase c = cases::read_run_case(a->case_file);
    core::ResultFolder out(output_folder(a->out, a->case_file), "--out", a->overwrite, command_line);
    const auto& p = c.physics.parameters;
    std::cout << "run: Q = " << p.Q << ", b = " << p.material.b << ", E/M = " << p.material.E_over_M
              << ", iota = " << p.iota << "; " << core::name_of(c.lattice.domain) << ", N = " << c.lattice.n_particles
              << ", seed = " << c.lattice.seed << ", outer " << core::name_of(c.boundary.outer) << "; split "
              << core::name_of(c.coupling.split) << ", Psi = " << c.coupling.terms.psi << ", xi = " << c.coupling.terms.xi
              << "; t_end = " << c.stepping.t_end << "\n";

    // 2. Build the lattice and the coupled model (mechanics factorised once, with the Eq. 20 springs).
    //    The beams are the toolkit's calibrated constants (E = 1; the lattice's nu is
    //    calibrated_continuum().poisson_ratio, docs/lattice.md), whatever [physics] nu says: nu there
    //    enters E/M (Eq. 22) only.
    const auto setup_start = std::chrono::steady_clock::now();
    const auto model = cases::make_coupled_model(c);
    const double setup_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - setup_start).count();
    std::cout << "lattice: " << model->lattice().n_particles() << " particles, " << model->lattice().n_beams()
              << " beams, " << model->lattice().n_triangles() << " triangles\n";

    // 3. Run: the initial state, then while time remains a coupled step; each step is recorded.
    cases::RunRecorder recorder(out.path(), c);
    cases::ProgressReporter progress(std::cout, "run");
    const core::InterruptRequest interrupt;  // Ctrl-C or SIGTERM: stop after the step, keep the results
    int step = 0;
    double step_seconds = 0.0;  // for the ETA of the progress line
    const auto run = model->run(c.stepping, [&](const lattice2d::CoupledModel& m, const lattice2d::CoupledStepSummary& s,
                                                bool is_output) {
      recorder.record(m, s, is_output);
      step_seconds += s.seconds;
      const int remaining = remaining_steps(m.time(), s.dt, c.stepping);
      progress.update(m.time(), c.stepping.t_end,
                      "step " + std::to_string(step) + ", broken " + std::to_string(m.n_broken()) + ", iterations " +
                          std::to_string(s.iterations) + ", contact switches " + std::to_string(s.n_contact_changes) +
                          ", refactorisations " + std::to_string(s.n_mechanics_factorizations) + " (" +
                          std::to_string(s.n_mechanics_update_failures) + " after failed updates), ETA " +
                          std::to_string(static_cast<int>(step > 0 ? step_seconds / step * remaining : 0.0)) + " s" +
                          (s.n_mechanics_update_failures > 0
                               ? "; last failed update: " + m.mechanics().solver().report().last_update_failure
                               : std::string()));
      ++step;
    }, [&] { return interrupt.signal() != 0; });
    char summary[500];
    std::snprintf(summary, sizeof summary,
                  "%d steps (%d halved), %d coupling iterations (= flow factorisations and solves), %d beams broken "
                  "(= factor downdates), %lld mechanical solves, %lld contact switches, %lld mechanical "
                  "refactorisations (%lld after failed updates), max volume-balance error %.2e; set-up %.1f s, "
                  "mechanics solves %.1f s, stresses and failure checks %.1f s, downdates %.1f s, geometry %.1f s, "
                  "flow %.1f s",
                  run.n_steps, run.n_step_halvings, run.total_iterations, model->n_broken(), run.n_mechanics_solves,
                  run.n_contact_changes, run.n_mechanics_factorizations, run.n_mechanics_update_failures,
                  run.max_balance_error, setup_seconds, run.mechanics_seconds, run.stress_seconds, run.break_seconds,
                  run.geometry_seconds, run.flow_seconds);
    progress.finish(summary);
    if (run.n_mechanics_update_failures > 0)  // each cost a refactorisation: say what CHOLMOD reported (docs/borehole_fracture.md)
      std::cout << "last failed update: " << model->mechanics().solver().report().last_update_failure << "\n";

    // 4. The resolved configuration beside the results, then everything appears at once. A run that
    //    stopped early (interrupted, or a numerical failure) keeps every step it finished, marked
    //    incomplete, with status.toml saying why and where it stopped.
    recorder.finish();
    core::write_file_atomically(out.path() / "config.toml", [&](std::ostream& f) {
      f << cases::run_case_to_toml(c, cases::to_toml(cases::make_provenance(command_line)));
    });
    if (!run.is_ok()) {
      const bool interrupted = run.status == lattice2d::CoupledStatus::interrupted;
      const std::string why = interrupted ? std::string("interrupted by ") + interrupt.signal_name()
                                          : "numerical failure: " + run.message;
      core::write_stopped_status(out.path() / "status.toml", "run", why, step - 1, model->time(), c.stepping.t_end, out.target());
      out.commit(why);
      std::cerr << "hmlattice run: " << core::one_line(why, 300) << "; the " << step - 1 << " steps done (t = "
                << model->time() << " of " << c.stepping.t_end << ") are in " << out.target().string()
                << ", marked incomplete (status.toml)\n";
      exit_code = interrupted ? interrupt.exit_code() : 1;
      return;
    }
    out.commit();
    std::cout << "Results: " << out.target().string() << (c.fracture_enabled ? "/{series,radial,breaks,breakdown,fractures,fracture_summary}.csv, " : "/{series,radial}.csv, ") << (c.output.vtk ? "vtk/lattice.pvd, " : "")
              << "config.toml\n";
  });
}

}  // namespace hm::app
