// hmlattice — command-line front end of the toolkit (Ulven & Sun 2017).
//
//   hmlattice verify [--tier quick|paper] [--out DIR]     run the verification suite, write a report
//   hmlattice fdm1d cases/fig10_fdm1d_b0.5.toml [--out DIR]   the radial 1D model (Appendix A)
//   hmlattice run cases/fig07_rudnicki_free.toml [--out DIR]   the coupled 2D lattice (Sections 2.1-2.3)
//   hmlattice fractures out/fig12_b0.2 [--link triangle]   recompute a run's fracture statistics
//   hmlattice analytic rudnicki --Q 0.1 --b 0.5 --t 3e-4 --r 0.01,0.02   closed forms as CSV
//   hmlattice sweep expand cases/sweep_fig18_quick.toml --out DIR   one case per combination of [sweep]
//   hmlattice sweep collect DIR --runs RUNS              the runs' results as one CSV
//   hmlattice case-format                                 the case-file reference (docs/case-format.md)
//
// Exit codes: 0 success; 1 a verification check failed; 2 bad input (one line on stderr naming the
// parameter, the value and what is allowed; nothing is written).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>
#include <string>

#include "commands.hpp"
#include "hm/case/blas_threads.hpp"
#include "hm/case/provenance.hpp"
#include "hm/core/input_error.hpp"

namespace {

std::string joined(int argc, char** argv) {
  std::string s;
  for (int i = 0; i < argc; ++i) s += (i ? " " : "") + std::string(argv[i]);
  return s;
}

// CLI11 reads an empty value as 0 for a number: "--Q ''" would run with Q = 0. Every option that
// takes a value refuses an empty one.
void reject_empty_values(CLI::App& app) {
  for (CLI::Option* opt : app.get_options())
    if (opt->get_type_size_max() > 0)
      opt->check(CLI::Validator(
          [](std::string& value) {
            return value.empty() ? std::string("'' (empty), allowed: a value") : std::string();
          },
          "", "non-empty"));
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) reject_empty_values(*sub);
}

// OpenMP's threads wait for their next parallel region asleep, not spinning: a spinning thread takes
// a core from the one doing the serial work between regions, and when another process holds the
// other core the default (spinning) threads ran a Fig. 12 case 1.4-2x slower than one thread; asleep,
// never slower, and as fast on an idle machine (docs/performance.md). libgomp reads OMP_WAIT_POLICY
// once, when it is loaded before main, so the program starts itself again with it set. A user's
// own OMP_WAIT_POLICY is kept; if the restart fails the run goes on with the default.
void restart_with_passive_openmp_waits(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
  if (::setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  ::execv("/proc/self/exe", argv);
}

}  // namespace

int main(int argc, char** argv) {
  restart_with_passive_openmp_waits(argv);
  hm::cases::limit_blas_threads();  // before any factorisation: see blas_threads.hpp
  CLI::App app{"hmlattice: fluid-driven fracture in porous rock, verified (Ulven & Sun 2017)", "hmlattice"};
  app.require_subcommand(1);
  const hm::cases::Provenance build = hm::cases::make_provenance("");
  app.set_version_flag("--version",
                       build.version + " (commit " + build.git_commit + ", " + build.build_type + " build)");
  int exit_code = 0;
  hm::app::add_verify_command(app, exit_code, joined(argc, argv));
  hm::app::add_fdm1d_command(app, exit_code, joined(argc, argv));
  hm::app::add_run_command(app, exit_code, joined(argc, argv));
  hm::app::add_fractures_command(app, joined(argc, argv));
  hm::app::add_analytic_command(app, exit_code);
  hm::app::add_case_format_command(app);
  hm::app::add_sweep_command(app, exit_code, joined(argc, argv));
  reject_empty_values(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    if (argc > 1 && argv[1][0] != '-') {
      std::string allowed;
      bool known = false;
      for (const auto* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        allowed += (allowed.empty() ? "" : ", ") + sub->get_name();
        known = known || sub->get_name() == argv[1];
      }
      if (!known) what = std::string("unknown subcommand '") + argv[1] + "', allowed: " + allowed;
    }
    std::cerr << "hmlattice: " << hm::core::one_line(what, 500) << " (see hmlattice --help)\n";
    return 2;
  } catch (const hm::InputError& e) {
    std::cerr << "hmlattice: " << hm::core::one_line(e.what(), 500) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "hmlattice: error: " << hm::core::one_line(e.what(), 500) << "\n";
    return 1;
  }
  return exit_code;
}
