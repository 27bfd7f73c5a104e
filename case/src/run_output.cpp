#include "hm/case/run_output.hpp"

#include <algorithm>
#include <cmath>

#include "hm/case/fracture_pressure.hpp"

#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/io/break_log.hpp"
#include "hm/lattice2d/io/fracture_tables.hpp"
#include "hm/lattice2d/io/radial_average.hpp"

namespace hm::cases {

using core::CsvWriter;

namespace lt = hm::lattice2d;

double injection_pressure(const lt::CoupledModel& model) {
  const auto& flow = model.flow();
  return flow.has_borehole() ? flow.borehole_pressure() : flow.pressure()[flow.source_triangle()];
}

Eigen::VectorXd crack_openings(const lt::CoupledModel& model) {
  const std::vector<lt::BeamState>& states = model.mechanics().states();
  std::vector<int> broken;
  for (std::size_t e = 0; e < states.size(); ++e)
    if (states[e] != lt::BeamState::intact) broken.push_back(static_cast<int>(e));
  Eigen::VectorXd opening = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(states.size()));
  for (const lt::CrackOpening& o : lt::crack_opening(model.lattice(), model.displacement(), broken))
    opening[o.beam] = o.normal_opening;
  return opening;
}

RadialFields radial_fields(const lt::CoupledModel& model, const std::vector<double>& edges) {
  const lt::Lattice& l = model.lattice();
  const lt::DualGraph& dual = model.reference_dual();
  const Eigen::VectorXd& u = model.displacement();
  Eigen::VectorXd u_r(l.n_triangles());
  for (int s = 0; s < l.n_triangles(); ++s) {
    double sum = 0.0;
    for (int i : l.triangles[static_cast<std::size_t>(s)]) {
      const Eigen::Vector2d x = l.points.col(i);
      const double r = x.norm();
      if (r > 0.0) sum += (u[3 * i] * x.x() + u[3 * i + 1] * x.y()) / r;  // u_r of the particle at r = 0 is 0
    }
    u_r[s] = sum / 3.0;
  }
  const lt::RadialProfile pu = lt::radial_average(dual, u_r, edges);
  const lt::RadialProfile pp = lt::radial_average(dual, model.pressure(), edges);
  RadialFields out;
  for (std::size_t k = 0; k < pu.shells.size(); ++k) {
    out.r_mid.push_back(0.5 * (pu.shells[k].r_inner + pu.shells[k].r_outer));
    out.r_mean.push_back(pu.shells[k].r_mean);
    out.u_r.push_back(pu.shells[k].mean);
    out.p.push_back(pp.shells[k].mean);
    out.n_triangles.push_back(pu.shells[k].n_triangles);
  }
  return out;
}

namespace {

const std::vector<std::string> series_columns = {"t",
                                                 "dt",
                                                 "p_h",
                                                 "injected",
                                                 "stored",
                                                 "coupling",
                                                 "outflow",
                                                 "balance_error",
                                                 "n_broken",
                                                 "iterations",
                                                 "pressure_residual",
                                                 "displacement_residual"};
const std::vector<std::string> radial_columns = {"t", "r", "r_mean", "n_triangles", "u_r", "p"};
const std::vector<std::string> fracture_pressure_columns = {
    "t",     "mean_all", "mean_away",         "min_away",     "n_all",       "n_away", "negative_area_fraction",
    "p_min", "p_max",    "borehole_backflow", "outer_inflow", "mouth_inflow"};

// The streamed CSV files in the table's order: the order of their lengths in a checkpoint.
std::vector<RunFileId> streamed_files() {
  std::vector<RunFileId> out;
  for (const RunFile& f : run_files)
    if (f.writing == RunFileWriting::streamed) out.push_back(f.id);
  return out;
}

// The folder of the VTK snapshots: the .pvd's.
std::filesystem::path vtk_folder(const std::filesystem::path& dir) {
  return run_file_path(dir, RunFileId::vtk).parent_path();
}

// The fracture statistics at time t, when the log held its first n events: broken beams never heal and
// only the break loop breaks them (logging each), so those events' beams are the broken ones at that
// time; the teeth logged by t are the softened beams (none under the brittle law).
lt::FractureSnapshot fracture_snapshot(const lt::Lattice& lattice, const std::vector<lt::BreakEvent>& log,
                                       std::size_t n, const std::vector<lt::ToothEvent>& teeth, double t,
                                       const lt::FractureStatisticsOptions& options) {
  const std::vector<lt::BreakEvent> prefix(log.begin(), log.begin() + static_cast<std::ptrdiff_t>(n));
  std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
  for (const lt::BreakEvent& e : prefix) broken[static_cast<std::size_t>(e.beam)] = true;
  return {t, lt::compute_fracture_statistics(lattice, broken, prefix, options,
                                             lt::softened_flags(teeth, lattice.n_beams(), t))};
}

}  // namespace

RunRecorder::RunRecorder(const std::filesystem::path& dir, const RunCase& c)
    : output_(c.output),
      r_min_(c.lattice.domain == lt::DomainShape::annulus ? c.lattice.inner_radius : 0.0),
      dir_(dir),
      files_(files_written(c)),
      fracture_(c.fracture_enabled),
      statistics_options_{c.output.statistics},
      sawtooth_(c.fracture_enabled && c.fracture_law == lt::FractureLaw::sawtooth) {
  for (const RunFile& f : files_)
    if (f.writing == RunFileWriting::streamed) streams_[f.id] = core::open_for_writing(run_file_path(dir, f.id));
  open_writers(core::CsvHeader::write);
  if (fracture_) lt::write_break_log_header(streams_[RunFileId::breaks], "time");
  if (output_.vtk) vtk_ = std::make_unique<lt::VtkSeries>(vtk_folder(dir), "lattice");
}

void RunRecorder::open_writers(core::CsvHeader header) {
  series_ = std::make_unique<CsvWriter>(streams_[RunFileId::series], series_columns, core::NonFinite::write, header);
  radial_ = std::make_unique<CsvWriter>(streams_[RunFileId::radial], radial_columns, core::NonFinite::write, header);
  if (fracture_)
    pressure_ = std::make_unique<CsvWriter>(streams_[RunFileId::fracture_pressure], fracture_pressure_columns,
                                            core::NonFinite::write, header);
}

RunRecorder::RunRecorder(const std::filesystem::path& dir, const RunCase& c, const lt::CoupledModel& model,
                         core::StateReader& r)
    : output_(c.output),
      r_min_(c.lattice.domain == lt::DomainShape::annulus ? c.lattice.inner_radius : 0.0),
      dir_(dir),
      files_(files_written(c)),
      fracture_(c.fracture_enabled),
      statistics_options_{c.output.statistics},
      sawtooth_(c.fracture_enabled && c.fracture_law == lt::FractureLaw::sawtooth),
      teeth_(model.tooth_log()) {
  std::vector<std::int64_t> sizes;
  r.get("recorder.file_sizes", sizes);
  const std::vector<RunFileId> streamed = streamed_files();
  if (sizes.size() != streamed.size())
    throw InputError(r.source() + ": at 'recorder.file_sizes': " + std::to_string(streamed.size()) +
                     " values expected");
  std::vector<double> b;
  r.get("recorder.breakdown", b);
  if (b.size() != 9) throw InputError(r.source() + ": at 'recorder.breakdown': 9 values expected");
  breakdown_ = {b[0], b[1], b[2], b[3], b[4], b[5], b[6], static_cast<int>(b[7])};
  last_p_h_ = b[8];
  std::vector<double> fracture_t;
  std::vector<std::int64_t> fracture_n;
  r.get("recorder.fracture_times", fracture_t);
  r.get("recorder.fracture_log_sizes", fracture_n);
  std::vector<double> vtk_t;
  std::string vtk_files;
  std::vector<std::int64_t> vtk_sizes;
  r.get("recorder.vtk_times", vtk_t);
  r.get("recorder.vtk_files", vtk_files);  // one name per line
  r.get("recorder.vtk_sizes", vtk_sizes);
  if (vtk_sizes.size() != vtk_t.size())
    throw InputError(r.source() + ": at 'recorder.vtk_sizes': one per snapshot time expected");

  const auto& log = model.break_log();
  if (fracture_t.size() != fracture_n.size())
    throw InputError(r.source() + ": at 'recorder.fracture_log_sizes': one per fracture time expected");
  for (std::size_t k = 0; k < fracture_t.size(); ++k) {
    if (fracture_n[k] < 0 || static_cast<std::size_t>(fracture_n[k]) > log.size())
      throw InputError(r.source() + ": at 'recorder.fracture_log_sizes': longer than the break log");
    fractures_.push_back(fracture_snapshot(model.lattice(), log, static_cast<std::size_t>(fracture_n[k]), teeth_,
                                           fracture_t[k], statistics_options_));
    fracture_log_sizes_.push_back(static_cast<std::size_t>(fracture_n[k]));
  }
  if (fracture_) breaks_ = log;
  std::vector<lt::PvdEntry> written;
  std::size_t from = 0;
  for (double t : vtk_t) {
    const std::size_t to = vtk_files.find('\n', from);
    written.push_back({t, vtk_files.substr(from, to - from)});
    from = to + 1;
  }
  // The snapshots written before the stop are part of the result as the CSV files are: a run
  // continued without one, or with one cut short, would be complete but for it.
  if (output_.vtk)
    for (std::size_t k = 0; k < written.size(); ++k) {
      const std::filesystem::path file = vtk_folder(dir) / written[k].file;
      std::error_code ec;
      std::string problem;
      if (!std::filesystem::is_regular_file(file, ec))
        problem = "is missing";
      else if (const auto size = static_cast<std::int64_t>(std::filesystem::file_size(file, ec)); size != vtk_sizes[k])
        problem = "has " + std::to_string(size) + " bytes, not the " + std::to_string(vtk_sizes[k]) +
                  " the stopped run wrote";
      if (!problem.empty())
        throw InputError("'" + file.string() + "' " + problem +
                         "; allowed: the run folder as the stopped run left it (rerun the case from its config.toml "
                         "instead)");
    }

  for (std::size_t k = 0; k < streamed.size(); ++k)
    if (writes(c, run_file(streamed[k])))
      streams_[streamed[k]] =
          core::open_for_appending(run_file_path(dir, streamed[k]), static_cast<std::uintmax_t>(sizes[k]));
  open_writers(core::CsvHeader::already_written);
  if (output_.vtk)
    vtk_ = std::make_unique<lt::VtkSeries>(vtk_folder(dir), "lattice", lt::VtkFormat::binary, std::move(written));
}

void RunRecorder::save_state(core::StateWriter& w) {
  const auto size_of = [](std::ofstream& f) {
    f.flush();
    return f.is_open() ? static_cast<std::int64_t>(f.tellp()) : std::int64_t{0};
  };
  std::vector<std::int64_t> sizes;
  for (RunFileId id : streamed_files()) sizes.push_back(streams_.count(id) ? size_of(streams_[id]) : 0);
  w.put("recorder.file_sizes", sizes);
  const Breakdown& b = breakdown_;
  w.put("recorder.breakdown", std::vector<double>{b.t_first, b.p_before, b.p_first, b.x_first, b.y_first, b.t_peak,
                                                  b.p_peak, static_cast<double>(b.n_broken), last_p_h_});
  std::vector<double> fracture_t;
  std::vector<std::int64_t> fracture_n;
  for (std::size_t k = 0; k < fractures_.size(); ++k) {
    fracture_t.push_back(fractures_[k].t);
    fracture_n.push_back(static_cast<std::int64_t>(fracture_log_sizes_[k]));
  }
  w.put("recorder.fracture_times", fracture_t);
  w.put("recorder.fracture_log_sizes", fracture_n);
  std::vector<double> vtk_t;
  std::string vtk_files;
  std::vector<std::int64_t> vtk_sizes;
  if (vtk_)
    for (const lt::PvdEntry& e : vtk_->entries()) {
      vtk_t.push_back(e.time);
      vtk_files += e.file + "\n";
      vtk_sizes.push_back(static_cast<std::int64_t>(std::filesystem::file_size(vtk_folder(dir_) / e.file)));
    }
  w.put("recorder.vtk_times", vtk_t);
  w.put("recorder.vtk_files", vtk_files);
  w.put("recorder.vtk_sizes", vtk_sizes);
}

void RunRecorder::record(const lt::CoupledModel& model, const lt::CoupledStepSummary& step, bool is_output) {
  const lt::FlowTotals& t = model.flow().totals();
  series_->row({model.time(), step.dt, injection_pressure(model), t.injected, t.storage, t.deformation, t.outflow,
                step.flow.balance_error, static_cast<double>(model.n_broken()), static_cast<double>(step.iterations),
                step.pressure_residual, step.displacement_residual});
  const double p_h = injection_pressure(model);
  Breakdown& b = breakdown_;
  if (p_h > b.p_peak) {
    b.p_peak = p_h;
    b.t_peak = model.time();
  }
  if (fracture_) {
    // The first break is the first beam that failed: a notch's beams (mode none) were cut.
    const auto& log = model.break_log();
    const auto failed = log.begin() + std::min<std::ptrdiff_t>(model.n_cut(), static_cast<std::ptrdiff_t>(log.size()));
    if (std::isnan(b.t_first) && failed != log.end()) {
      b.t_first = model.time();
      b.p_before = last_p_h_;
      b.p_first = p_h;
      b.x_first = failed->position.x();
      b.y_first = failed->position.y();
    }
    const std::vector<lt::BreakEvent> new_breaks(log.begin() + static_cast<std::ptrdiff_t>(breaks_.size()), log.end());
    std::ofstream& breaks_file = streams_[RunFileId::breaks];
    lt::write_break_log_rows(breaks_file, new_breaks);
    breaks_file.flush();
    breaks_.insert(breaks_.end(), new_breaks.begin(), new_breaks.end());
    b.n_broken = model.n_broken();
  }
  if (sawtooth_) {
    const auto& log = model.tooth_log();
    teeth_.insert(teeth_.end(), log.begin() + static_cast<std::ptrdiff_t>(teeth_.size()), log.end());
  }
  streams_[RunFileId::series].flush();
  last_p_h_ = p_h;
  if (!is_output) return;
  const RadialFields f = radial_fields(model, lt::uniform_shell_edges(r_min_, output_.radial_max, output_.radial_bins));
  for (std::size_t k = 0; k < f.r_mid.size(); ++k)
    radial_->row({model.time(), f.r_mid[k], f.r_mean[k], static_cast<double>(f.n_triangles[k]), f.u_r[k], f.p[k]});
  streams_[RunFileId::radial].flush();
  if (fracture_) {
    fractures_.push_back(fracture_snapshot(model.lattice(), model.break_log(), model.break_log().size(), teeth_,
                                           model.time(), statistics_options_));
    fracture_log_sizes_.push_back(model.break_log().size());
    const FracturePressure fp = fracture_pressure(model);
    pressure_->row({model.time(), fp.mean_all, fp.mean_away, fp.min_away, static_cast<double>(fp.n_all),
                    static_cast<double>(fp.n_away), fp.negative_area_fraction, fp.p_min, fp.p_max, fp.borehole_backflow,
                    fp.outer_inflow, fp.mouth_inflow});
    streams_[RunFileId::fracture_pressure].flush();
  }
  if (vtk_) {
    lt::LatticeSnapshot snapshot;
    snapshot.time = model.time();
    snapshot.displacement = model.displacement();
    snapshot.pressure = model.pressure().head(model.lattice().n_triangles());
    snapshot.beam_states = model.mechanics().states();
    snapshot.particle_stress = model.particle_stress().stress;
    if (fracture_) snapshot.beam_fields.push_back({"failure_ratio", model.failure_ratio()});
    if (sawtooth_) {
      Eigen::VectorXd stiffness(model.lattice().n_beams());
      for (int e = 0; e < stiffness.size(); ++e)
        stiffness[e] = model.mechanics().states()[static_cast<std::size_t>(e)] == lt::BeamState::intact
                           ? model.mechanics().stiffness_factor(e)
                           : 0.0;
      snapshot.beam_fields.push_back({"stiffness_factor", stiffness});
    }
    snapshot.beam_fields.push_back({"crack_opening", crack_openings(model)});
    if (model.flow().parameters().fracture_flow.law == lt::FractureFlow::cubic) {
      // The aperture that conducts (w (opening + residual)), where crack_opening is the opening alone.
      Eigen::VectorXd aperture(model.lattice().n_beams());
      for (int e = 0; e < aperture.size(); ++e) aperture[e] = model.flow().crack_aperture(e);
      snapshot.beam_fields.push_back({"crack_aperture", aperture});
    }
    vtk_->write(model.lattice(), model.current_dual(), snapshot);
  }
}

}  // namespace hm::cases

namespace hm::cases {

void RunRecorder::finish() {
  for (auto& [id, stream] : streams_) core::close_checked(stream, run_file_path(dir_, id));
  for (const RunFile& f : files_)
    if (f.writing == RunFileWriting::whole) write_whole(f.id);
}

void RunRecorder::write_whole(RunFileId id) const {
  const std::filesystem::path path = run_file_path(dir_, id);
  switch (id) {
    case RunFileId::teeth: lt::write_tooth_log(path, teeth_, "time"); return;
    case RunFileId::fractures: lt::write_fracture_table(path, fractures_); return;
    case RunFileId::fracture_summary: lt::write_fracture_summary(path, fractures_); return;
    case RunFileId::breakdown:
      core::write_file_atomically(path, [&](std::ostream& file) {
        CsvWriter breakdown(file, {"t_first_break", "p_h_before", "p_h_first_break", "x_first_break", "y_first_break",
                                   "t_peak", "p_h_peak", "n_broken"});
        const Breakdown& b = breakdown_;
        breakdown.row({b.t_first, b.p_before, b.p_first, b.x_first, b.y_first, b.t_peak, b.p_peak,
                       static_cast<double>(b.n_broken)});
      });
      return;
    case RunFileId::config: return;  // the command writes the resolved case before the run
    default: throw std::logic_error("RunRecorder: no writer for " + std::string(run_file(id).name));
  }
}

}  // namespace hm::cases
