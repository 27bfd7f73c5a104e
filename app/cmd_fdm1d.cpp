// hmlattice fdm1d <case.toml> [--set table.key=value ...] [--out DIR] [--overwrite]
//
// Runs the radial 1D poroelastic model of the paper's Appendix A (monolithic implicit Euler) on a
// case file and writes, into DIR (default out/<case name>):
//   borehole.csv, profiles.csv, probes.csv, steady_state.csv  (see hm/case/fdm1d_output.hpp)
//   config.toml                              the resolved case + provenance; rerunnable as a case
// SIGINT or SIGTERM stops it after the current step: the steps done are kept, marked incomplete,
// with status.toml (exit 130 or 143).
// DIR must be new or empty, or an earlier result folder with --overwrite (hm/core/result_folder.hpp).
// Example: hmlattice fdm1d cases/fig10_fdm1d_b0.5.toml --out out/fig10
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "hm/case/fdm1d_case.hpp"
#include "hm/case/fdm1d_output.hpp"
#include "hm/case/progress.hpp"
#include "hm/case/provenance.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/interrupt.hpp"
#include "hm/core/result_folder.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace hm::app {

void add_fdm1d_command(CLI::App& app, int& exit_code, const std::string& command_line) {
  struct Args {
    std::string case_file, out;
    std::vector<std::string> set;  // --set table.key=value
    bool overwrite = false;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("fdm1d", "Run the radial 1D finite-difference model (Appendix A) on a case");
  cmd->add_option("case", a->case_file, "case file (TOML), e.g. cases/fig10_fdm1d_b0.5.toml")->required();
  add_output_options(*cmd, a->out, a->overwrite);
  add_set_option(*cmd, a->set);
  cmd->callback([a, &exit_code, command_line] {
    // 1. Read and validate everything, the output folder included, before computing.
    const cases::Fdm1dCase c = cases::read_fdm1d_case(a->case_file, a->set);
    core::ResultFolder out(output_folder(a->out, a->case_file), "--out", a->overwrite, command_line);
    const auto& p = c.physics.parameters;
    std::cout << "fdm1d: Q = " << p.Q << ", b = " << p.material.b << ", nu = " << p.material.nu
              << ", E/M = " << p.material.E_over_M << ", R_i = " << p.R_i
              << ", vol_strain = " << core::name_of(p.material.vol_strain) << "; n_r = " << c.numerics.n_r
              << ", t_end = " << c.numerics.t_end << "\n";

    // 2. Run, with a progress line on long runs; every step is written as it is finished.
    cases::ProgressReporter progress(std::cout, "fdm1d");
    cases::Fdm1dRecorder recorder(out.path(), c.numerics.probe_radii);
    const core::InterruptRequest interrupt;  // Ctrl-C or SIGTERM: stop after the step, keep the results
    const auto result = fdm1d::run_fdm1d(
        p, c.numerics, c.rest, [&](double t, double t_end) { progress.update(t, t_end); },
        [&](const fdm1d::Fdm1dResult& so_far) { recorder.record(so_far); }, [&] { return interrupt.signal() != 0; });
    const auto& s = result.summary;
    char balance[32];
    std::snprintf(balance, sizeof balance, "%.2e", s.max_balance_error);
    progress.finish(std::to_string(s.n_steps) + " steps, " + std::to_string(s.n_factorisations) +
                    " factorisations, max volume-balance error " + balance);
    const bool interrupted = s.status == fdm1d::Fdm1dSummary::Status::interrupted;
    if (!s.is_success() && !interrupted) {
      std::cerr << "hmlattice fdm1d: numerical failure: " << s.message << "\n";
      // An overflow comes from the inputs: bad input (2); a singular matrix is the solver's (1).
      exit_code = s.status == fdm1d::Fdm1dSummary::Status::non_finite ? 2 : 1;
      return;
    }

    // 3. The resolved configuration beside the results, then everything appears at once. An
    //    interrupted run keeps every step it finished, marked incomplete, with status.toml saying
    //    where it stopped (the format of `hmlattice run`).
    recorder.finish(p);
    core::write_file_atomically(out.path() / "config.toml", [&](std::ostream& f) {
      f << cases::fdm1d_case_to_toml(c, cases::to_toml(cases::make_provenance(command_line)));
    });
    if (interrupted) {
      const double t_last = result.borehole.back().t;
      const std::string why = std::string("interrupted by ") + interrupt.signal_name();
      core::write_stopped_status(out.path() / "status.toml", "fdm1d", why, s.n_steps, t_last, c.numerics.t_end,
                                 out.target());
      out.commit(why);
      std::cerr << "hmlattice fdm1d: " << why << "; the " << s.n_steps << " steps done (t = " << t_last << " of "
                << c.numerics.t_end << ") are in " << out.target().string() << ", marked incomplete (status.toml)\n";
      exit_code = interrupt.exit_code();
      return;
    }
    out.commit();
    std::cout << "Results: " << out.target().string() << "/{borehole,profiles,probes,steady_state}.csv, config.toml\n";
  });
}

}  // namespace hm::app
