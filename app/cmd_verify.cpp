// hmlattice verify: run every registered benchmark and write report.md + metrics.json.
#include <iostream>

#include "commands.hpp"
#include "hm/verification/benchmark.hpp"
#include "hm/verification/harness.hpp"

namespace hm::app {

void add_verify_command(CLI::App& app, int& exit_code, const std::string& command_line) {
  auto* cmd = app.add_subcommand("verify", "Run the verification suite and write DIR/report.md, DIR/metrics.json");
  struct Options {
    std::string tier = "quick", out = "out/verify", filter;
    bool overwrite = false;
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("--tier", opt->tier, "quick (minutes, run by the tests) or paper (paper resolution)")
      ->capture_default_str();
  cmd->add_option("--out", opt->out,
                  "output folder: a new or empty folder, or an earlier report with --overwrite")
      ->capture_default_str();
  cmd->add_flag("--overwrite", opt->overwrite, "replace the output folder if it holds an earlier hmlattice result");
  cmd->add_option("--filter", opt->filter, "run only benchmarks whose id contains this text");
  cmd->callback([opt, &exit_code, command_line] {
    verification::HarnessOptions options;
    options.tier = core::from_name<verification::Tier>(opt->tier, "--tier");
    options.out_dir = opt->out;
    options.overwrite = opt->overwrite;
    options.filter = opt->filter;
    options.command_line = command_line;
    const auto summary = verification::run_harness(verification::all_benchmarks(), options, std::cout);
    std::cout << "\n" << summary.n_benchmarks << " benchmarks, " << summary.n_metrics << " metrics: "
              << summary.n_failed << " failed, " << summary.n_benchmark_errors << " errors, "
              << summary.n_missing_figures << " figures missing\n"
              << "Report: " << summary.report.string() << "\n";
    exit_code = summary.ok() ? 0 : 1;
  });
}

}  // namespace hm::app
