#pragma once
// Writes the verification report (markdown) and the machine-readable metrics (JSON).
#include <filesystem>
#include <string>
#include <vector>

#include "hm/case/provenance.hpp"
#include "hm/verification/benchmark.hpp"

namespace hm::verification {

/// One benchmark's outcome as the report sees it.
struct BenchmarkOutcome {
  const Benchmark* benchmark = nullptr;
  BenchmarkResult result;
  std::string error;                       ///< non-empty if the benchmark threw
  std::vector<std::string> figure_errors;  ///< one per figure that could not be drawn
  double seconds = 0.0;
};

void write_report_markdown(const std::filesystem::path& file, const std::vector<BenchmarkOutcome>& outcomes,
                           const cases::Provenance& provenance, Tier tier);
void write_metrics_json(const std::filesystem::path& file, const std::vector<BenchmarkOutcome>& outcomes);

/// "3.14e-05"-style formatting used in every report table.
std::string format_number(double value);
/// The benchmarks' short name for format_number, in the prose they build.
inline std::string fmt(double value) { return format_number(value); }

/// A metric that passes when `value` is at most `tolerance` (an error against a reference of 0).
inline Metric at_most_metric(const std::string& name, double value, double tolerance, bool gating,
                             const std::string& why) {
  return {.name = name,
          .value = value,
          .reference = 0.0,
          .tolerance = tolerance,
          .comparison = Comparison::at_most,
          .justification = why,
          .gating = gating};
}

}  // namespace hm::verification
