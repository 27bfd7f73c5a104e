#pragma once
/// \file
/// Runs benchmarks, draws their figures and writes report.md and metrics.json.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "hm/verification/benchmark.hpp"

namespace hm::verification {

struct HarnessOptions {
  Tier tier = Tier::quick;
  /// A new or empty folder, or (with overwrite) an earlier result folder (hm/core/result_folder.hpp).
  std::filesystem::path out_dir = "out/verify";
  bool overwrite = false;
  std::string command_line;  ///< recorded in the report for provenance
  /// Only benchmarks whose id contains this text (empty: all).
  std::string filter;
  /// Read the planned runs found here instead of running them (BenchmarkContext::runs_dir); empty: none.
  std::filesystem::path runs_dir;
  /// Benchmarks run at the same time, each on one OpenMP thread when more than one (1: one after the
  /// other with the default threads). The report is the same in either case, in the benchmarks' order.
  int jobs = 1;
};

struct HarnessSummary {
  int n_benchmarks = 0;
  int n_metrics = 0;
  int n_failed = 0;            ///< gating metrics that failed
  int n_benchmark_errors = 0;  ///< benchmarks that threw
  int n_missing_figures = 0;
  std::filesystem::path report;
  bool ok() const { return n_failed == 0 && n_benchmark_errors == 0; }
};

/// The benchmarks of `tier` (quick ones run in both tiers) whose id contains `filter`, in order.
/// Throws hm::InputError if none: a filter that selects nothing is a typo, not an empty report.
std::vector<const Benchmark*> select_benchmarks(const std::vector<Benchmark>& benchmarks, Tier tier,
                                                const std::string& filter);

/// Checks every planned run of `selected` against `runs_dir` before anything runs: `runs_dir` must be
/// a folder; a run folder runs_dir/<label> that exists must be complete (cases::run_folder_status) and
/// hold the planned case (its config.toml, provenance aside). Throws hm::InputError with one line
/// naming the folder (and the first differing key) otherwise. Absent ones are run by their benchmark
/// as without --runs.
struct RunFolderCheck {
  int planned = 0;  ///< planned runs of the selected benchmarks
  int found = 0;    ///< of them in runs_dir, complete and of the same case
};
RunFolderCheck check_run_folders(const std::vector<const Benchmark*>& selected, const std::filesystem::path& runs_dir);

/// `hmlattice verify --write-cases DIR`: writes the planned runs of `selected` as case files
/// DIR/<label>.toml (the resolved case, rerunnable with `hmlattice run`) and DIR/index.csv (name,
/// benchmark; the names a workflow runs into <runs>/<name>/), as a result folder
/// (hm/core/result_folder.hpp). Returns the number of cases.
int write_planned_cases(const std::vector<const Benchmark*>& selected, const std::filesystem::path& dir, bool overwrite,
                        const std::string& command_line);

/// Runs the selected benchmarks (progress on `log`), then their figure scripts, then writes
/// out_dir/report.md and out_dir/metrics.json. The output folder appears (or replaces an earlier
/// result) only when the run completes, so a crashed run leaves no half-written report; a refused
/// out_dir throws hm::InputError before any benchmark runs.
HarnessSummary run_harness(const std::vector<Benchmark>& benchmarks, const HarnessOptions& options, std::ostream& log);

}  // namespace hm::verification
