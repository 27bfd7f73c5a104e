#pragma once
/// \file
/// The verification harness's vocabulary: a benchmark is a small descriptor (what is compared with
/// what, how, and why the tolerance is what it is) plus a function that runs it and returns metrics.
#include <array>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "hm/case/run_case.hpp"
#include "hm/core/enum_names.hpp"

namespace hm::verification {

/// quick: seconds, runs in CI on every change. paper: paper resolution, runs on request.
enum class Tier { quick, paper };
constexpr auto enum_names(Tier) { return core::enum_table<Tier>({{Tier::quick, "quick"}, {Tier::paper, "paper"}}); }

/// How a metric's value is judged against its reference and tolerance.
enum class Comparison {
  abs_error,  ///< |value - reference| <= tolerance
  rel_error,  ///< |value - reference| <= tolerance * |reference|
  at_most,    ///< value <= tolerance (reference shown for context, e.g. an error norm)
  at_least,   ///< value >= tolerance (e.g. an observed convergence order floor)
};

/// One checked number. `gating` metrics decide the exit code of `hmlattice verify`; non-gating ones
/// (e.g. the paper's own reading of its figures) are reported beside the paper's value but never
/// fail the run, so nothing is tuned to hit them.
struct Metric {
  std::string name;        ///< what is measured, e.g. "max |p - p_B3| / p_h"
  double value = 0.0;      ///< what the toolkit computed
  double reference = 0.0;  ///< what it is compared with (analytic, 1D, paper)
  double tolerance = 0.0;  ///< see Comparison
  Comparison comparison = Comparison::abs_error;
  std::string justification;  ///< where the tolerance comes from
  bool gating = true;

  bool passes() const;
};

/// A free-form table for the report (convergence table, paper-vs-toolkit table).
struct Table {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

/// A figure drawn by figures/<script> from CSV files the benchmark wrote into the data folder.
/// The script is called as: python3 figures/<script> --data <data_dir>/<data_subdir> --out <figure_dir>,
/// and must write <figure_dir>/<file> (PNG; PDF beside it).
struct Figure {
  std::string script;  ///< e.g. "verify_borehole_steady.py"
  std::string file;    ///< e.g. "verify_borehole_steady.png"
  std::string caption;
  std::string data_subdir = "";  ///< e.g. a run folder written like `hmlattice fdm1d` writes it
};

struct BenchmarkResult {
  std::vector<Metric> metrics;
  std::vector<Table> tables;
  std::vector<Figure> figures;
  std::vector<std::string> notes;  ///< one paragraph each, markdown
};

/// What a benchmark may use while it runs.
struct BenchmarkContext {
  Tier tier = Tier::quick;
  std::filesystem::path data_dir;  ///< write CSV for figures here (exists)
  /// In the paper tier every benchmark (a quick one runs its paper sizes there) may print progress lines
  /// of its long runs here; null in the quick tier.
  std::ostream* progress = nullptr;
  /// `hmlattice verify --runs DIR`: a planned run (Benchmark::planned_runs) whose folder DIR/<label>
  /// exists is read from there instead of run (the harness has checked that it is complete and of the
  /// same case); empty: every run is run here.
  std::filesystem::path runs_dir;
};

/// One run of a case file a benchmark makes: what `hmlattice run` would run into a folder <label>.
struct PlannedRun {
  std::string label;  ///< file-name safe, unique over every benchmark of both tiers
  cases::RunCase c;
};

struct Benchmark {
  std::string id;           ///< short, unique, file-name safe: "analytic.steady_borehole"
  std::string title;        ///< heading in the report
  std::string description;  ///< what is compared with what (markdown)
  /// quick benchmarks run in both tiers; paper benchmarks only in the paper tier.
  Tier tier = Tier::quick;
  std::function<BenchmarkResult(const BenchmarkContext&)> run;
  /// The runs of case files it makes (empty for a benchmark that runs nothing of the kind): what
  /// `hmlattice verify --write-cases` writes for a workflow engine, and what `--runs` may read back.
  std::function<std::vector<PlannedRun>()> planned_runs = {};
  /// The paper's result figures it draws ("7", "15", "C2"): the report's list of every figure and the
  /// benchmarks that regenerate it.
  std::vector<std::string> paper_figures = {};
  /// Roughly how long its quick tier takes on one core, in seconds (0: a few at most). Several workers
  /// start the longest first, so that a long benchmark does not start last and run on alone.
  double quick_seconds = 0.0;
};

/// One of the paper's result figures: its number ("7", "C2") and what it shows.
struct PaperFigure {
  std::string number, subject;
};
/// The paper's 14 result figures, in its order (Benchmark::paper_figures names them by number).
const std::vector<PaperFigure>& paper_result_figures();

/// Every registered benchmark, in report order. Each module's benchmarks are added by one
/// function (add_analytic_benchmarks, ...), listed in registry.cpp: adding one is a few lines.
const std::vector<Benchmark>& all_benchmarks();

void add_analytic_benchmarks(std::vector<Benchmark>& into);
void add_fdm1d_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_elastic_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_fracture_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_propagation_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_kgd_transition_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_fracture_energy_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_coupled_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_vs_fdm1d_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_borehole_fracture_benchmarks(std::vector<Benchmark>& into);
void add_lattice2d_paper_figure_benchmarks(std::vector<Benchmark>& into);
void add_insitu_benchmarks(std::vector<Benchmark>& into);
void add_breakdown_benchmarks(std::vector<Benchmark>& into);

}  // namespace hm::verification
