#pragma once
/// \file
/// The fracture tables of a run: fractures.csv (one row per fracture per output time) and
/// fracture_summary.csv (one row per output time).
#include <filesystem>
#include <vector>

#include "hm/lattice2d/fracture/fracture_statistics.hpp"

namespace hm::lattice2d {

/// Writes one row per fracture per snapshot, via a temporary file renamed into place. Columns:
///   t, fracture (id), kind (radial|secondary), n_beams, connected_to_borehole (0/1),
///   reaches_outer (0/1), r_min, r_max, length, angle_deg, n_tensile, n_shear, extent.
/// Numbers with 10 significant digits. Throws std::runtime_error naming the path if it cannot write.
void write_fracture_table(const std::filesystem::path& path, const std::vector<FractureSnapshot>& snapshots);

/// Writes one row per snapshot, via a temporary file renamed into place. Columns:
///   t, n_broken, n_fractures, n_radial, n_radial_reaching_outer, n_secondary, n_arms, n_tensile,
///   n_shear, max_radial_extent, n_secondary_sizable, n_arms_fixed_gap.
/// Throws std::runtime_error naming the path if it cannot write.
void write_fracture_summary(const std::filesystem::path& path, const std::vector<FractureSnapshot>& snapshots);

}  // namespace hm::lattice2d
