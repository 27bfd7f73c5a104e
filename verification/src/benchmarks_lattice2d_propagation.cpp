// Crack propagation against LEFM: a dry crack grown from a notch by raising its volume (Griffith's
// toughness-dominated growth), under the saw-tooth law and, beside it, the paper's brittle beam; and the
// same crack driven by fluid through the coupled model (the toughness-dominated KGD crack).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "crack_growth.hpp"
#include "hm/case/run_case.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/verification/benchmark.hpp"
#include "kgd_run.hpp"
#include "report_writer.hpp"

namespace hm::verification {

namespace {

namespace l2 = hm::lattice2d;
using core::CsvWriter;

struct Variant {
  std::string label;
  bool sawtooth;
  PressurisedFaces faces;
  SofteningPath path = SofteningPath::teeth;
};

// The released over the booked energy of each tooth, a row and a metric each.
void add_teeth_release(const CrackGrowthRun& run, const std::string& at, Table& teeth_table,
                       std::vector<Metric>& metrics) {
  for (std::size_t i = 0; i < run.booked_by_tooth.size(); ++i) {
    const double ratio = run.released_by_tooth[i] / run.booked_by_tooth[i];
    teeth_table.rows.push_back({std::to_string(i), fmt(ratio)});
    // Stepping a beam's stiffness down at fixed load can only release more than the beam's own
    // triangle: the rest of the lattice relaxes too (the minimum of the new energy is below its value
    // at the old displacement). Less would mean the law's stresses and the mechanics disagree.
    metrics.push_back({.name = "released / booked energy of tooth " + std::to_string(i) + " (" + at + ")",
                       .value = ratio,
                       .reference = 1.0,
                       .tolerance = 1.0 - 1e-6,
                       .comparison = Comparison::at_least,
                       .justification = "a stiffness drop at fixed volume releases at least the beam's own "
                                        "energy; 1e-6 for the 1e-9 snapping and round-off"});
  }
}

BenchmarkResult griffith_growth(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const bool paper = ctx.tier == Tier::paper;
  const double t_u = l2::StrengthSpec{}.tensile_strength;
  const double g_f = kGrowthCharacteristicLength * t_u * t_u;  // over E R, with E = 1
  const auto [e_prime, k_c] = griffith_constants(g_f);
  const std::vector<long long> sizes =
      paper ? std::vector<long long>{15000, 30000, 60000} : std::vector<long long>{15000};
  std::vector<Variant> variants = {{"sawtooth, dry process zone", true, PressurisedFaces::broken},
                                   {"sawtooth, pressure in the process zone", true, PressurisedFaces::with_softening},
                                   {"brittle (the paper's)", false, PressurisedFaces::broken}};
  // The teeth's limit studies where K's excess comes from and costs half the quick Griffith time, so it
  // runs in the paper tier only (its code path is tested in tests/verification/test_crack_growth.cpp).
  if (paper)
    variants.insert(variants.begin() + 2, {"the teeth's envelope followed continuously, pressure in the process zone",
                                           true, PressurisedFaces::with_softening, SofteningPath::continuous});
  const std::filesystem::path out_path = ctx.data_dir / "lattice2d_griffith_growth.csv";
  std::ofstream out = core::open_for_writing(out_path);
  // Each variant by its flags: sawtooth (0: the brittle law), its process zone wet by damage, its
  // envelope followed continuously (0: by teeth).
  CsvWriter csv(out, {"sawtooth", "wet", "continuous", "n_particles", "seed", "volume", "pressure", "half_length",
                      "booked", "work", "mechanical_work", "n_broken", "half_length_griffith", "k_over_k_c"});
  Table table{"Crack grown from a notch |x| < 0.05 by its volume in a free disk of radius 1: G_f/(E R) = " + fmt(g_f) +
                  " (l_ch = " + fmt(kGrowthCharacteristicLength) + " R), K_c = sqrt(E' G_f) = " + fmt(k_c) +
                  "; measured over c in [0.1, 0.3]",
              {"law", "N", "growth points", "K = p sqrt(pi c) (median) / K_c", "booked energy per crack length / G_f",
               "cost (W - pV/2) per crack length / G_f", "rock's dissipation per crack length / G_f", "beams broken",
               "solves", "seconds"},
              {}};
  Table teeth_table{
      "Energy released by the events of each tooth (the drop of pV/2 at fixed V) over what the law booked "
      "for them, N = 15000, sawtooth with a dry process zone; the last tooth includes the beam's break",
      {"tooth", "released / booked"},
      {}};
  for (std::size_t v = 0; v < variants.size(); ++v)
    for (long long n : sizes) {
      CrackGrowthSpec spec;
      spec.n_particles = n;
      spec.fracture_energy = variants[v].sawtooth ? g_f : 0.0;
      spec.faces = variants[v].faces;
      spec.path = variants[v].path;
      const CrackGrowthRun run = grow_pressurised_crack(spec);
      for (const GrowthPoint& g : run.points)
        csv.row({variants[v].sawtooth ? 1.0 : 0.0, variants[v].faces == PressurisedFaces::with_softening ? 1.0 : 0.0,
                 variants[v].path == SofteningPath::continuous ? 1.0 : 0.0, static_cast<double>(n), 1.0, g.volume,
                 g.pressure, g.half_length, g.booked, g.work, g.mechanical_work, static_cast<double>(g.n_broken),
                 griffith_half_length(g.volume, {e_prime, k_c}),
                 g.pressure * std::sqrt(std::numbers::pi * g.half_length) / k_c});
      const GrowthMeasures m = measure_growth(run);
      table.rows.push_back({variants[v].label, std::to_string(n), std::to_string(m.n), fmt(m.toughness / k_c),
                            variants[v].sawtooth ? fmt(m.booked / g_f) : "-", fmt(m.released / g_f), fmt(m.rock / g_f),
                            std::to_string(run.n_broken), std::to_string(run.n_solves), fmt(run.seconds)});
      const std::string at = variants[v].label + ", N = " + std::to_string(n);
      res.metrics.push_back({.name = "K_c fitted along the growth / sqrt(E' G_f) (" + at + ")",
                             .value = m.toughness / k_c,
                             .reference = 1.0,
                             .tolerance = 0.10,
                             .comparison = Comparison::rel_error,
                             .justification = "the goal (10%); not met yet: the events release more than the law books "
                                              "(see the note), so shown, not gated",
                             .gating = false});
      if (variants[v].sawtooth && v == 0 && n == sizes.front()) add_teeth_release(run, at, teeth_table, res.metrics);
    }
  res.tables.push_back(table);
  res.tables.push_back(teeth_table);
  res.figures.push_back({"verify_griffith_growth.py", "verify_griffith_growth.png",
                         "Crack grown from a notch by its volume (l_ch = " + fmt(kGrowthCharacteristicLength) +
                             " R, the law's calibrated strength): its half length against Griffith's c(V), and "
                             "K = p sqrt(pi c) against K_c = sqrt(E' G_f) along the growth (the fit's range shaded)."});
  core::close_checked(out, out_path);
  return res;
}

// --- the fluid-driven crack ---------------------------------------------------------------------------

// The crack's volume over the injected volume at the last state with c up to the growth window's end:
// a crack grown further may break through the disk's drained rim (the brittle law's does at N = 3000,
// t = 4.3e-8, c = 0.55) and lose its fluid there, which says nothing of the coupling.
double fluid_in_crack_while_growing(const KgdRun& run) {
  const auto last = std::find_if(run.points.rbegin(), run.points.rend(),
                                 [](const KgdPoint& p) { return p.half_length <= kGrowthFitTo; });
  return last == run.points.rend() ? 0.0 : last->crack_volume / last->injected;
}

// The largest share of the fractures' area under suction while the fed crack is in the growth window:
// a nucleus ahead of a tip, joined to the crack by no broken beam, is fed only through the tight rock and
// draws suction that holds the tip shut (docs/fracture_law.md).
double suction_while_growing(const KgdRun& run) {
  double worst = 0.0;
  for (const KgdPoint& p : run.points)
    if (p.half_length <= kGrowthFitTo) worst = std::max(worst, p.suction);
  return worst;
}

struct KgdMeasures {
  int n = 0;                  // growth states with c in [kGrowthFitFrom, kGrowthFitTo]
  double toughness = 0.0;     // median p sqrt(pi c)
  double length_ratio = 0.0;  // median c / c_Griffith(injected volume)
};

KgdMeasures measure(const KgdRun& run, double e_prime, double k_c) {
  KgdMeasures g;
  std::vector<double> k, ratio;
  // The states from which the crack grows, as the dry benchmark's growth points: the state before each
  // step with events (the step's first event comes within 2% of its threshold, the overshoot retry),
  // not the states in between, where the pressure is still rising to the next event.
  for (std::size_t i = 1; i < run.points.size(); ++i) {
    if (run.points[i].events == 0) continue;
    const KgdPoint& p = run.points[i - 1];
    if (p.half_length < kGrowthFitFrom || p.half_length > kGrowthFitTo) continue;
    k.push_back(p.pressure * std::sqrt(std::numbers::pi * p.half_length));
    ratio.push_back(p.half_length / griffith_half_length(p.injected, {e_prime, k_c}));
  }
  g.n = static_cast<int>(k.size());
  if (k.empty()) return g;
  std::sort(k.begin(), k.end());
  std::sort(ratio.begin(), ratio.end());
  g.toughness = k[k.size() / 2];
  g.length_ratio = ratio[ratio.size() / 2];
  return g;
}

// One coupled run's metrics: it reaches t_end (gated for the saw-tooth law), the fluid is in the crack,
// and (shown) its K against the dry crack's and against K_c.
void add_kgd_metrics(const std::string& at, bool sawtooth, const KgdRun& run, double fluid_in_crack, double k_fluid,
                     double k_dry, double k_c, std::vector<Metric>& metrics) {
  metrics.push_back({.name = "largest share of the fractures' area under suction, c <= 0.3 (" + at + ")",
                     .value = suction_while_growing(run),
                     .reference = 0.0,
                     .tolerance = 0.05,
                     .comparison = Comparison::abs_error,
                     .justification = "0 when the crack grows as one fed crack; nuclei ahead of a tip that no "
                                      "broken beam joins to the crack are fed only through the tight rock, draw "
                                      "suction and hold the tip shut, which the dry crack (pressure on every "
                                      "broken beam) does not know; shown, not gated",
                     .gating = false});
  metrics.push_back({.name = "the coupled run reaches t_end (" + at + ")",
                     .value = run.ok ? 1.0 : 0.0,
                     .reference = 1.0,
                     .tolerance = 1.0,
                     .comparison = Comparison::at_least,
                     .justification = run.ok ? "the fluid-driven crack runs to its end" : run.message,
                     .gating = sawtooth});
  metrics.push_back({.name = "fluid in the crack / injected, c <= 0.3 (" + at + ")",
                     .value = fluid_in_crack,
                     .reference = 1.0,
                     .tolerance = 0.02,
                     .comparison = Comparison::rel_error,
                     .justification = "leak-off into the tight rock and its storage: ~1% estimated from the "
                                      "diffusion length sqrt(t/(E/M)) along the crack"});
  metrics.push_back({.name = "K of the fluid-driven crack / K of the dry crack (" + at + ")",
                     .value = k_dry > 0.0 ? k_fluid / k_dry : 0.0,
                     .reference = 1.0,
                     .tolerance = 0.2,
                     .comparison = Comparison::rel_error,
                     .justification = "the same toughness if the coupled model delivers the whole pressure to "
                                      "the crack's faces; shown, not gated: the time-driven run and the "
                                      "event-driven dry growth take different event sequences, and at "
                                      "N = 3000 (l_ch about two beams) K swings by +-30% along the growth",
                     .gating = false});
  metrics.push_back({.name = "K fitted along the growth / sqrt(E' G_f) (" + at + ")",
                     .value = k_fluid / k_c,
                     .reference = 1.0,
                     .tolerance = 0.10,
                     .comparison = Comparison::rel_error,
                     .justification = sawtooth ? "the goal (10%); not met: the law's own overshoot, as in "
                                                 "lattice2d.griffith_growth; shown, not gated"
                                               : "the paper's beam has no fracture energy: its K against the saw-tooth "
                                                 "law's K_c for comparison (it rises with N, "
                                                 "lattice2d.fracture_energy); shown, not gated",
                     .gating = false});
}

// The dry crack on the same lattice, strengths and law as the coupled case `c` (its G_f `g_f`, 0 for
// the brittle law): what the fluid should reproduce.
CrackGrowthSpec dry_twin(const cases::RunCase& c, double g_f) {
  CrackGrowthSpec dry;
  dry.n_particles = c.lattice.n_particles;
  dry.lattice_seed = c.lattice.seed;
  dry.strength_seed = c.strength.seed;
  dry.notch_half_length = 0.05;
  dry.fracture_energy = g_f;
  dry.teeth = c.sawtooth.teeth;
  dry.strength_factor = c.sawtooth.strength_factor;
  dry.max_half_length = kGrowthFitTo + 0.02;
  // The coupled model's fluid-filled crack wets the law's process zone by damage (CoupledModel::
  // crack_weights): the dry growth pressurises the same faces.
  dry.faces = PressurisedFaces::with_softening;
  return dry;
}

BenchmarkResult kgd_toughness(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const bool paper = ctx.tier == Tier::paper;
  const std::filesystem::path case_file = std::filesystem::path(HM_SOURCE_DIR) / "cases" / "kgd_toughness_quick.toml";
  const cases::RunCase base = cases::read_run_case(case_file);
  const double g_f = base.sawtooth.fracture_energy;
  const auto [e_prime, k_c] = griffith_constants(g_f);
  const std::vector<long long> sizes =
      paper ? std::vector<long long>{15000, 30000, 60000} : std::vector<long long>{base.lattice.n_particles};
  const std::filesystem::path out_path = ctx.data_dir / "lattice2d_kgd_toughness.csv";
  std::ofstream out = core::open_for_writing(out_path);
  CsvWriter csv(out, {"law", "n_particles", "t", "injected", "crack_volume", "pressure", "half_length", "n_broken"});
  Table table{"The fluid-driven crack of cases/kgd_toughness_quick.toml (G_f/(E R) = " + fmt(g_f) +
                  ", K_c = sqrt(E' G_f) = " + fmt(k_c) +
                  "), measured over c in [0.1, 0.3]; the dry crack grown by its volume on the same lattice "
                  "and law beside it",
              {"law", "N", "growth states", "K / K_c (fluid)", "K / K_c (dry)", "c / c_Griffith(V)",
               "fluid in the crack (c <= 0.3)", "area under suction (c <= 0.3, largest)", "max balance error", "steps",
               "passes", "seconds"},
              {}};
  // By size, both laws at each: a paper-tier run stopped part-way has whole comparisons.
  for (long long n : sizes)
    for (const bool sawtooth : {true, false}) {
      cases::RunCase c = base;
      c.lattice.n_particles = n;
      if (!sawtooth) {
        // The brittle law under the saw-tooth law's event control: one break per converged state, each
        // step's first within 2% of its threshold, so that the crack grows at its volume as the dry twin
        // does. With the brittle law's own (every break of a pass at the pass's pressures) the crack runs
        // through the disk in one pass at t ~ 1.3e-8 at every N (103 to 647 breaks), which nearly cuts
        // the free disk in two and ends the run.
        c = cases::read_run_case(
            case_file, {"fracture.law=\"brittle\"", "fracture.fracture_energy=0", "coupling.events_per_check=1",
                        "coupling.fracture_check=\"at_convergence\"", "numerics.overshoot_tolerance=0.02"});
        c.lattice.n_particles = n;
      }
      const std::string law = sawtooth ? "sawtooth" : "brittle";
      const std::string at = law + ", N = " + std::to_string(n);
      const KgdRun run = run_kgd(c);
      for (const KgdPoint& p : run.points)
        csv.row({sawtooth ? 1.0 : 0.0, static_cast<double>(n), p.t, p.injected, p.crack_volume, p.pressure,
                 p.half_length, static_cast<double>(p.n_broken)});
      const KgdMeasures m = measure(run, e_prime, k_c);
      const GrowthMeasures d = measure_growth(grow_pressurised_crack(dry_twin(c, sawtooth ? g_f : 0.0)));
      const double fluid_in_crack = fluid_in_crack_while_growing(run);
      table.rows.push_back({law, std::to_string(n), std::to_string(m.n), fmt(m.toughness / k_c), fmt(d.toughness / k_c),
                            fmt(m.length_ratio), fmt(fluid_in_crack), fmt(suction_while_growing(run)),
                            fmt(run.max_balance), std::to_string(run.n_steps), std::to_string(run.passes),
                            fmt(run.seconds)});
      if (ctx.progress)
        *ctx.progress << "[kgd_toughness] " << at << ": K / K_c " << fmt(m.toughness / k_c) << " (dry "
                      << fmt(d.toughness / k_c) << "), c / c_Griffith " << fmt(m.length_ratio)
                      << ", fluid in the crack " << fmt(fluid_in_crack) << ", "
                      << (run.ok ? "reached t_end" : "stopped: " + run.message) << ", " << fmt(run.seconds) << " s\n"
                      << std::flush;
      add_kgd_metrics(at, sawtooth, run, fluid_in_crack, m.toughness, d.toughness, k_c, res.metrics);
    }
  res.tables.push_back(table);
  core::close_checked(out, out_path);
  return res;
}

}  // namespace

void add_lattice2d_propagation_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({"lattice2d.griffith_growth", "Lattice: Griffith's toughness-dominated crack growth (saw-tooth law)",
                  "A dry crack grown from a notch by raising its volume, its K = p sqrt(pi c) against K_c = "
                  "sqrt(E' G_f), and the energy it dissipates per unit length against G_f; the paper's brittle beam "
                  "beside it.",
                  Tier::quick, griffith_growth});
  into.back().quick_seconds = 100;  // in the test command's run, two benchmarks beside the other tests
  into.push_back({"lattice2d.kgd_toughness", "Lattice: a fluid-driven crack in the toughness-dominated regime (KGD)",
                  "The notch of the Griffith benchmark fed by a point source through the coupled model (b = 0, "
                  "fluid-filled crack): the fluid reaching the crack, its K against the dry crack's and against "
                  "K_c = sqrt(E' G_f).",
                  Tier::quick, kgd_toughness});
  into.back().quick_seconds = 110;
}

}  // namespace hm::verification
