#include "hm/verification/harness.hpp"

#include <chrono>
#include <exception>
#include <string>

#include "figure_runner.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/result_folder.hpp"
#include "report_writer.hpp"

namespace hm::verification {

using cases::make_provenance;

namespace fs = std::filesystem;

std::vector<const Benchmark*> select_benchmarks(const std::vector<Benchmark>& benchmarks, Tier tier,
                                                const std::string& filter) {
  std::vector<const Benchmark*> selected;
  for (const auto& b : benchmarks)
    if ((tier == Tier::paper || b.tier == Tier::quick) && b.id.find(filter) != std::string::npos)
      selected.push_back(&b);
  if (selected.empty())
    throw InputError("--filter = '" + core::echo(filter) + "' matches no benchmark id of the " + core::name_of(tier) +
                     " tier, allowed: part of an id (" +
                     (benchmarks.empty() ? std::string("none registered") : "e.g. '" + benchmarks.front().id + "'") + ")");
  return selected;
}

HarnessSummary run_harness(const std::vector<Benchmark>& benchmarks, const HarnessOptions& options,
                           std::ostream& log) {
  const std::vector<const Benchmark*> selected = select_benchmarks(benchmarks, options.tier, options.filter);
  // Run folders made elsewhere (a workflow engine) are checked before anything is written or run.
  if (!options.runs_dir.empty()) {
    const RunFolderCheck check = check_run_folders(selected, options.runs_dir);
    log << "--runs " << options.runs_dir.string() << ": " << check.found << " of the " << check.planned
        << " planned runs found there (complete, same case), " << check.planned - check.found << " to run here\n";
  }

  core::ResultFolder out(options.out_dir, "--out", options.overwrite, options.command_line);
  const fs::path data_dir = out.path() / "data", figure_dir = out.path() / "figures";
  fs::create_directories(data_dir);
  fs::create_directories(figure_dir);

  HarnessSummary summary;
  std::vector<BenchmarkOutcome> outcomes;
  for (std::size_t i = 0; i < selected.size(); ++i) {
    BenchmarkOutcome o;
    o.benchmark = selected[i];
    // Paper-tier benchmarks run for minutes to hours: their progress lines go between two headings.
    const std::string heading = "[" + std::to_string(i + 1) + "/" + std::to_string(selected.size()) + "] " + o.benchmark->id;
    const bool long_running = o.benchmark->tier == Tier::paper;
    log << heading << (long_running ? " ...\n" : " ... ") << std::flush;
    const auto start = std::chrono::steady_clock::now();
    try {
      o.result = o.benchmark->run(BenchmarkContext{options.tier, data_dir, long_running ? &log : nullptr, options.runs_dir});
    } catch (const std::exception& e) {
      o.error = e.what();
    }
    // One folder per benchmark: a quick and a paper benchmark draw files of the same name.
    if (!o.result.figures.empty()) fs::create_directories(figure_dir / o.benchmark->id);
    for (const auto& f : o.result.figures)
      if (auto why = draw_figure(f, data_dir, figure_dir / o.benchmark->id); !why.empty())
        o.figure_errors.push_back(why);
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    int failed = 0;
    for (const auto& m : o.result.metrics) failed += (m.gating && !m.passes());
    summary.n_metrics += static_cast<int>(o.result.metrics.size());
    summary.n_failed += failed;
    summary.n_benchmark_errors += !o.error.empty();
    summary.n_missing_figures += static_cast<int>(o.figure_errors.size());
    if (long_running) log << heading << " ... ";
    if (!o.error.empty())
      log << "ERROR: " << o.error << "\n";
    else
      log << (failed ? "FAILED " + std::to_string(failed) + " of " : "ok, ")
          << o.result.metrics.size() << " metrics (" << format_number(o.seconds) << " s)\n";
    for (const auto& e : o.figure_errors) log << "    figure missing: " << e << "\n";
    outcomes.push_back(std::move(o));
  }
  summary.n_benchmarks = static_cast<int>(outcomes.size());

  write_report_markdown(out.path() / "report.md", outcomes, make_provenance(options.command_line), options.tier);
  write_metrics_json(out.path() / "metrics.json", outcomes);
  out.commit();
  summary.report = out.target() / "report.md";
  return summary;
}

}  // namespace hm::verification
