// Running the Fig. 12/13 cases for the verification harness: see borehole_fracture_runs.hpp.
#include "borehole_fracture_runs.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>

#include "fdm1d_sampling.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/fdm1d_output.hpp"
#include "hm/case/progress.hpp"
#include "hm/case/provenance.hpp"
#include "hm/case/run_files.hpp"
#include "hm/case/run_output.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/io/break_log.hpp"
#include "hm/lattice2d/io/radial_average.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "report_writer.hpp"

namespace hm::verification::borehole_fracture {

using cases::injection_pressure;
using cases::make_provenance;
using cases::ProgressReporter;
using cases::radial_fields;
using cases::RadialFields;
using cases::run_case_to_toml;
using cases::RunCase;
using cases::RunRecorder;
using cases::to_toml;
using cases::write_fdm1d_results;

namespace lt = hm::lattice2d;
namespace fs = std::filesystem;

namespace {

/// u_r of the lattice against 1D at time t, shell by shell (Fig. 13's comparison): the max of
/// |u_r/u_r,1D - 1| and the mean of u_r/u_r,1D over the shells; nothing if the reference has no snapshot at t.
struct RadialComparison {
  double max_error = kNaN, mean_ratio = kNaN;
};

RadialComparison u_r_against_1d(const std::vector<double>& u_r, const std::vector<double>& edges,
                                const fdm1d::Fdm1dResult& ref, double t) {
  RadialComparison c;
  for (const auto& s1 : ref.snapshots) {
    if (std::abs(s1.t - t) > 1e-9 * t) continue;
    double e_max = 0.0, sum = 0.0;
    for (std::size_t k = 0; k < u_r.size() && k + 1 < edges.size(); ++k) {
      const double ratio = u_r[k] / shell_mean(ref.r, s1.u_r, edges[k], edges[k + 1]);
      e_max = std::max(e_max, std::abs(ratio - 1.0));
      sum += ratio;
    }
    c.max_error = e_max;
    c.mean_ratio = u_r.empty() ? kNaN : sum / static_cast<double>(u_r.size());
  }
  return c;
}

/// A numeric CSV file as the recorder writes it (csv_number: "nan" for NaN), by column.
class CsvColumns {
 public:
  explicit CsvColumns(const fs::path& path) : path_(path) {
    std::ifstream in(path);
    std::string line;
    if (!in || !std::getline(in, line))
      throw std::runtime_error(path.string() + ": cannot be read (a run folder of `hmlattice run` has it)");
    const std::vector<std::string> header = split(line);
    std::vector<std::vector<double>*> by_position;
    for (const auto& name : header) by_position.push_back(&columns_[name]);
    for (int line_no = 2; std::getline(in, line); ++line_no) {
      if (line.empty()) continue;
      const std::vector<std::string> fields = split(line);
      if (fields.size() != header.size())
        throw std::runtime_error(path.string() + ":" + std::to_string(line_no) + ": " + std::to_string(fields.size()) +
                                 " fields, the header has " + std::to_string(header.size()));
      for (std::size_t k = 0; k < fields.size(); ++k)
        by_position[k]->push_back(std::strtod(fields[k].c_str(), nullptr));
      ++n_rows_;
    }
  }
  const std::vector<double>& operator[](const std::string& column) const {
    const auto it = columns_.find(column);
    if (it == columns_.end()) throw std::runtime_error(path_.string() + ": no column " + column);
    return it->second;
  }
  std::size_t n_rows() const { return n_rows_; }

 private:
  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields(1);
    for (char ch : line) {
      if (ch == ',')
        fields.emplace_back();
      else if (ch != '\r')
        fields.back() += ch;
    }
    return fields;
  }
  fs::path path_;
  std::map<std::string, std::vector<double>> columns_;
  std::size_t n_rows_ = 0;
};

/// The shells' u_r at time t in radial.csv, in order.
std::vector<double> radial_u_r_at(const CsvColumns& radial, double t) {
  std::vector<double> u_r;
  for (std::size_t k = 0; k < radial.n_rows(); ++k)
    if (radial["t"][k] == t) u_r.push_back(radial["u_r"][k]);
  return u_r;
}

/// The shell edges radial.csv was written on (RunRecorder's).
std::vector<double> recorder_shell_edges(const RunCase& c) {
  const double r_min = c.lattice.domain == lt::DomainShape::annulus ? c.lattice.inner_radius : 0.0;
  return lt::uniform_shell_edges(r_min, c.output.radial_max, c.output.radial_bins);
}

RunOutcome describe(const RunCase& c, const std::string& label) {
  RunOutcome o;
  o.label = label;
  o.b = c.physics.parameters.material.b;
  o.Q = c.physics.parameters.Q;
  o.n_particles = c.lattice.n_particles;
  o.seed = c.lattice.seed;
  o.R_i = c.physics.parameters.R_i;
  o.eq16_node = c.flow.borehole_storage == lt::BoreholeStorage::biot_modulus &&
                c.flow.borehole_deformation == lt::BoreholeDeformation::biot;
  return o;
}

}  // namespace

/// The 1D reference of a case: fdm1d (Appendix A, no fracture, flux-boundary borehole) with the
/// calibrated lattice's nu and the case's E/M, plane-strain volumetric strain (as benchmarks_lattice2d_vs_fdm1d.cpp),
/// on the case's dt sequence and output times.
analytic::DimensionlessParameters reference_parameters(const RunCase& c) {
  analytic::DimensionlessParameters p = c.physics.parameters;
  p.material.nu = lt::calibrated_continuum(c.stiffness_scaling).poisson_ratio;
  p.material.vol_strain = analytic::VolStrain::plane_strain;
  return p;
}

fdm1d::Fdm1dResult run_reference(const RunCase& c) {
  const analytic::DimensionlessParameters p = reference_parameters(c);
  fdm1d::Fdm1dNumerics n;
  n.n_r = 400;  // steady state within ~0.2% of Appendix B; far finer than the lattice
  n.dt_initial = c.stepping.dt_initial;
  n.dt_growth = c.stepping.dt_growth;
  n.dt_max = c.stepping.dt_max;
  n.t_end = c.stepping.t_end;
  n.output_times = c.stepping.output_times;
  n.output_times.erase(std::remove_if(n.output_times.begin(), n.output_times.end(),
                                      [&](double t) { return t >= c.stepping.t_end * (1 - 1e-12); }),
                       n.output_times.end());
  // An isotropic in-situ stress is the 1D model's rest state; a deviatoric one has no 1D counterpart.
  const fdm1d::RestState rest =
      c.insitu.S_H == c.insitu.S_h ? fdm1d::RestState{c.insitu.S_H, c.insitu.p0} : fdm1d::RestState{};
  fdm1d::Fdm1dResult r = fdm1d::run_fdm1d(p, n, rest);
  if (!r.summary.is_success()) throw std::runtime_error("fdm1d failed: " + r.summary.message);
  return r;
}

fdm1d::Fdm1dResult write_reference(const RunCase& c, const fs::path& root) {
  const fdm1d::Fdm1dResult ref = run_reference(c);
  const fs::path d = root / ("fdm1d_b" + fmt(c.physics.parameters.material.b));
  fs::create_directories(d);
  write_fdm1d_results(d, ref, reference_parameters(c));
  return ref;
}

namespace {

// The series: steps, passes, the balance, the count that must never fall, and p_h against the 1D
// model before the first break (the largest deviation after the window, and the last); returns the
// last deviation and its time.
std::pair<double, double> read_series(const CsvColumns& series, const fdm1d::Fdm1dResult& ref, RunOutcome& o) {
  const auto &t = series["t"], &p_h = series["p_h"], &n_broken = series["n_broken"];
  o.n_steps = static_cast<int>(series.n_rows()) - 1;  // a row per accepted step and one at t = 0
  double passes = 0.0;
  for (double it : series["iterations"]) passes += it;
  o.passes = static_cast<int>(passes);
  o.max_balance = 0.0;
  for (double e : series["balance_error"]) o.max_balance = std::max(o.max_balance, e);
  // Never heal: the count never falls (a beam logged twice in breaks.csv was intact in between).
  // Before the first break: p_h against 1D.
  double pre_last_ratio = kNaN, pre_last_t = kNaN, last_n_broken = 0.0;
  for (std::size_t k = 0; k < series.n_rows(); ++k) {
    if (n_broken[k] < last_n_broken) ++o.n_broken_decreases;
    last_n_broken = n_broken[k];
    if (n_broken[k] != 0.0 || t[k] <= 0.0) continue;
    const double ratio = p_h[k] / borehole_pressure_at(ref, t[k]) - 1.0;
    pre_last_ratio = ratio, pre_last_t = t[k];
    if (t[k] >= kWindow * (1 - 1e-12) && (std::isnan(o.pre_max) || std::abs(ratio) > o.pre_max))
      o.pre_max = std::abs(ratio), o.pre_max_t = t[k];
  }
  return {pre_last_ratio, pre_last_t};
}

// breakdown.csv and, if a beam broke, the first break from breaks.csv (and the beams logged twice);
// `pre_last` is read_series's last deviation before it, and its time.
void read_first_break(const RunCase& c, const fs::path& dir, std::pair<double, double> pre_last, RunOutcome& o) {
  const CsvColumns breakdown(cases::run_file_path(dir, cases::RunFileId::breakdown));
  o.t_first = breakdown["t_first_break"].at(0);
  o.p_before = breakdown["p_h_before"].at(0);
  o.p_first = breakdown["p_h_first_break"].at(0);
  o.t_peak = breakdown["t_peak"].at(0);
  o.p_peak = breakdown["p_h_peak"].at(0);
  if (std::isnan(o.t_first)) return;
  const fs::path breaks_file = cases::run_file_path(dir, cases::RunFileId::breaks);
  const std::vector<lt::BreakEvent> log = lt::read_break_log(breaks_file);
  if (log.empty()) throw std::runtime_error(breaks_file.string() + ": no break, breakdown.csv has one");
  o.r_first = log.front().position.norm();
  o.mode_first = log.front().mode;
  o.length_first = lt::generate_lattice(c.lattice).length[static_cast<std::size_t>(log.front().beam)];
  std::vector<int> beams;
  for (const auto& e : log) beams.push_back(e.beam);
  std::sort(beams.begin(), beams.end());
  o.n_healed = static_cast<int>(beams.size() -
                                static_cast<std::size_t>(std::unique(beams.begin(), beams.end()) - beams.begin()));
  o.pre_last = std::abs(pre_last.first), o.pre_last_t = pre_last.second, o.pre_signed_last = pre_last.first;
}

// The output times: fracture statistics, p_h (from the series), and u_r against 1D while still unbroken.
void read_snapshots(const RunCase& c, const fs::path& dir, const CsvColumns& series, const fdm1d::Fdm1dResult& ref,
                    RunOutcome& o) {
  const auto &t = series["t"], &p_h = series["p_h"];
  const CsvColumns summary(cases::run_file_path(dir, cases::RunFileId::fracture_summary)),
      radial(cases::run_file_path(dir, cases::RunFileId::radial));
  const std::vector<double> edges = recorder_shell_edges(c);
  for (std::size_t k = 0; k < summary.n_rows(); ++k) {
    Snapshot snap;
    snap.t = summary["t"][k];
    if (snap.t <= 0.0) continue;
    const auto at = std::find(t.begin(), t.end(), snap.t);
    snap.p_h = at == t.end() ? kNaN : p_h[static_cast<std::size_t>(at - t.begin())];
    const auto count = [&](const char* column) { return static_cast<int>(summary[column][k]); };
    snap.stats.n_broken = count("n_broken");
    snap.stats.n_fractures = count("n_fractures");
    snap.stats.n_radial = count("n_radial");
    snap.stats.n_radial_reaching_outer = count("n_radial_reaching_outer");
    snap.stats.n_secondary = count("n_secondary");
    snap.stats.n_secondary_sizable = count("n_secondary_sizable");
    snap.stats.n_arms = count("n_arms");
    snap.stats.n_tensile = count("n_tensile");
    snap.stats.n_shear = count("n_shear");
    snap.stats.max_radial_extent = summary["max_radial_extent"][k];
    snap.u_r = radial_u_r_at(radial, snap.t);
    const RadialComparison u = u_r_against_1d(snap.u_r, edges, ref, snap.t);
    snap.u_ratio_mean = u.mean_ratio;
    if (snap.stats.n_broken == 0) snap.u_pre = u.max_error;
    o.snaps.push_back(snap);
  }
}

// The sizable secondary fractures at each output time, at the outer boundary or inside (fractures.csv),
// and the pressure in the fractures (fracture_pressure.csv; a folder written before the recorder wrote it
// has none, and its metrics stay out of the report).
void read_fracture_tables(const fs::path& dir, RunOutcome& o) {
  if (fs::exists(cases::run_file_path(dir, cases::RunFileId::fractures))) {
    const CsvColumns fractures(cases::run_file_path(dir, cases::RunFileId::fractures));
    const double sizable = lt::FractureStatisticsOptions{}.sizable_extent;
    for (std::size_t k = 0; k < fractures.n_rows(); ++k) {
      if (fractures["connected_to_borehole"][k] != 0.0 || fractures["extent"][k] < sizable) continue;
      for (Snapshot& snap : o.snaps)
        if (snap.t == fractures["t"][k])
          ++(fractures["reaches_outer"][k] != 0.0 ? snap.secondary_at_outer : snap.secondary_inside);
    }
  }
  if (!fs::exists(cases::run_file_path(dir, cases::RunFileId::fracture_pressure))) return;
  const CsvColumns pressure(cases::run_file_path(dir, cases::RunFileId::fracture_pressure));
  for (Snapshot& snap : o.snaps)
    for (std::size_t k = 0; k < pressure.n_rows(); ++k) {
      if (pressure["t"][k] != snap.t) continue;
      snap.fp = {pressure["mean_all"][k],
                 pressure["mean_away"][k],
                 pressure["min_away"][k],
                 static_cast<int>(pressure["n_all"][k]),
                 static_cast<int>(pressure["n_away"][k]),
                 pressure["negative_area_fraction"][k],
                 pressure["p_min"][k],
                 pressure["p_max"][k],
                 pressure["borehole_backflow"][k],
                 pressure["outer_inflow"][k],
                 pressure["mouth_inflow"][k]};
    }
}

}  // namespace

RunOutcome read_run(const RunCase& c, const std::string& label, const fs::path& dir, const fdm1d::Fdm1dResult& ref) {
  RunOutcome o = describe(c, label);
  o.ok = true;
  o.seconds = o.mechanics = o.fracture = o.geometry = o.flow = kNaN;  // not in the files
  o.n_halvings = -1;
  const CsvColumns series(cases::run_file_path(dir, cases::RunFileId::series));
  read_first_break(c, dir, read_series(series, ref, o), o);
  read_snapshots(c, dir, series, ref, o);
  read_fracture_tables(dir, o);
  return o;
}

TwinOutcome read_twin(const RunCase& twin_case, const fs::path& dir, const fdm1d::Fdm1dResult& ref) {
  TwinOutcome o;
  o.ok = true;
  o.t_end = twin_case.stepping.t_end;
  const CsvColumns series(cases::run_file_path(dir, cases::RunFileId::series)),
      radial(cases::run_file_path(dir, cases::RunFileId::radial));
  const auto &t = series["t"], &p_h = series["p_h"];
  for (std::size_t k = 0; k < series.n_rows(); ++k) {
    if (t[k] < kWindow * (1 - 1e-12)) continue;
    const double e = std::abs(p_h[k] / borehole_pressure_at(ref, t[k]) - 1.0);
    if (std::isnan(o.max_error) || e > o.max_error) o.max_error = e, o.max_error_t = t[k];
  }
  if (series.n_rows() == 0 || t.back() < o.t_end * (1 - 1e-12)) return o;
  o.end_error = std::abs(p_h.back() / borehole_pressure_at(ref, t.back()) - 1.0);
  o.u_error = u_r_against_1d(radial_u_r_at(radial, t.back()), recorder_shell_edges(twin_case), ref, t.back()).max_error;
  return o;
}

RunOutcome run_case(const RunCase& c, const std::string& label, const fs::path& root, const fdm1d::Fdm1dResult& ref,
                    std::ostream* progress) {
  // The run writes its folder as `hmlattice run` does; its numbers are then read from there (read_run),
  // as from a folder a workflow made, so that both give the same. The observer keeps what the files
  // do not hold: the timing split and every beam's never-heal check.
  const auto model = cases::make_coupled_model(c);
  const fs::path dir = root / label;
  fs::create_directories(dir);
  RunRecorder recorder(dir, c);
  std::vector<bool> was_broken(static_cast<std::size_t>(model->lattice().n_beams()), false);
  int n_healed = 0;
  std::optional<ProgressReporter> reporter;
  if (progress) reporter.emplace(*progress, label, 60.0);
  // As `hmlattice run` does with [fracture] stop_at_first_break: the step that breaks the first beam is
  // recorded as an output time's and is the last; the run is complete then (or at t_end, unbroken).
  const auto run = model->run(
      c.stepping,
      [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
        recorder.record(m, s, out || c.reached_first_break(m));
        if (reporter) reporter->update(m.time(), c.stepping.t_end, "broken " + std::to_string(m.n_broken()));
        const auto& states = m.mechanics().states();
        for (std::size_t e = 0; e < states.size(); ++e) {
          const bool broken = states[e] != lt::BeamState::intact;
          if (was_broken[e] && !broken) ++n_healed;
          was_broken[e] = was_broken[e] || broken;
        }
      },
      [&] { return c.reached_first_break(*model); });
  const bool complete = run.is_ok() || c.reached_first_break(*model);
  if (reporter)
    reporter->finish(complete ? std::to_string(run.n_steps) + " steps, " + std::to_string(run.total_iterations) +
                                    " passes, " + std::to_string(model->n_broken()) + " broken"
                              : "failed: " + run.message);
  if (!complete) {  // the folder stays, with the series up to the failure, for a look
    RunOutcome o = describe(c, label);
    o.message = run.message;
    return o;
  }
  recorder.finish();
  core::write_file_atomically(dir / "config.toml", [&](std::ostream& out) {
    out << run_case_to_toml(c, to_toml(make_provenance("hmlattice verify, run " + label)));
  });
  RunOutcome o = read_run(c, label, dir, ref);
  o.n_healed = std::max(o.n_healed, n_healed);
  o.n_halvings = run.n_step_halvings;
  o.seconds = run.step_seconds;
  o.mechanics = run.mechanics_seconds;
  o.fracture = run.stress_seconds + run.break_seconds;
  o.geometry = run.geometry_seconds;
  o.flow = run.flow_seconds;
  return o;
}

RunCase flux_twin_case(const RunCase& c) {
  RunCase tc = c;
  tc.fracture_enabled = false;
  tc.flow.borehole_storage = lt::BoreholeStorage::none;
  tc.flow.borehole_deformation = lt::BoreholeDeformation::none;
  tc.stepping.t_end = c.stepping.output_times.empty() ? c.stepping.t_end : c.stepping.output_times.front();
  tc.stepping.output_times.clear();
  tc.output.vtk = false;
  return tc;
}

TwinOutcome run_flux_twin(const RunCase& c, const std::string& label, const fs::path& root,
                          const fdm1d::Fdm1dResult& ref) {
  const RunCase tc = flux_twin_case(c);
  const auto model = cases::make_coupled_model(tc);
  const fs::path dir = root / label;
  fs::create_directories(dir);
  RunRecorder recorder(dir, tc);
  const auto run = model->run(tc.stepping, [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
    recorder.record(m, s, out);
  });
  if (!run.is_ok()) return TwinOutcome{.ok = false, .t_end = tc.stepping.t_end};
  recorder.finish();
  core::write_file_atomically(dir / "config.toml", [&](std::ostream& out) {
    out << run_case_to_toml(tc, to_toml(make_provenance("hmlattice verify, run " + label)));
  });
  return read_twin(tc, dir, ref);
}

RunSource::RunSource(fs::path root, fs::path runs_dir, std::ostream* progress)
    : root_(std::move(root)), runs_dir_(std::move(runs_dir)), progress_(progress) {}

bool RunSource::is_read(const std::string& label) const {
  std::error_code ec;
  return !runs_dir_.empty() && fs::exists(runs_dir_ / label, ec);
}

std::string RunSource::folder(const std::string& label) const {
  if (label.empty() || !is_read(label)) return label;
  return fs::absolute(runs_dir_ / label).lexically_normal().string();
}

RunOutcome RunSource::run(const RunCase& c, const std::string& label, const fdm1d::Fdm1dResult& ref) {
  if (!is_read(label)) return run_case(c, label, root_, ref, progress_);
  read_.push_back(label);
  return read_run(c, label, runs_dir_ / label, ref);
}

TwinOutcome RunSource::twin(const RunCase& c, const std::string& label, const fdm1d::Fdm1dResult& ref) {
  if (!is_read(label)) return run_flux_twin(c, label, root_, ref);
  read_.push_back(label);
  return read_twin(flux_twin_case(c), runs_dir_ / label, ref);
}

std::string RunSource::note() const {
  if (runs_dir_.empty()) return "";
  std::string labels;
  for (const auto& l : read_) labels += (labels.empty() ? "" : ", ") + l;
  return "Runs read from `--runs " + runs_dir_.string() +
         "` (made by `hmlattice run`, e.g. through the workflow; "
         "checked to be complete and of the benchmark's case): " +
         (labels.empty() ? "none" : labels) +
         "; the others were run here. A read run's files hold no timing split (nan).";
}

RunCase with_lattice(RunCase c, long long n_particles, unsigned long long seed) {
  c.lattice.n_particles = n_particles;
  c.lattice.seed = seed;
  c.strength.seed = seed;
  return c;
}

RunCase with_eq16_borehole_node(RunCase c) {
  c.flow.borehole_storage = lt::BoreholeStorage::biot_modulus;
  c.flow.borehole_deformation = lt::BoreholeDeformation::biot;
  return c;
}

}  // namespace hm::verification::borehole_fracture
