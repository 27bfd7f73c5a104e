// The paper's other fracture figures, each beside what the paper says of it (paper_readings.hpp):
//   Figs. 14-15  Q = 0.01, iota = 1e3 (fast flow in the fractures), b = 0.2 and 0.8
//   Fig. 16      Q = 1, iota = 1e3 (high injection rate)
//   Fig. 17      Q = 1, iota = 1e6 (tight rock)
//   Figs. 19-20  b = 0.5, Q = 0.01, iota = 1 at t* = 2.5e-2 on lattices of six resolutions
// Each is a spec file in verification/specs/ (figure_specs.hpp): the paper's readings, the titles, the
// plots and the seed scatter; the runners here are the two kinds of benchmark a spec can ask for. The
// cases are read from cases/ (quick tier, <fig>_b<b>_quick.toml, the quick sweep's resolutions) and
// cases/paper/ (paper tier: N = 1e5 and the spec's seed scatter; the paper sweep), so the harness runs
// what `hmlattice run` runs. Each run goes through the
// Fig. 12 machinery (borehole_fracture_runs.hpp): its folder is written as `hmlattice run` writes it and
// its numbers are read back from there, so a folder a workflow made gives the same report.
//
// What gates (whatever the resolution): every run completes, the volume balance holds to round-off, the
// first break is tensile and at the borehole wall, a radial fracture forms, broken beams never heal.
// What the paper says (counts, which fractures reach r = 1, where secondary fractures form, the sign of
// the pressure in the fractures, backflow into the borehole or the domain, the borehole pressure drop,
// Fig. 15's and Fig. 20's displacements) is shown beside ours and never gates: nothing is tuned to it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "borehole_fracture_report.hpp"
#include "borehole_fracture_runs.hpp"
#include "figure_specs.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/sweep.hpp"
#include "hm/verification/benchmark.hpp"
#include "paper_readings.hpp"
#include "report_writer.hpp"

namespace hm::verification {

using cases::read_run_case;
using cases::RunCase;

namespace {

using namespace borehole_fracture;
namespace fs = std::filesystem;

const fs::path kCases = fs::path(HM_SOURCE_DIR) / "cases";

// --- runner "borehole_pair" (Figs. 14-17): one case per b, two b per figure ---------------------------

const std::vector<std::string> kB = {"0.2", "0.8"};

std::string quick_label(const FigureSpec& f, const std::string& b) { return f.id + "_b" + b + "_quick"; }
std::string paper_label(const FigureSpec& f, const std::string& b) { return f.id + "_b" + b; }
std::string seed_label(const FigureSpec& f, const std::string& b, unsigned long long seed) {
  return paper_label(f, b) + "_N" + std::to_string(f.scatter_particles) + "_seed" + std::to_string(seed);
}
RunCase quick_case(const FigureSpec& f, const std::string& b) {
  return read_run_case(kCases / (quick_label(f, b) + ".toml"));
}
RunCase paper_case(const FigureSpec& f, const std::string& b) {
  return read_run_case(kCases / "paper" / (paper_label(f, b) + ".toml"));
}

std::vector<PlannedRun> planned(const FigureSpec& f, Tier tier) {
  std::vector<PlannedRun> runs;
  for (const std::string& b : kB) {
    if (tier == Tier::quick) {
      runs.push_back({quick_label(f, b), quick_case(f, b)});
      continue;
    }
    const RunCase c = paper_case(f, b);
    runs.push_back({paper_label(f, b), c});
    for (unsigned long long seed : f.scatter_seeds)
      runs.push_back({seed_label(f, b, seed), with_lattice(c, f.scatter_particles, seed)});
  }
  return runs;
}

std::string paper_text(const FigureSpec& f) {
  std::string s;
  for (const std::string& b : kB) {
    const PaperReading& r = f.panel(std::stod(b)).reading;
    s += (s.empty() ? "" : "; ") + ("b = " + b + ": \"" + r.quote + "\"");
  }
  return f.figure + ": " + s;
}

// Fig. 15: u_r of the fracturing lattice against the 1D model without fracture, per output time.
Table displacement_table() {
  return {
      "Fig. 15: the lattice's radially averaged u_r over the 1D model's without fracture (mean over the shells of "
      "u_r/u_r,1D; max |u_r/u_r,1D - 1| while unbroken). Paper: b = 0.2 unbroken at t* = 2.3e-3 and 4.5e-3 with "
      "the lattice on the 1D curve, then u_r above it at most positions; b = 0.8 unbroken at 2.3e-3 and 4.5e-3, "
      "then u_r below it at all positions",
      {"run", "t*", "n_broken", "mean u_r/u_r,1D", "max |u_r/u_r,1D - 1| (unbroken)", "paper"},
      {}};
}

/// The paper's u_r against the 1D model: unbroken up to last_unbroken_t, then above or below it.
struct DisplacementReading {
  double last_unbroken_t = 0.0;
  bool above_after = false;
};

std::string fig15_statement(const DisplacementReading& paper, bool unbroken, bool first_fractured) {
  if (unbroken) return "unbroken, on the 1D curve";
  if (!first_fractured) return "";
  return paper.above_after ? "fractured: above 1D at most positions" : "fractured: below 1D at all positions";
}

void add_displacement_rows(const FigureSpec& f, const RunOutcome& o, Table& t, std::vector<Metric>& m) {
  const DisplacementReading paper{*f.unbroken_until, *f.panel(o.b).u_r_above_1d};
  bool fractured_seen = false;
  for (const Snapshot& s : o.snaps) {
    const bool unbroken = s.t <= paper.last_unbroken_t * (1 + 1e-9);
    const bool first_fractured = !unbroken && !fractured_seen;
    fractured_seen = fractured_seen || !unbroken;
    t.rows.push_back({run_name(o), fmt(s.t), std::to_string(s.stats.n_broken), fmt(s.u_ratio_mean), fmt(s.u_pre),
                      fig15_statement(paper, unbroken, first_fractured)});
    const std::string why = "the paper's Fig. 15 (N = 1e5, one realisation); shown, not tuned";
    const std::string tag = run_name(o) + ": ";
    if (unbroken) {
      m.push_back({.name = tag + "unbroken at t* = " + fmt(s.t) + " (broken beams)",
                   .value = double(s.stats.n_broken),
                   .reference = 0.0,
                   .tolerance = 0.0,
                   .comparison = Comparison::abs_error,
                   .justification = why,
                   .gating = false});
      m.push_back({.name = tag + "mean u_r/u_r,1D at t* = " + fmt(s.t),
                   .value = s.u_ratio_mean,
                   .reference = 1.0,
                   .tolerance = 0.05,
                   .comparison = Comparison::rel_error,
                   .justification = why + "; 5% as the 2D-vs-1D comparison before fracture (lattice2d.vs_fdm1d)",
                   .gating = false});
    } else if (first_fractured) {
      const bool above = paper.above_after;
      m.push_back({.name = tag + "mean u_r/u_r,1D at the first fractured time of Fig. 15, t* = " + fmt(s.t),
                   .value = s.u_ratio_mean,
                   .reference = 1.0,
                   .tolerance = 1.0,
                   .comparison = above ? Comparison::at_least : Comparison::at_most,
                   .justification = why + (above ? ": above the 1D curve" : ": below the 1D curve"),
                   .gating = false});
    }
  }
}

BenchmarkResult run_fracture_figure(const FigureSpec& f, const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const std::string subdir = f.id + (ctx.tier == Tier::quick ? "_quick" : "_paper");
  const fs::path root = ctx.data_dir / subdir;
  fs::create_directories(root);
  RunSource source(root, ctx.runs_dir, ctx.progress);
  const std::string paper = paper_text(f);
  Table snaps = snapshot_table(paper), fluid = fluid_table(paper), breakdown = breakdown_table(),
        timing = timing_table();
  Table displacement = displacement_table();
  Table scatter = scatter_table(f.scatter_particles), scatter_bd = scatter_breakdown_table(f.scatter_particles);
  std::vector<RunOutcome> runs;
  std::vector<bool> in_figure;
  for (const std::string& b : kB) {
    const RunCase c = ctx.tier == Tier::quick ? quick_case(f, b) : paper_case(f, b);
    const fdm1d::Fdm1dResult ref = write_reference(c, root);
    runs.push_back(source.run(c, ctx.tier == Tier::quick ? quick_label(f, b) : paper_label(f, b), ref));
    in_figure.push_back(true);
    if (ctx.tier == Tier::quick) continue;
    std::vector<RunOutcome> seeds;
    for (unsigned long long seed : f.scatter_seeds)
      seeds.push_back(source.run(with_lattice(c, f.scatter_particles, seed), seed_label(f, b, seed), ref));
    add_scatter_rows(b, seeds, scatter, scatter_bd);
    for (auto& s : seeds) runs.push_back(std::move(s)), in_figure.push_back(false);
  }
  write_index(root, runs, in_figure, source);
  for (const auto& o : runs) {
    const PaperReading& reading = f.panel(o.b).reading;
    add_snapshot_rows(o, snaps, reading);
    add_fluid_rows(o, fluid);
    add_breakdown_row(o, breakdown);
    add_timing_row(o, timing);
    add_gating_metrics(o, res.metrics);
    add_paper_metrics(o, res.metrics, reading);
    if (f.unbroken_until) add_displacement_rows(f, o, displacement, res.metrics);
  }
  res.tables = {snaps, fluid};
  if (f.unbroken_until) res.tables.push_back(displacement);
  if (ctx.tier == Tier::paper) res.tables.insert(res.tables.end(), {scatter, scatter_bd});
  res.tables.insert(res.tables.end(), {breakdown, timing});
  res.figures = f.figures(subdir, ctx.tier == Tier::quick ? "quick tier" : "paper tier, N = 1e5");
  res.notes.push_back(notes_common());
  if (const std::string read = source.note(); !read.empty()) res.notes.push_back(read);
  res.notes.push_back("Data: " + subdir + "/<case>/ as `hmlattice run` writes it, " + subdir +
                      "/fdm1d_b<b>/ as `hmlattice fdm1d` writes it (the 1D reference at the case's output times), "
                      "runs.csv. The output times are the case files' (their comments say how they were chosen).");
  return res;
}

// --- runner "refinement" (Figs. 19-20): one case on lattices of several resolutions ------------------

/// The resolutions of a refinement sweep case (its [sweep] lattice.n_particles), each a RunCase,
/// expanded as `hmlattice sweep expand` does into root/<name>_cases/.
std::vector<RunCase> refinement_cases(const fs::path& sweep_case, const fs::path& root) {
  const fs::path folder = root / (sweep_case.stem().string() + "_cases");
  fs::remove_all(folder);  // our own staging of an earlier run of this benchmark into the same data folder
  fs::create_directories(folder);
  const cases::SweepExpansion e = cases::expand_sweep(sweep_case, folder);
  std::vector<RunCase> out;
  for (const auto& combination : e.combinations) out.push_back(read_run_case(folder / (combination.name + ".toml")));
  std::sort(out.begin(), out.end(),
            [](const RunCase& a, const RunCase& b) { return a.lattice.n_particles < b.lattice.n_particles; });
  return out;
}

fs::path refinement_sweep(const FigureSpec& f, Tier tier) {
  return kCases / (tier == Tier::quick ? f.quick_sweep : f.paper_sweep);
}

/// Seeds per resolution: the spec's scatter where a run is cheap (the quick tier's coarsest lattice;
/// N <= the scatter's in the paper tier, minutes a run), seed 1 above.
std::vector<unsigned long long> refinement_seeds(const FigureSpec& f, long long n, Tier tier, bool coarsest) {
  const bool scatter = tier == Tier::quick ? coarsest : n <= f.scatter_particles;
  return scatter ? f.scatter_seeds : std::vector<unsigned long long>{1};
}

/// Unique over both tiers (the quick and the paper sweep share their coarsest lattice).
std::string refinement_label(const FigureSpec& f, long long n, unsigned long long seed, Tier tier) {
  return f.id + (tier == Tier::quick ? "_quick" : "") + "_N" + std::to_string(n) + "_seed" + std::to_string(seed);
}

/// What the sweep plans, without the expansion's files (for --write-cases): the same RunCases.
std::vector<PlannedRun> planned_refinement(const FigureSpec& f, Tier tier) {
  const fs::path tmp = fs::temp_directory_path() / ("hmlattice-" + f.id + "-plan-" + std::to_string(::getpid()));
  const std::vector<RunCase> cases = refinement_cases(refinement_sweep(f, tier), tmp);
  fs::remove_all(tmp);
  std::vector<PlannedRun> runs;
  for (const RunCase& c : cases)
    for (unsigned long long seed : refinement_seeds(f, c.lattice.n_particles, tier, &c == &cases.front()))
      runs.push_back(
          {refinement_label(f, c.lattice.n_particles, seed, tier), with_lattice(c, c.lattice.n_particles, seed)});
  return runs;
}

Table refinement_table() {
  return {
      "Fig. 19: the state at the last output time per resolution (mean ± sd over the seeds where there are "
      "several): broken beams, radial fractures as arms and clusters, radial clusters at r = 1, the longest "
      "radial fracture's r_max, the pressure range, p_h. Paper (Section 3.6): 2 fractures at 684 particles, 4 at "
      "every finer resolution, similar lengths and maximum pressure",
      {"N (target)", "seeds", "t*", "n_broken", "arms", "radial (clusters)", "radial at r = 1", "r_max radial", "p min",
       "p max", "p_h", "paper: fractures"},
      {}};
}

Table refinement_displacement_table() {
  return {
      "Fig. 20: each resolution's radially averaged u_r (seed 1) against the finest lattice's at the same time: "
      "mean over the shells of u_r/u_r,finest and the max |u_r/u_r,finest - 1|. Paper: the five highest "
      "resolutions almost identical, the lowest noticeably lower",
      {"N (target)", "t*", "mean u_r/u_r,finest", "max |u_r/u_r,finest - 1|", "mean u_r/u_r,1D (no fracture)"},
      {}};
}

struct ShellRatio {
  double mean = kNaN, max_error = kNaN;
};

ShellRatio shell_ratio(const std::vector<double>& u, const std::vector<double>& finest) {
  ShellRatio r;
  if (u.empty() || u.size() != finest.size()) return r;
  double sum = 0.0, e = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) sum += u[k] / finest[k], e = std::max(e, std::abs(u[k] / finest[k] - 1.0));
  r.mean = sum / static_cast<double>(u.size());
  r.max_error = e;
  return r;
}

// One resolution's row of the refinement table: its seeds, and the means and deviations over them of the
// last snapshot's counts, extent, fracture pressures and p_h, beside the paper's count.
std::vector<std::string> resolution_row(const FigureSpec& f, const std::vector<const RunOutcome*>& group) {
  const auto last = [&](auto of) {
    std::vector<double> v;
    for (const RunOutcome* o : group)
      if (o->ok && !o->snaps.empty()) v.push_back(of(o->snaps.back()));
    return mean_sd(v);
  };
  std::string seeds;
  for (const RunOutcome* o : group) seeds += (seeds.empty() ? "" : ", ") + std::to_string(o->seed);
  const RunOutcome& first = *group.front();
  return {std::to_string(first.n_particles),
          seeds,
          first.snaps.empty() ? "-" : fmt(first.snaps.back().t),
          last([](const Snapshot& s) { return double(s.stats.n_broken); }),
          last([](const Snapshot& s) { return double(s.stats.n_arms); }),
          last([](const Snapshot& s) { return double(s.stats.n_radial); }),
          last([](const Snapshot& s) { return double(s.stats.n_radial_reaching_outer); }),
          last([](const Snapshot& s) { return s.stats.max_radial_extent; }),
          last([](const Snapshot& s) { return s.fp.p_min; }),
          last([](const Snapshot& s) { return s.fp.p_max; }),
          last([](const Snapshot& s) { return s.p_h; }),
          f.panel(first.b, first.n_particles).reading.fractures_text()};
}

BenchmarkResult run_refinement(const FigureSpec& f, const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const std::string subdir = f.id + (ctx.tier == Tier::quick ? "_quick" : "_paper");
  const fs::path root = ctx.data_dir / subdir;
  fs::create_directories(root);
  RunSource source(root, ctx.runs_dir, ctx.progress);
  const std::vector<RunCase> resolutions = refinement_cases(refinement_sweep(f, ctx.tier), root);
  const fdm1d::Fdm1dResult ref = write_reference(resolutions.front(), root);
  Table table = refinement_table(), displacement = refinement_displacement_table(),
        snaps = snapshot_table("Section 3.6, Fig. 19: 2 fractures at 684 particles, 4 above"),
        breakdown = breakdown_table(), timing = timing_table();
  std::vector<RunOutcome> runs;
  std::vector<bool> in_figure;
  std::vector<std::vector<const RunOutcome*>> by_resolution;
  for (const RunCase& c : resolutions) {
    const long long n = c.lattice.n_particles;
    for (unsigned long long seed : refinement_seeds(f, n, ctx.tier, &c == &resolutions.front())) {
      runs.push_back(source.run(with_lattice(c, n, seed), refinement_label(f, n, seed, ctx.tier), ref));
      in_figure.push_back(seed == 1);
    }
  }
  write_index(root, runs, in_figure, source);
  for (const auto& o : runs) {
    if (by_resolution.empty() || by_resolution.back().front()->n_particles != o.n_particles)
      by_resolution.emplace_back();
    by_resolution.back().push_back(&o);
    const PaperReading& reading = f.panel(o.b, o.n_particles).reading;
    add_snapshot_rows(o, snaps, reading);
    add_breakdown_row(o, breakdown);
    add_timing_row(o, timing);
    add_gating_metrics(o, res.metrics);
    add_paper_metrics(o, res.metrics, reading);
  }
  const RunOutcome& finest = *by_resolution.back().front();
  for (const auto& group : by_resolution) {
    const RunOutcome& first = *group.front();
    table.rows.push_back(resolution_row(f, group));
    if (first.snaps.empty() || finest.snaps.empty()) continue;
    const ShellRatio r = shell_ratio(first.snaps.back().u_r, finest.snaps.back().u_r);
    displacement.rows.push_back({std::to_string(first.n_particles), fmt(first.snaps.back().t), fmt(r.mean),
                                 fmt(r.max_error), fmt(first.snaps.back().u_ratio_mean)});
    if (&first == &finest) continue;
    const bool coarsest = &group == &by_resolution.front();
    // The paper's words, "almost identical", read as within 5% of the finest; "noticeably lower" as below it.
    res.metrics.push_back(
        {.name = "N = " + std::to_string(first.n_particles) +
                 ", seed 1: mean u_r/u_r,finest at t* = " + fmt(first.snaps.back().t),
         .value = r.mean,
         .reference = 1.0,
         .tolerance = coarsest ? 1.0 : 0.05,
         .comparison = coarsest ? Comparison::at_most : Comparison::rel_error,
         .justification = std::string("the paper's Fig. 20: ") +
                          (coarsest ? "the lowest resolution gives noticeably lower u_r"
                                    : "the higher resolutions give almost identical u_r (our reading: "
                                      "within 5%)") +
                          "; shown, not tuned",
         .gating = false});
  }
  res.tables = {table, displacement, snaps, breakdown, timing};
  const std::string what = ctx.tier == Tier::quick ? "quick tier" : "paper tier";
  res.figures = f.figures(subdir, what);
  res.notes.push_back(notes_common());
  if (const std::string read = source.note(); !read.empty()) res.notes.push_back(read);
  res.notes.push_back("The resolutions are the sweep case's (" + refinement_sweep(f, ctx.tier).filename().string() +
                      "; the paper gives only 684 and 170 158, the four between are a geometric series). Data: " +
                      subdir + "/" + f.id + "[_quick]_N<N>_seed<s>/ as `hmlattice run` writes it, runs.csv.");
  return res;
}

}  // namespace

void add_lattice2d_paper_figure_benchmarks(std::vector<Benchmark>& into) {
  for (const FigureSpec& spec : figure_specs()) {
    if (spec.runner == FigureRunner::none) continue;
    const FigureSpec* f = &spec;
    const auto run = [f](const BenchmarkContext& ctx) {
      return f->runner == FigureRunner::refinement ? run_refinement(*f, ctx) : run_fracture_figure(*f, ctx);
    };
    const auto plan = [f](Tier tier) {
      return f->runner == FigureRunner::refinement ? planned_refinement(*f, tier) : planned(*f, tier);
    };
    into.push_back({.id = "lattice2d." + f->id + "_quick",
                    .title = f->quick_title,
                    .description = f->quick_description,
                    .tier = Tier::quick,
                    .run = run,
                    .planned_runs = [plan] { return plan(Tier::quick); },
                    .paper_figures = f->paper_figures});
    into.push_back({.id = "lattice2d." + f->id,
                    .title = f->paper_title,
                    .description = f->paper_description,
                    .tier = Tier::paper,
                    .run = run,
                    .planned_runs = [plan] { return plan(Tier::paper); },
                    .paper_figures = f->paper_figures});
  }
}

}  // namespace hm::verification
