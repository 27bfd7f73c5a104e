// Crack propagation against LEFM: a dry crack grown from a notch by raising its volume (Griffith's
// toughness-dominated growth), under the saw-tooth law and, beside it, the paper's brittle beam.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/verification/benchmark.hpp"
#include "crack_growth.hpp"
#include "report_writer.hpp"

namespace hm::verification {

namespace {

namespace l2 = hm::lattice2d;
using core::CsvWriter;

std::string fmt(double x) { return format_number(x); }

// l_ch = E G_f / T_u^2 = 0.04 R: the fit's shortest crack, c = 0.1, is 2.5 l_ch (c >= 2 l_ch), and the
// beams (mean length 0.016 R at N = 1.5e4) are 2.5 times shorter than l_ch.
constexpr double kCharacteristicLength = 0.04;
// The growth the toughness is fitted on: c from 0.1 to 0.3 (the notch's 0.05 is left behind).
constexpr double kFitFrom = 0.1, kFitTo = 0.3;

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  return sxx > 0 ? sxy / sxx : 0.0;
}

struct GrowthMeasures {
  int n = 0;               // growth points with c in [kFitFrom, kFitTo]
  double toughness = 0.0;  // median of p sqrt(pi c) over them
  double booked = 0.0;     // d(booked energy) / d(2c): the law's G_f times the crack's facets per length
  double released = 0.0;   // d(W - (1/2) p V) / d(2c): what the growth actually dissipated per crack length
};

GrowthMeasures measure(const CrackGrowthRun& run) {
  GrowthMeasures g;
  std::vector<double> k, length, booked, released;
  for (const GrowthPoint& p : run.points) {
    if (p.half_length < kFitFrom || p.half_length > kFitTo) continue;
    k.push_back(p.pressure * std::sqrt(std::numbers::pi * p.half_length));
    length.push_back(2 * p.half_length);
    booked.push_back(p.booked);
    released.push_back(p.work - 0.5 * p.pressure * p.volume);
  }
  g.n = static_cast<int>(k.size());
  if (k.size() < 2) return g;
  std::sort(k.begin(), k.end());
  g.toughness = k[k.size() / 2];
  g.booked = slope(length, booked);
  g.released = slope(length, released);
  return g;
}

struct Variant {
  std::string label;
  bool sawtooth;
  PressurisedFaces faces;
};

BenchmarkResult griffith_growth(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const bool paper = ctx.tier == Tier::paper;
  const double t_u = l2::StrengthSpec{}.tensile_strength;
  const double g_f = kCharacteristicLength * t_u * t_u;  // over E R, with E = 1
  const l2::ElasticConstants continuum = l2::calibrated_continuum();
  const double e_prime = continuum.youngs_modulus / (1 - continuum.poisson_ratio * continuum.poisson_ratio);
  const double k_c = std::sqrt(e_prime * g_f);
  const std::vector<long long> sizes = paper ? std::vector<long long>{15000, 30000, 60000} : std::vector<long long>{15000};
  const std::vector<Variant> variants = {
      {"sawtooth, dry process zone", true, PressurisedFaces::broken},
      {"sawtooth, pressure in the process zone", true, PressurisedFaces::with_softening},
      {"brittle (the paper's)", false, PressurisedFaces::broken}};
  const std::filesystem::path out_path = ctx.data_dir / "lattice2d_griffith_growth.csv";
  std::ofstream out = core::open_for_writing(out_path);
  CsvWriter csv(out, {"variant", "n_particles", "seed", "volume", "pressure", "half_length", "booked", "work", "n_broken"});
  Table table{"Crack grown from a notch |x| < 0.05 by its volume in a free disk of radius 1: G_f/(E R) = " + fmt(g_f) +
                  " (l_ch = " + fmt(kCharacteristicLength) + " R), K_c = sqrt(E' G_f) = " + fmt(k_c) +
                  "; measured over c in [0.1, 0.3]",
              {"law", "N", "growth points", "K = p sqrt(pi c) (median) / K_c", "booked energy per crack length / G_f",
               "dissipated (W - pV/2) per crack length / G_f", "beams broken", "solves", "seconds"},
              {}};
  Table teeth_table{"Energy released by the events of each tooth (the drop of pV/2 at fixed V) over what the law booked "
                    "for them, N = 15000, sawtooth with a dry process zone; the last tooth includes the beam's break",
                    {"tooth", "released / booked"},
                    {}};
  for (std::size_t v = 0; v < variants.size(); ++v)
    for (long long n : sizes) {
      CrackGrowthSpec spec;
      spec.n_particles = n;
      spec.fracture_energy = variants[v].sawtooth ? g_f : 0.0;
      spec.faces = variants[v].faces;
      const CrackGrowthRun run = grow_pressurised_crack(spec);
      for (const GrowthPoint& g : run.points)
        csv.row({static_cast<double>(v), static_cast<double>(n), 1.0, g.volume, g.pressure, g.half_length, g.booked,
                 g.work, static_cast<double>(g.n_broken)});
      const GrowthMeasures m = measure(run);
      table.rows.push_back({variants[v].label, std::to_string(n), std::to_string(m.n), fmt(m.toughness / k_c),
                            variants[v].sawtooth ? fmt(m.booked / g_f) : "-", fmt(m.released / g_f),
                            std::to_string(run.n_broken), std::to_string(run.n_solves), fmt(run.seconds)});
      const std::string at = variants[v].label + ", N = " + std::to_string(n);
      res.metrics.push_back({.name = "K_c fitted along the growth / sqrt(E' G_f) (" + at + ")",
                             .value = m.toughness / k_c, .reference = 1.0, .tolerance = 0.10,
                             .comparison = Comparison::rel_error,
                             .justification = "the goal (10%); not met yet: the events release more than the law books "
                                              "(see the note), so shown, not gated",
                             .gating = false});
      if (!variants[v].sawtooth || v != 0 || n != sizes.front()) continue;
      for (std::size_t i = 0; i < run.booked_by_tooth.size(); ++i) {
        const double ratio = run.released_by_tooth[i] / run.booked_by_tooth[i];
        teeth_table.rows.push_back({std::to_string(i), fmt(ratio)});
        // Stepping a beam's stiffness down at fixed load can only release more than the beam's own
        // triangle: the rest of the lattice relaxes too (the minimum of the new energy is below its value
        // at the old displacement). Less would mean the law's stresses and the mechanics disagree.
        res.metrics.push_back({.name = "released / booked energy of tooth " + std::to_string(i) + " (" + at + ")",
                               .value = ratio, .reference = 1.0, .tolerance = 1.0 - 1e-6,
                               .comparison = Comparison::at_least,
                               .justification = "a stiffness drop at fixed volume releases at least the beam's own "
                                                "energy; 1e-6 for the 1e-9 snapping and round-off"});
      }
    }
  res.tables.push_back(table);
  res.tables.push_back(teeth_table);
  res.notes.push_back(
      "Griffith's pressurised crack in an infinite plane grows at p sqrt(pi c) = K_c; with the law's fracture energy "
      "K_c = sqrt(E' G_f), E' = E/(1 - nu^2) of the calibrated continuum. The crack's half length c is half the "
      "x-span of the broken beams' faces. Each growth point is the pressure at which the next event (a tooth or a "
      "break) happens, the crack's volume raised to it; events at the same volume after it are an unstable jump. "
      "The booked energy is the law's: G_f times the facet of each beam taken through all its teeth, and the "
      "teeth given way of the others. The dissipated energy is the pressure's work minus the energy stored, "
      "W - pV/2, which is what the growth actually cost.");
  res.notes.push_back(
      "What this shows (the law is not verified yet): the lattice books about 1.25 G_f per unit crack length (the "
      "crack's facets zig-zag, and beams beside it soften too), but the growth dissipates 2-3.5 times G_f. Two "
      "mechanisms, measured per tooth in the second table: (1) each tooth is a stiffness drop at fixed volume, and "
      "the lattice around the beam relaxes with it: for a beam of stiffness k in series with a surrounding of "
      "stiffness K_s the release over the beam's own triangle is (k + K_s)/(k' + K_s), between 1 and the "
      "reduction factor a = k/k' = 2, largest at the first teeth, where the beam is stiff; (2) with a dry process "
      "zone, a beam that breaks adds its facet to the pressurised crack at once, and that jump releases tens of "
      "times the last tooth's energy. Pressure in the process zone (weighted by each beam's damage) removes (2) "
      "and brings K to about 1.25 K_c; finer teeth reduce (1) only slowly (a = 1.25 with 25 teeth: released 2.0 "
      "G_f). docs/fracture_law.md has the study.");
  res.figures.clear();
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
}

}  // namespace hm::verification
