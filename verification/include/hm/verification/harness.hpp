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
};

struct HarnessSummary {
  int n_benchmarks = 0;
  int n_metrics = 0;
  int n_failed = 0;           ///< gating metrics that failed
  int n_benchmark_errors = 0; ///< benchmarks that threw
  int n_missing_figures = 0;
  std::filesystem::path report;
  bool ok() const { return n_failed == 0 && n_benchmark_errors == 0; }
};

/// Runs the selected benchmarks (progress on `log`), then their figure scripts, then writes
/// out_dir/report.md and out_dir/metrics.json. The output folder appears (or replaces an earlier
/// result) only when the run completes, so a crashed run leaves no half-written report; a refused
/// out_dir throws hm::InputError before any benchmark runs.
HarnessSummary run_harness(const std::vector<Benchmark>& benchmarks, const HarnessOptions& options,
                           std::ostream& log);


}  // namespace hm::verification
