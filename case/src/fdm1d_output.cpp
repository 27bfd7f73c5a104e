#include "hm/case/fdm1d_output.hpp"

#include <utility>

#include "hm/analytic/failure_criteria.hpp"
#include "hm/analytic/steady_borehole.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/validation.hpp"

namespace hm::cases {

using core::CsvWriter;

namespace {

std::vector<std::string> probe_columns(const std::vector<double>& probe_radii) {
  std::vector<std::string> columns = {"t"};
  for (double r : probe_radii) columns.push_back("p_r" + core::format_value(r));
  return columns;
}

}  // namespace

Fdm1dRecorder::Fdm1dRecorder(const std::filesystem::path& dir, const std::vector<double>& probe_radii)
    : dir_(dir),
      borehole_file_(core::open_for_writing(dir / "borehole.csv")),
      profiles_file_(core::open_for_writing(dir / "profiles.csv")),
      probes_file_(core::open_for_writing(dir / "probes.csv")) {
  borehole_ = std::make_unique<CsvWriter>(
      borehole_file_,
      std::vector<std::string>{"t", "p_h", "injected", "stored", "outflow", "balance_error", "sigma_r_wall",
                               "sigma_theta_wall", "sigma_z_wall", "coulomb_wall"},
      core::NonFinite::reject);
  profiles_ = std::make_unique<CsvWriter>(
      profiles_file_, std::vector<std::string>{"t", "r", "p", "u_r", "sigma_r", "sigma_theta", "sigma_z", "coulomb"},
      core::NonFinite::reject);
  probes_ = std::make_unique<CsvWriter>(probes_file_, probe_columns(probe_radii), core::NonFinite::reject);
}

void Fdm1dRecorder::record(const hm::fdm1d::Fdm1dResult& res) {
  if (r_.empty()) r_ = res.r;  // the grid never changes during a run
  for (; n_samples_ < res.borehole.size(); ++n_samples_) {
    const auto& s = res.borehole[n_samples_];
    borehole_->row(
        {s.t, s.p_h, s.injected, s.stored, s.outflow, s.balance_error, s.sigma_r, s.sigma_theta, s.sigma_z, s.coulomb});
    std::vector<double> row = {s.t};
    row.insert(row.end(), res.probe_p[n_samples_].begin(), res.probe_p[n_samples_].end());
    probes_->row(row);
  }
  for (; n_snapshots_ < res.snapshots.size(); ++n_snapshots_) {
    const auto& s = res.snapshots[n_snapshots_];
    for (std::size_t i = 0; i < res.r.size(); ++i)
      profiles_->row({s.t, res.r[i], s.p[i], s.u_r[i], s.sigma_r[i], s.sigma_theta[i], s.sigma_z[i], s.coulomb[i]});
  }
  // Every step reaches the files: a run stopped at any moment keeps the steps it finished. A failed
  // write (a full disk) ends the run now, while errno still names the reason.
  for (auto [file, name] : {std::pair{&borehole_file_, "borehole.csv"}, std::pair{&probes_file_, "probes.csv"},
                            std::pair{&profiles_file_, "profiles.csv"}}) {
    file->flush();
    if (!*file) core::close_checked(*file, dir_ / name);
  }
}

void Fdm1dRecorder::finish(const hm::analytic::DimensionlessParameters& params) {
  core::close_checked(borehole_file_, dir_ / "borehole.csv");
  core::close_checked(profiles_file_, dir_ / "profiles.csv");
  core::close_checked(probes_file_, dir_ / "probes.csv");
  core::write_file_atomically(dir_ / "steady_state.csv", [&](std::ostream& f) {
    CsvWriter w(f, {"r", "p", "u_r", "sigma_r", "sigma_theta", "sigma_z", "coulomb"}, core::NonFinite::reject);
    const analytic::SteadyBorehole steady(params.Q, params.material.b, params.material.nu, params.R_i);
    for (double r : r_) {
      const analytic::RadialState s = steady.state(r);
      const auto [s1, s3] = analytic::major_minor({s.sigma_r, s.sigma_theta, s.sigma_z});
      w.row({r, s.p, s.u_r, s.sigma_r, s.sigma_theta, s.sigma_z, analytic::coulomb_stress(s1, s3, params.friction)});
    }
  });
}

void write_fdm1d_results(const std::filesystem::path& dir, const hm::fdm1d::Fdm1dResult& result,
                         const hm::analytic::DimensionlessParameters& params) {
  Fdm1dRecorder recorder(dir, result.probe_radii);
  recorder.record(result);
  recorder.finish(params);
}

}  // namespace hm::cases
