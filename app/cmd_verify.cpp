// hmlattice verify: run every registered benchmark and write report.md + metrics.json.
//   hmlattice verify --tier quick --out out/verify
// The runs of case files a benchmark makes (lattice2d.fig12*) can be made elsewhere, e.g. by the
// Snakemake workflow on a cluster (docs/cluster.md), and read back:
//   hmlattice verify --tier paper --write-cases out/verify_cases    # <label>.toml + index.csv; runs nothing
//   hmlattice run out/verify_cases/<label>.toml --out out/verify_runs/<label>     # each, anywhere
//   hmlattice verify --tier paper --runs out/verify_runs --out out/verify_paper
// With --runs, a planned run whose folder is there is read (refused, exit 2, if it is not complete or
// holds another case); one that is not there is run here as without --runs.
#include <algorithm>
#include <iostream>
#include <thread>

#include "commands.hpp"
#include "hm/verification/benchmark.hpp"
#include "hm/verification/harness.hpp"

namespace hm::app {

void add_verify_command(CLI::App& app, int& exit_code, const std::string& command_line) {
  auto* cmd = app.add_subcommand("verify", "Run the verification suite and write DIR/report.md, DIR/metrics.json");
  struct Options {
    std::string tier = "quick", out = "out/verify", filter, runs, write_cases;
    bool overwrite = false, list = false;
    int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  };
  auto opt = std::make_shared<Options>();
  cmd->add_option("--tier", opt->tier, "quick (minutes, run by the tests) or paper (paper resolution)")
      ->capture_default_str();
  cmd->add_option("--out", opt->out, "output folder: a new or empty folder, or an earlier report with --overwrite")
      ->capture_default_str();
  cmd->add_flag("--overwrite", opt->overwrite, "replace the output folder if it holds an earlier hmlattice result");
  cmd->add_option("--jobs", opt->jobs,
                  "benchmarks run at the same time, each on one thread (default: one per core; 1: one after the "
                  "other, threaded)")
      ->capture_default_str();
  cmd->add_option("--filter", opt->filter, "run only benchmarks whose id contains this text");
  auto* runs = cmd->add_option("--runs", opt->runs,
                               "read the benchmarks' runs of case files from DIR/<label>/ where present (hmlattice run "
                               "folders, e.g. the workflow's); absent ones are run here");
  cmd->add_option("--write-cases", opt->write_cases,
                  "write the benchmarks' runs of case files as DIR/<label>.toml and DIR/index.csv, run nothing "
                  "(with --overwrite: replace an earlier such folder)")
      ->excludes(runs)
      ->excludes("--out");
  cmd->add_flag("--list", opt->list,
                "print the benchmarks of the tier (with --filter: those selected) and what each checks; run nothing")
      ->excludes(runs)
      ->excludes("--write-cases")
      ->excludes("--out")
      ->excludes("--overwrite");
  cmd->callback([opt, &exit_code, command_line] {
    const auto tier = core::from_name<verification::Tier>(opt->tier, "--tier");
    if (opt->list) {
      const auto selected = verification::select_benchmarks(verification::all_benchmarks(), tier, opt->filter);
      for (const verification::Benchmark* b : selected) {
        std::cout << b->id << " (" << core::name_of(b->tier) << " tier";
        for (std::size_t k = 0; k < b->paper_figures.size(); ++k)
          std::cout << (k == 0 ? "; the paper's Fig. " : ", ") << b->paper_figures[k];
        std::cout << "): " << b->title << "\n    " << b->description << "\n";
      }
      std::cout << selected.size() << " benchmarks in the " << opt->tier << " tier"
                << (opt->filter.empty() ? "" : " whose id contains '" + opt->filter + "'") << "\n";
      return;
    }
    if (!opt->write_cases.empty()) {
      const auto selected = verification::select_benchmarks(verification::all_benchmarks(), tier, opt->filter);
      const int n = verification::write_planned_cases(selected, opt->write_cases, opt->overwrite, command_line);
      std::cout << n << " cases of the " << opt->tier << " tier's runs written to " << opt->write_cases
                << "/ (index.csv: name, benchmark); run each with hmlattice run <case> --out <runs>/<name>, then "
                << "hmlattice verify --tier " << opt->tier << " --runs <runs>\n";
      return;
    }
    verification::HarnessOptions options;
    options.tier = tier;
    options.runs_dir = opt->runs;
    options.out_dir = opt->out;
    options.overwrite = opt->overwrite;
    options.filter = opt->filter;
    options.jobs = opt->jobs;
    options.command_line = command_line;
    const auto summary = verification::run_harness(verification::all_benchmarks(), options, std::cout);
    std::cout << "\n"
              << summary.n_benchmarks << " benchmarks, " << summary.n_metrics << " metrics: " << summary.n_failed
              << " failed, " << summary.n_benchmark_errors << " errors, " << summary.n_missing_figures
              << " figures missing\n"
              << "Report: " << summary.report.string() << "\n";
    exit_code = summary.ok() ? 0 : 1;
  });
}

}  // namespace hm::app
