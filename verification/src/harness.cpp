#include "hm/verification/harness.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <numeric>
#include <omp.h>
#include <streambuf>
#include <string>
#include <string_view>
#include <thread>

#include "benchmark_notes.hpp"
#include "figure_runner.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/result_folder.hpp"
#include "report_writer.hpp"

namespace hm::verification {

using cases::make_provenance;
using cases::Provenance;

namespace fs = std::filesystem;

namespace {

/// A stream whose complete lines go to `log` under `mutex`, each after `prefix`: progress lines of
/// benchmarks that run at the same time, each line whole. No put area: every write reaches xsputn or
/// overflow, so a line goes out as soon as it ends.
class LockedLines : private std::streambuf {
 public:
  LockedLines(std::ostream& log, std::mutex& mutex, std::string prefix)
      : log_(log), mutex_(mutex), prefix_(std::move(prefix)), stream_(this) {}
  LockedLines(const LockedLines&) = delete;
  LockedLines& operator=(const LockedLines&) = delete;
  ~LockedLines() override {
    if (!pending_.empty()) pending_ += '\n';
    emit();
  }
  std::ostream& stream() { return stream_; }

 private:
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    pending_.append(s, static_cast<std::size_t>(n));
    emit();
    return n;
  }
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    xsputn(&ch, 1);
    return c;
  }
  void emit() {  // the complete lines of pending_
    const std::size_t end = pending_.rfind('\n');
    if (end == std::string::npos) return;
    std::lock_guard lock(mutex_);
    for (std::size_t from = 0; from <= end;) {
      const std::size_t to = pending_.find('\n', from) + 1;
      log_ << prefix_ << std::string_view(pending_).substr(from, to - from);
      from = to;
    }
    log_ << std::flush;
    pending_.erase(0, end + 1);
  }
  std::ostream& log_;
  std::mutex& mutex_;
  std::string prefix_;
  std::string pending_;
  std::ostream stream_;
};

/// Runs one benchmark and draws its figures; an exception becomes the outcome's error.
BenchmarkOutcome run_one(const Benchmark& benchmark, Tier tier, const fs::path& data_dir, const fs::path& figure_dir,
                         const fs::path& runs_dir, std::ostream* progress) {
  BenchmarkOutcome o;
  o.benchmark = &benchmark;
  const auto start = std::chrono::steady_clock::now();
  try {
    o.result = benchmark.run(BenchmarkContext{tier, data_dir, progress, runs_dir});
    for (std::string& note : benchmark_notes(benchmark.id)) o.result.notes.push_back(std::move(note));
  } catch (const std::exception& e) {
    o.error = e.what();
  }
  // One folder per benchmark: a quick and a paper benchmark draw files of the same name.
  if (!o.result.figures.empty()) fs::create_directories(figure_dir / benchmark.id);
  for (const auto& f : o.result.figures)
    if (auto why = draw_figure(f, data_dir, figure_dir / benchmark.id); !why.empty()) o.figure_errors.push_back(why);
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return o;
}

int failed_metrics(const BenchmarkOutcome& o) {
  int failed = 0;
  for (const auto& m : o.result.metrics) failed += (m.gating && !m.passes());
  return failed;
}

void log_outcome(const BenchmarkOutcome& o, std::ostream& log) {
  const int failed = failed_metrics(o);
  if (!o.error.empty())
    log << "ERROR: " << o.error << "\n";
  else
    log << (failed ? "FAILED " + std::to_string(failed) + " of " : "ok, ") << o.result.metrics.size() << " metrics ("
        << format_number(o.seconds) << " s)\n";
  for (const auto& e : o.figure_errors) log << "    figure missing: " << e << "\n";
  log << std::flush;
}

}  // namespace

std::vector<const Benchmark*> select_benchmarks(const std::vector<Benchmark>& benchmarks, Tier tier,
                                                const std::string& filter) {
  std::vector<const Benchmark*> selected;
  for (const auto& b : benchmarks)
    if ((tier == Tier::paper || b.tier == Tier::quick) && b.id.find(filter) != std::string::npos)
      selected.push_back(&b);
  if (selected.empty())
    throw InputError("--filter = '" + core::echo(filter) + "' matches no benchmark id of the " + core::name_of(tier) +
                     " tier, allowed: part of an id (" +
                     (benchmarks.empty() ? std::string("none registered") : "e.g. '" + benchmarks.front().id + "'") +
                     ")");
  return selected;
}

HarnessSummary run_harness(const std::vector<Benchmark>& benchmarks, const HarnessOptions& options, std::ostream& log) {
  if (options.jobs < 1) throw InputError("--jobs = " + std::to_string(options.jobs) + ", allowed: an integer >= 1");
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
  // What the figure scripts name in their footers: the data's version, commit and command.
  const Provenance provenance = make_provenance(options.command_line);
  core::write_file_atomically(data_dir / "provenance.toml",
                              [&](std::ostream& os) { os << cases::to_toml(provenance); });

  const std::size_t n = selected.size();
  const int jobs = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(options.jobs), n));
  std::vector<BenchmarkOutcome> outcomes(n);
  std::mutex log_mutex;
  std::atomic<std::size_t> next{0};
  // Several workers take the benchmarks longest first (the longest-processing-time rule: with two
  // workers and right times the last ends within 7/6 of the best order's time); one takes them in
  // report order.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (jobs > 1)
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return selected[a]->quick_seconds > selected[b]->quick_seconds;
    });
  // Each worker takes the next benchmark not yet started. With more than one worker each runs its
  // benchmarks on one OpenMP thread: two workers on two cores then cost no more than one benchmark each
  // (the lattice's threaded loops lose to serial on a taken core), and the benchmarks' own sizes are
  // mostly below the threaded loops' thresholds anyway.
  std::exception_ptr failure;  // the first error outside a benchmark (a folder that cannot be written)
  const auto work = [&] {
    if (jobs > 1) omp_set_num_threads(1);
    try {
      for (std::size_t k; (k = next++) < n;) {
        const std::size_t i = order[k];
        const Benchmark& benchmark = *selected[i];
        const std::string heading = "[" + std::to_string(i + 1) + "/" + std::to_string(n) + "] " + benchmark.id;
        // In the paper tier benchmarks run for minutes to hours (quick ones at paper sizes too): their
        // progress lines go between two headings, each line whole and, with several workers, marked
        // with its benchmark.
        const bool long_running = options.tier == Tier::paper;
        LockedLines progress(log, log_mutex, jobs > 1 ? benchmark.id + ": " : "");
        if (long_running || jobs == 1) {
          std::lock_guard lock(log_mutex);
          log << heading << (long_running ? " ...\n" : " ... ") << std::flush;
        }
        outcomes[i] = run_one(benchmark, options.tier, data_dir, figure_dir, options.runs_dir,
                              long_running ? &progress.stream() : nullptr);
        std::lock_guard lock(log_mutex);
        if (long_running || jobs > 1) log << heading << " ... ";
        log_outcome(outcomes[i], log);
      }
    } catch (...) {
      std::lock_guard lock(log_mutex);
      if (!failure) failure = std::current_exception();
      next = n;  // the others finish what they run and start nothing new
    }
  };
  if (jobs <= 1) {
    work();
  } else {
    std::vector<std::thread> workers;
    for (int w = 0; w < jobs; ++w) workers.emplace_back(work);
    for (auto& w : workers) w.join();
  }
  if (failure) std::rethrow_exception(failure);

  HarnessSummary summary;
  for (const auto& o : outcomes) {
    summary.n_failed += failed_metrics(o);
    summary.n_metrics += static_cast<int>(o.result.metrics.size());
    summary.n_benchmark_errors += !o.error.empty();
    summary.n_missing_figures += static_cast<int>(o.figure_errors.size());
  }
  summary.n_benchmarks = static_cast<int>(outcomes.size());

  write_report_markdown(out.path() / "report.md", outcomes, provenance, options.tier);
  write_metrics_json(out.path() / "metrics.json", outcomes);
  out.commit();
  summary.report = out.target() / "report.md";
  return summary;
}

}  // namespace hm::verification
