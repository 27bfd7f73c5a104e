#pragma once
/// \file
/// Gathering the results of an expanded sweep (sweep.hpp): one CSV row per combination of its
/// index.csv, from the run folder of that name.
#include <filesystem>
#include <ostream>

namespace hm::cases {

/// How many combinations of a sweep have a complete run folder, a stopped or unfinished one, or none.
struct SweepCollectCounts {
  int complete = 0;
  int incomplete = 0;
  int missing = 0;
  int other_case = 0;  ///< complete runs of another case than their combination's
};

/// The state of a run folder as collect_sweep reports it: "complete" (a result folder whose marker says
/// it finished), "incomplete" (stopped before t_end, still being written, or not written by hmlattice)
/// or "missing" (nothing there). Reads only.
std::string run_folder_status(const std::filesystem::path& run);

/// Writes to `csv` one row per combination of `sweep_folder`/index.csv (an `hmlattice sweep expand`
/// folder), in its order: name, the swept values, `status` (complete: `runs_folder`/<name> is a
/// result folder whose marker says it finished; incomplete: a folder that stopped before t_end, is
/// still being written or was not written by hmlattice; missing: nothing there; other case: a finished
/// run whose resolved config.toml is not its combination's case, e.g. made before the sweep was
/// changed: its results are left out, never listed under the combination's values), `wall_seconds`
/// (from the run's config.toml provenance time to its marker's, to 1 s; complete runs only), the
/// columns of breakdown.csv and the last row of fracture_summary.csv with `final_` in front (the
/// state at t_end; both files only for a run with fracture enabled). Values are copied as the run
/// wrote them; a column a run lacks is empty. Throws hm::InputError if `sweep_folder` has no
/// readable index.csv. Reads only.
SweepCollectCounts collect_sweep(const std::filesystem::path& sweep_folder, const std::filesystem::path& runs_folder,
                                 std::ostream& csv);

}  // namespace hm::cases
