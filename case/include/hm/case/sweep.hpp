#pragma once
/// \file
/// Sweep cases: a case file with a [sweep] table that names a list of values for some keys,
///
///   [sweep]
///   "physics.Q" = [1e-3, 1e-2]
///   "lattice.seed" = [1, 2]
///
/// stands for one case per combination of the lists (their cartesian product). expand_sweep() writes
/// each combination as a resolved case file (every default filled in, as a run's config.toml) named
/// after its swept values, e.g. `Q=0.001_seed=1.toml`, and an index.csv; collect_sweep()
/// (sweep_collect.hpp) gathers the runs' results. Every combination is read and validated by the
/// model's own case reader before anything is kept, so a sweep that expands is a set of valid cases.
/// What a sweep cannot do: sweep two keys together (zipped lists), or sweep a key outside a table
/// (`model`) or inside a sub-table.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hm::cases {

/// One swept key.
struct SweepAxis {
  std::string key;                  ///< "table.key", as in [sweep]
  std::string short_name;           ///< its part in combination names: `key` after the dot, unless two axes share it
  std::vector<std::string> values;  ///< each value as it appears in names and index.csv
};

/// One expanded case.
struct SweepCombination {
  std::string name;                 ///< the file's stem, e.g. "Q=0.001_seed=1" (letters, digits, . _ = + -)
  std::vector<std::string> values;  ///< one per axis, as in SweepAxis::values
};

/// What expand_sweep() wrote.
struct SweepExpansion {
  std::string model;                           ///< "lattice2d" or "fdm1d"
  std::string command;                         ///< the hmlattice command that runs each case: "run" or "fdm1d"
  std::vector<SweepAxis> axes;                 ///< in the order of the [sweep] table in the file
  std::vector<SweepCombination> combinations;  ///< the first axis varies slowest
  long long n_planned = 0;                     ///< the product of the lists' sizes
  bool stopped = false;                        ///< `stop` ended it before the last combination
};

/// The largest sweep expand_sweep() writes unless told otherwise (`--max-combinations`).
inline constexpr long long default_max_combinations = 10000;

/// Name of the index of an expanded sweep: columns name, command, then one per swept key.
inline constexpr const char* sweep_index_name = "index.csv";

/// Expands the sweep case `case_file` into `folder` (an existing empty folder: the staging folder of
/// a ResultFolder): `<name>.toml` per combination and index.csv. Throws hm::InputError with one line
/// naming the file, [sweep], the key, the value and what is allowed — a missing or empty [sweep], a
/// key that is not "table.key", an empty list or one mixing types or holding tables, two
/// combinations with one name — or, for a combination the model's reader refuses, its name and the
/// reader's message ("[physics] Q = -1, allowed: 0 <= Q <= 1e6"). Files already written to `folder`
/// are then left for the caller to discard with the folder.
/// More than `max_combinations` combinations is refused before any is written (a list typed with an
/// extra zero must not fill a disk with case files); the case's own value of a swept key, which the
/// sweep replaces, is checked by the reader as well (a file `run` would refuse is not expanded). `stop`
/// is asked before each combination: when it returns true the expansion ends early with `stopped` set
/// (the caller discards the folder).
SweepExpansion expand_sweep(const std::filesystem::path& case_file, const std::filesystem::path& folder,
                            long long max_combinations = default_max_combinations,
                            const std::function<bool()>& stop = {});

/// The [sweep] section of the case-format reference (markdown).
std::string sweep_reference_markdown();

}  // namespace hm::cases
