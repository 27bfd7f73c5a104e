#pragma once
/// \file
/// Fracture statistics of a finished run, recomputed from its files (`hmlattice fractures`): a rule
/// of fracture_statistics.hpp changes without re-running a case that took an hour.
#include <filesystem>
#include <optional>
#include <string>

#include "hm/lattice2d/fracture/fracture_statistics.hpp"

namespace hm::cases {

/// What recompute_fracture_statistics found.
struct FractureReanalysis {
  int n_snapshots = 0;  ///< rows of fracture_summary.csv
  int n_breaks = 0;     ///< events of breaks.csv
};

/// The counting rules to change; an empty one keeps the run's config.toml value (its default for a
/// run written before the key existed).
struct StatisticsChange {
  std::optional<hm::lattice2d::FractureLink> link;       ///< [output] fracture_link
  std::optional<double> arm_gap;                         ///< [output] arm_gap, over R
  std::optional<hm::lattice2d::SoftenedBeams> softened;  ///< [output] softened_beams
};

/// Rewrites fractures.csv and fracture_summary.csv of the run in `run_dir` (written by
/// `hmlattice run` with fracture enabled) with its config.toml's counting rules changed by `change`:
/// the lattice is rebuilt from its config.toml, a snapshot at time t holds the beams of breaks.csv
/// logged at a time <= t (and, under the saw-tooth law, the softened beams of teeth.csv logged by t),
/// and the snapshot times are those of the old fracture_summary.csv. config.toml's [output]
/// fracture_link, arm_gap and softened_beams become the rules used ([provenance] kept, the command
/// added as a comment). Every file is replaced atomically, after everything has been read
/// and computed.
/// Throws hm::InputError naming the folder or file if run_dir is not such a run, std::runtime_error
/// "<file>:<line>: ..." if a file is damaged.
FractureReanalysis recompute_fracture_statistics(const std::filesystem::path& run_dir, const StatisticsChange& change,
                                                 const std::string& command_line);

}  // namespace hm::cases
