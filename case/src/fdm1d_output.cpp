#include "hm/case/fdm1d_output.hpp"

#include "hm/analytic/failure_criteria.hpp"
#include "hm/analytic/steady_borehole.hpp"
#include "hm/core/validation.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/csv_writer.hpp"

namespace hm::cases {

using core::CsvWriter;

void write_fdm1d_results(const std::filesystem::path& dir, const hm::fdm1d::Fdm1dResult& res,
                         const hm::analytic::DimensionlessParameters& params) {
  core::write_file_atomically(dir / "borehole.csv", [&](std::ostream& f) {
    CsvWriter w(f, {"t", "p_h", "injected", "stored", "outflow", "balance_error", "sigma_r_wall",
                    "sigma_theta_wall", "sigma_z_wall", "coulomb_wall"}, core::NonFinite::reject);
    for (const auto& s : res.borehole)
      w.row({s.t, s.p_h, s.injected, s.stored, s.outflow, s.balance_error, s.sigma_r, s.sigma_theta, s.sigma_z,
             s.coulomb});
  });
  core::write_file_atomically(dir / "profiles.csv", [&](std::ostream& f) {
    CsvWriter w(f, {"t", "r", "p", "u_r", "sigma_r", "sigma_theta", "sigma_z", "coulomb"}, core::NonFinite::reject);
    for (const auto& s : res.snapshots)
      for (std::size_t i = 0; i < res.r.size(); ++i)
        w.row({s.t, res.r[i], s.p[i], s.u_r[i], s.sigma_r[i], s.sigma_theta[i], s.sigma_z[i], s.coulomb[i]});
  });
  core::write_file_atomically(dir / "probes.csv", [&](std::ostream& f) {
    std::vector<std::string> columns = {"t"};
    for (double r : res.probe_radii) columns.push_back("p_r" + core::format_value(r));
    CsvWriter w(f, columns, core::NonFinite::reject);
    for (std::size_t k = 0; k < res.borehole.size(); ++k) {
      std::vector<double> row = {res.borehole[k].t};
      row.insert(row.end(), res.probe_p[k].begin(), res.probe_p[k].end());
      w.row(row);
    }
  });
  core::write_file_atomically(dir / "steady_state.csv", [&](std::ostream& f) {
    CsvWriter w(f, {"r", "p", "u_r", "sigma_r", "sigma_theta", "sigma_z", "coulomb"}, core::NonFinite::reject);
    const analytic::SteadyBorehole steady(params.Q, params.material.b, params.material.nu, params.R_i);
    for (double r : res.r) {
      const analytic::RadialState s = steady.state(r);
      const auto [s1, s3] = analytic::major_minor({s.sigma_r, s.sigma_theta, s.sigma_z});
      w.row({r, s.p, s.u_r, s.sigma_r, s.sigma_theta, s.sigma_z, analytic::coulomb_stress(s1, s3, params.friction)});
    }
  });
}

}  // namespace hm::cases
