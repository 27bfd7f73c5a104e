#pragma once
/// \file
/// Output of a 2D coupled run (`hmlattice run`), read by figures/ and by users; which files a run
/// writes, and how, is the table run_files.hpp. Their columns:
///   series.csv  one row per accepted step (and t = 0): t, dt, p_h, injected, stored, coupling, outflow,
///               balance_error, n_broken, iterations, pressure_residual, displacement_residual.
///               Volumes are totals since t = 0 (dimensionless areas); injected = stored + coupling +
///               outflow, with coupling = b sum (V - V^0) the fluid taken up by the deformation;
///               balance_error is that step's relative error (FlowStepSummary). p_h is the borehole
///               pressure (annulus) or the pressure of the source triangle (disk).
///   radial.csv  t, r, r_mean, n_triangles, u_r, p at each output time: shell averages over triangles
///               binned by their undeformed centroid radius (radial_average.hpp); u_r of a triangle is
///               the mean radial displacement of its three particles.
///   vtk/lattice_NNNN.vtu + vtk/lattice.pvd  snapshots at the output times (pressure per triangle,
///               beam states).
/// With fracture enabled, also:
///   breaks.csv     the break log (failure.hpp's columns, load column "time"), in the order of breaking;
///   breakdown.csv  one row: t_first_break, p_h_before (p_h^n of the step that broke the first beam),
///                  p_h_first_break (its converged p_h^{n+1}), x_first_break, y_first_break,
///                  t_peak, p_h_peak (largest p_h of the run), n_broken (at the end); NaN where nothing
///                  broke. The breakdown pressure of Section 3.5 is p_h_first_break (and the peak if later);
///   fractures.csv  per output time, one row per fracture (clusters of broken beams through shared
///                  particles, or triangles: [output] fracture_link; fracture_statistics.hpp): kind
///                  radial|secondary, extent, angle, modes;
///   fracture_summary.csv  per output time: counts of fractures, radial ones, those reaching the outer
///                  boundary, secondary ones, arms crossing r = R_i + (1 - R_i)/4 (gaps of 3 beam lengths
///                  and of [output] arm_gap), tensile/shear breaks;
///   fracture_pressure.csv  per output time: the fluid in the fractures and the backflows
///                  (fracture_pressure.hpp's FracturePressure, one column per field).
/// With [fracture] law = "sawtooth", also teeth.csv (break_log.hpp's write_tooth_log, load column
/// "time"): every tooth that gave way, written when the run ends; and the VTK beam field
/// stiffness_factor (1 intact, between 0 and 1 softened, 0 broken).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <vector>

#include "hm/case/run_case.hpp"
#include "hm/case/run_files.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/fracture/fracture_statistics.hpp"
#include "hm/lattice2d/io/vtk_writer.hpp"

namespace hm::cases {

/// Section 3.5's breakdown of a run so far: the first break and the peak borehole pressure p_h.
struct Breakdown {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double t_first = none;                  ///< time of the step that broke the first beam (NaN while nothing broke)
  double p_before = none;                 ///< p_h^n of that step
  double p_first = none;                  ///< its converged p_h^{n+1}: the breakdown pressure
  double x_first = none, y_first = none;  ///< midpoint of the first broken beam
  double t_peak = 0.0, p_peak = -std::numeric_limits<double>::infinity();  ///< largest p_h so far
  int n_broken = 0;
  bool has_broken() const { return !std::isnan(t_first); }
};

/// Writes the files above into `dir` (created by the caller) while a CoupledModel runs; pass
/// record() as the model's observer. series.csv and breaks.csv are flushed at every step, so an
/// interrupted or failed run keeps every step it finished. Nothing here decides anything about the run.
class RunRecorder {
 public:
  RunRecorder(const std::filesystem::path& dir, const RunCase& c);
  /// A recorder that continues a run resumed from a checkpoint: reads what save_state wrote (after the
  /// model's state, with `model` restored from it) and appends to the files in `dir`, cut back to
  /// their length at the checkpoint. Throws hm::InputError for a damaged folder or state.
  RunRecorder(const std::filesystem::path& dir, const RunCase& c, const hm::lattice2d::CoupledModel& model,
              core::StateReader& r);
  /// What a resumed recorder needs (file lengths, breakdown, output snapshots so far); flushes the files.
  void save_state(core::StateWriter& w);
  void record(const hm::lattice2d::CoupledModel& model, const hm::lattice2d::CoupledStepSummary& step, bool is_output);
  /// Closes the CSV files and writes the fracture files; throws std::runtime_error if a write failed.
  void finish();
  /// The breakdown up to the last record() (first break only with fracture enabled).
  const Breakdown& breakdown() const { return breakdown_; }

 private:
  void open_writers(core::CsvHeader header);
  void write_whole(RunFileId id) const;

  RunOutput output_;
  double r_min_ = 0.0;
  std::filesystem::path dir_;
  std::vector<RunFile> files_;  // the files this run writes (run_files.hpp)
  bool fracture_ = false;
  hm::lattice2d::FractureStatisticsOptions statistics_options_;
  Breakdown breakdown_;
  double last_p_h_ = 0.0;
  std::vector<hm::lattice2d::BreakEvent> breaks_;
  bool sawtooth_ = false;                         // law = "sawtooth": teeth.csv
  std::vector<hm::lattice2d::ToothEvent> teeth_;  // the model's tooth log at the last record()
  std::vector<hm::lattice2d::FractureSnapshot> fractures_;
  std::vector<std::size_t> fracture_log_sizes_;  // break-log length at each snapshot
  std::map<RunFileId, std::ofstream> streams_;   // the streamed files, open while the run goes
  std::unique_ptr<core::CsvWriter> series_, radial_, pressure_;
  std::unique_ptr<hm::lattice2d::VtkSeries> vtk_;
};

/// The radially averaged u_r and p of the model's current state on `edges` (helper of RunRecorder,
/// also used by the benchmarks): one entry per shell.
struct RadialFields {
  std::vector<double> r_mid, r_mean, u_r, p;
  std::vector<int> n_triangles;
};
RadialFields radial_fields(const hm::lattice2d::CoupledModel& model, const std::vector<double>& edges);

/// Per beam, the normal opening (u_j - u_i).n_ij of a broken beam (> 0: its faces apart; over R), 0 for
/// an intact one: the VTK snapshots' crack_opening.
Eigen::VectorXd crack_openings(const hm::lattice2d::CoupledModel& model);

/// The borehole pressure (annulus) or the source triangle's pressure (disk).
double injection_pressure(const hm::lattice2d::CoupledModel& model);

}  // namespace hm::cases
