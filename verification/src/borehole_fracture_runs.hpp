#pragma once
// Running the Fig. 12/13 cases for the verification harness (benchmarks_lattice2d_borehole_fracture.cpp):
// one fracturing run with what it showed (breakdown, fracture statistics and the pressure in the fractures
// per output time, never-heal checks, the 2D-vs-1D borehole pressure before the first break), its
// unfractured flux-borehole twin, and the 1D reference. Each run's folder is written as `hmlattice run`
// writes it (RunRecorder), the reference's as `hmlattice fdm1d` writes it.
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "hm/case/fracture_pressure.hpp"
#include "hm/case/run_case.hpp"
#include "hm/fdm1d/fdm1d.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/fracture/fracture_statistics.hpp"

namespace hm::verification::borehole_fracture {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The p_h comparison with 1D starts at t* = 1e-3, as in benchmarks_lattice2d_vs_fdm1d.cpp: before it the
/// wall's pressure boundary layer sqrt(t/S) is thinner than the lattice spacing and the lattice's p_h
/// is far above the 1D one whatever the borehole node (docs/lattice_vs_fdm1d.md).
inline constexpr double kWindow = 1e-3;

using cases::FracturePressure;

/// The state at one output time.
struct Snapshot {
  double t = 0.0, p_h = 0.0;
  hm::lattice2d::FractureStatistics stats;
  FracturePressure fp;
  double u_pre = kNaN;         // before the first break only: max over shells |u_r/u_r,1D - 1| (information)
  double u_ratio_mean = kNaN;  // the mean over shells of u_r/u_r,1D (1D without fracture)
  std::vector<double> u_r;     // the shells' u_r (radial.csv)
  // Secondary fractures at least sizable_extent long: touching the outer boundary, or inside the domain.
  int secondary_at_outer = 0, secondary_inside = 0;
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
  double b = 0.0, Q = 0.0;
  long long n_particles = 0;
  unsigned long long seed = 0;
  double R_i = 0.0;
  bool eq16_node = false;  // the borehole node of Eq. 16 as printed instead of the cases' flux boundary
  bool ok = false;
  std::string message;
  int n_steps = 0, passes = 0, n_halvings = 0;
  double seconds = 0.0, mechanics = 0.0, fracture = 0.0, geometry = 0.0, flow = 0.0, max_balance = 0.0;
  std::vector<Snapshot> snaps;
  // Breakdown (Section 3.5), as RunRecorder's breakdown.csv.
  double t_first = kNaN, p_before = kNaN, p_first = kNaN, r_first = kNaN, length_first = kNaN;
  hm::lattice2d::FailureMode mode_first = hm::lattice2d::FailureMode::none;
  double t_peak = 0.0, p_peak = -std::numeric_limits<double>::infinity();
  // Broken beams never heal: steps where n_broken fell, and beams found intact after having broken.
  int n_broken_decreases = 0, n_healed = 0;
  // p_h against the 1D model (no fracture) before the first break.
  double pre_max = kNaN, pre_max_t = kNaN;    // max |p_h/p_h,1D - 1| for t* >= kWindow, and where
  double pre_last = kNaN, pre_last_t = kNaN;  // at the last step before the breaking one (any t*)
  double pre_signed_last = kNaN;              // p_h/p_h,1D - 1 there (signed)
  std::string twin_label;                     // empty: no twin run
  TwinOutcome twin;
  std::string eq16_label;  // the folder of the same case with Eq. 16's borehole node; empty: none
};

/// The 1D model's parameters for case `c`: its physics with the calibrated lattice's nu and
/// plane-strain volumetric strain (the lattice is a plane-strain continuum).
analytic::DimensionlessParameters reference_parameters(const cases::RunCase& c);

/// The 1D model on case `c`'s material (the calibrated lattice's nu, plane strain), dt sequence and
/// output times, from the case's rest state when its in-situ stress is isotropic (fdm1d::RestState).
fdm1d::Fdm1dResult run_reference(const cases::RunCase& c);

/// The 1D reference of a case (fdm1d: Appendix A, no fracture, flux-boundary borehole, with the calibrated
/// lattice's nu), written to root/fdm1d_b<b>/ as `hmlattice fdm1d` writes it.
fdm1d::Fdm1dResult write_reference(const cases::RunCase& c, const std::filesystem::path& root);

/// What the files of run folder `dir` of case `c` (as `hmlattice run` writes it, complete) show: every
/// field of RunOutcome but the pressure in the fractures (VTK only: left NaN, n_away = 0) and the timing
/// split (NaN; n_halvings -1). Numbers as the CSV files hold them (10 significant digits). Throws
/// std::runtime_error naming a missing or damaged file.
RunOutcome read_run(const cases::RunCase& c, const std::string& label, const std::filesystem::path& dir,
                    const fdm1d::Fdm1dResult& ref);

/// Runs case `c` with fracture into root/label/, then reads its numbers from there (read_run), so that
/// a folder made by `hmlattice run` gives the same; adds what only the running model shows (the
/// pressure in the fractures, the timing split, a beam found intact after breaking). `progress`
/// (null: silent) gets a line a minute and one at the end: the paper tier's runs take up to an hour.
RunOutcome run_case(const cases::RunCase& c, const std::string& label, const std::filesystem::path& root,
                    const fdm1d::Fdm1dResult& ref, std::ostream* progress = nullptr);

/// The unfractured flux-borehole twin of `c`, to the case's first output time.
cases::RunCase flux_twin_case(const cases::RunCase& c);

/// What the twin's run folder shows (`twin_case` = flux_twin_case(c)).
TwinOutcome read_twin(const cases::RunCase& twin_case, const std::filesystem::path& dir, const fdm1d::Fdm1dResult& ref);

/// Runs the twin of `c` into root/label/ and reads it (read_twin).
TwinOutcome run_flux_twin(const cases::RunCase& c, const std::string& label, const std::filesystem::path& root,
                          const fdm1d::Fdm1dResult& ref);

/// Where a benchmark's runs come from: run here into root/<label> (hmlattice verify's single-process
/// mode), or read from runs_dir/<label> when that folder exists (`hmlattice verify --runs DIR`; the
/// harness has checked it is complete and of the same case: check_run_folders).
class RunSource {
 public:
  RunSource(std::filesystem::path root, std::filesystem::path runs_dir, std::ostream* progress);
  RunOutcome run(const cases::RunCase& c, const std::string& label, const fdm1d::Fdm1dResult& ref);
  /// The flux-borehole twin of the fracturing case `c`.
  TwinOutcome twin(const cases::RunCase& c, const std::string& label, const fdm1d::Fdm1dResult& ref);
  /// The folder of run `label` for runs.csv: the label (under root) if run here, else the absolute path.
  std::string folder(const std::string& label) const;
  /// For the report: which runs were read from runs_dir ("" without runs_dir).
  std::string note() const;

 private:
  bool is_read(const std::string& label) const;
  std::filesystem::path root_, runs_dir_;
  std::ostream* progress_;
  std::vector<std::string> read_;
};

/// `c` on a lattice of n_particles with `seed` for the lattice and the strengths (a seed scatter).
cases::RunCase with_lattice(cases::RunCase c, long long n_particles, unsigned long long seed);

/// `c` with the paper's Eq. 16 borehole node (storage (E/M) V_h dp_h and b dV_h, errata E15) instead of
/// the cases' flux boundary.
cases::RunCase with_eq16_borehole_node(cases::RunCase c);

}  // namespace hm::verification::borehole_fracture
