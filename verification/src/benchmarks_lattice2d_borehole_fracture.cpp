// Fluid-driven fracture from a borehole (Section 3.3, Figs. 12-13; the breakdown pressure of Section 3.5):
// continuous injection Q = 0.01 into the borehole of a free annulus, iota = 1 (no faster flow in the
// fractures), b = 0.2 and 0.8, fracture on. The cases are read from cases/ with read_run_case, so the
// harness runs exactly what `hmlattice run` runs:
//   quick tier  cases/fig12_b0.2_quick.toml, cases/fig12_b0.8_quick.toml (N = 3000)
//   paper tier  cases/paper/fig12_b0.2.toml, cases/paper/fig12_b0.8.toml (N = 1e5), and each case at
//               N = 2e4 with seeds 1, 2, 3 (lattice and strengths) for the seed scatter.
//
// What gates (what must hold whatever the resolution): the run completes, the volume balance holds to
// round-off, the first break is tensile and at the borehole wall, at least one radial fracture forms,
// broken beams never heal. What is shown beside the paper and never gates (nothing is tuned to it): the
// number of radial fractures (3 for b = 0.2, 7 for b = 0.8), that they all reach the outer boundary,
// and that the pressure in the fractures is negative. The borehole pressure before the first break is
// compared with the 1D model (fdm1d, no fracture), not gating: the lattice cannot resolve the wall's
// pressure boundary layer in the first steps (see the metric's justification); the unfractured twin of
// each case is what is gated against 1D.
//
// Each run's folder is written as `hmlattice run` writes it (RunRecorder), each 1D run as
// `hmlattice fdm1d` writes it, plus runs.csv (which folder is which), for figures/fig12_fracture_pressure.py
// and figures/fig13_displacement_vs_1d.py. docs/borehole_fracture.md explains the definitions.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hm/fdm1d/fdm1d.hpp"
#include "hm/lattice2d/calibration.hpp"
#include "hm/lattice2d/coupled_model.hpp"
#include "hm/lattice2d/fracture_statistics.hpp"
#include "hm/lattice2d/radial_average.hpp"
#include "hm/lattice2d/strength.hpp"
#include "hm/verification/benchmark.hpp"
#include "hm/verification/fdm1d_output.hpp"
#include "hm/verification/progress.hpp"
#include "hm/verification/provenance.hpp"
#include "hm/verification/run_case.hpp"
#include "hm/verification/run_output.hpp"
#include "report_writer.hpp"
#include "fdm1d_sampling.hpp"

namespace hm::verification {

namespace {

namespace lt = hm::lattice2d;
namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
std::string fmt(double x) { return format_number(x); }

/// The paper's counts of radial fractures (Section 3.3: "3 nearly equidistant fractures for b = 0.2,
/// and 7 fractures for b = 0.8").
int paper_fracture_count(double b) { return b < 0.5 ? 3 : 7; }

/// The p_h comparison with 1D starts at t* = 1e-3, as in benchmarks_lattice2d_vs_fdm1d.cpp: before it the
/// wall's pressure boundary layer sqrt(t/S) is thinner than the lattice spacing and the lattice's p_h
/// is far above the 1D one whatever the borehole node (docs/lattice_vs_fdm1d.md).
constexpr double kWindow = 1e-3;

/// Mean pressure in the fractures at one time (our definition, docs/borehole_fracture.md): the
/// area-weighted mean over the "fracture triangles", those with a broken beam among their three beams
/// (the fluid cells that hold the open volume). `away` excludes the triangles that have a borehole-wall
/// beam: their pressure is tied to p_h through the wall segment (flow_network.hpp), so they show the
/// borehole, not the fracture.
struct FracturePressure {
  double mean_all = kNaN, mean_away = kNaN, min_away = kNaN;
  int n_all = 0, n_away = 0;
  double negative_area_fraction = kNaN;  // of the `away` triangles' area with p < 0
};

FracturePressure fracture_pressure(const lt::CoupledModel& m) {
  const lt::Lattice& l = m.lattice();
  const auto& states = m.mechanics().states();
  const Eigen::VectorXd& area = m.current_dual().triangle_area;
  const Eigen::VectorXd& p = m.pressure();
  double a_all = 0.0, pa_all = 0.0, a_away = 0.0, pa_away = 0.0, a_neg = 0.0;
  FracturePressure f;
  for (int s = 0; s < l.n_triangles(); ++s) {
    bool cracked = false, wall = false;
    for (int e : l.triangle_beams[static_cast<std::size_t>(s)]) {
      cracked = cracked || states[static_cast<std::size_t>(e)] != lt::BeamState::intact;
      wall = wall || l.beam_boundary[static_cast<std::size_t>(e)] == lt::BoundaryTag::inner;
    }
    if (!cracked) continue;
    ++f.n_all;
    a_all += area[s];
    pa_all += area[s] * p[s];
    if (wall) continue;
    ++f.n_away;
    a_away += area[s];
    pa_away += area[s] * p[s];
    if (p[s] < 0.0) a_neg += area[s];
    f.min_away = std::isnan(f.min_away) ? p[s] : std::min(f.min_away, p[s]);
  }
  if (f.n_all > 0) f.mean_all = pa_all / a_all;
  if (f.n_away > 0) f.mean_away = pa_away / a_away, f.negative_area_fraction = a_neg / a_away;
  return f;
}

/// The state at one output time.
struct Snapshot {
  double t = 0.0, p_h = 0.0;
  lt::FractureStatistics stats;
  FracturePressure fp;
  double u_pre = kNaN;  // before the first break only: max over shells |u_r/u_r,1D - 1| (information)
};

/// The same case without fracture, with fdm1d's flux-boundary borehole (borehole_storage = none,
/// borehole_deformation = none, as the cases have since errata E15), to the first output time: the
/// lattice's own error against 1D before fracture (Fig. 13's dashed curves).
struct TwinOutcome {
  bool ok = false;
  double t_end = 0.0;
  double max_error = kNaN, max_error_t = kNaN;  // max |p_h/p_h,1D - 1| for t* >= kWindow
  double u_error = kNaN;                        // max over shells |u_r/u_r,1D - 1| at t_end
  double end_error = kNaN;                      // |p_h/p_h,1D - 1| at t_end
};

/// One 2D run and what it showed.
struct RunOutcome {
  std::string label;  // the data folder
  double b = 0.0;
  long long n_particles = 0;
  unsigned long long seed = 0;
  double R_i = 0.0;
  bool ok = false;
  std::string message;
  int n_steps = 0, passes = 0, n_halvings = 0;
  double seconds = 0.0, mechanics = 0.0, fracture = 0.0, geometry = 0.0, flow = 0.0, max_balance = 0.0;
  std::vector<Snapshot> snaps;
  // Breakdown (Section 3.5), as RunRecorder's breakdown.csv.
  double t_first = kNaN, p_before = kNaN, p_first = kNaN, r_first = kNaN, length_first = kNaN;
  lt::FailureMode mode_first = lt::FailureMode::none;
  double t_peak = 0.0, p_peak = -std::numeric_limits<double>::infinity();
  // Broken beams never heal: steps where n_broken fell, and beams found intact after having broken.
  int n_broken_decreases = 0, n_healed = 0;
  // p_h against the 1D model (no fracture) before the first break.
  double pre_max = kNaN, pre_max_t = kNaN;  // max |p_h/p_h,1D - 1| for t* >= kWindow, and where
  double pre_last = kNaN, pre_last_t = kNaN;  // at the last step before the breaking one (any t*)
  double pre_signed_last = kNaN;               // p_h/p_h,1D - 1 there (signed)
  std::string twin_label;  // empty: no twin run
  TwinOutcome twin;
};

/// The 1D reference of a case: fdm1d (Appendix A, no fracture, flux-boundary borehole) with the
/// calibrated lattice's nu and the case's E/M, plane-strain volumetric strain (as benchmarks_lattice2d_vs_fdm1d.cpp),
/// on the case's dt sequence and output times.
fdm1d::Fdm1dResult run_reference(const RunCase& c) {
  analytic::DimensionlessParameters p = c.physics.parameters;
  p.material.nu = lt::calibrated_continuum(c.stiffness_scaling).poisson_ratio;
  p.material.vol_strain = analytic::VolStrain::plane_strain;
  fdm1d::Fdm1dNumerics n;
  n.n_r = 400;  // steady state within ~0.2% of Appendix B; far finer than the lattice
  n.dt_initial = c.stepping.dt_initial;
  n.dt_growth = c.stepping.dt_growth;
  n.dt_max = c.stepping.dt_max;
  n.t_end = c.stepping.t_end;
  n.output_times = c.output.times;
  n.output_times.erase(std::remove_if(n.output_times.begin(), n.output_times.end(),
                                      [&](double t) { return t >= c.stepping.t_end * (1 - 1e-12); }),
                       n.output_times.end());
  fdm1d::Fdm1dResult r = fdm1d::run_fdm1d(p, n);
  if (!r.summary.is_success()) throw std::runtime_error("fdm1d failed: " + r.summary.message);
  return r;
}

/// `progress` (null: silent) gets a line a minute and one at the end: the paper tier's runs take up to an hour.
RunOutcome run_case(const RunCase& c, const std::string& label, const fs::path& root, const fdm1d::Fdm1dResult& ref,
                    std::ostream* progress = nullptr) {
  RunOutcome o;
  o.label = label;
  o.b = c.physics.parameters.material.b;
  o.n_particles = c.lattice.n_particles;
  o.seed = c.lattice.seed;
  o.R_i = c.physics.parameters.R_i;
  // As verification/app/cmd_run.cpp: calibrated beams, strengths drawn per beam, the case's break loop.
  lt::CoupledModel model(lt::generate_lattice(c.lattice), c.beams(), c.boundary, c.mechanics,
                         c.flow_parameters(), c.coupling);
  model.enable_fracture(lt::draw_beam_strengths(c.strength, model.lattice().n_beams()), c.break_loop);
  const fs::path dir = root / label;
  fs::create_directories(dir);
  RunRecorder recorder(dir, c);
  const std::vector<double> edges =
      lt::uniform_shell_edges(o.R_i, c.output.radial_max, c.output.radial_bins);
  std::vector<bool> was_broken(static_cast<std::size_t>(model.lattice().n_beams()), false);
  int last_n_broken = 0;
  double last_p_h = 0.0;
  double pre_last_t = kNaN, pre_last_ratio = kNaN;
  std::optional<ProgressReporter> reporter;
  if (progress) reporter.emplace(*progress, label, 60.0);
  const auto run = model.run(c.stepping, [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
    recorder.record(m, s, out);
    const double t = m.time(), p_h = injection_pressure(m);
    if (reporter) reporter->update(t, c.stepping.t_end, "broken " + std::to_string(m.n_broken()));
    o.seconds += s.seconds;
    o.mechanics += s.mechanics_seconds;
    o.fracture += s.stress_seconds + s.break_seconds;
    o.geometry += s.geometry_seconds;
    o.flow += s.flow_seconds;
    if (p_h > o.p_peak) o.p_peak = p_h, o.t_peak = t;
    // Never heal: a beam once broken is never intact again, and the count never falls.
    const auto& states = m.mechanics().states();
    for (std::size_t e = 0; e < states.size(); ++e) {
      const bool broken = states[e] != lt::BeamState::intact;
      if (was_broken[e] && !broken) ++o.n_healed;
      was_broken[e] = was_broken[e] || broken;
    }
    if (m.n_broken() < last_n_broken) ++o.n_broken_decreases;
    last_n_broken = m.n_broken();
    const auto& log = m.break_log();
    if (std::isnan(o.t_first) && !log.empty()) {
      const lt::BreakEvent& e = log.front();
      o.t_first = t;
      o.p_before = last_p_h;
      o.p_first = p_h;
      o.r_first = e.position.norm();
      o.length_first = m.lattice().length[e.beam];
      o.mode_first = e.mode;
      o.pre_last = std::abs(pre_last_ratio), o.pre_last_t = pre_last_t, o.pre_signed_last = pre_last_ratio;
    }
    if (std::isnan(o.t_first) && t > 0.0) {
      const double ratio = p_h / borehole_pressure_at(ref, t) - 1.0;
      pre_last_ratio = ratio, pre_last_t = t;
      if (t >= kWindow * (1 - 1e-12) && (std::isnan(o.pre_max) || std::abs(ratio) > o.pre_max))
        o.pre_max = std::abs(ratio), o.pre_max_t = t;
    }
    last_p_h = p_h;
    if (!out || t <= 0.0) return;
    Snapshot snap;
    snap.t = t;
    snap.p_h = p_h;
    snap.stats = lt::compute_fracture_statistics(m.lattice(), states, log);
    snap.fp = fracture_pressure(m);
    if (log.empty()) {  // still unbroken: the radial u_r against 1D (the first curve of Fig. 13)
      for (const auto& s1 : ref.snapshots) {
        if (std::abs(s1.t - t) > 1e-9 * t) continue;
        const RadialFields f = radial_fields(m, edges);
        double e_max = 0.0;
        for (std::size_t k = 0; k < f.u_r.size(); ++k)
          e_max = std::max(e_max, std::abs(f.u_r[k] / shell_mean(ref.r, s1.u_r, edges[k], edges[k + 1]) - 1.0));
        snap.u_pre = e_max;
      }
    }
    o.snaps.push_back(snap);
  });
  o.ok = run.is_ok();
  o.message = run.message;
  o.n_steps = run.n_steps;
  o.passes = run.total_iterations;
  o.n_halvings = run.n_step_halvings;
  o.max_balance = run.max_balance_error;
  if (reporter)
    reporter->finish(o.ok ? std::to_string(o.n_steps) + " steps, " + std::to_string(o.passes) + " passes, " +
                                std::to_string(model.n_broken()) + " broken"
                          : "failed: " + o.message);
  if (!o.ok) return o;  // the folder stays, with the series up to the failure, for a look
  recorder.finish();
  std::ofstream(dir / "config.toml") << run_case_to_toml(
      c, to_toml(make_provenance("hmlattice verify (lattice2d.fig12 benchmark), run " + label)));
  return o;
}

TwinOutcome run_flux_twin(const RunCase& c, const std::string& label, const fs::path& root,
                          const fdm1d::Fdm1dResult& ref) {
  RunCase tc = c;
  tc.fracture_enabled = false;
  tc.borehole_storage = lt::BoreholeStorage::none;
  tc.borehole_deformation = lt::BoreholeDeformation::none;
  tc.stepping.t_end = c.output.times.empty() ? c.stepping.t_end : c.output.times.front();
  tc.stepping.output_times.clear();
  tc.output.times.clear();
  tc.output.vtk = false;
  TwinOutcome o;
  o.t_end = tc.stepping.t_end;
  lt::CoupledModel model(lt::generate_lattice(tc.lattice), tc.beams(), tc.boundary,
                         tc.mechanics, tc.flow_parameters(), tc.coupling);
  const fs::path dir = root / label;
  fs::create_directories(dir);
  RunRecorder recorder(dir, tc);
  const std::vector<double> edges = lt::uniform_shell_edges(c.physics.parameters.R_i, tc.output.radial_max,
                                                            tc.output.radial_bins);
  const auto run = model.run(tc.stepping, [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
    recorder.record(m, s, out);
    const double t = m.time();
    if (t >= kWindow * (1 - 1e-12)) {
      const double e = std::abs(injection_pressure(m) / borehole_pressure_at(ref, t) - 1.0);
      if (std::isnan(o.max_error) || e > o.max_error) o.max_error = e, o.max_error_t = t;
    }
    if (!out || t < o.t_end * (1 - 1e-12)) return;
    o.end_error = std::abs(injection_pressure(m) / borehole_pressure_at(ref, t) - 1.0);
    for (const auto& s1 : ref.snapshots) {
      if (std::abs(s1.t - t) > 1e-9 * t) continue;
      const RadialFields f = radial_fields(m, edges);
      o.u_error = 0.0;
      for (std::size_t k = 0; k < f.u_r.size(); ++k)
        o.u_error = std::max(o.u_error, std::abs(f.u_r[k] / shell_mean(ref.r, s1.u_r, edges[k], edges[k + 1]) - 1.0));
    }
  });
  o.ok = run.is_ok();
  if (o.ok) recorder.finish();
  return o;
}

// --- reporting ----------------------------------------------------------------------------------

std::string run_name(const RunOutcome& o) {
  return "b = " + fmt(o.b) + ", N = " + std::to_string(o.n_particles) + ", seed " + std::to_string(o.seed);
}

std::string sign_word(double x) { return std::isnan(x) ? "-" : (x < 0.0 ? "negative" : "positive"); }

Table snapshot_table() {
  return {"Per output time: broken beams; radial fractures as clusters (connected to the borehole) and as arms "
          "crossing r = R_i + (1 - R_i)/4; radial clusters reaching r = 1; secondary clusters (all, and those at least "
          "0.05 R long: most are single broken beams); borehole pressure; "
          "mean pressure in the fracture triangles (area-weighted over triangles with a broken beam, without / with "
          "the borehole-wall triangles) and its sign. Paper (Section 3.3, Fig. 12): 3 radial fractures for b = 0.2, "
          "7 for b = 0.8, all at r = 1 at the last time, negative pressure in the fractures",
          {"run", "t*", "n_broken", "radial (clusters)", "arms", "radial at r = 1", "secondary", "secondary >= 0.05", "p_h",
           "p in fractures (no wall tri.)", "with wall tri.", "min p in fractures", "sign", "paper: fractures"},
          {}};
}

void add_snapshot_rows(const RunOutcome& o, Table& t) {
  for (const auto& s : o.snaps)
    t.rows.push_back({run_name(o), fmt(s.t), std::to_string(s.stats.n_broken), std::to_string(s.stats.n_radial),
                      std::to_string(s.stats.n_arms), std::to_string(s.stats.n_radial_reaching_outer),
                      std::to_string(s.stats.n_secondary), std::to_string(s.stats.n_secondary_sizable), fmt(s.p_h), fmt(s.fp.mean_away) + " (" + std::to_string(s.fp.n_away) + " tri.)",
                      fmt(s.fp.mean_all), fmt(s.fp.min_away), sign_word(s.fp.mean_away),
                      std::to_string(paper_fracture_count(o.b)) + (&s == &o.snaps.back() ? ", all at r = 1" : "")});
}

Table breakdown_table() {
  return {"Breakdown (Section 3.5): the step that broke the first beam (its time, p_h^n before it, its converged "
          "p_h^{n+1}), where and how the first beam broke, the peak borehole pressure; before the first break, the "
          "2D p_h against fdm1d (no fracture, flux-boundary borehole) for t* >= " + fmt(kWindow),
          {"run", "t* first break", "p_h before", "p_h at first break", "first break: r (R_i), mode",
           "t* peak", "p_h peak", "max |p_h/p_h,1D - 1| before, t* >= " + fmt(kWindow) + " (at t*)", "p_h/p_h,1D - 1 just before (t*)",
           "max |u_r/u_r,1D - 1| unbroken snapshot", "flux-borehole twin: |p_h/p_h,1D - 1| at its end; max for t* >= " + fmt(kWindow) + " (at t*)",
           "twin: max |u_r/u_r,1D - 1| (t*)"},
          {}};
}

void add_breakdown_row(const RunOutcome& o, Table& t) {
  std::string u = "-";
  for (const auto& s : o.snaps)
    if (!std::isnan(s.u_pre)) u = fmt(s.u_pre) + " (t* = " + fmt(s.t) + ")";
  t.rows.push_back({run_name(o), fmt(o.t_first), fmt(o.p_before), fmt(o.p_first),
                    fmt(o.r_first) + " (" + fmt(o.R_i) + "), " + lt::to_string(o.mode_first), fmt(o.t_peak),
                    fmt(o.p_peak), fmt(o.pre_max) + " (" + fmt(o.pre_max_t) + ")",
                    fmt(o.pre_signed_last) + " (" + fmt(o.pre_last_t) + ")", u,
                    o.twin_label.empty() ? "-" : fmt(o.twin.end_error) + "; " + fmt(o.twin.max_error) + " (" + fmt(o.twin.max_error_t) + ")",
                    o.twin_label.empty() ? "-" : fmt(o.twin.u_error) + " (" + fmt(o.twin.t_end) + ")"});
}

Table timing_table() {
  return {"Runs: steps, coupling passes, step halvings, wall time and its split (sums of CoupledStepSummary's "
          "mechanical solves (break loops' included), stresses + downdates, geometry, flow), max volume-balance error "
          "per step",
          {"run", "steps", "passes", "halvings", "wall s", "mechanics s", "stresses + downdates s", "geometry s", "flow s",
           "balance"},
          {}};
}

void add_timing_row(const RunOutcome& o, Table& t) {
  t.rows.push_back({run_name(o), std::to_string(o.n_steps), std::to_string(o.passes), std::to_string(o.n_halvings),
                    fmt(o.seconds), fmt(o.mechanics), fmt(o.fracture), fmt(o.geometry), fmt(o.flow),
                    fmt(o.max_balance)});
}

Metric flag(const std::string& name, bool value, const std::string& why, bool gating = true) {
  return {.name = name, .value = value ? 1.0 : 0.0, .reference = 1.0, .tolerance = 0.0,
          .comparison = Comparison::abs_error, .justification = why, .gating = gating};
}

/// What must hold for every run (gating), and the 1D comparison before the first break (not gating).
void add_gating_metrics(const RunOutcome& o, std::vector<Metric>& m) {
  const std::string tag = run_name(o) + ": ";
  m.push_back(flag(tag + "run completed (every step converged)", o.ok,
                   "a numerical failure is a failure: " + (o.message.empty() ? std::string("ok") : o.message)));
  m.push_back({.name = tag + "volume balance, max relative error per step", .value = o.max_balance,
               .reference = 0.0, .tolerance = 1e-8, .comparison = Comparison::at_most,
               .justification = "the flow scheme is conservative by construction, broken segments included: round-off "
                                "(issue 5: <= 1e-8)"});
  m.push_back(flag(tag + "first break tensile, at the borehole wall (|r - R_i| <= its beam length)",
                   o.mode_first == lt::FailureMode::tensile && std::abs(o.r_first - o.R_i) <= o.length_first,
                   "Section 3.2/3.3: the hoop stress is largest and tensile at the wall, so fractures initiate there "
                   "in tension (measured: r = " + fmt(o.r_first) + ", " + lt::to_string(o.mode_first) + ")"));
  m.push_back({.name = tag + "radial fractures at the last output time", .value = o.snaps.empty() ? 0.0 : static_cast<double>(o.snaps.back().stats.n_radial),
               .reference = 1.0, .tolerance = 1.0, .comparison = Comparison::at_least,
               .justification = "Fig. 12: radial fractures initiate at the borehole wall in both cases; how many is "
                                "the non-gating comparison below"});
  m.push_back({.name = tag + "broken beams found intact again, and steps where n_broken fell",
               .value = static_cast<double>(o.n_healed + o.n_broken_decreases), .reference = 0.0, .tolerance = 0.0,
               .comparison = Comparison::at_most,
               .justification = "Section 2.1: breaking is irreversible (no healing); checked after every step"});
  m.push_back({.name = tag + "|p_h/p_h,1D - 1| at the last step before the first break (t* = " + fmt(o.pre_last_t) + ")",
               .value = o.pre_last, .reference = 0.0, .tolerance = 0.05, .comparison = Comparison::at_most,
               .justification = "information, not gating: the first breaks come in the first steps, where the lattice "
                                "cannot resolve the wall's pressure boundary layer sqrt(t/S) (p_h +73% to +250% above 1D at "
                                "t* = 1e-5, N = 1e4, docs/lattice_vs_fdm1d.md; nan: the first step already broke). Eq. 16's "
                                "borehole node instead holds p_h 75-83% below 1D (errata E15); the unfractured twin below "
                                "is what is gated",
               .gating = false});
  if (o.twin_label.empty()) return;
  // The twin's tolerances. N >= 1e4: issue 5's 5% (lattice2d.vs_fdm1d holds it at N = 1e4 and 3e4 with
  // the same borehole). Coarser (the quick tier's N = 3000, h ~ 0.034): regression guards at ~1.5x the
  // values measured on 2026-11-22 (seed 1), each with its reason.
  const bool fine = o.n_particles >= 10000;
  m.push_back(flag(tag + "flux-borehole twin (no fracture) completed", o.twin.ok, "a numerical failure is a failure"));
  m.push_back({.name = tag + "flux-borehole twin: |p_h/p_h,1D - 1| at t* = " + fmt(o.twin.t_end),
               .value = o.twin.end_error, .reference = 0.0, .tolerance = 0.05, .comparison = Comparison::at_most,
               .justification = "issue 5: the borehole pressure within 5% of 1D (measured at N = 3000: 0.3% for b = "
                                "0.2 at t* = 4.5e-3, 4.6% for b = 0.8 at t* = 2.3e-3)"});
  m.push_back({.name = tag + "flux-borehole twin: max |p_h/p_h,1D - 1|, " + fmt(kWindow) + " <= t* <= " + fmt(o.twin.t_end),
               .value = o.twin.max_error, .reference = 0.0, .tolerance = fine ? 0.05 : 0.13,
               .comparison = Comparison::at_most,
               .justification = fine ? std::string("issue 5's 5% over t* >= 1e-3, as lattice2d.vs_fdm1d")
                                     : std::string("regression guard at N = 3000: measured 0.7% (b = 0.2), 11.2% (b = 0.8, at "
                                                   "t* = 1.06e-3, where the wall boundary layer sqrt(t/S) = 0.024 is under "
                                                   "one lattice spacing, 0.034; it decays to 4.6% by t* = 2.3e-3)")});
  m.push_back({.name = tag + "flux-borehole twin: max |u_r/u_r,1D - 1| over shells at t* = " + fmt(o.twin.t_end),
               .value = o.twin.u_error, .reference = 0.0, .tolerance = fine ? 0.05 : 0.12,
               .comparison = Comparison::at_most,
               .justification = fine ? std::string("issue 5's 5%, as lattice2d.vs_fdm1d")
                                     : std::string("regression guard at N = 3000: the wall row's first-order error, 7.6% "
                                                   "at N = 4000 (lattice2d.vs_fdm1d_quick), 2.3-3.2% at N = 1e4; "
                                                   "measured 8.1% (b = 0.2), 2.5% (b = 0.8)")});
}

/// The paper's reading of Fig. 12, shown beside ours (never gating).
void add_paper_metrics(const RunOutcome& o, std::vector<Metric>& m) {
  if (o.snaps.empty()) return;
  const std::string tag = run_name(o) + ": ";
  const Snapshot& last = o.snaps.back();
  const double paper = paper_fracture_count(o.b);
  const std::string why = "the paper's Fig. 12 (Section 3.3, N = 1e5, one realisation): shown, not tuned";
  m.push_back({.name = tag + "radial fractures (arms) at t* = " + fmt(last.t), .value = static_cast<double>(last.stats.n_arms),
               .reference = paper, .tolerance = 0.0, .comparison = Comparison::abs_error, .justification = why,
               .gating = false});
  m.push_back({.name = tag + "radial fractures (clusters) at t* = " + fmt(last.t),
               .value = static_cast<double>(last.stats.n_radial), .reference = paper, .tolerance = 0.0,
               .comparison = Comparison::abs_error, .justification = why, .gating = false});
  m.push_back(flag(tag + "every radial fracture reaches r = 1 at t* = " + fmt(last.t),
                   last.stats.n_radial > 0 && last.stats.n_radial_reaching_outer == last.stats.n_radial,
                   why + " (" + std::to_string(last.stats.n_radial_reaching_outer) + " of " +
                       std::to_string(last.stats.n_radial) + ")",
                   false));
  for (const auto& s : o.snaps) {
    if (s.fp.n_away == 0) continue;
    m.push_back({.name = tag + "mean pressure in the fractures (no wall triangles) at t* = " + fmt(s.t),
                 .value = s.fp.mean_away, .reference = 0.0, .tolerance = 0.0, .comparison = Comparison::at_most,
                 .justification = "Section 3.3: negative pressure in and along the fractures for iota = 1 (the open "
                                  "volume cannot be filled); shown, not tuned",
                 .gating = false});
  }
}

/// runs.csv: which folder is which (text columns; read by the figure scripts with csv.DictReader).
void write_index(const fs::path& root, const std::vector<RunOutcome>& runs, const std::vector<bool>& in_figure) {
  std::ofstream f(root / "runs.csv");
  f << "run,b,n_particles,seed,fdm1d,figure,flux_twin\n";
  for (std::size_t k = 0; k < runs.size(); ++k)
    f << runs[k].label << "," << fmt(runs[k].b) << "," << runs[k].n_particles << "," << runs[k].seed << ",fdm1d_b"
      << fmt(runs[k].b) << "," << (in_figure[k] ? 1 : 0) << "," << runs[k].twin_label << "\n";
  f.close();
  if (!f) throw std::runtime_error("cannot write " + (root / "runs.csv").string());
}

fdm1d::Fdm1dResult write_reference(const RunCase& c, const fs::path& root) {
  const fdm1d::Fdm1dResult ref = run_reference(c);
  const fs::path d = root / ("fdm1d_b" + fmt(c.physics.parameters.material.b));
  fs::create_directories(d);
  analytic::DimensionlessParameters p = c.physics.parameters;
  p.material.nu = lt::calibrated_continuum(c.stiffness_scaling).poisson_ratio;
  p.material.vol_strain = analytic::VolStrain::plane_strain;
  write_fdm1d_results(d, ref, p);
  return ref;
}

std::vector<Figure> figures(const std::string& subdir, const std::string& what) {
  return {{"fig12_fracture_pressure.py", "fig12_fracture_pressure.png",
           "Fig. 12 (" + what + "): pressure per triangle (diverging colours centred on 0, limits from each snapshot's "
           "min and max), broken beams in black, the borehole outline, at the case's output times; b = 0.2 (top), "
           "0.8 (bottom).",
           subdir},
          {"fig13_displacement_vs_1d.py", "fig13_displacement_vs_1d.png",
           "Fig. 13 (" + what + "): radially averaged u_r of the fracturing lattice (solid, markers) and of fdm1d "
           "without fracture (dashed) at the paper's times; borehole pressure 2D vs 1D with the first break marked.",
           subdir}};
}

std::string notes_common() {
  return "Definitions (docs/borehole_fracture.md): a *fracture* is a cluster of broken beams connected through shared "
         "particles (fracture_statistics.hpp; `hmlattice fractures <run> --link triangle` recomputes a run with the "
         "stricter shared-triangle rule, which cut the N = 1e5 fractures into pieces); *radial* clusters contain a "
         "broken borehole-wall beam. Cracks that "
         "merge at the wall form one cluster, so the count comparable with the paper's figure is the number of "
         "*arms*: groups of broken beams crossing the circle r = R_i + (1 - R_i)/4. The *pressure in the fractures* "
         "is the area-weighted mean over the triangles that have a broken beam, without the triangles on the "
         "borehole wall (their pressure follows p_h through the wall segment); the mean with them is shown beside. "
         "The 1D reference is fdm1d with the calibrated lattice's nu = " + fmt(lt::calibrated_continuum().poisson_ratio) +
         ", the case's E/M, plane-strain volumetric strain, n_r = 400, on the case's dt sequence; it has no "
         "fracture and a flux-boundary borehole (no storage), as the cases (errata E15: Eq. 16's borehole node "
         "would hold p_h 75-83% below 1D before the first break). What is gated against 1D is the *unfractured twin* "
         "(same case and lattice, fracture off, to the first output time; folders <case>_flux_borehole/, dotted in "
         "Fig. 13).";
}

// --- quick tier ---------------------------------------------------------------------------------

BenchmarkResult fig12_quick(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const fs::path root = ctx.data_dir / "fig12_quick";
  fs::create_directories(root);
  Table snaps = snapshot_table(), breakdown = breakdown_table(), timing = timing_table();
  std::vector<RunOutcome> runs;
  for (const std::string name : {"fig12_b0.2_quick", "fig12_b0.8_quick"}) {
    const RunCase c = read_run_case(fs::path(HM_SOURCE_DIR) / "cases" / (name + ".toml"));
    const fdm1d::Fdm1dResult ref = write_reference(c, root);
    runs.push_back(run_case(c, name, root, ref));
    runs.back().twin_label = name + "_flux_borehole";
    runs.back().twin = run_flux_twin(c, runs.back().twin_label, root, ref);
  }
  write_index(root, runs, {true, true});
  for (const auto& o : runs) {
    add_snapshot_rows(o, snaps);
    add_breakdown_row(o, breakdown);
    add_timing_row(o, timing);
    add_gating_metrics(o, res.metrics);
    add_paper_metrics(o, res.metrics);
  }
  res.tables = {snaps, breakdown, timing};
  res.figures = figures("fig12_quick", "quick tier, N = 3000");
  res.notes.push_back(notes_common());
  res.notes.push_back("At N = 3000 the lattice spacing is ~0.034 (the borehole is ~25 spacings round): the fracture "
                      "counts are a first look, not the paper's resolution (the paper tier runs N = 1e5 and a seed "
                      "scatter at N = 2e4). Data: fig12_quick/<case>/ as `hmlattice run` writes it, "
                      "fig12_quick/fdm1d_b<b>/ as `hmlattice fdm1d` writes it, runs.csv.");
  return res;
}

// --- paper tier ---------------------------------------------------------------------------------

/// The seed scatter's resolution: our choice, ~5x cheaper than N = 1e5 (~3-5 min a run) and ~2.5 spacings
/// finer than the quick tier.
constexpr long long kScatterN = 20000;

std::string mean_sd(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return fmt(mean) + " ± " + fmt(x.size() > 1 ? std::sqrt(ss / (n - 1.0)) : 0.0);
}

BenchmarkResult fig12_paper(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const fs::path root = ctx.data_dir / "fig12_paper";
  fs::create_directories(root);
  Table snaps = snapshot_table(), breakdown = breakdown_table(), timing = timing_table();
  Table scatter{"Seed scatter at N = " + std::to_string(kScatterN) + " (seeds 1, 2, 3 of the lattice and the strengths): "
                "mean ± sample standard deviation over the three runs",
                {"b", "t*", "n_broken", "radial (clusters)", "arms", "radial at r = 1", "secondary", "secondary >= 0.05",
                 "p in fractures (no wall tri.)", "p_h"},
                {}};
  Table scatter_bd{"Seed scatter at N = " + std::to_string(kScatterN) + ": breakdown, mean ± sd over seeds 1, 2, 3",
                   {"b", "t* first break", "p_h at first break", "t* peak", "p_h peak"},
                   {}};
  std::vector<RunOutcome> runs;
  std::vector<bool> in_figure;
  for (const std::string b : {"0.2", "0.8"}) {
    const RunCase c = read_run_case(fs::path(HM_SOURCE_DIR) / "cases" / "paper" / ("fig12_b" + b + ".toml"));
    const fdm1d::Fdm1dResult ref = write_reference(c, root);
    runs.push_back(run_case(c, "fig12_b" + b, root, ref, ctx.progress));
    runs.back().twin_label = "fig12_b" + b + "_flux_borehole";
    runs.back().twin = run_flux_twin(c, runs.back().twin_label, root, ref);
    in_figure.push_back(true);
    std::vector<RunOutcome> seeds;
    for (unsigned long long seed : {1ULL, 2ULL, 3ULL}) {
      RunCase cs = c;
      cs.lattice.n_particles = kScatterN;
      cs.lattice.seed = seed;
      cs.strength.seed = seed;
      seeds.push_back(run_case(cs, "fig12_b" + b + "_N" + std::to_string(kScatterN) + "_seed" + std::to_string(seed),
                               root, ref, ctx.progress));
    }
    // Mean ± sd per output time (the runs share the output times; a failed run is left out).
    std::vector<const RunOutcome*> ok;
    for (const auto& s : seeds)
      if (s.ok) ok.push_back(&s);
    if (!ok.empty()) {
      for (std::size_t k = 0; k < ok.front()->snaps.size(); ++k) {
        std::vector<double> nb, nr, na, no, ns, nz, fp, ph;
        for (const RunOutcome* s : ok) {
          if (k >= s->snaps.size()) continue;
          const Snapshot& q = s->snaps[k];
          nb.push_back(q.stats.n_broken), nr.push_back(q.stats.n_radial), na.push_back(q.stats.n_arms);
          no.push_back(q.stats.n_radial_reaching_outer), ns.push_back(q.stats.n_secondary);
          nz.push_back(q.stats.n_secondary_sizable);
          fp.push_back(q.fp.mean_away), ph.push_back(q.p_h);
        }
        scatter.rows.push_back({b, fmt(ok.front()->snaps[k].t), mean_sd(nb), mean_sd(nr), mean_sd(na), mean_sd(no),
                                mean_sd(ns), mean_sd(nz), mean_sd(fp), mean_sd(ph)});
      }
      std::vector<double> tf, pf, tp, pp;
      for (const RunOutcome* s : ok) tf.push_back(s->t_first), pf.push_back(s->p_first), tp.push_back(s->t_peak), pp.push_back(s->p_peak);
      scatter_bd.rows.push_back({b, mean_sd(tf), mean_sd(pf), mean_sd(tp), mean_sd(pp)});
    }
    for (auto& s : seeds) {
      runs.push_back(std::move(s));
      in_figure.push_back(false);
    }
  }
  write_index(root, runs, in_figure);
  for (const auto& o : runs) {
    add_snapshot_rows(o, snaps);
    add_breakdown_row(o, breakdown);
    add_timing_row(o, timing);
    add_gating_metrics(o, res.metrics);
    add_paper_metrics(o, res.metrics);
  }
  res.tables = {snaps, scatter, breakdown, scatter_bd, timing};
  res.figures = figures("fig12_paper", "paper tier, N = 1e5");
  res.notes.push_back(notes_common());
  res.notes.push_back("Data: fig12_paper/fig12_b<b>/ (N = 1e5, the figures) and fig12_paper/fig12_b<b>_N" +
                      std::to_string(kScatterN) + "_seed<s>/ (the scatter), as `hmlattice run` writes them; "
                      "fig12_paper/fdm1d_b<b>/, runs.csv.");
  return res;
}

}  // namespace

void add_lattice2d_borehole_fracture_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({.id = "lattice2d.fig12_quick",
                  .title = "Fracture from a pressurised borehole, b = 0.2 and 0.8, N = 3000 (Figs. 12-13, quick)",
                  .description = "cases/fig12_b0.2_quick.toml and cases/fig12_b0.8_quick.toml (Q = 0.01, iota = 1, "
                                 "free annulus): fracture counts, breakdown pressure and the pressure in the "
                                 "fractures per output time, beside the paper's Fig. 12; the borehole pressure "
                                 "before the first break against fdm1d.",
                  .tier = Tier::quick,
                  .run = fig12_quick});
  into.push_back({.id = "lattice2d.fig12",
                  .title = "Fracture from a pressurised borehole, b = 0.2 and 0.8, N = 1e5 and a seed scatter at "
                           "N = 2e4 (Figs. 12-13)",
                  .description = "cases/paper/fig12_b0.2.toml and cases/paper/fig12_b0.8.toml at the paper's "
                                 "resolution, and each at N = 2e4 with seeds 1, 2, 3: as the quick benchmark, plus "
                                 "mean ± sd over the seeds and each run's wall time.",
                  .tier = Tier::paper,
                  .run = fig12_paper});
}

}  // namespace hm::verification
