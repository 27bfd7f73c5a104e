// In-situ (far-field) stress on the dry lattice: the wall's hoop stress against the finite annulus,
// and the jacketed breakdown pressure and angle against the annulus' Hubbert-Willis criterion.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/analytic/insitu_annulus.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/far_field.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"
#include "hm/verification/benchmark.hpp"
#include "report_writer.hpp"

namespace hm::verification {

namespace {

namespace l2 = hm::lattice2d;
namespace an = hm::analytic;

constexpr double degree = std::numbers::pi / 180.0;
constexpr double T_u = 2e-4;      // Table 1's tensile strength over E, uniform over the beams
constexpr double theta_H = 30 * degree;  // off the lattice's axes

std::string fmt(double x) { return format_number(x); }

// Beam stresses of the displacement u (intact lattice, no crack tips).
l2::BeamStress beam_stress_of(const l2::Lattice& l, const l2::DualGraph& dual, const Eigen::VectorXd& u) {
  const l2::BeamParameters beams = l2::calibrated_beam_parameters();
  return l2::compute_beam_stress(l, l2::compute_particle_stress(l, dual, l2::compute_beam_forces(l, beams, u)));
}

Eigen::VectorXd solve_dry(const l2::Lattice& l, const l2::BoundaryConditions& bc) {
  l2::BeamMechanics m(l, l2::calibrated_beam_parameters(), bc);
  const l2::MechanicsSummary s = m.solve();
  if (!s.is_converged()) throw std::runtime_error("in-situ benchmark: dry solve failed: " + s.message);
  return m.displacement();
}

struct Breakdown {
  double p_w = 0.0;     // wall pressure of the first beam at sigma_1 = T_u
  double psi = 0.0;     // its angle from the S_H axis, folded to [0, 90] degrees
  double radius = 0.0;  // its midpoint's distance from the centre
};

// The lattice's jacketed breakdown under the far field plus a growing wall pressure. The stresses
// are linear in the loads, sigma(p_w) = sigma_far + p_w sigma_unit per beam, and the largest beam
// sigma_1 is convex in p_w (the largest eigenvalue of an affine matrix function), so the p_w where
// it first reaches T_u is found by bisection to 1e-10 relative.
Breakdown jacketed_breakdown(const l2::Lattice& l, const l2::BeamStress& far, const l2::BeamStress& unit) {
  auto largest = [&](double p, int* at) {
    double best = -1e300;
    for (Eigen::Index e = 0; e < far.stress.cols(); ++e) {
      const Eigen::Vector3d s = far.stress.col(e) + p * unit.stress.col(e);
      const double s1 = l2::principal_pair(s[0], s[1], s[2]).sigma_1;
      if (s1 > best) {
        best = s1;
        if (at) *at = static_cast<int>(e);
      }
    }
    return best;
  };
  double lo = 0.0, hi = 1e-4;
  if (largest(0.0, nullptr) >= T_u) hi = 0.0;  // broken at rest
  while (largest(hi, nullptr) < T_u) hi *= 2.0;
  for (int k = 0; k < 200 && hi - lo > 1e-10 * hi; ++k) (largest(0.5 * (lo + hi), nullptr) < T_u ? lo : hi) = 0.5 * (lo + hi);
  int beam = 0;
  largest(hi, &beam);
  const auto [i, j] = l.beams[static_cast<std::size_t>(beam)];
  const Eigen::Vector2d x = 0.5 * (l.points.col(i) + l.points.col(j));
  const double psi = std::abs(std::remainder(std::atan2(x.y(), x.x()) - theta_H, std::numbers::pi));
  return {hi, psi, x.norm()};
}

// Least-squares slope of the lattice's wall hoop stress against the annulus' (the over-read), and the
// RMS of what the slope leaves, over max |sigma_theta|; rows to the CSV.
struct WallHoop {
  double slope = 0.0, residual = 0.0;
};

WallHoop wall_hoop(const l2::Lattice& l, const l2::DualGraph& dual, const Eigen::VectorXd& u,
                   const an::InSituAnnulus& exact, core::CsvWriter& csv, double tag) {
  const l2::ParticleStress ps =
      l2::compute_particle_stress(l, dual, l2::compute_beam_forces(l, l2::calibrated_beam_parameters(), u));
  std::vector<double> lattice, annulus;
  for (int i = 0; i < l.n_particles(); ++i) {
    if (l.boundary[static_cast<std::size_t>(i)] != l2::BoundaryTag::inner) continue;
    const Eigen::Vector2d x = l.points.col(i);
    const Eigen::Vector2d er = x.normalized(), et(-er.y(), er.x());
    Eigen::Matrix2d s;
    s << ps.stress(0, i), ps.stress(2, i), ps.stress(2, i), ps.stress(1, i);
    const double theta = std::atan2(x.y(), x.x());
    lattice.push_back(et.dot(s * et));
    annulus.push_back(exact.state(exact.inner_radius(), theta).sigma_theta);
    csv.row({tag, std::remainder(theta - theta_H, 2 * std::numbers::pi) / degree, lattice.back(), annulus.back()});
  }
  double sxy = 0, sxx = 0, scale = 0;
  for (std::size_t k = 0; k < lattice.size(); ++k) {
    sxy += lattice[k] * annulus[k];
    sxx += annulus[k] * annulus[k];
    scale = std::max(scale, std::abs(annulus[k]));
  }
  WallHoop w{sxy / sxx, 0.0};
  for (std::size_t k = 0; k < lattice.size(); ++k) w.residual += std::pow(lattice[k] - w.slope * annulus[k], 2);
  w.residual = std::sqrt(w.residual / static_cast<double>(lattice.size())) / scale;
  return w;
}

BenchmarkResult insitu_dry(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const l2::ElasticConstants cal = l2::calibrated_continuum();
  const double R_i = 0.138;
  const long long n = ctx.tier == Tier::paper ? 100000 : 10000;
  const std::vector<std::uint64_t> seeds = {1, 2, 3};
  // Mean stress 2e-4 throughout; S_H - S_h = 0, 1e-4, 2e-4.
  const std::vector<an::FarFieldStress> fields = {{2e-4, 2e-4, theta_H}, {2.5e-4, 1.5e-4, theta_H}, {3e-4, 1e-4, theta_H}};

  const std::filesystem::path hoop_path = ctx.data_dir / "insitu_wall_hoop.csv";
  const std::filesystem::path breakdown_path = ctx.data_dir / "insitu_breakdown.csv";
  std::ofstream hoop_out = core::open_for_writing(hoop_path), breakdown_out = core::open_for_writing(breakdown_path);
  core::CsvWriter hoop_csv(hoop_out, {"field", "psi_deg", "sigma_theta_lattice", "sigma_theta_annulus"});
  core::CsvWriter breakdown_csv(breakdown_out, {"S_H", "S_h", "seed", "p_b_lattice", "psi_deg", "p_b_annulus",
                                                "p_b_overread", "p_b_hubbert_willis"});
  Table table{"Dry annulus R_i = 0.138, N = " + std::to_string(n) + ", free outer boundary under the far field (S_H at " +
                  "30 degrees from x), wall pressure p_w growing, uniform strengths T_u = 2e-4; lattice against the "
                  "finite annulus (E = 1, nu = " + fmt(cal.poisson_ratio) + ")",
              {"S_H", "S_h", "seed", "wall hoop over-read k", "RMS residual", "p_b lattice", "angle from S_H [deg]",
               "p_b annulus (jacketed)", "p_b with over-read k", "lattice / annulus", "Hubbert-Willis (Kirsch)"},
              {}};
  double worst_angle = 0.0, worst_radius = 0.0, worst_overread_error = 0.0;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const an::FarFieldStress& far = fields[f];
    const an::BreakdownParameters dry{.T_u = T_u, .p0 = 0.0, .b = 0.0, .nu = cal.poisson_ratio};
    const double p_annulus = an::annulus_jacketed_breakdown(far, dry, R_i).p_w;
    const double p_kirsch = an::hubbert_willis_breakdown(far, dry).p_w;
    for (std::uint64_t seed : seeds) {
      l2::LatticeSpec spec;
      spec.domain = l2::DomainShape::annulus;
      spec.inner_radius = R_i;
      spec.n_particles = n;
      spec.seed = seed;
      const l2::Lattice l = l2::generate_lattice(spec);
      const l2::DualGraph dual = l2::build_dual_graph(l);
      l2::BoundaryConditions loaded, unit;
      loaded.outer_stress = l2::far_field_tensor(far);
      unit.inner_pressure = 1.0;
      const Eigen::VectorXd u_far = solve_dry(l, loaded), u_unit = solve_dry(l, unit);
      const an::InSituAnnulus exact(far, 0.0, R_i, cal.poisson_ratio);
      const WallHoop w = wall_hoop(l, dual, u_far, exact, hoop_csv, static_cast<double>(f));
      const Breakdown b = jacketed_breakdown(l, beam_stress_of(l, dual, u_far), beam_stress_of(l, dual, u_unit));
      // With the hoop stress read k times too high everywhere on the wall, sigma_theta = T_u / k
      // there: the annulus' criterion with T_u / k.
      an::BreakdownParameters overread = dry;
      overread.T_u = T_u / w.slope;
      const double p_overread = an::annulus_jacketed_breakdown(far, overread, R_i).p_w;
      if (far.S_H > far.S_h) worst_angle = std::max(worst_angle, b.psi);
      worst_radius = std::max(worst_radius, std::abs(b.radius - R_i));
      worst_overread_error = std::max(worst_overread_error, std::abs(b.p_w / p_overread - 1.0));
      table.rows.push_back({fmt(far.S_H), fmt(far.S_h), std::to_string(seed), fmt(w.slope), fmt(w.residual), fmt(b.p_w),
                            far.S_H > far.S_h ? fmt(b.psi / degree) : "(isotropic)", fmt(p_annulus), fmt(p_overread),
                            fmt(b.p_w / p_annulus), fmt(p_kirsch)});
      breakdown_csv.row({far.S_H, far.S_h, static_cast<double>(seed), b.p_w, b.psi / degree, p_annulus, p_overread,
                         p_kirsch});
    }
  }
  res.tables.push_back(table);
  core::close_checked(hoop_out, hoop_path);
  core::close_checked(breakdown_out, breakdown_path);
  res.metrics.push_back({.name = "largest angle of the first broken beam from the S_H axis [deg], S_H > S_h, 3 seeds",
                         .value = worst_angle / degree, .tolerance = 15.0, .comparison = Comparison::at_most,
                         .justification = "the annulus' hoop stress is largest on the S_H axis; the wall has ~40 "
                                          "segments at N = 1e4 (9 degrees each) and the particle stress scatters by "
                                          "~25% (docs/lattice.md), which can move the largest ratio by about a "
                                          "segment: 15 degrees"});
  res.metrics.push_back({.name = "largest |r - R_i| of the first broken beam's midpoint", .value = worst_radius,
                         .tolerance = 0.03, .comparison = Comparison::at_most,
                         .justification = "the wall's hoop stress is the largest tension; 0.03 is about two spacings "
                                          "at N = 1e4"});
  res.metrics.push_back({.name = "largest |p_b lattice / p_b(annulus with T_u / k) - 1| (k the wall over-read)",
                         .value = worst_overread_error, .tolerance = 0.25, .comparison = Comparison::at_most,
                         .justification = "information: the lattice breaks where one wall beam's stress, not the "
                                          "wall's mean over-read, reaches T_u; the beams scatter about the mean by "
                                          "the RMS residual of the table",
                         .gating = false});
  res.notes.push_back(
      "The lattice breaks down at a lower wall pressure than the finite annulus (column lattice / annulus, "
      "0.69-0.96 at N = 1e4), for two reasons. (1) The wall row's particle stress reads the hoop stress k times "
      "too high: k = 1.18-1.26, the least-squares slope over the whole wall, compressive parts included (the "
      "Lame benchmark's 1.46 is the mean ratio on a uniformly tensile wall, docs/lattice.md). The column 'p_b "
      "with over-read k' is the annulus' criterion with T_u / k. (2) One beam breaks, not the mean: the wall "
      "beams scatter about the slope by the RMS residual (7-12%), and the largest of ~40 wall beams sits about "
      "two residuals high. That is largest for the isotropic field, where the whole wall is equally tensile "
      "and every beam competes (lattice 27% below the over-read estimate), and smallest for S_H = 3 S_h, where "
      "only the beams near the S_H axis do. The breaking beam sits at the wall within 11 degrees of the S_H "
      "axis, as Hubbert-Willis and the annulus say. Kirsch's value (infinite plate) differs from the annulus "
      "by O(R_i^2) (docs/insitu.md). The displacement field is checked against the annulus in "
      "tests/lattice2d/test_far_field.cpp (RMS 0.73% of max |u| at N = 1e4).");
  res.figures.push_back({"verify_insitu.py", "verify_insitu.png",
                         "Dry lattice under a far field: wall hoop stress against the angle from S_H (markers: wall "
                         "particles; lines: finite annulus), and the jacketed breakdown pressure against S_H - S_h "
                         "(markers: lattice seeds; lines: annulus, annulus with the over-read, Kirsch).",
                         ""});
  return res;
}

}  // namespace

void add_insitu_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({"lattice2d.insitu_dry", "Lattice under an in-situ far field: wall hoop stress and jacketed breakdown",
                  "Dry annulus under S_H, S_h (mean 2e-4, S_H - S_h = 0, 1e-4, 2e-4) applied as outer traction, then a "
                  "growing wall pressure: the wall particles' hoop stress against the finite-annulus solution, and "
                  "the wall pressure and angle of the first beam at T_u against the annulus' Hubbert-Willis "
                  "criterion (docs/insitu.md).",
                  Tier::quick, insitu_dry});
}

}  // namespace hm::verification
