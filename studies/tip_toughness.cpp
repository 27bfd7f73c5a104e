// Study (an executable, not a test; it asserts nothing): does the crack-tip rule of Fig. 2 give the dry
// lattice a toughness? The rule multiplies the stress of an intact beam in a crack-tip triangle by
// (L_ij / 2 L_m)^(1/2), meant to turn the beam-averaged tip stress, which falls like L^(-1/2), into an
// L-independent K / sqrt(pi L_m), so that a crack advances at K_c ~ T_u sqrt(pi L_m) on any lattice.
// Measured here, with fracture on and the model's defaults otherwise (calibrated facet beams, uniform
// +-5% strengths, and also no heterogeneity to separate the rule from the disorder):
//  (a) the annulus R_i = 0.138, R = 1, free outer boundary, borehole-wall pressure p only (dry: no pore
//      pressure, crack faces unloaded), with a radial wall crack pre-cut from the borehole (the beams a
//      radial ray from the hole crosses, the way beams_crossing_segment finds a crack's beams) of
//      1, 2, 4, 8 beams, and the intact wall;
//  (b) Sneddon's straight crack of half-length c in the disk, pressurised on its faces.
// For each case the smallest load at which a beam meets Eq. 11 or the tensile criterion is found from
// one solve at unit load: the lattice problem and both failure measures are positively homogeneous of
// degree one in the load (fracture.hpp), so p_c = 1 / max over intact beams of the failure ratio at p = 1,
// with each beam's own crack-tip factor; the beam that attains it is reported (crack tip or not). The
// solve does not depend on L_m, so each solve serves every L_m. Then
//   K_c = p_c sqrt(pi c) F,
// with F = 1 for Sneddon's crack and, for the wall crack, the weight-function F of a crack-line stress
// (wall_crack_geometry_factor below; references in docs/fracture_study.md).
// Run: OMP_NUM_THREADS=1 HM_TIP_CSV_DIR=docs/reports/fracture-study-A build/studies/study_tip_toughness
// (markdown tables on stdout, each tagged [name]; 3.5-4.5 min on one core at 4 seeds, ~85% of it at N = 8e4).
// Knobs (environment): HM_TIP_N comma-separated particle counts (default 5000,20000,80000),
// HM_TIP_SEEDS lattice seeds 1..n (default 4), HM_TIP_SEEDS_LARGEST seeds at the largest N (default
// HM_TIP_SEEDS), HM_TIP_ANGLES wall-crack rays per lattice (default 4, at 90 degree spacing),
// HM_TIP_CSV_DIR: every printed table also as <name>_<default|none>.csv there (small, long form),
// HM_TIP_ROWS_DIR: one row per crack and variant there (wall_crack.csv, sneddon.csv; ~0.4 MB at 4 seeds).
// Findings: docs/fracture_study.md, "Study A".
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hm/analytic/lame.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"

using namespace hm::lattice2d;

namespace {

constexpr double kInnerRadius = 0.138;                            // Table 1: R_i / R
const std::vector<double> kMaterialLengths{3.13e-3, 1e-3, 3e-4};  // L_m / R; 3.13e-3 is the default
const std::vector<int> kWallCrackBeams{1, 2, 4, 8};
const std::vector<double> kSneddonHalfLengths{0.05, 0.1, 0.2};  // c / R: fixed physical cracks

// ---------------------------------------------------------------------------------------------------
// Continuum reference

// F of K = p sqrt(pi c) F for a radial crack of depth c from the wall of the pressurised annulus, crack
// faces unloaded: the uncracked crack-line hoop stress sigma_theta(r) (Lame, the library's) put on the
// faces of an edge crack in a half-plane through that geometry's point-force weight function (Tada, Paris
// & Irwin's handbook, Hartranft-Sih fit):
//   K = int_0^c sigma(x) 2 / sqrt(pi c) (1.3 - 0.3 (x/c)^(5/4)) / sqrt(1 - (x/c)^2) dx,
// so F = (2/pi) int_0^(pi/2) sigma_theta(R_i + c sin phi)/p (1.3 - 0.3 sin^(5/4) phi) dphi (x = c sin phi
// removes the end singularity; the integrand is smooth, the midpoint rule is exact to ~1e-7 here).
// Uniform sigma gives 1.1222 sigma (the exact edge-crack 1.1215). Limits: the hole's curvature and the
// finite outer radius enter only through sigma_theta, not through the weight function; docs/.
double wall_crack_geometry_factor(double c, const hm::analytic::LameCylinder& lame_unit_pressure) {
  constexpr int n = 2000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double phi = (k + 0.5) * (0.5 * std::numbers::pi / n), s = std::sin(phi);
    sum += lame_unit_pressure.state(kInnerRadius + c * s).sigma_theta * (1.3 - 0.3 * std::pow(s, 1.25));
  }
  return (2.0 / std::numbers::pi) * sum * (0.5 * std::numbers::pi / n);
}

// ---------------------------------------------------------------------------------------------------
// First break by homogeneity

struct FirstBreak {
  double pressure = 0.0;  // p_c / E
  int beam = -1;
  hm::analytic::FailureMode mode = hm::analytic::FailureMode::none;
  double tip_factor = 1.0;  // the breaking beam's crack-tip factor (1 when not at a tip or the rule is off)
  bool at_tip = false;      // the breaking beam lies in a crack-tip triangle (whether or not the rule is on)
  bool on_wall = false;     // one of its particles is on the borehole wall
  Eigen::Vector2d midpoint = Eigen::Vector2d::Zero();
};

// The first break of `m`'s current broken set, `m` solved at unit load: over all intact beams (`any`),
// and over the crack-tip beams only (`tip`: the load at which the crack itself advances; beam -1 if there
// is no crack tip). A far wall beam may break before the crack advances; K_c is judged on `tip`.
struct FirstBreaks {
  FirstBreak any, tip;
};
FirstBreaks first_breaks(const BeamMechanics& m, const DualGraph& dual, const BeamStrengths& strengths,
                         const CrackTipOptions& tip) {
  const Lattice& lattice = m.lattice();
  const BeamStress stress = current_beam_stress(m, dual, tip);
  const FailureField field = evaluate_failure(stress, strengths, m.states());
  const std::vector<bool> at_tip = find_crack_tip_beams(lattice, m.states());
  auto record = [&](int e) {
    FirstBreak out;
    if (e < 0) return out;
    const double ratio = field.ratio[e];
    out.beam = e;
    out.pressure = 1.0 / ratio;
    // The mode at the break, judged just above it as the load stepping's snap does (fracture.cpp).
    const double at_break = (1.0 + 1e-9) / ratio;
    out.mode = FailureCriterion(strengths.friction)
                   .check(at_break * stress.sigma_1[e], at_break * stress.sigma_3[e], strengths.tensile[e],
                          strengths.compressive[e])
                   .mode;
    out.tip_factor = stress.crack_tip_factor[e];
    out.at_tip = at_tip[static_cast<std::size_t>(e)];
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    out.on_wall = lattice.boundary[static_cast<std::size_t>(i)] == BoundaryTag::inner ||
                  lattice.boundary[static_cast<std::size_t>(j)] == BoundaryTag::inner;
    out.midpoint = 0.5 * (lattice.points.col(i) + lattice.points.col(j));
    return out;
  };
  // The failure ratio at p = 1 is the ratio per unit load: the beam with the largest breaks first.
  int any = -1, tip_beam = -1;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (m.states()[static_cast<std::size_t>(e)] != BeamState::intact) continue;
    if (any < 0 || field.ratio[e] > field.ratio[any]) any = e;
    if (at_tip[static_cast<std::size_t>(e)] && (tip_beam < 0 || field.ratio[e] > field.ratio[tip_beam])) tip_beam = e;
  }
  return {record(any), record(tip_beam)};
}

// 0 = the breaking beam is a crack-tip beam, 1 = elsewhere on the borehole wall, 2 = elsewhere.
double where_code(const FirstBreak& b) { return b.at_tip ? 0.0 : b.on_wall ? 1.0 : 2.0; }

// The crack-tip variants judged on every broken set: the rule off, then each L_m.
std::vector<CrackTipOptions> tip_variants() {
  std::vector<CrackTipOptions> out(1);
  out[0].enabled = false;
  for (double l_m : kMaterialLengths) {
    CrackTipOptions o;
    o.material_length = l_m;
    out.push_back(o);
  }
  return out;
}
double material_length_of(const CrackTipOptions& o) { return o.enabled ? o.material_length : 0.0; }

// Strength variants: the default (uniform +-5%, strength seed 1) and none (every beam exactly T_u, C_u).
std::vector<StrengthSpec> strength_variants() {
  StrengthSpec none;
  none.distribution = StrengthDistribution::none;
  return {StrengthSpec{}, none};
}

// ---------------------------------------------------------------------------------------------------
// Results, kept for the summary tables

struct Row {
  std::string study;  // "wall" or "sneddon"
  long long n = 0;
  int seed = 0, ray = 0, strengths = 0;  // strengths: 0 uniform (default), 1 none
  double l_m = 0;                        // 0: rule off
  int n_crack_beams = 0;                 // 0: intact wall
  double c_nominal = 0;                  // Sneddon: the cut's half-length c / R
  double c = 0, h = 0, f = 0, p_init = 0;
  double first_to_tip = 0;  // first breaking beam's midpoint to the (nearest) crack tip
  double tip_to_tip = 0;    // the same for the breaking tip beam of `tip`
  FirstBreak first;         // first break anywhere
  FirstBreak tip;           // first break of a crack-tip beam: the crack's own advance
  /// K at the crack's advance, p_tip sqrt(pi c) F.
  double k_c() const { return tip.pressure * std::sqrt(std::numbers::pi * c) * f; }
  /// K at the first break anywhere, p_first sqrt(pi c) F: what the break loop sees when the first beam
  /// to go is a neighbour of the tip triangle rather than one of its two beams.
  double k_first() const { return first.pressure * std::sqrt(std::numbers::pi * c) * f; }
};
std::vector<Row> g_rows;

double env_number(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v ? std::atof(v) : fallback;
}

std::vector<long long> env_list(const char* name, const std::vector<long long>& fallback) {
  const char* v = std::getenv(name);
  if (!v) return fallback;
  std::vector<long long> out;
  std::stringstream s(v);
  for (std::string item; std::getline(s, item, ',');) out.push_back(std::atoll(item.c_str()));
  return out;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ---------------------------------------------------------------------------------------------------
// (a) Radial wall crack

// The beams a radial ray at `angle` crosses, from just inside the hole (so the wall beam it passes is the
// first) out to R_i + span, ordered along the ray: breaking the first k makes a wall crack of k beams.
std::vector<int> radial_crack_beams(const Lattice& lattice, double angle, double span) {
  const Eigen::Vector2d d(std::cos(angle), std::sin(angle));
  const Eigen::Vector2d a = 0.5 * kInnerRadius * d, b = (kInnerRadius + span) * d;
  std::vector<int> beams = beams_crossing_segment(lattice, a, b);
  // Distance along the ray of the crossing: (x_i + t (x_j - x_i) - a) x d = 0.
  auto along = [&](int e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const Eigen::Vector2d p = lattice.points.col(i), q = lattice.points.col(j) - p;
    const double t = ((a - p).x() * d.y() - (a - p).y() * d.x()) / (q.x() * d.y() - q.y() * d.x());
    return (p + t * q - a).dot(d);
  };
  std::sort(beams.begin(), beams.end(), [&](int x, int y) { return along(x) < along(y); });
  return beams;
}

// The crack's tip: the Voronoi point (circumcentre) of the triangle beyond its last broken beam, where the
// last crack face ends (the faces are the broken beams' Voronoi segments). -1 if the ray's beams are not
// a chain of shared triangles (a ray through a particle; not expected on a random lattice).
int tip_triangle(const Lattice& lattice, const std::vector<int>& crack, int n) {
  const auto& last = lattice.beam_triangles[static_cast<std::size_t>(crack[static_cast<std::size_t>(n - 1)])];
  if (n == 1) return last[0];  // the wall beam has one triangle
  const auto& before = lattice.beam_triangles[static_cast<std::size_t>(crack[static_cast<std::size_t>(n - 2)])];
  const bool shares_0 = last[0] == before[0] || last[0] == before[1];
  const bool shares_1 = last[1] >= 0 && (last[1] == before[0] || last[1] == before[1]);
  if (shares_0 == shares_1) return -1;
  return shares_0 ? last[1] : last[0];
}

void wall_crack_study(long long n_target, int seed, int n_rays) {
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.inner_radius = kInnerRadius;
  spec.n_particles = n_target;
  spec.seed = static_cast<std::uint64_t>(seed);
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  const double h = lattice.length.mean();
  const hm::analytic::LameCylinder lame(1.0, 0.0, kInnerRadius, 1.0, calibrated_continuum().poisson_ratio);
  BoundaryConditions bc;
  bc.inner_pressure = 1.0;  // unit reference load: every failure ratio is then per unit wall pressure
  const auto variants = tip_variants();
  const auto strength_specs = strength_variants();
  std::vector<BeamStrengths> strengths;
  for (const auto& s : strength_specs) strengths.push_back(draw_beam_strengths(s, lattice.n_beams()));
  const int max_beams = kWallCrackBeams.back();

  for (int ray = 0; ray < n_rays; ++ray) {
    const double angle = ray * 0.5 * std::numbers::pi + 0.1;  // off the axes: no symmetry of the sampler
    const std::vector<int> crack = radial_crack_beams(lattice, angle, 3.0 * max_beams * h);
    if (static_cast<int>(crack.size()) < max_beams) {
      std::printf("  [N %lld seed %d ray %d: only %zu beams on the ray, skipped]\n", n_target, seed, ray, crack.size());
      continue;
    }
    BeamMechanics m(lattice, calibrated_beam_parameters(), bc);
    std::vector<double> p_init(strengths.size());
    for (int k = 0; k <= max_beams; ++k) {
      if (k > 0) m.break_beam(crack[static_cast<std::size_t>(k - 1)]);
      if (k > 0 && std::find(kWallCrackBeams.begin(), kWallCrackBeams.end(), k) == kWallCrackBeams.end()) continue;
      const MechanicsSummary solved = m.solve(false);
      if (!solved.is_converged()) {
        std::printf("  [N %lld seed %d ray %d, %d beams: solve failed: %s]\n", n_target, seed, ray, k,
                    solved.message.c_str());
        break;
      }
      double c = 0.0, f = 0.0;
      Eigen::Vector2d tip_point = kInnerRadius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      if (k > 0) {
        const int t = tip_triangle(lattice, crack, k);
        if (t < 0) {
          std::printf("  [N %lld seed %d ray %d: crack beams not a triangle chain, skipped]\n", n_target, seed, ray);
          break;
        }
        tip_point = dual.dual_point.col(t);
        c = tip_point.norm() - kInnerRadius;
        f = wall_crack_geometry_factor(c, lame);
      }
      for (std::size_t s = 0; s < strengths.size(); ++s)
        for (const auto& tip : variants) {
          Row r;
          r.study = "wall";
          r.n = lattice.n_particles();
          r.seed = seed;
          r.ray = ray;
          r.strengths = static_cast<int>(s);
          r.l_m = material_length_of(tip);
          r.n_crack_beams = k;
          r.c = c;
          r.h = h;
          r.f = f;
          const FirstBreaks fb = first_breaks(m, dual, strengths[s], tip);
          r.first = fb.any;
          r.tip = fb.tip;
          if (k == 0) p_init[s] = r.first.pressure;  // no crack tip: the same for every variant
          r.p_init = p_init[s];
          r.first_to_tip = (r.first.midpoint - tip_point).norm();
          r.tip_to_tip = (r.tip.midpoint - tip_point).norm();
          g_rows.push_back(r);
        }
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// (b) Sneddon's crack in the disk

void sneddon_study(long long n_target, int seed) {
  LatticeSpec spec;
  spec.domain = DomainShape::disk;
  spec.n_particles = n_target;
  spec.seed = static_cast<std::uint64_t>(seed);
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  const double h = lattice.length.mean();
  const auto variants = tip_variants();
  const auto strength_specs = strength_variants();
  std::vector<BeamStrengths> strengths;
  for (const auto& s : strength_specs) strengths.push_back(draw_beam_strengths(s, lattice.n_beams()));
  for (double c_nominal : kSneddonHalfLengths) {
    BeamMechanics m(lattice, calibrated_beam_parameters(), BoundaryConditions{});  // free outer boundary
    const std::vector<int> crack = beams_crossing_segment(lattice, {-c_nominal, 0.0}, {c_nominal, 0.0});
    for (int e : crack) m.break_beam(e);
    m.set_external_forces(crack_face_forces(lattice, dual, crack, 1.0));  // unit crack pressure
    const MechanicsSummary solved = m.solve(false);
    if (!solved.is_converged()) {
      std::printf("  [Sneddon N %lld seed %d c %g: solve failed: %s]\n", n_target, seed, c_nominal,
                  solved.message.c_str());
      continue;
    }
    // The crack's ends are the outermost Voronoi points of its broken beams' triangles (as the Sneddon
    // benchmark measures c_eff), within about half a spacing of +-c.
    Eigen::Vector2d left(1e9, 0.0), right(-1e9, 0.0);
    for (int e : crack)
      for (int t : lattice.beam_triangles[static_cast<std::size_t>(e)])
        if (t >= 0) {
          if (dual.dual_point(0, t) < left.x()) left = dual.dual_point.col(t);
          if (dual.dual_point(0, t) > right.x()) right = dual.dual_point.col(t);
        }
    for (std::size_t s = 0; s < strengths.size(); ++s)
      for (const auto& tip : variants) {
        Row r;
        r.study = "sneddon";
        r.n = lattice.n_particles();
        r.seed = seed;
        r.strengths = static_cast<int>(s);
        r.l_m = material_length_of(tip);
        r.n_crack_beams = static_cast<int>(crack.size());
        r.c_nominal = c_nominal;
        r.c = 0.5 * (right.x() - left.x());
        r.h = h;
        r.f = 1.0;
        const FirstBreaks fb = first_breaks(m, dual, strengths[s], tip);
        r.first = fb.any;
        r.tip = fb.tip;
        r.first_to_tip = std::min((r.first.midpoint - left).norm(), (r.first.midpoint - right).norm());
        r.tip_to_tip = std::min((r.tip.midpoint - left).norm(), (r.tip.midpoint - right).norm());
        g_rows.push_back(r);
      }
  }
}

// ---------------------------------------------------------------------------------------------------
// Tables

std::string lm_name(double l_m) {
  char buf[32];
  if (l_m == 0.0) return "off";
  std::snprintf(buf, sizeof buf, "%.3g", l_m);
  return buf;
}

struct Mean {
  double sum = 0, sum2 = 0;
  int n = 0;
  void add(double x) { sum += x, sum2 += x * x, ++n; }
  double mean() const { return n ? sum / n : NAN; }
  double sd() const { return n > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))) : 0.0; }
};

// What K_c is measured against: the rule's intended T_u sqrt(pi L_m) (Section 2.1's argument: a tip beam
// averages K / sqrt(2 pi r) over its length L, i.e. K sqrt(2 / (pi L)), times (L / 2 L_m)^(1/2)); with the
// rule off, the same argument without the factor, T_u sqrt(pi h / 2), h the mean beam length.
double k_scale(const Row& r) {
  const double t_u = StrengthSpec{}.tensile_strength;
  return t_u * std::sqrt(std::numbers::pi * (r.l_m > 0 ? r.l_m : 0.5 * r.h));
}

void write_rows_csv(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  for (const std::string study : {"wall", "sneddon"}) {
    const auto path = dir / (study == "wall" ? "wall_crack.csv" : "sneddon.csv");
    std::ofstream out = hm::core::open_for_writing(path);
    hm::core::CsvWriter csv(out, {"n_particles",
                                  "seed",
                                  "ray",
                                  "strengths_none",
                                  "L_m",
                                  "crack_beams",
                                  "c_nominal",
                                  "c",
                                  "h_mean",
                                  "F",
                                  "p_init",
                                  "p_first",
                                  "first_where",
                                  "first_mode_shear",
                                  "first_tip_factor",
                                  "first_distance_to_tip_over_h",
                                  "p_tip",
                                  "tip_mode_shear",
                                  "tip_tip_factor",
                                  "tip_distance_to_tip_over_h",
                                  "K_c",
                                  "K_c_over_scale"});
    for (const Row& r : g_rows) {
      if (r.study != study) continue;
      const bool crack = r.tip.beam >= 0;
      csv.row({static_cast<double>(r.n),
               static_cast<double>(r.seed),
               static_cast<double>(r.ray),
               static_cast<double>(r.strengths),
               r.l_m,
               static_cast<double>(r.n_crack_beams),
               r.c_nominal,
               r.c,
               r.h,
               r.f,
               r.p_init,
               r.first.pressure,
               where_code(r.first),
               r.first.mode == hm::analytic::FailureMode::shear ? 1.0 : 0.0,
               r.first.tip_factor,
               r.first_to_tip / r.h,
               crack ? r.tip.pressure : NAN,
               crack ? (r.tip.mode == hm::analytic::FailureMode::shear ? 1.0 : 0.0) : NAN,
               crack ? r.tip.tip_factor : NAN,
               crack ? r.tip_to_tip / r.h : NAN,
               crack ? r.k_c() : NAN,
               crack ? r.k_c() / k_scale(r) : NAN});
    }
    hm::core::close_checked(out, path);
  }
}

long long n_key(const Row& r) { return (r.n + 500) / 1000; }  // target N in thousands: groups seeds
int column_of(const Row& r) {
  return r.study == "wall" ? r.n_crack_beams : static_cast<int>(std::lround(1000 * r.c_nominal));
}

// Where the printed tables also go as CSV (HM_TIP_CSV_DIR; empty: nowhere), one file per table.
std::filesystem::path g_csv_dir;
std::string strengths_slug(int strengths) { return strengths ? "none" : "default"; }

// Cells (N, L_m) x crack size of the mean over seeds (and rays) of value(row), rows with a NaN skipped.
using Cells = std::map<std::pair<long long, double>, std::map<int, Mean>>;
template <class Value>
Cells collect(const std::string& study, int strengths, Value value) {
  Cells cells;
  for (const Row& r : g_rows) {
    if (r.study != study || r.strengths != strengths) continue;
    const double v = value(r);
    if (!std::isnan(v)) cells[{n_key(r), -r.l_m}][column_of(r)].add(v);  // -L_m: largest L_m first, "off" last
  }
  return cells;
}

// Prints the table of value(row) and, with a CSV directory, writes <name>_<strengths>.csv in long form
// (N_thousands, L_m (0 = rule off), crack size, mean, sd, count).
template <class Value>
void table(const std::string& name, const char* title, const std::string& study, int strengths,
           const std::vector<int>& columns, const char* column_unit, Value value) {
  const Cells cells = collect(study, strengths, value);
  std::printf("\n%s, %s strengths; mean ± sd (count) over seeds%s [%s]\n| N / 1e3 | L_m |", title,
              strengths ? "no-heterogeneity" : "default ±5%", study == "wall" ? " and rays" : "", name.c_str());
  for (int c : columns) std::printf(" %d %s |", c, column_unit);
  std::printf("\n|---|---|");
  for (std::size_t k = 0; k < columns.size(); ++k) std::printf("---|");
  std::printf("\n");
  for (const auto& [key, row] : cells) {
    std::printf("| %lld | %s |", key.first, lm_name(-key.second).c_str());
    for (int c : columns) {
      const auto it = row.find(c);
      if (it == row.end())
        std::printf(" – |");
      else
        std::printf(" %.3g ± %.2g (%d) |", it->second.mean(), it->second.sd(), it->second.n);
    }
    std::printf("\n");
  }
  if (g_csv_dir.empty()) return;
  const auto path = g_csv_dir / (name + "_" + strengths_slug(strengths) + ".csv");
  std::ofstream out = hm::core::open_for_writing(path);
  hm::core::CsvWriter csv(
      out, {"n_thousands", "L_m", study == "wall" ? "crack_beams" : "c_thousandths", "mean", "sd", "count"});
  for (const auto& [key, row] : cells)
    for (const auto& [col, m] : row)
      csv.row({static_cast<double>(key.first), -key.second, static_cast<double>(col), m.mean(), m.sd(),
               static_cast<double>(m.n)});
  hm::core::close_checked(out, path);
}

// The drift of K_c with N at fixed L_m: the weighted least-squares slope alpha of log mean K_c against
// log N (K_c ~ N^alpha; the beam length h ~ N^(-1/2), so K_c ~ h^(-2 alpha)), weights from each cell's
// standard error of the mean, and alpha's standard error from them.
template <class Value>
void drift_table(const std::string& name, const std::string& study, int strengths, const std::vector<int>& columns,
                 const char* column_unit, Value k_of_row) {
  const Cells cells = collect(study, strengths, k_of_row);
  struct Point {
    double x, y, w;
  };
  std::map<double, std::map<int, std::vector<Point>>> points;  // -L_m -> column -> (log N, log K, weight)
  for (const auto& [key, row] : cells)
    for (const auto& [col, m] : row) {
      const double rel_se = m.n > 1 ? m.sd() / std::sqrt(static_cast<double>(m.n)) / m.mean() : 1.0;
      points[key.second][col].push_back({std::log(1000.0 * key.first), std::log(m.mean()), 1.0 / (rel_se * rel_se)});
    }
  std::printf(
      "\nDrift exponent alpha ± standard error of K ~ N^alpha at fixed L_m (%s crack, %s strengths; 0 = "
      "mesh-independent) [%s]\n| L_m |",
      study.c_str(), strengths ? "no-heterogeneity" : "default", name.c_str());
  for (int c : columns) std::printf(" %d %s |", c, column_unit);
  std::printf("\n|---|");
  for (std::size_t k = 0; k < columns.size(); ++k) std::printf("---|");
  std::printf("\n");
  std::ofstream out;
  std::optional<hm::core::CsvWriter> csv;
  const auto path = g_csv_dir / (name + "_" + strengths_slug(strengths) + ".csv");
  if (!g_csv_dir.empty()) {
    out = hm::core::open_for_writing(path);
    csv.emplace(
        out, std::vector<std::string>{"L_m", study == "wall" ? "crack_beams" : "c_thousandths", "alpha", "alpha_se"});
  }
  for (const auto& [neg_lm, by_col] : points) {
    std::printf("| %s |", lm_name(-neg_lm).c_str());
    for (int c : columns) {
      const auto it = by_col.find(c);
      if (it == by_col.end() || it->second.size() < 2) {
        std::printf(" – |");
        continue;
      }
      double sw = 0, sx = 0, sy = 0;
      for (const Point& q : it->second) sw += q.w, sx += q.w * q.x, sy += q.w * q.y;
      const double xm = sx / sw, ym = sy / sw;
      double sxx = 0, sxy = 0;
      for (const Point& q : it->second) sxx += q.w * (q.x - xm) * (q.x - xm), sxy += q.w * (q.x - xm) * (q.y - ym);
      const double alpha = sxy / sxx, se = std::sqrt(1.0 / sxx);
      std::printf(" %.3f ± %.3f |", alpha, se);
      if (csv) csv->row({-neg_lm, static_cast<double>(c), alpha, se});
    }
    std::printf("\n");
  }
  if (csv) hm::core::close_checked(out, path);
}

// Where the first beam (anywhere) breaks, per (N, L_m): counts tip / wall (not tip) / elsewhere.
void where_table(const std::string& name, const std::string& study, int strengths) {
  std::map<std::pair<long long, double>, std::array<int, 3>> count;
  for (const Row& r : g_rows) {
    if (r.study != study || r.strengths != strengths || r.tip.beam < 0) continue;
    count[{n_key(r), -r.l_m}][static_cast<std::size_t>(where_code(r.first))]++;
  }
  std::printf(
      "\nWhere the first beam breaks (%s crack, %s strengths): counts over all cracks of crack-tip beam / other wall "
      "beam / elsewhere [%s]\n| N / 1e3 | L_m | tip | wall | elsewhere |\n|---|---|---|---|---|\n",
      study.c_str(), strengths ? "no-heterogeneity" : "default", name.c_str());
  for (const auto& [key, c] : count)
    std::printf("| %lld | %s | %d | %d | %d |\n", key.first, lm_name(-key.second).c_str(), c[0], c[1], c[2]);
  if (g_csv_dir.empty()) return;
  const auto path = g_csv_dir / (name + "_" + strengths_slug(strengths) + ".csv");
  std::ofstream out = hm::core::open_for_writing(path);
  hm::core::CsvWriter csv(out, {"n_thousands", "L_m", "tip", "wall", "elsewhere"});
  for (const auto& [key, c] : count)
    csv.row({static_cast<double>(key.first), -key.second, static_cast<double>(c[0]), static_cast<double>(c[1]),
             static_cast<double>(c[2])});
  hm::core::close_checked(out, path);
}

}  // namespace

int main() {
  try {
    const std::vector<long long> ns = env_list("HM_TIP_N", {5000, 20000, 80000});
    const int n_seeds = static_cast<int>(env_number("HM_TIP_SEEDS", 4));
    const int n_seeds_largest = static_cast<int>(env_number("HM_TIP_SEEDS_LARGEST", n_seeds));
    const int n_rays = static_cast<int>(env_number("HM_TIP_ANGLES", 4));
    const long long n_largest = *std::max_element(ns.begin(), ns.end());
    if (const char* dir = std::getenv("HM_TIP_CSV_DIR")) {
      g_csv_dir = dir;
      std::filesystem::create_directories(g_csv_dir);
    }
    const double t_u = StrengthSpec{}.tensile_strength;
    std::printf("# Crack-tip rule toughness study (T_u = %g, C_u = %g, mu_i = %g; calibrated facet beams, nu = %.3f)\n",
                t_u, StrengthSpec{}.compressive_strength, StrengthSpec{}.friction,
                calibrated_continuum().poisson_ratio);
    const auto t_all = std::chrono::steady_clock::now();
    for (long long n : ns)
      for (int seed = 1; seed <= (n == n_largest ? n_seeds_largest : n_seeds); ++seed) {
        const auto t0 = std::chrono::steady_clock::now();
        wall_crack_study(n, seed, n_rays);
        const double t_wall = seconds_since(t0);
        sneddon_study(n, seed);
        std::printf("  N %lld seed %d: wall cracks %.1f s, Sneddon %.1f s\n", n, seed, t_wall,
                    seconds_since(t0) - t_wall);
        std::fflush(stdout);
      }
    std::printf("  total %.1f s\n", seconds_since(t_all));

    // The continuum's initiation pressure: Lame's wall hoop stress per unit pressure reaching T_u.
    const hm::analytic::LameCylinder lame(1.0, 0.0, kInnerRadius, 1.0, calibrated_continuum().poisson_ratio);
    const double p_lame = t_u / lame.state(kInnerRadius).sigma_theta;
    const std::vector<int> wall_cols{1, 2, 4, 8};
    std::vector<int> sneddon_cols;
    for (double c : kSneddonHalfLengths) sneddon_cols.push_back(static_cast<int>(std::lround(1000 * c)));
    const std::string k_title = "K_c / K_rule, K_rule = T_u sqrt(pi L_m) (rule on) or T_u sqrt(pi h/2) (rule off)";
    const std::string k_raw = "K_c / T_u (units R^(1/2))";
    for (int s : {0, 1}) {
      std::printf("\n## %s strengths\n", s ? "No-heterogeneity" : "Default (uniform ±5%)");
      table(
          "wall_p_first_over_p_lame",
          "Wall crack: p_first / p_Lame, first break anywhere (0 beams: the intact wall's initiation p_init; p_Lame = "
          "T_u (1 - R_i^2)/(1 + R_i^2))",
          "wall", s, {0, 1, 2, 4, 8}, "beams", [&](const Row& r) { return r.first.pressure / p_lame; });
      table("wall_p_tip_over_p_init",
            "Wall crack: p_tip / p_init, the crack's advance over the intact wall's initiation", "wall", s, wall_cols,
            "beams", [](const Row& r) { return r.tip.beam >= 0 ? r.tip.pressure / r.p_init : NAN; });
      // p_tip is proportional to L_m^(1/2) (the tip beam's stress carries (L/2 L_m)^(1/2), p_init has no tip),
      // so L_m (p_init / p_tip)^2 is the L_m at which this crack advances exactly at the initiation pressure.
      table("wall_L_m_balance", "Wall crack: L_m at which p_tip = p_init, L_m (p_init / p_tip)^2 (rule-on rows agree)",
            "wall", s, wall_cols, "beams", [](const Row& r) {
              return r.tip.beam >= 0 && r.l_m > 0 ? r.l_m * std::pow(r.p_init / r.tip.pressure, 2) : NAN;
            });
      where_table("wall_first_break_where", "wall", s);
      table("wall_c_over_h",
            "Wall crack: c / h, depth of the crack's Voronoi tip below the wall over the mean beam length", "wall", s,
            wall_cols, "beams", [](const Row& r) { return r.tip.beam >= 0 ? r.c / r.h : NAN; });
      table("wall_F", "Wall crack: F(c)", "wall", s, wall_cols, "beams",
            [](const Row& r) { return r.tip.beam >= 0 ? r.f : NAN; });
      table("wall_K_c", ("Wall crack: " + k_raw).c_str(), "wall", s, wall_cols, "beams",
            [&](const Row& r) { return r.tip.beam >= 0 ? r.k_c() / t_u : NAN; });
      table("wall_K_c_over_K_rule", ("Wall crack: " + k_title).c_str(), "wall", s, wall_cols, "beams",
            [](const Row& r) { return r.tip.beam >= 0 ? r.k_c() / k_scale(r) : NAN; });
      drift_table("wall_K_c_drift", "wall", s, wall_cols, "beams",
                  [](const Row& r) { return r.tip.beam >= 0 ? r.k_c() : NAN; });
      table("sneddon_crack_beams", "Sneddon crack: crack beams", "sneddon", s, sneddon_cols, "c/1e-3",
            [](const Row& r) { return static_cast<double>(r.n_crack_beams); });
      table("sneddon_K_c", ("Sneddon crack: " + k_raw).c_str(), "sneddon", s, sneddon_cols, "c/1e-3",
            [&](const Row& r) { return r.k_c() / t_u; });
      table("sneddon_K_c_over_K_rule", ("Sneddon crack: " + k_title).c_str(), "sneddon", s, sneddon_cols, "c/1e-3",
            [](const Row& r) { return r.k_c() / k_scale(r); });
      table("sneddon_p_first_over_p_tip",
            "Sneddon crack: p_first / p_tip (< 1: a beam away from the tips breaks first)", "sneddon", s, sneddon_cols,
            "c/1e-3", [](const Row& r) { return r.first.pressure / r.tip.pressure; });
      drift_table("sneddon_K_c_drift", "sneddon", s, sneddon_cols, "c/1e-3", [](const Row& r) { return r.k_c(); });
      table("sneddon_K_first_over_K_rule",
            "Sneddon crack: K_first / K_rule, K_first = p_first sqrt(pi c): the first break anywhere (a tip "
            "triangle's neighbour where it goes first)",
            "sneddon", s, sneddon_cols, "c/1e-3", [](const Row& r) { return r.k_first() / k_scale(r); });
      drift_table("sneddon_K_first_drift", "sneddon", s, sneddon_cols, "c/1e-3",
                  [](const Row& r) { return r.k_first(); });
    }
    if (const char* dir = std::getenv("HM_TIP_ROWS_DIR")) write_rows_csv(dir);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "study_tip_toughness: %s\n", e.what());
    return 1;
  }
  return 0;
}
