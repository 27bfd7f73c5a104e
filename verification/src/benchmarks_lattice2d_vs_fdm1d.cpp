// The 2D coupled lattice against the radial 1D model before fracture (Sections 3.2-3.3; the dashed
// curves of Figs. 13 and 15): continuous injection Q = 0.01 into the borehole of a free annulus
// (R_i = 0.138), fracture off, b = 0.2, 0.5, 0.8. Compared: the borehole pressure history p_h(t) and
// the radially averaged u_r and p at several times. This is the one place that runs both models.
//
// How the two are made to describe the same problem:
//  - the borehole. fdm1d's borehole is a flux boundary at r = R_i (no storage, no b dV_h term), so the
//    lattice's borehole node is configured as borehole_storage = none, borehole_deformation = none
//    (docs/flow.md, "Borehole storage"). With that the plain coupling loop (undrained split, Psi = 1.3, no
//    relaxation) converges in ~10 passes per step.
//  - the continuum. The calibrated lattice is E = 1.000, nu = 0.250 (calibrated_continuum(); 0.2236
//    with the paper's uniform beams), so fdm1d is run with that nu and the model's own E/M (Eq. 22 at Table 1 with nu =
//    0.25: the same number in both models), vol_strain = plane-strain (the lattice's volumetric strain is the
//    triangle-area change). A 1D run with nu = 0.25 (the paper's comparison) is shown beside it, not gating.
//  - time. Both run implicit Euler on the same dt sequence (dt from 1e-5, growth 1.2, dt_max 2e-3,
//    steps shortened to land on the output times), so their difference is the lattice's spatial
//    discretisation, not a time error. A 1D run with finer steps (dt / 10, growth 1.02) shows how large that shared
//    time error is (information).
//  - averaging. The lattice's shell value is the area-weighted mean over the triangles whose centroid
//    lies in the shell (radial_fields); the 1D value is the area-weighted mean of the nodal profile over
//    the same shell, integral f r dr / integral r dr.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fdm1d_sampling.hpp"
#include "hm/analytic/physical_parameters.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/fdm1d_output.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/run_output.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/fdm1d/fdm1d.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/io/radial_average.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/verification/benchmark.hpp"
#include "report_writer.hpp"

namespace hm::verification {

using cases::injection_pressure;
using cases::radial_fields;
using cases::RadialFields;
using cases::RunCase;
using cases::RunRecorder;
using cases::write_fdm1d_results;
using core::CsvWriter;

namespace {

namespace lt = hm::lattice2d;
namespace fs = std::filesystem;

constexpr double kQ = 0.01;
constexpr int kShells = 20;  // shells 0.0431 wide on [R_i, 1], ~2 mean beam lengths at N = 1e4 (h = 0.020)

/// The shared time stepping (our choice, as cases/borehole_b0.5_nofracture.toml).
struct Stepping {
  double dt_initial = 1e-5, dt_growth = 1.2, dt_max = 2e-3, t_end = 0.1;
  std::vector<double> times;  // compared profile times; t_end among them
};

/// One 2D-vs-1D comparison.
struct Comparison1d {
  double b = 0.5;
  long long n_particles = 10000;
  Stepping stepping;
};

/// The p_h history is compared for t* >= kWindow: before it the pressure boundary layer at the wall,
/// sqrt(t/S) (S = 0.34, 0.97, 1.76 for b = 0.2, 0.5, 0.8), is thinner than ~1.2 mean beam lengths
/// at N = 1e4 (h = 0.020) for b = 0.8, and the lattice cannot resolve it (docs/lattice_vs_fdm1d.md).
constexpr double kWindow = 1e-3;
constexpr double kEarly = 1e-4;  // the early-time error shown (and checked to shrink under refinement)

std::string run_label(double b, long long n) {
  std::string label = "b";  // appended piecewise: gcc 12's -Wrestrict misfires on "b" + std::string
  label += fmt(b);
  label += "_N";
  label += std::to_string(n);
  return label;
}

/// The 2D case: the lattice annulus with the flux-boundary borehole, fracture off.
RunCase lattice_case(const Comparison1d& v) {
  RunCase c;
  c.physics.parameters = analytic::table1_borehole(v.b, kQ);  // nu = 0.25, E/M by Eq. 22, R_i = 0.138
  c.lattice.domain = lt::DomainShape::annulus;
  c.lattice.inner_radius = c.physics.parameters.R_i;
  c.lattice.n_particles = v.n_particles;
  c.lattice.seed = 1;
  c.boundary.outer = lt::BoundarySupport::free;
  c.flow.borehole_storage = lt::BoreholeStorage::none;
  c.flow.borehole_deformation = lt::BoreholeDeformation::none;
  c.coupling.split = lt::CouplingSplit::undrained;
  c.coupling.terms.psi = 1.3;
  c.coupling.relaxation = lt::CouplingRelaxation::none;
  c.stepping.dt_initial = v.stepping.dt_initial;
  c.stepping.dt_growth = v.stepping.dt_growth;
  c.stepping.dt_max = v.stepping.dt_max;
  c.stepping.t_end = v.stepping.t_end;
  c.stepping.output_times = v.stepping.times;
  c.output.vtk = false;
  c.output.radial_bins = kShells;
  c.output.radial_max = 1.0;
  return c;
}

/// The 1D reference: the lattice's continuum (nu = calibrated) unless `nu` is given; E/M the model's.
/// `fine` refines time: dt_initial and dt_max / 10 and growth 1.02 (dt/t ~ 0.02 instead of ~ 0.17 while
/// the steps grow).
fdm1d::Fdm1dResult run_reference(double b, const Stepping& s, double nu, bool fine = false) {
  analytic::DimensionlessParameters p = analytic::table1_borehole(b, kQ);  // E/M at nu = 0.25
  p.material.nu = nu;
  p.material.vol_strain = analytic::VolStrain::plane_strain;
  fdm1d::Fdm1dNumerics n;
  n.n_r = 400;  // steady state within ~0.2% of Appendix B (fdm1d.steady_state); far finer than the lattice
  n.dt_initial = fine ? s.dt_initial / 10 : s.dt_initial;
  n.dt_growth = fine ? 1.02 : s.dt_growth;
  n.dt_max = fine ? s.dt_max / 10 : s.dt_max;
  n.t_end = s.t_end;
  n.output_times = s.times;
  return fdm1d::run_fdm1d(p, n);
}

const fdm1d::Fdm1dSnapshot& snapshot_at(const fdm1d::Fdm1dResult& r, double t) {
  for (const auto& s : r.snapshots)
    if (std::abs(s.t - t) <= 1e-9 * t) return s;
  throw std::runtime_error("fdm1d has no snapshot at t = " + fmt(t));
}

/// Errors at one compared time.
struct ProfileErrors {
  double t = 0.0;
  double u_local = 0.0;               // max over shells of |u2 - u1| / u1 (u1 the 1D shell mean, > 0)
  double u_max = 0.0;                 // max over shells of |u2 - u1| / max u1
  double p = 0.0;                     // max over shells of |p2 - p1| / p_h,1D(t)
  double u_local25 = 0.0, p25 = 0.0;  // the same against fdm1d with nu = 0.25 (the paper's comparison)
  // Fluid taken up by the deformation since t = 0, b (V - V0) summed over the rock: lattice over 1D - 1,
  // and the difference over the injected volume Q t.
  double uptake_rel = 0.0, uptake_of_injected = 0.0;
  double r_u_local = 0.0, r_p = 0.0;  // where
};

struct Outcome {
  Comparison1d setting;
  std::vector<ProfileErrors> profiles;
  std::vector<std::pair<double, double>> p_h_error;  // (t, p_h2/p_h1 - 1) after every step
  double p_h_window = 0.0, p_h_window_t = 0.0;       // max |p_h2/p_h1 - 1| for t >= kWindow, and where
  double p_h_half_window = 0.0;                      // ... for t >= kWindow / 2 (information)
  double p_h_first = 0.0, p_h_first_t = 0.0;         // |p_h2/p_h1 - 1| at the first step
  double p_h_early = 0.0;                            // ... at the last step with t <= kEarly
  int n_steps = 0, passes = 0, max_passes = 0;
  double seconds = 0.0, max_balance = 0.0;
  bool ok = false;
  std::string message;
  // 1D, information: nu = 0.25 vs the lattice's nu, and the shared time error.
  double nu_u = 0.0, nu_p = 0.0, nu_p_h = 0.0;
  double dt_p_h = 0.0, dt_u = 0.0;
};

/// The borehole pressure's errors over the run, from o.p_h_error: first step, early, windows.
void summarise_p_h_errors(Outcome& o) {
  for (const auto& [t, e] : o.p_h_error) {
    if (o.p_h_first_t == 0.0) o.p_h_first = std::abs(e), o.p_h_first_t = t;
    if (t <= kEarly * (1 + 1e-12)) o.p_h_early = std::abs(e);
    if (t >= 0.5 * kWindow * (1 - 1e-12)) o.p_h_half_window = std::max(o.p_h_half_window, std::abs(e));
    if (t >= kWindow * (1 - 1e-12) && std::abs(e) > o.p_h_window) o.p_h_window = std::abs(e), o.p_h_window_t = t;
  }
}

/// 1D against 1D: the effect of nu (the paper's 0.25 vs the lattice's) and of the shared dt.
void compare_1d_variants(const fdm1d::Fdm1dResult& ref, const fdm1d::Fdm1dResult& ref25,
                         const fdm1d::Fdm1dResult& ref_fine, Outcome& o) {
  for (std::size_t k = 0; k < ref.snapshots.size(); ++k) {
    const auto &a = ref.snapshots[k], &n25 = ref25.snapshots[k], &fine = snapshot_at(ref_fine, a.t);
    const double p_h = a.p.front();
    double u_scale = 0.0;
    for (double u : a.u_r) u_scale = std::max(u_scale, std::abs(u));
    for (std::size_t i = 0; i < ref.r.size(); ++i) {
      o.nu_u = std::max(o.nu_u, std::abs(n25.u_r[i] - a.u_r[i]) / u_scale);
      o.nu_p = std::max(o.nu_p, std::abs(n25.p[i] - a.p[i]) / p_h);
      o.dt_u = std::max(o.dt_u, std::abs(fine.u_r[i] - a.u_r[i]) / u_scale);
    }
  }
  for (const auto& h : ref.borehole)
    if (h.t >= kWindow * (1 - 1e-12)) {
      o.nu_p_h = std::max(o.nu_p_h, std::abs(borehole_pressure_at(ref25, h.t) / h.p_h - 1.0));
      o.dt_p_h = std::max(o.dt_p_h, std::abs(borehole_pressure_at(ref_fine, h.t) / h.p_h - 1.0));
    }
}

/// The 1D run's folder (as `hmlattice fdm1d` writes it) and its profiles, both nu, for the figure.
void write_1d_profiles(double b, const fdm1d::Fdm1dResult& ref, const fdm1d::Fdm1dResult& ref25, const fs::path& root,
                       CsvWriter& p1d_csv) {
  const fs::path d1 = root / ("fdm1d_b" + fmt(b));
  fs::create_directories(d1);
  write_fdm1d_results(d1, ref, analytic::table1_borehole(b, kQ));
  for (std::size_t k = 0; k < ref.snapshots.size(); ++k)
    for (std::size_t i = 0; i < ref.r.size(); ++i)
      p1d_csv.row({b, ref.snapshots[k].t, ref.r[i], ref.snapshots[k].u_r[i], ref.snapshots[k].p[i],
                   ref25.snapshots[k].u_r[i], ref25.snapshots[k].p[i]});
}

/// Runs both models for one setting, writes the CSV for the figure, returns the errors.
Outcome compare(const Comparison1d& v, const fs::path& root, CsvWriter& ph_csv, CsvWriter& p2d_csv, CsvWriter* p1d_csv,
                Table& profile_table) {
  Outcome o;
  o.setting = v;
  const double nu_lattice = lt::calibrated_continuum().poisson_ratio;
  const fdm1d::Fdm1dResult ref = run_reference(v.b, v.stepping, nu_lattice);
  const fdm1d::Fdm1dResult ref25 = run_reference(v.b, v.stepping, 0.25);
  const fdm1d::Fdm1dResult ref_fine = run_reference(v.b, v.stepping, nu_lattice, true);
  if (!ref.summary.is_success() || !ref25.summary.is_success() || !ref_fine.summary.is_success())
    throw std::runtime_error("fdm1d failed: " + ref.summary.message + ref25.summary.message + ref_fine.summary.message);
  if (p1d_csv) write_1d_profiles(v.b, ref, ref25, root, *p1d_csv);

  // The 2D run, written as `hmlattice run` writes it.
  const RunCase c = lattice_case(v);
  const auto model = cases::make_coupled_model(c);
  const fs::path dir = root / run_label(v.b, v.n_particles);
  fs::create_directories(dir);
  RunRecorder recorder(dir, c);
  const std::vector<double> edges = lt::uniform_shell_edges(c.physics.parameters.R_i, 1.0, kShells);
  const auto run = model->run(c.stepping, [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
    recorder.record(m, s, out);
    const double t = m.time();
    if (t <= 0.0) return;
    o.max_passes = std::max(o.max_passes, s.iterations);
    const double p2 = injection_pressure(m), p1 = borehole_pressure_at(ref, t), p25 = borehole_pressure_at(ref25, t);
    ph_csv.row({v.b, static_cast<double>(v.n_particles), t, p2, p1, p25});
    o.p_h_error.emplace_back(t, p2 / p1 - 1.0);
    if (!out) return;
    const RadialFields f = radial_fields(m, edges);
    const fdm1d::Fdm1dSnapshot& s1 = snapshot_at(ref, t);
    const fdm1d::Fdm1dSnapshot& s25 = snapshot_at(ref25, t);
    const double p_h1 = p1;
    ProfileErrors pe;
    pe.t = t;
    // The 1D rock's area change is exactly 2 pi [r u]_{R_i}^{1} (eps_r + eps_theta = (r u)'/r).
    const double uptake_1d = v.b * 2.0 * std::numbers::pi * (s1.u_r.back() - ref.r.front() * s1.u_r.front());
    const double uptake_2d = m.flow().totals().deformation;
    pe.uptake_rel = uptake_2d / uptake_1d - 1.0;
    pe.uptake_of_injected = (uptake_2d - uptake_1d) / (kQ * t);
    double u_scale = 0.0;
    std::vector<double> u1(f.r_mean.size()), q1(f.r_mean.size());
    for (std::size_t k = 0; k < f.r_mean.size(); ++k) {
      u1[k] = shell_mean(ref.r, s1.u_r, edges[k], edges[k + 1]);
      q1[k] = shell_mean(ref.r, s1.p, edges[k], edges[k + 1]);
      u_scale = std::max(u_scale, std::abs(u1[k]));
      const double u25 = shell_mean(ref25.r, s25.u_r, edges[k], edges[k + 1]);
      const double q25 = shell_mean(ref25.r, s25.p, edges[k], edges[k + 1]);
      pe.u_local25 = std::max(pe.u_local25, std::abs(f.u_r[k] / u25 - 1.0));
      pe.p25 = std::max(pe.p25, std::abs(f.p[k] - q25) / borehole_pressure_at(ref25, t));
    }
    for (std::size_t k = 0; k < f.r_mean.size(); ++k) {
      const double eu = std::abs(f.u_r[k] - u1[k]) / std::abs(u1[k]), ep = std::abs(f.p[k] - q1[k]) / p_h1;
      if (eu > pe.u_local) pe.u_local = eu, pe.r_u_local = f.r_mean[k];
      pe.u_max = std::max(pe.u_max, std::abs(f.u_r[k] - u1[k]) / u_scale);
      if (ep > pe.p) pe.p = ep, pe.r_p = f.r_mean[k];
      p2d_csv.row({v.b, static_cast<double>(v.n_particles), t, f.r_mean[k], f.u_r[k], u1[k], f.p[k], q1[k],
                   f.u_r[k] / u1[k] - 1.0, (f.p[k] - q1[k]) / p_h1});
    }
    o.profiles.push_back(pe);
    profile_table.rows.push_back({fmt(v.b), std::to_string(v.n_particles), fmt(t), fmt(p_h1),
                                  fmt(pe.u_local) + " (r = " + fmt(pe.r_u_local) + ")", fmt(pe.u_max),
                                  fmt(pe.p) + " (r = " + fmt(pe.r_p) + ")", fmt(pe.u_local25), fmt(pe.p25),
                                  fmt(pe.uptake_rel) + " (" + fmt(pe.uptake_of_injected) + ")"});
  });
  recorder.finish();
  o.ok = run.is_ok();
  o.message = run.message;
  o.n_steps = run.n_steps;
  o.passes = run.total_iterations;
  o.seconds = run.seconds;
  o.max_balance = run.max_balance_error;
  summarise_p_h_errors(o);
  compare_1d_variants(ref, ref25, ref_fine, o);
  return o;
}

Table profile_table() {
  return {
      "Radially averaged u_r and p, lattice vs fdm1d (20 shells on [R_i, 1]; 1D = area-weighted shell mean of "
      "the nodal profile): u_r error relative to the 1D shell value (gating) and to the largest 1D u_r; p error "
      "over the 1D borehole pressure at that time; two columns against fdm1d with nu = 0.25; the fluid taken up by "
      "the deformation, b (V - V0) over the rock (lattice: series.csv's coupling; 1D: b 2 pi [r u] from R_i "
      "to 1), lattice over 1D - 1 and (the difference over the injected volume Q t)",
      {"b", "N", "t*", "p_h (1D)", "max |u_r/u_r,1D - 1| (at r*)", "max |u_r - u_r,1D| / max u_r,1D",
       "max |p - p_1D| / p_h,1D (at r*)", "u_r vs 1D nu = 0.25", "p vs 1D nu = 0.25",
       "b dV: lattice / 1D - 1 (of Q t)"},
      {}};
}

Table run_table() {
  return {"Runs: 2D steps, coupling passes, wall time; |p_h/p_h,1D - 1| of the borehole pressure history",
          {"b", "N", "steps", "passes (max/step)", "seconds", "max for t* >= " + fmt(kWindow) + " (at t*)",
           "max for t* >= " + fmt(0.5 * kWindow), "at t* = " + fmt(kEarly), "at the first step (t*)", "balance"},
          {}};
}

Table one_d_table() {
  return {
      "fdm1d against itself (information): the paper's nu = 0.25 against the lattice's nu, and a finer time "
      "stepping (dt / 10, growth 1.02) against the shared dt sequence (max over the compared times; u_r over max u_r, "
      "p over p_h; p_h for t* >= " +
          fmt(kWindow) + ")",
      {"b", "u_r: nu 0.25 vs lattice", "p: nu 0.25 vs lattice", "p_h: nu 0.25 vs lattice", "u_r: fine dt vs dt",
       "p_h: fine dt vs dt"},
      {}};
}

void add_rows(const Outcome& o, Table& runs, Table* one_d) {
  const auto& v = o.setting;
  runs.rows.push_back({fmt(v.b), std::to_string(v.n_particles), std::to_string(o.n_steps),
                       std::to_string(o.passes) + " (" + std::to_string(o.max_passes) + ")", fmt(o.seconds),
                       fmt(o.p_h_window) + " (" + fmt(o.p_h_window_t) + ")", fmt(o.p_h_half_window), fmt(o.p_h_early),
                       fmt(o.p_h_first) + " (" + fmt(o.p_h_first_t) + ")", fmt(o.max_balance)});
  if (one_d) one_d->rows.push_back({fmt(v.b), fmt(o.nu_u), fmt(o.nu_p), fmt(o.nu_p_h), fmt(o.dt_u), fmt(o.dt_p_h)});
}

Metric completed_metric(const Outcome& o) {
  return {.name = run_label(o.setting.b, o.setting.n_particles) + ": run completed (every step converged, plain loop)",
          .value = o.ok ? 1.0 : 0.0,
          .reference = 1.0,
          .tolerance = 0.0,
          .comparison = Comparison::abs_error,
          .justification = "a numerical failure is a failure: " + (o.message.empty() ? "ok" : o.message)};
}

Metric balance_metric(const Outcome& o) {
  return at_most_metric(
      "volume balance, max relative error per step (" + run_label(o.setting.b, o.setting.n_particles) + ")",
      o.max_balance, 1e-8, true,
      "the flow scheme is conservative by construction: round-off (measured <= 1.3e-13 per step; 1e-8 "
      "leaves margin)");
}

/// The comparison's CSV files (one set per tier), read by figures/verify_lattice_vs_fdm1d.py.
struct Files {
  fs::path folder;
  std::ofstream ph_file, p2d_file, p1d_file;
  std::unique_ptr<CsvWriter> ph, p2d, p1d;
  explicit Files(const fs::path& root)
      : folder(root),
        ph_file(core::open_for_writing(root / "ph_history.csv")),
        p2d_file(core::open_for_writing(root / "profiles_2d.csv")),
        p1d_file(core::open_for_writing(root / "profiles_1d.csv")) {
    core::write_file_atomically(root / "window.csv", [](std::ostream& window_file) {
      CsvWriter(window_file, {"t_window", "t_early"}).row({kWindow, kEarly});
    });
    ph = std::make_unique<CsvWriter>(ph_file, std::vector<std::string>{"b", "N", "t", "p_h", "p_h_1d", "p_h_1d_nu025"});
    p2d = std::make_unique<CsvWriter>(
        p2d_file, std::vector<std::string>{"b", "N", "t", "r_mean", "u_r", "u_r_1d", "p", "p_1d", "u_rel", "p_rel"});
    p1d = std::make_unique<CsvWriter>(p1d_file,
                                      std::vector<std::string>{"b", "t", "r", "u_r", "p", "u_r_nu025", "p_nu025"});
  }
  void close() {
    core::close_checked(ph_file, folder / "ph_history.csv");
    core::close_checked(p2d_file, folder / "profiles_2d.csv");
    core::close_checked(p1d_file, folder / "profiles_1d.csv");
  }
};

std::string notes_common() {
  return "The lattice's borehole node is the 1D model's flux boundary (borehole_storage = none, borehole_deformation "
         "= none); fdm1d runs with the calibrated lattice's nu = " +
         fmt(lt::calibrated_continuum().poisson_ratio) +
         ", the model's E/M (Eq. 22 at nu = 0.25) and vol_strain = plane-strain, n_r = 400, on the same dt sequence "
         "as the lattice (dt from 1e-5, growth 1.2, dt_max 2e-3), so the shared implicit-Euler error (~1% of p_h, "
         "last table) cancels. Errors: u_r relative to the 1D shell value at each shell (the largest error is at the "
         "first shell, where u_r is largest, so it equals the error over max u_r except where noted); p over the 1D "
         "p_h at that time (p changes sign in the far field). docs/lattice_vs_fdm1d.md explains the comparison and "
         "the numbers. CSV: ph_history.csv, profiles_2d.csv (lattice shells with the 1D shell means), "
         "profiles_1d.csv (1D nodes, with the nu = 0.25 run); each lattice run as `hmlattice run` writes it in "
         "b<b>_N<N>/, each 1D run as `hmlattice fdm1d` writes it in fdm1d_b<b>/.";
}

// --- quick tier: b = 0.5, N = 4000, to t* = 0.025 ---------------------------------------------

BenchmarkResult vs_fdm1d_quick(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const fs::path root = ctx.data_dir / "vs_fdm1d_quick";
  fs::create_directories(root);
  Files files(root);
  Table profiles = profile_table(), runs = run_table(), one_d = one_d_table();
  Comparison1d v;
  v.b = 0.5;
  v.n_particles = 4000;
  v.stepping.t_end = 0.025;
  v.stepping.times = {2.3e-3, 0.025};
  const Outcome o = compare(v, root, *files.ph, *files.p2d, files.p1d.get(), profiles);
  files.close();
  add_rows(o, runs, &one_d);
  res.metrics.push_back(completed_metric(o));
  res.metrics.push_back(balance_metric(o));
  // N = 4000 (h ~ 0.03) is coarser than the paper tier's 1e4: the tolerances are the measured errors at
  // this resolution (2026-11-22, seed 1) with a margin of ~1.5, a regression guard for CI; the 5% that
  // the lattice's discretisation error meets at N = 1e4 and 3e4 is checked in the paper tier.
  const std::string why = "regression guard at N = 4000: measured ";
  const auto& early = o.profiles.front();
  const auto& late = o.profiles.back();
  res.metrics.push_back(
      at_most_metric("N = 4000, t* = 2.3e-3: max |u_r/u_r,1D - 1| over shells", early.u_local, 0.10, true,
                     why + "7.8% (first shell, the lattice low); 5% is the paper tier's, at N >= 1e4"));
  res.metrics.push_back(at_most_metric(
      "N = 4000, t* = 2.3e-3: max |p - p_1D| / p_h,1D over shells", early.p, 0.13, true,
      why + "4.4% (first shell; 9.1% with uniform beams): the wall boundary layer sqrt(t/S) = 0.049 spans 1.6 "
            "mean beam lengths (h = 0.031); 5% is the paper tier's, at N >= 1e4"));
  res.metrics.push_back(
      at_most_metric("N = 4000, t* = 0.025: max |u_r/u_r,1D - 1| over shells", late.u_local, 0.10, true,
                     why + "7.6% (first shell, the lattice low: the wall row at h = 0.031 is stiffer "
                           "than the continuum, first order in h); 5% is the paper tier's, at N >= 1e4"));
  res.metrics.push_back(at_most_metric("N = 4000, t* = 0.025: max |p - p_1D| / p_h,1D over shells", late.p, 0.05, true,
                                       why + "1.6%, within the paper tier's 5% already"));
  res.metrics.push_back(at_most_metric("N = 4000: max |p_h/p_h,1D - 1| for t* >= " + fmt(kWindow), o.p_h_window, 0.05,
                                       true, why + "2.5%, within the paper tier's 5% over the window already"));
  res.tables = {runs, profiles, one_d};
  res.figures.push_back({"verify_lattice_vs_fdm1d.py", "verify_lattice_vs_fdm1d.png",
                         "Lattice (markers) against fdm1d (lines; dotted: nu = 0.25) before fracture, b = 0.5, N = "
                         "4000: borehole pressure and its relative error (shaded: the window and +-5%), radially "
                         "averaged u_r and p at t* = 2.3e-3 and 0.025.",
                         "vs_fdm1d_quick"});
  res.notes.push_back(notes_common());
  return res;
}

// --- paper tier: b = 0.2, 0.5, 0.8 at N = 1e4 to t* = 0.1, and at N = 3e4 to t* = 0.025 ------------

// One paper-tier run's metrics: it completed, its balance, its profiles and p_h against the 1D model at
// the compared times (gated at 5%), and against the 1D model with the paper's nu (shown).
void add_paper_run_metrics(const Outcome& o, std::vector<Metric>& metrics) {
  const std::string why =
      "the lattice's spatial discretisation error against 1D (same time steps): radially averaged "
      "u_r and p within 5% over [R_i, 1] at each compared time";
  const std::string why_ph =
      "the lattice's discretisation error in the borehole pressure history: within 5% over "
      "t* >= " +
      fmt(kWindow) +
      " (before it the wall boundary layer sqrt(t/S) is thinner than ~1.2 mean beam lengths "
      "at N = 1e4 for b = 0.8)";
  const std::string tag = run_label(o.setting.b, o.setting.n_particles);
  metrics.push_back(completed_metric(o));
  metrics.push_back(balance_metric(o));
  for (const auto& pe : o.profiles) {
    metrics.push_back(at_most_metric(tag + ", t* = " + fmt(pe.t) + ": max |u_r/u_r,1D - 1| over shells", pe.u_local,
                                     0.05, true, why));
    metrics.push_back(
        at_most_metric(tag + ", t* = " + fmt(pe.t) + ": max |p - p_1D| / p_h,1D over shells", pe.p, 0.05, true, why));
  }
  metrics.push_back(
      at_most_metric(tag + ": max |p_h/p_h,1D - 1| for t* >= " + fmt(kWindow), o.p_h_window, 0.05, true, why_ph));
  metrics.push_back(at_most_metric(tag + ": max |p_h/p_h,1D - 1| for t* >= " + fmt(0.5 * kWindow), o.p_h_half_window,
                                   0.05, false,
                                   "information: the window's edge; at N = 1e4, b = 0.8 the lattice is still 5% high "
                                   "at t* = 6e-4, where sqrt(t/S) ~ 1 lattice spacing"));
  double u25 = 0.0, p25 = 0.0;
  for (const auto& pe : o.profiles) u25 = std::max(u25, pe.u_local25), p25 = std::max(p25, pe.p25);
  metrics.push_back(at_most_metric(tag + ": against fdm1d with the paper's nu = 0.25, max |u_r/u_r,1D - 1| (all times)",
                                   u25, 0.05, false,
                                   "information: the paper compares with nu = 0.25; the lattice's calibrated nu is " +
                                       fmt(lt::calibrated_continuum().poisson_ratio) +
                                       " (the same column when they agree; 0.2236 with uniform beams moves the 1D u_r "
                                       "by ~2.5% of max u_r)"));
  metrics.push_back(at_most_metric(tag + ": against fdm1d with nu = 0.25, max |p - p_1D| / p_h,1D (all times)", p25,
                                   0.05, false, "information: as above; nu moves the 1D p by < 1% of p_h"));
}

BenchmarkResult vs_fdm1d_paper(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const fs::path root = ctx.data_dir / "vs_fdm1d_paper";
  fs::create_directories(root);
  Files files(root);
  Table profiles = profile_table(), runs = run_table(), one_d = one_d_table();
  const std::vector<double> bs = {0.2, 0.5, 0.8};
  std::vector<Outcome> coarse, fine;
  for (double b : bs) {  // N = 1e4: Figs. 13 and 15's unfractured times (2.3e-3, 4.5e-3) and three later ones
    Comparison1d v;
    v.b = b;
    v.stepping.times = {2.3e-3, 4.5e-3, 0.025, 0.05, 0.1};
    coarse.push_back(compare(v, root, *files.ph, *files.p2d, files.p1d.get(), profiles));
  }
  for (double b : bs) {  // N = 3e4 to t* = 0.025: does the difference shrink?
    Comparison1d v;
    v.b = b;
    v.n_particles = 30000;
    v.stepping.t_end = 0.025;
    v.stepping.times = {2.3e-3, 4.5e-3, 0.025};
    fine.push_back(compare(v, root, *files.ph, *files.p2d, nullptr, profiles));
  }
  files.close();
  for (std::size_t k = 0; k < bs.size(); ++k) {
    add_rows(coarse[k], runs, &one_d);
    add_paper_run_metrics(coarse[k], res.metrics);
  }
  for (std::size_t k = 0; k < bs.size(); ++k) {
    const Outcome &c = coarse[k], &f = fine[k];
    add_rows(f, runs, nullptr);
    add_paper_run_metrics(f, res.metrics);
    const std::string b = "b = " + fmt(bs[k]);
    res.metrics.push_back({.name = b + ": |p_h/p_h,1D - 1| at t* = " + fmt(kEarly) + ", N = 1e4 over N = 3e4",
                           .value = c.p_h_early / f.p_h_early,
                           .reference = 1.0,
                           .tolerance = 1.0,
                           .comparison = Comparison::at_least,
                           .justification = "the early-time excess of the lattice's p_h (an unresolved boundary layer) "
                                            "must shrink under refinement"});
    res.metrics.push_back({.name = b + ": max |u_r/u_r,1D - 1| at t* = 2.3e-3, N = 1e4 over N = 3e4",
                           .value = c.profiles.front().u_local / f.profiles.front().u_local,
                           .reference = 1.0,
                           .tolerance = 1.0,
                           .comparison = Comparison::at_least,
                           .justification = "information: with the facet-scaled lattice the largest u_r difference is "
                                            "at most ~3% at N = 1e4 and not always at the wall (measured 2.3-3.2% at "
                                            "N = 1e4, 1.2-2.4% at 3e4, 2026-11-22): at the level of the shell means' "
                                            "sampling scatter, where the ratio is noise; each run's 5% above gates",
                           .gating = false});
    res.metrics.push_back({.name = b + ": max |p - p_1D| / p_h,1D at t* = 2.3e-3, N = 1e4 over N = 3e4",
                           .value = c.profiles.front().p / f.profiles.front().p,
                           .reference = 1.0,
                           .tolerance = 1.0,
                           .comparison = Comparison::at_least,
                           .justification = "information: the first shell's p is shown, not gated (the shell average "
                                            "of a steep wall profile)",
                           .gating = false});
  }
  res.tables = {runs, profiles, one_d};
  res.figures.push_back({"verify_lattice_vs_fdm1d.py", "verify_lattice_vs_fdm1d.png",
                         "Lattice (markers; filled N = 1e4, open N = 3e4) against fdm1d (lines; dotted: nu = 0.25) "
                         "before fracture, b = 0.2, 0.5, 0.8: borehole pressure and its relative error (shaded: the "
                         "window and +-5%), radially averaged u_r and p at the compared times (the dashed curves of "
                         "Figs. 13 and 15).",
                         "vs_fdm1d_paper"});
  res.notes.push_back(notes_common());
  return res;
}

}  // namespace

void add_lattice2d_vs_fdm1d_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({.id = "lattice2d.vs_fdm1d_quick",
                  .title = "Coupled lattice against fdm1d before fracture, b = 0.5, N = 4000",
                  .description = "The borehole annulus, Q = 0.01, fracture off, flux-boundary borehole: p_h(t) and "
                                 "radially averaged u_r and p at t* = 2.3e-3 and 0.025 against `hmlattice fdm1d` "
                                 "with the lattice's nu.",
                  .tier = Tier::quick,
                  .run = vs_fdm1d_quick});
  into.push_back({.id = "lattice2d.vs_fdm1d",
                  .title = "Coupled lattice against fdm1d before fracture, b = 0.2, 0.5, 0.8 (Figs. 13, 15 dashed)",
                  .description = "As the quick benchmark for b = 0.2, 0.5, 0.8 at N = 1e4 to t* = 0.1 (profiles at "
                                 "t* = 2.3e-3, 4.5e-3, 0.025, 0.05, 0.1) and at N = 3e4 to t* = 0.025.",
                  .tier = Tier::paper,
                  .run = vs_fdm1d_paper});
}

}  // namespace hm::verification
