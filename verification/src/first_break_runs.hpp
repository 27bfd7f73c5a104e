#pragma once
// A lattice run that ends at its first break ([fracture] stop_at_first_break, Section 3.5's breakdown
// pressure), for the Fig. 18 benchmark: run into root/<label>/ as `hmlattice run` writes it, or read from
// runs_dir/<label>/ when a workflow made it there (`hmlattice verify --runs`), and read back with
// borehole_fracture::read_run either way, so that both give the same numbers.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "borehole_fracture_runs.hpp"
#include "hm/case/run_case.hpp"

namespace hm::verification::breakdown {

class FirstBreakRuns {
 public:
  FirstBreakRuns(std::filesystem::path root, std::filesystem::path runs_dir, std::ostream* progress);
  /// Case `c` (stop_at_first_break set) as run `label`; `ref` is the 1D model on the case's steps
  /// (borehole_fracture::run_reference), for the p_h comparison before the break. `seconds` is the run's
  /// wall time (NaN for a read run).
  borehole_fracture::RunOutcome run(const cases::RunCase& c, const std::string& label, const fdm1d::Fdm1dResult& ref);
  /// For the report: which runs were read from runs_dir ("" without runs_dir).
  std::string note() const;

 private:
  std::filesystem::path root_, runs_dir_;
  std::ostream* progress_;
  std::vector<std::string> read_;
};

}  // namespace hm::verification::breakdown
