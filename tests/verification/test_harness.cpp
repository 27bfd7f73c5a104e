// The harness judges metrics as documented, writes report.md and metrics.json, records a
// benchmark that throws as an error, and leaves no output folder behind when it is interrupted.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <omp.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "hm/verification/harness.hpp"
#include "run_command.hpp"

using namespace hm::verification;
using hm::test::slurp;
using hm::test::TempDir;

namespace {
Metric metric(double value, double reference, double tolerance, Comparison how = Comparison::abs_error,
              bool gating = true) {
  Metric m;
  m.name = "metric";
  m.value = value;
  m.reference = reference;
  m.tolerance = tolerance;
  m.comparison = how;
  m.justification = "round-off";
  m.gating = gating;
  return m;
}
}  // namespace

TEST_CASE("Metrics pass or fail exactly at their tolerance", "[verification][harness]") {
  CHECK(metric(1.05, 1.0, 0.1).passes());
  CHECK_FALSE(metric(1.2, 1.0, 0.1).passes());
  CHECK(metric(2.1, 2.0, 0.06, Comparison::rel_error).passes());
  CHECK_FALSE(metric(2.2, 2.0, 0.06, Comparison::rel_error).passes());
  CHECK(metric(1e-9, 0.0, 1e-8, Comparison::at_most).passes());
  CHECK_FALSE(metric(1e-7, 0.0, 1e-8, Comparison::at_most).passes());
  CHECK(metric(1.95, 0.0, 1.8, Comparison::at_least).passes());
  CHECK_FALSE(metric(1.5, 0.0, 1.8, Comparison::at_least).passes());
  CHECK_FALSE(metric(std::nan(""), 0.0, 1.0, Comparison::at_most).passes());
}

TEST_CASE("The harness writes report and metrics, and a failing gating metric fails the run",
          "[verification][harness]") {
  TempDir dir("harness");
  std::vector<Benchmark> benchmarks = {
      {"demo.good", "Good", "passes", Tier::quick,
       [](const BenchmarkContext&) {
         BenchmarkResult r;
         r.metrics.push_back(metric(1e-9, 0.0, 1e-6, Comparison::at_most));
         r.metrics.push_back(metric(0.3, 0.22, 0.01, Comparison::abs_error, false));
         return r;
       }},
      {"demo.bad", "Bad", "fails", Tier::quick,
       [](const BenchmarkContext&) {
         BenchmarkResult r;
         r.metrics.push_back(metric(1.0, 0.0, 1e-6, Comparison::at_most));
         return r;
       }},
      {"demo.throws", "Throws", "errors", Tier::quick,
       [](const BenchmarkContext&) -> BenchmarkResult { throw std::runtime_error("solver diverged"); }},
      {"demo.paper", "Paper only", "skipped in quick", Tier::paper,
       [](const BenchmarkContext&) -> BenchmarkResult { throw std::logic_error("must not run in quick tier"); }},
  };
  HarnessOptions options;
  options.out_dir = dir.path / "report";
  std::ostringstream log;
  const HarnessSummary s = run_harness(benchmarks, options, log);
  CHECK(s.n_benchmarks == 3);
  CHECK(s.n_metrics == 3);
  CHECK(s.n_failed == 1);  // the non-gating paper value differs but does not count
  CHECK(s.n_benchmark_errors == 1);
  CHECK_FALSE(s.ok());

  const auto json = nlohmann::json::parse(slurp(options.out_dir / "metrics.json"));
  REQUIRE(json.size() == 4);  // 3 metrics + 1 error record
  CHECK(json[0]["benchmark"] == "demo.good");
  CHECK(json[0]["pass"] == true);
  CHECK(json[1]["gating"] == false);
  CHECK(json[2]["pass"] == false);
  CHECK(json[3]["error"] == "solver diverged");

  const std::string md = slurp(options.out_dir / "report.md");
  CHECK_THAT(md, Catch::Contains("| metric | 1.000e-09 | — | ≤ 1.000e-06 | pass | round-off |"));
  CHECK_THAT(md, Catch::Contains("differs (info)"));
  CHECK_THAT(md, Catch::Contains("**The benchmark stopped with an error:** solver diverged"));
}

TEST_CASE("In the paper tier every benchmark prints progress between two headings, in the quick tier none",
          "[verification][harness]") {
  TempDir dir("harness_progress");
  int quick_streams = 0;
  std::vector<Benchmark> benchmarks = {
      {"demo.quick", "Quick", "", Tier::quick,
       [&](const BenchmarkContext& ctx) {
         // A quick benchmark runs its paper sizes in the paper tier: it may take as long.
         quick_streams += ctx.progress != nullptr;
         if (ctx.progress) *ctx.progress << "[run] larger\n";
         return BenchmarkResult{};
       }},
      {"demo.long", "Long", "", Tier::paper,
       [](const BenchmarkContext& ctx) {
         REQUIRE(ctx.progress != nullptr);
         *ctx.progress << "[run] half way\n";
         return BenchmarkResult{};
       }},
  };
  HarnessOptions options;
  options.tier = Tier::paper;
  options.out_dir = dir.path / "report";
  std::ostringstream log;
  REQUIRE(run_harness(benchmarks, options, log).ok());
  CHECK(quick_streams == 1);
  CHECK_THAT(log.str(), Catch::StartsWith("[1/2] demo.quick ...\n[run] larger\n[1/2] demo.quick ... ok, 0 metrics ("));
  CHECK_THAT(log.str(), Catch::Contains("[2/2] demo.long ...\n[run] half way\n[2/2] demo.long ... ok, 0 metrics ("));

  options.tier = Tier::quick;
  options.out_dir = dir.path / "quick";
  std::ostringstream quick_log;
  REQUIRE(run_harness(benchmarks, options, quick_log).ok());
  CHECK(quick_streams == 1);  // no stream in the quick tier
  CHECK_THAT(quick_log.str(), Catch::StartsWith("[1/1] demo.quick ... ok, 0 metrics ("));
}

TEST_CASE("Figures of the same file name from two benchmarks go to separate folders", "[verification][harness]") {
  // The quick and the paper Fig. 12 benchmarks both draw fig12_fracture_pressure.png: one shared
  // folder let the second overwrite the first, and the report showed the same picture twice.
  TempDir dir("harness_figures");
  auto with_figure = [](const BenchmarkContext&) {
    BenchmarkResult r;
    r.figures.push_back({"no_such_script.py", "same.png", "caption", ""});
    return r;
  };
  std::vector<Benchmark> benchmarks = {{"demo.quick", "Quick", "", Tier::quick, with_figure},
                                       {"demo.paper", "Paper", "", Tier::paper, with_figure}};
  HarnessOptions options;
  options.tier = Tier::paper;
  options.out_dir = dir.path / "report";
  std::ostringstream log;
  const auto summary = run_harness(benchmarks, options, log);
  CHECK(summary.n_missing_figures == 2);  // the script does not exist: reported, not hidden
  const std::string md = slurp(options.out_dir / "report.md");
  CHECK_THAT(md, Catch::Contains("](figures/demo.quick/same.png)"));
  CHECK_THAT(md, Catch::Contains("](figures/demo.paper/same.png)"));
  CHECK(std::filesystem::is_directory(options.out_dir / "figures" / "demo.quick"));
  CHECK(std::filesystem::is_directory(options.out_dir / "figures" / "demo.paper"));
}

TEST_CASE("Every result figure of the paper is drawn by a registered benchmark, each declared figure is the paper's",
          "[verification][harness]") {
  std::set<std::string> declared, papers;
  for (const PaperFigure& f : paper_result_figures()) papers.insert(f.number);
  CHECK(papers.size() == 14);  // Figs. 7, 8, 10-20 and C2
  for (const Benchmark& b : all_benchmarks())
    for (const std::string& f : b.paper_figures) {
      INFO(b.id << " declares Fig. " << f);
      CHECK(papers.count(f) == 1);
      declared.insert(f);
    }
  for (const std::string& f : papers) {
    INFO("Fig. " << f);
    CHECK(declared.count(f) == 1);
  }
}

TEST_CASE("Two workers start the longest benchmarks first, one worker takes them in report order",
          "[verification][harness]") {
  TempDir dir("harness_order");
  std::mutex mutex;
  std::vector<int> started;
  std::atomic<int> n_started{0};
  const std::array<double, 4> seconds{0.0, 5.0, 0.0, 9.0};
  std::vector<Benchmark> benchmarks;
  for (int id = 0; id < 4; ++id) {
    benchmarks.push_back({"demo.b" + std::to_string(id), "B", "", Tier::quick, [&, id](const BenchmarkContext&) {
                            {
                              std::lock_guard lock(mutex);
                              started.push_back(id);
                            }
                            ++n_started;
                            // The long ones hold their worker until both workers have started one (at most
                            // 20 s), so that the first two starts are the two workers' first picks.
                            for (int i = 0; i < 2000 && seconds[id] > 0.0 && n_started < 2; ++i)
                              std::this_thread::sleep_for(std::chrono::milliseconds(10));
                            BenchmarkResult r;
                            r.metrics.push_back(metric(0.1 * id, 0.0, 1.0));
                            return r;
                          }});
    benchmarks.back().quick_seconds = seconds[id];
  }
  HarnessOptions options;
  options.jobs = 2;
  options.out_dir = dir.path / "two";
  std::ostringstream log;
  REQUIRE(run_harness(benchmarks, options, log).ok());
  REQUIRE(started.size() == 4);
  CHECK(std::set<int>{started[0], started[1]} == std::set<int>{1, 3});
  started.clear();
  n_started = 0;
  options.jobs = 1;
  options.out_dir = dir.path / "one";
  std::ostringstream serial_log;
  REQUIRE(run_harness(benchmarks, options, serial_log).ok());
  CHECK(started == std::vector<int>{0, 1, 2, 3});
  // The report is in registration order either way.
  CHECK(slurp(dir.path / "two" / "metrics.json") == slurp(dir.path / "one" / "metrics.json"));
}

TEST_CASE("Benchmarks run side by side write the report of one after the other, each on one thread",
          "[verification][harness]") {
  TempDir dir("harness_jobs");
  // The first benchmark waits (at most 20 s) for the second to start: with two workers they overlap.
  std::atomic<bool> second_started{false}, overlapped{false};
  std::atomic<int> threads_seen{0};
  const auto body = [&](int id, const BenchmarkContext& ctx) {
    if (id == 1) second_started = true;
    if (id == 0)
      for (int i = 0; i < 2000 && !(overlapped = second_started.load()); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    threads_seen = std::max(threads_seen.load(), omp_get_max_threads());
    // Progress written in pieces: each line must reach the log whole, marked with its benchmark.
    *ctx.progress << "[run] benchmark " << id << " at ";
    *ctx.progress << "half way\n";
    BenchmarkResult r;
    r.metrics.push_back(metric(0.1 * id, 0.0, 1.0));
    return r;
  };
  std::vector<Benchmark> benchmarks;
  for (int id = 0; id < 3; ++id)
    benchmarks.push_back({"demo.b" + std::to_string(id), "B", "", Tier::paper,
                          [&, id](const BenchmarkContext& ctx) { return body(id, ctx); }});
  HarnessOptions options;
  options.tier = Tier::paper;
  options.jobs = 2;
  options.out_dir = dir.path / "side_by_side";
  std::ostringstream log;
  REQUIRE(run_harness(benchmarks, options, log).ok());
  CHECK(overlapped);
  CHECK(threads_seen == 1);
  for (int id = 0; id < 3; ++id)
    CHECK_THAT(log.str(), Catch::Contains("demo.b" + std::to_string(id) + ": [run] benchmark " + std::to_string(id) +
                                          " at half way\n"));

  options.jobs = 1;
  options.out_dir = dir.path / "one_after_the_other";
  second_started = false;
  std::ostringstream serial_log;
  std::thread release([&] {  // the serial run's first benchmark must not wait 20 s for the second
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    second_started = true;
  });
  REQUIRE(run_harness(benchmarks, options, serial_log).ok());
  release.join();
  CHECK(slurp(dir.path / "side_by_side" / "metrics.json") == slurp(dir.path / "one_after_the_other" / "metrics.json"));

  options.jobs = 0;
  options.out_dir = dir.path / "none";
  CHECK_THROWS_WITH(run_harness(benchmarks, options, serial_log), "--jobs = 0, allowed: an integer >= 1");
  CHECK_FALSE(std::filesystem::exists(options.out_dir));
}
