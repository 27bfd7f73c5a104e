#include "hm/lattice2d/io/fracture_tables.hpp"

#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"

namespace hm::lattice2d {

using core::csv_number;

void write_fracture_table(const std::filesystem::path& path, const std::vector<FractureSnapshot>& snapshots) {
  core::write_file_atomically(path, [&](std::ostream& out) {
    out << "t,fracture,kind,n_beams,connected_to_borehole,reaches_outer,r_min,r_max,length,angle_deg,n_tensile,"
           "n_shear,extent\n";
    for (const FractureSnapshot& snap : snapshots)
      for (const Fracture& f : snap.stats.fractures)
        out << csv_number(snap.t) << ',' << f.id << ',' << core::name_of(f.kind) << ',' << f.n_beams() << ','
            << (f.connected_to_borehole ? 1 : 0) << ',' << (f.reaches_outer ? 1 : 0) << ',' << csv_number(f.r_min)
            << ',' << csv_number(f.r_max) << ',' << csv_number(f.length) << ',' << csv_number(f.angle_deg) << ','
            << f.n_tensile << ',' << f.n_shear << ',' << csv_number(f.extent) << '\n';
  });
}

void write_fracture_summary(const std::filesystem::path& path, const std::vector<FractureSnapshot>& snapshots) {
  core::write_file_atomically(path, [&](std::ostream& out) {
    out << "t,n_broken,n_fractures,n_radial,n_radial_reaching_outer,n_secondary,n_arms,n_tensile,n_shear,"
           "max_radial_extent,n_secondary_sizable,n_arms_fixed_gap\n";
    for (const FractureSnapshot& snap : snapshots) {
      const FractureStatistics& s = snap.stats;
      out << csv_number(snap.t) << ',' << s.n_broken << ',' << s.n_fractures << ',' << s.n_radial << ','
          << s.n_radial_reaching_outer << ',' << s.n_secondary << ',' << s.n_arms << ',' << s.n_tensile << ','
          << s.n_shear << ',' << csv_number(s.max_radial_extent) << ',' << s.n_secondary_sizable << ','
          << s.n_arms_fixed_gap << '\n';
    }
  });
}

}  // namespace hm::lattice2d
