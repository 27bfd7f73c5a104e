// Running the Fig. 12/13 cases for the verification harness: see borehole_fracture_runs.hpp.
#include "borehole_fracture_runs.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "fdm1d_sampling.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/io/radial_average.hpp"
#include "hm/case/fdm1d_output.hpp"
#include "hm/case/progress.hpp"
#include "hm/case/provenance.hpp"
#include "hm/case/run_output.hpp"
#include "report_writer.hpp"

namespace hm::verification::borehole_fracture {

using cases::ProgressReporter;
using cases::RadialFields;
using cases::RunCase;
using cases::RunRecorder;
using cases::injection_pressure;
using cases::make_provenance;
using cases::radial_fields;
using cases::run_case_to_toml;
using cases::to_toml;
using cases::write_fdm1d_results;

namespace lt = hm::lattice2d;
namespace fs = std::filesystem;

namespace {

std::string fmt(double x) { return format_number(x); }

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

/// u_r of the lattice against 1D at time t, shell by shell (Fig. 13's comparison): the max of
/// |u_r/u_r,1D - 1| and the mean of u_r/u_r,1D over the shells; nothing if the reference has no snapshot at t.
struct RadialComparison {
  double max_error = kNaN, mean_ratio = kNaN;
};

RadialComparison u_r_against_1d(const lt::CoupledModel& m, const std::vector<double>& edges,
                                 const fdm1d::Fdm1dResult& ref, double t) {
  RadialComparison c;
  for (const auto& s1 : ref.snapshots) {
    if (std::abs(s1.t - t) > 1e-9 * t) continue;
    const RadialFields f = radial_fields(m, edges);
    double e_max = 0.0, sum = 0.0;
    for (std::size_t k = 0; k < f.u_r.size(); ++k) {
      const double ratio = f.u_r[k] / shell_mean(ref.r, s1.u_r, edges[k], edges[k + 1]);
      e_max = std::max(e_max, std::abs(ratio - 1.0));
      sum += ratio;
    }
    c.max_error = e_max;
    c.mean_ratio = f.u_r.empty() ? kNaN : sum / static_cast<double>(f.u_r.size());
  }
  return c;
}

}  // namespace

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

RunOutcome run_case(const RunCase& c, const std::string& label, const fs::path& root, const fdm1d::Fdm1dResult& ref,
                    std::ostream* progress) {
  RunOutcome o;
  o.label = label;
  o.b = c.physics.parameters.material.b;
  o.n_particles = c.lattice.n_particles;
  o.seed = c.lattice.seed;
  o.R_i = c.physics.parameters.R_i;
  o.eq16_node = c.borehole_storage == lt::BoreholeStorage::biot_modulus &&
                c.borehole_deformation == lt::BoreholeDeformation::biot;
  const auto model = cases::make_coupled_model(c);
  const fs::path dir = root / label;
  fs::create_directories(dir);
  RunRecorder recorder(dir, c);
  const std::vector<double> edges =
      lt::uniform_shell_edges(o.R_i, c.output.radial_max, c.output.radial_bins);
  std::vector<bool> was_broken(static_cast<std::size_t>(model->lattice().n_beams()), false);
  int last_n_broken = 0;
  double pre_last_t = kNaN, pre_last_ratio = kNaN;
  std::optional<ProgressReporter> reporter;
  if (progress) reporter.emplace(*progress, label, 60.0);
  const auto run = model->run(c.stepping, [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
    recorder.record(m, s, out);
    const double t = m.time(), p_h = injection_pressure(m);
    if (reporter) reporter->update(t, c.stepping.t_end, "broken " + std::to_string(m.n_broken()));
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
    if (std::isnan(o.t_first) && recorder.breakdown().has_broken()) {
      const lt::BreakEvent& e = log.front();
      o.t_first = recorder.breakdown().t_first;
      o.p_before = recorder.breakdown().p_before;
      o.p_first = recorder.breakdown().p_first;
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
    if (!out || t <= 0.0) return;
    Snapshot snap;
    snap.t = t;
    snap.p_h = p_h;
    snap.stats = lt::compute_fracture_statistics(m.lattice(), states, log);
    snap.fp = fracture_pressure(m);
    if (log.empty()) {  // still unbroken: the radial u_r against 1D (the first curve of Fig. 13)
      const RadialComparison u = u_r_against_1d(m, edges, ref, t);
      snap.u_pre = u.max_error;
      snap.u_ratio_mean = u.mean_ratio;
    }
    o.snaps.push_back(snap);
  });
  o.ok = run.is_ok();
  o.message = run.message;
  o.n_steps = run.n_steps;
  o.passes = run.total_iterations;
  o.n_halvings = run.n_step_halvings;
  o.max_balance = run.max_balance_error;
  o.seconds = run.step_seconds;
  o.mechanics = run.mechanics_seconds;
  o.fracture = run.stress_seconds + run.break_seconds;
  o.geometry = run.geometry_seconds;
  o.flow = run.flow_seconds;
  o.p_peak = recorder.breakdown().p_peak;
  o.t_peak = recorder.breakdown().t_peak;
  if (reporter)
    reporter->finish(o.ok ? std::to_string(o.n_steps) + " steps, " + std::to_string(o.passes) + " passes, " +
                                std::to_string(model->n_broken()) + " broken"
                          : "failed: " + o.message);
  if (!o.ok) return o;  // the folder stays, with the series up to the failure, for a look
  recorder.finish();
  core::write_file_atomically(dir / "config.toml", [&](std::ostream& out) {
    out << run_case_to_toml(c, to_toml(make_provenance("hmlattice verify (lattice2d.fig12 benchmark), run " + label)));
  });
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
  const auto model = cases::make_coupled_model(tc);
  const fs::path dir = root / label;
  fs::create_directories(dir);
  RunRecorder recorder(dir, tc);
  const std::vector<double> edges = lt::uniform_shell_edges(c.physics.parameters.R_i, tc.output.radial_max,
                                                            tc.output.radial_bins);
  const auto run = model->run(tc.stepping, [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
    recorder.record(m, s, out);
    const double t = m.time();
    if (t >= kWindow * (1 - 1e-12)) {
      const double e = std::abs(injection_pressure(m) / borehole_pressure_at(ref, t) - 1.0);
      if (std::isnan(o.max_error) || e > o.max_error) o.max_error = e, o.max_error_t = t;
    }
    if (!out || t < o.t_end * (1 - 1e-12)) return;
    o.end_error = std::abs(injection_pressure(m) / borehole_pressure_at(ref, t) - 1.0);
    o.u_error = u_r_against_1d(m, edges, ref, t).max_error;
  });
  o.ok = run.is_ok();
  if (o.ok) recorder.finish();
  return o;
}

RunCase with_eq16_borehole_node(RunCase c) {
  c.borehole_storage = lt::BoreholeStorage::biot_modulus;
  c.borehole_deformation = lt::BoreholeDeformation::biot;
  return c;
}

}  // namespace hm::verification::borehole_fracture
