#pragma once
/// \file
/// CSV output of a 1D run, read by figures/fig10_*.py and fig11_*.py and by users:
///   borehole.csv  t, p_h, injected, stored, outflow, balance_error, wall stresses and sigma_CC
///   profiles.csv  t, r, p, u_r, sigma_r, sigma_theta, sigma_z, coulomb (one row per node and time)
///   probes.csv    t, p_r<radius> for each probe radius
///   steady_state.csv  r, p, u_r, sigma_r, sigma_theta, sigma_z, coulomb of the corrected Appendix B
///                     at the grid nodes: the state the run tends to (dashed in Figs. 10, 11)
#include <filesystem>
#include <fstream>
#include <memory>

#include "hm/analytic/physical_parameters.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace hm::cases {

/// Writes the files above into `dir` (created by the caller) while run_fdm1d runs; pass record() as
/// its observer. borehole.csv, probes.csv and profiles.csv are flushed at every step, so an interrupted
/// run keeps every step it finished. Rows with inf or nan are refused (hm::InputError: the inputs
/// overflowed double precision).
class Fdm1dRecorder {
 public:
  Fdm1dRecorder(const std::filesystem::path& dir, const std::vector<double>& probe_radii);
  /// Appends what `so_far` holds beyond the previous call.
  void record(const hm::fdm1d::Fdm1dResult& so_far);
  /// Closes the CSV files and writes steady_state.csv on the grid of the last record(); throws
  /// std::runtime_error if a write failed.
  void finish(const hm::analytic::DimensionlessParameters& params);

 private:
  std::filesystem::path dir_;
  std::ofstream borehole_file_, profiles_file_, probes_file_;
  std::unique_ptr<core::CsvWriter> borehole_, profiles_, probes_;
  std::size_t n_samples_ = 0, n_snapshots_ = 0;
  std::vector<double> r_;
};

/// The files above of a finished (or stopped) run at once.
void write_fdm1d_results(const std::filesystem::path& dir, const hm::fdm1d::Fdm1dResult& result,
                         const hm::analytic::DimensionlessParameters& params);

}  // namespace hm::cases
