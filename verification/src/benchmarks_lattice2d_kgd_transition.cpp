// The KGD fracture between its vertices: the fluid-driven crack of cases/kgd_transition_quick.toml (a
// viscous fluid, the cubic law) beside its toughness-dominated twin (iota = 1e12, uniform pressure in the
// crack; the same lattice, strengths and notch), against Dontsov's (2017) closed form. The ratio of their
// lengths at the same injected volume cancels most of what the lattice's toughness does not know (its
// excess over sqrt(E' G_f), its jumps): the twin's length gives the lattice's K, hence the toughness
// number K_m, and the closed form says how much shorter the viscous crack is at that K_m.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "crack_growth.hpp"
#include "hm/analytic/kgd_transition.hpp"
#include "hm/case/run_case.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/verification/benchmark.hpp"
#include "kgd_run.hpp"
#include "report_writer.hpp"

namespace hm::verification {

namespace {

// The twin: the same case with a crack so conductive that its pressure is uniform (the K-vertex's).
const std::vector<std::string> kToughnessTwin = {"physics.iota=1e12",
                                                 "flow.fracture_flow=\"permeability\"",
                                                 "flow.rock_permeability=0",
                                                 "flow.crack_aperture=\"axial\"",
                                                 "coupling.crack_stabiliser=\"uniform_pressure\"",
                                                 "fracture.notch_aperture=0"};

// Where the lengths are compared: every 1e-6 (a few hundred steps of dt_max = 2e-7 in a run), while the
// twin's half length is in the growth window of the other propagation benchmarks (from two notch lengths
// to 0.3, before the disk's free edge at r = 1 adds to K). Both cracks grow in jumps of a few beams, so a
// ratio at one time says more about the jumps' timing than about the crack: the comparison is of the
// window's geometric means, the average height of the staircases.
constexpr double kSampleEvery = 1e-6;

struct Sample {
  double t = 0.0, twin_length = 0.0, viscous_length = 0.0, twin_volume = 0.0;
};

std::vector<Sample> sample(const KgdRun& twin, const KgdRun& viscous, double t_end) {
  std::vector<Sample> samples;
  if (twin.points.empty() || viscous.points.empty()) return samples;
  for (int k = 1; k * kSampleEvery <= t_end * (1 + 1e-9); ++k) {
    const double t = k * kSampleEvery;
    const KgdPoint& a = kgd_state_at(twin, t);
    const KgdPoint& v = kgd_state_at(viscous, t);
    // A run that stopped early has no state near t; states are otherwise within one step (dt_max) of t.
    if (a.t < t - kSampleEvery || v.t < t - kSampleEvery) break;
    if (a.half_length < kGrowthFitFrom || a.half_length > kGrowthFitTo) continue;
    samples.push_back({t, a.half_length, v.half_length, a.injected});
  }
  return samples;
}

// One lattice's comparison over the window.
struct LengthComparison {
  int n = 0;
  double from = 0.0, to = 0.0;
  double toughness = 0.0;         // the twin's K, geometric mean over the samples
  double toughness_number = 0.0;  // K_m at that K
  double ratio = 0.0;             // viscous over twin length, geometric mean
  double expected = 0.0;          // Dontsov's ratio at K_m (the same at every t: both lengths grow as t^(2/3))
};

LengthComparison compare(const std::vector<Sample>& samples, double e_prime, double mu_prime, double q) {
  LengthComparison c;
  c.n = static_cast<int>(samples.size());
  if (samples.empty()) return c;
  double log_k = 0.0, log_ratio = 0.0;
  for (const Sample& s : samples) {
    // The twin's crack is Griffith's holding its volume: c = (E' V / (2 sqrt(pi) K))^(2/3) gives its K.
    log_k += std::log(e_prime * s.twin_volume / (2 * std::sqrt(std::numbers::pi) * std::pow(s.twin_length, 1.5)));
    log_ratio += std::log(s.viscous_length / s.twin_length);
  }
  c.from = samples.front().t;
  c.to = samples.back().t;
  c.toughness = std::exp(log_k / c.n);
  c.ratio = std::exp(log_ratio / c.n);
  c.toughness_number = analytic::kgd_toughness_number(e_prime, mu_prime, q, c.toughness);
  const double t = c.to;
  c.expected = analytic::kgd_transition_scales(c.toughness_number).gamma *
               analytic::kgd_length_scale(e_prime, mu_prime, q, t) /
               griffith_half_length(q * t, {e_prime, c.toughness});
  return c;
}

double mean_of(const std::vector<double>& x) {
  double sum = 0.0;
  for (const double v : x) sum += v;
  return x.empty() ? 0.0 : sum / static_cast<double>(x.size());
}

BenchmarkResult kgd_transition(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const bool paper = ctx.tier == Tier::paper;
  const std::filesystem::path case_file = std::filesystem::path(HM_SOURCE_DIR) / "cases" / "kgd_transition_quick.toml";
  // The case stops at t = 6e-5, where the twin on its N = 3000 lattice leaves the window (c = 0.3); the
  // paper tier's finer lattices are tougher (shorter cracks) and run on to 8e-5.
  std::vector<std::string> overrides =
      paper ? std::vector<std::string>{"numerics.t_end=8e-5"} : std::vector<std::string>{};
  const cases::RunCase viscous_case = cases::read_run_case(case_file, overrides);
  overrides.insert(overrides.end(), kToughnessTwin.begin(), kToughnessTwin.end());
  const cases::RunCase twin_case = cases::read_run_case(case_file, overrides);
  const double e_prime = griffith_constants(viscous_case.sawtooth.fracture_energy).e_prime;
  const double mu_prime = 12 * viscous_case.flow.fracture_flow.permeability;  // docs/flow.md: mu' = 12 k/R^2
  const double q = viscous_case.physics.parameters.Q;
  const double t_end = viscous_case.stepping.t_end;
  const std::vector<long long> sizes = paper ? std::vector<long long>{10000} : std::vector<long long>{3000};
  const std::vector<std::uint64_t> seeds = paper ? std::vector<std::uint64_t>{1, 2, 3} : std::vector<std::uint64_t>{1};

  const std::filesystem::path out_path = ctx.data_dir / "lattice2d_kgd_transition.csv";
  std::ofstream out = core::open_for_writing(out_path);
  core::CsvWriter csv(out,
                      {"viscous", "n_particles", "seed", "t", "injected", "crack_volume", "pressure", "half_length"});
  const std::filesystem::path samples_path = ctx.data_dir / "lattice2d_kgd_transition_ratio.csv";
  std::ofstream samples_out = core::open_for_writing(samples_path);
  core::CsvWriter samples_csv(samples_out, {"n_particles", "seed", "t", "ratio", "mean_ratio", "expected"});
  Table table{"The viscous crack of cases/kgd_transition_quick.toml (cubic law, mu' = 12 k/R^2 = " + fmt(mu_prime) +
                  ", Q = " + fmt(q) +
                  ") and its toughness-dominated twin (iota = 1e12) on the same lattice, sampled every 1e-6 while "
                  "the twin's c is in [0.1, 0.3]: the twin's K (Griffith's crack holding the volume; geometric mean), "
                  "K_m = K' (E'^3 mu' Q)^(-1/4), the ratio of the half lengths at the same injected volume "
                  "(geometric mean) and Dontsov's at that K_m",
              {"N", "seed", "window t", "samples", "K of the twin", "K_m", "ratio (lattice)", "ratio (Dontsov)",
               "lattice / Dontsov"},
              {}};
  std::vector<double> all;
  for (const long long n : sizes)
    for (const std::uint64_t seed : seeds) {
      cases::RunCase v = viscous_case, a = twin_case;
      for (cases::RunCase* c : {&v, &a}) {
        c->lattice.n_particles = n;
        c->lattice.seed = seed;
        c->strength.seed = seed;
      }
      const std::string at = "N = " + std::to_string(n) + ", seed " + std::to_string(seed);
      const KgdRun twin = run_kgd(a);
      const KgdRun viscous = run_kgd(v);
      for (const auto& [flag, run] : {std::pair{0.0, &twin}, std::pair{1.0, &viscous}})
        for (const KgdPoint& p : run->points)
          csv.row({flag, static_cast<double>(n), static_cast<double>(seed), p.t, p.injected, p.crack_volume, p.pressure,
                   p.half_length});
      const std::vector<Sample> samples = sample(twin, viscous, t_end);
      const LengthComparison m = compare(samples, e_prime, mu_prime, q);
      for (const Sample& x : samples)
        samples_csv.row({static_cast<double>(n), static_cast<double>(seed), x.t, x.viscous_length / x.twin_length,
                         m.ratio, m.expected});
      const double agreement = m.n > 0 ? m.ratio / m.expected : 0.0;
      table.rows.push_back({std::to_string(n), std::to_string(seed), fmt(m.from) + " - " + fmt(m.to),
                            std::to_string(m.n), fmt(m.toughness), fmt(m.toughness_number), fmt(m.ratio),
                            fmt(m.expected), fmt(agreement)});
      if (m.n > 0) all.push_back(std::log(agreement));
      if (ctx.progress)
        *ctx.progress << "[kgd_transition] " << at << ": lattice / Dontsov " << fmt(agreement) << " (K_m "
                      << fmt(m.toughness_number) << ", " << m.n << " samples); twin "
                      << (twin.ok ? "reached t_end" : twin.message) << " in " << fmt(twin.seconds) << " s, viscous "
                      << (viscous.ok ? "reached t_end" : viscous.message) << " in " << fmt(viscous.seconds) << " s\n"
                      << std::flush;
      for (const auto& [name, run] : {std::pair{"toughness twin", &twin}, std::pair{"viscous", &viscous}})
        res.metrics.push_back({.name = std::string("the ") + name + " run reaches t_end (" + at + ")",
                               .value = run->ok ? 1.0 : 0.0,
                               .reference = 1.0,
                               .tolerance = 1.0,
                               .comparison = Comparison::at_least,
                               .justification = run->ok ? "the fluid-driven crack runs to its end" : run->message});
      const double held =
          viscous.points.empty() ? 0.0 : viscous.points.back().crack_volume / viscous.points.back().injected;
      res.metrics.push_back({.name = "fluid held by the solid's opening / injected at t_end, viscous (" + at + ")",
                             .value = held,
                             .reference = 1.0,
                             .tolerance = 0.01,
                             .comparison = Comparison::rel_error,
                             .justification = "no leak-off, the closed form's assumption: the tight rock's storage "
                                              "takes 0.15% at N = 3000"});
      res.metrics.push_back({.name = "samples in the growth window (" + at + ")",
                             .value = static_cast<double>(m.n),
                             .reference = 10.0,
                             .tolerance = 10.0,
                             .comparison = Comparison::at_least,
                             .justification = "the twin's crack passes c = 0.1 to 0.3 within the run (every 1e-6): a "
                                              "comparison at all"});
      res.metrics.push_back({.name = "viscous / toughness-dominated length, lattice over Dontsov (" + at + ")",
                             .value = agreement,
                             .reference = 1.0,
                             .tolerance = 0.10,
                             .comparison = Comparison::rel_error,
                             .justification = "one lattice: its cracks grow in jumps of a few beams and unequal "
                                              "wings, and the ratio of two single runs scatters by +-15% at "
                                              "N = 3000 (docs/flow.md); shown, not gated",
                             .gating = false});
    }
  if (paper)
    res.metrics.push_back(
        {.name = "viscous / toughness-dominated length, lattice over Dontsov, geometric mean over seeds",
         .value = std::exp(mean_of(all)),
         .reference = 1.0,
         .tolerance = 0.10,
         .comparison = Comparison::rel_error,
         .justification = "the goal: 10% on the mean of three lattices at N = 1e4; shown, not "
                          "gated until the paper tier has measured its scatter",
         .gating = false});
  res.tables.push_back(table);
  res.figures.push_back({"verify_kgd_transition.py", "verify_kgd_transition.png",
                         "Left: the half lengths of both runs of each lattice (the window shaded). Right: the "
                         "viscous crack's half length over its toughness-dominated twin's at the same injected "
                         "volume (dots, every 1e-6 in the window), their geometric mean (line) and Dontsov's ratio "
                         "at the twin's toughness number (dotted)."});
  core::close_checked(out, out_path);
  core::close_checked(samples_out, samples_path);
  return res;
}

}  // namespace

void add_lattice2d_kgd_transition_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({"lattice2d.kgd_transition", "Lattice: the KGD fracture between its toughness and viscosity vertices",
                  "A viscous crack under the cubic law beside its toughness-dominated twin on the same lattice: the "
                  "ratio of their lengths at the same injected volume against Dontsov's closed form at the twin's "
                  "toughness number.",
                  Tier::quick, kgd_transition});
  into.back().quick_seconds = 650;  // in the test command's run, two benchmarks beside the other tests
}

}  // namespace hm::verification
