// In-situ (far-field) stress: on the dry lattice, the wall's hoop stress against the finite annulus and
// the jacketed breakdown pressure and angle against the annulus' Hubbert-Willis criterion; with
// injection (cases/insitu_*_quick.toml), where the coupled lattice breaks, in which direction its
// fractures grow, and its breakdown pressure beside Hubbert-Willis and Haimson-Fairhurst.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "borehole_fracture_runs.hpp"
#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/analytic/insitu_annulus.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/provenance.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/run_output.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/fdm1d/wall_failure.hpp"
#include "hm/lattice2d/fracture/fracture_statistics.hpp"
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
constexpr double T_u = 2e-4;             // Table 1's tensile strength over E, uniform over the beams
constexpr double theta_H = 30 * degree;  // off the lattice's axes

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
  for (int k = 0; k < 200 && hi - lo > 1e-10 * hi; ++k)
    (largest(0.5 * (lo + hi), nullptr) < T_u ? lo : hi) = 0.5 * (lo + hi);
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

// Over every field and seed: the displacement against the annulus, the first break on the S_H axis at
// the wall, and (shown) the breakdown against the annulus with the wall's over-read.
void add_insitu_dry_metrics(double worst_u_rms, double worst_angle, double worst_radius, double worst_overread_error,
                            std::vector<Metric>& metrics) {
  metrics.push_back({.name = "largest RMS of |u - u_annulus| over max |u_annulus|, every field and seed",
                     .value = worst_u_rms,
                     .tolerance = 0.011,
                     .comparison = Comparison::at_most,
                     .justification = "the dry lattice's displacement against the finite annulus (InSituAnnulus, "
                                      "the calibrated E and nu, rigid motion removed as the solve's gauge): first "
                                      "order in the spacing, largest in the wall row (docs/lattice.md); measured "
                                      "0.73% for S_H = 3 S_h, seed 1, at N = 1e4 (2.0% at 2500); 1.1% is 1.5 times "
                                      "that, and finer lattices are closer"});
  metrics.push_back({.name = "largest angle of the first broken beam from the S_H axis [deg], S_H > S_h, 3 seeds",
                     .value = worst_angle / degree,
                     .tolerance = 15.0,
                     .comparison = Comparison::at_most,
                     .justification = "the annulus' hoop stress is largest on the S_H axis; the wall has ~40 "
                                      "segments at N = 1e4 (9 degrees each) and the particle stress scatters by "
                                      "~25% (docs/lattice.md), which can move the largest ratio by about a "
                                      "segment: 15 degrees"});
  metrics.push_back({.name = "largest |r - R_i| of the first broken beam's midpoint",
                     .value = worst_radius,
                     .tolerance = 0.03,
                     .comparison = Comparison::at_most,
                     .justification = "the wall's hoop stress is the largest tension; 0.03 is about two spacings "
                                      "at N = 1e4"});
  metrics.push_back({.name = "largest |p_b lattice / p_b(annulus with T_u / k) - 1| (k the wall over-read)",
                     .value = worst_overread_error,
                     .tolerance = 0.25,
                     .comparison = Comparison::at_most,
                     .justification = "information: the lattice breaks where one wall beam's stress, not the "
                                      "wall's mean over-read, reaches T_u; the beams scatter about the mean by "
                                      "the RMS residual of the table",
                     .gating = false});
}

BenchmarkResult insitu_dry(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const l2::ElasticConstants cal = l2::calibrated_continuum();
  const double R_i = 0.138;
  const long long n = ctx.tier == Tier::paper ? 100000 : 10000;
  const std::vector<std::uint64_t> seeds = {1, 2, 3};
  // Mean stress 2e-4 throughout; S_H - S_h = 0, 1e-4, 2e-4.
  const std::vector<an::FarFieldStress> fields = {
      {2e-4, 2e-4, theta_H}, {2.5e-4, 1.5e-4, theta_H}, {3e-4, 1e-4, theta_H}};

  const std::filesystem::path hoop_path = ctx.data_dir / "insitu_wall_hoop.csv";
  const std::filesystem::path breakdown_path = ctx.data_dir / "insitu_breakdown.csv";
  std::ofstream hoop_out = core::open_for_writing(hoop_path), breakdown_out = core::open_for_writing(breakdown_path);
  core::CsvWriter hoop_csv(hoop_out, {"field", "psi_deg", "sigma_theta_lattice", "sigma_theta_annulus"});
  core::CsvWriter breakdown_csv(breakdown_out, {"S_H", "S_h", "seed", "p_b_lattice", "psi_deg", "p_b_annulus",
                                                "p_b_overread", "p_b_hubbert_willis"});
  Table table{"Dry annulus R_i = 0.138, N = " + std::to_string(n) +
                  ", free outer boundary under the far field (S_H at " +
                  "30 degrees from x), wall pressure p_w growing, uniform strengths T_u = 2e-4; lattice against the "
                  "finite annulus (E = 1, nu = " +
                  fmt(cal.poisson_ratio) + ")",
              {"S_H", "S_h", "seed", "u: RMS error", "u: max error", "wall hoop over-read k", "RMS residual",
               "p_b lattice", "angle from S_H [deg]", "p_b annulus (jacketed)", "p_b with over-read k",
               "lattice / annulus", "Hubbert-Willis (Kirsch)"},
              {}};
  double worst_angle = 0.0, worst_radius = 0.0, worst_overread_error = 0.0, worst_u_rms = 0.0;
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
      const l2::DisplacementError u_error =
          l2::displacement_error(l, u_far, l2::annulus_displacement(l, exact, cal.youngs_modulus));
      worst_u_rms = std::max(worst_u_rms, u_error.rms);
      const Breakdown b = jacketed_breakdown(l, beam_stress_of(l, dual, u_far), beam_stress_of(l, dual, u_unit));
      // With the hoop stress read k times too high everywhere on the wall, sigma_theta = T_u / k
      // there: the annulus' criterion with T_u / k.
      an::BreakdownParameters overread = dry;
      overread.T_u = T_u / w.slope;
      const double p_overread = an::annulus_jacketed_breakdown(far, overread, R_i).p_w;
      if (far.S_H > far.S_h) worst_angle = std::max(worst_angle, b.psi);
      worst_radius = std::max(worst_radius, std::abs(b.radius - R_i));
      worst_overread_error = std::max(worst_overread_error, std::abs(b.p_w / p_overread - 1.0));
      table.rows.push_back({fmt(far.S_H), fmt(far.S_h), std::to_string(seed), fmt(u_error.rms), fmt(u_error.max),
                            fmt(w.slope), fmt(w.residual), fmt(b.p_w),
                            far.S_H > far.S_h ? fmt(b.psi / degree) : "(isotropic)", fmt(p_annulus), fmt(p_overread),
                            fmt(b.p_w / p_annulus), fmt(p_kirsch)});
      breakdown_csv.row(
          {far.S_H, far.S_h, static_cast<double>(seed), b.p_w, b.psi / degree, p_annulus, p_overread, p_kirsch});
    }
  }
  res.tables.push_back(table);
  core::close_checked(hoop_out, hoop_path);
  core::close_checked(breakdown_out, breakdown_path);
  add_insitu_dry_metrics(worst_u_rms, worst_angle, worst_radius, worst_overread_error, res.metrics);
  res.figures.push_back({"verify_insitu.py", "verify_insitu.png",
                         "Dry lattice under a far field: wall hoop stress against the angle from S_H (markers: wall "
                         "particles; lines: finite annulus), and the jacketed breakdown pressure against S_H - S_h "
                         "(markers: lattice seeds; lines: annulus, annulus with the over-read, Kirsch).",
                         ""});
  return res;
}

// --- Injection under the far field --------------------------------------------------------------

struct InjectionRun {
  cases::RunCase c;
  cases::Breakdown breakdown;
  l2::FractureStatistics stats;
  double orientation = 0.0;    // axial mean direction of the radial fractures' broken beams [rad, 0..pi)
  double concentration = 0.0;  // its resultant length (1: all along one line)
  double seconds = 0.0;
};

// Runs `c` into dir as `hmlattice run` writes it (to the first break with `to_first_break`), and
// measures the fractures at the end.
InjectionRun run_injection(const cases::RunCase& c, const std::filesystem::path& dir, bool to_first_break = false) {
  const auto start = std::chrono::steady_clock::now();
  InjectionRun run{c, {}, {}, 0.0, 0.0, 0.0};
  std::filesystem::create_directories(dir);
  auto model = cases::make_coupled_model(c);
  cases::RunRecorder recorder(dir, c);
  const l2::CoupledRunSummary s = model->run(
      c.stepping,
      [&](const l2::CoupledModel& m, const l2::CoupledStepSummary& step, bool out) {
        recorder.record(m, step, out || (to_first_break && m.n_broken() > m.n_cut()));
      },
      [&] { return to_first_break && model->n_broken() > model->n_cut(); });
  recorder.finish();
  if (!s.is_ok() && s.status != l2::CoupledStatus::interrupted)
    throw std::runtime_error("in-situ injection run " + dir.filename().string() + ": " + s.message);
  core::write_file_atomically(dir / "config.toml", [&](std::ostream& out) {
    out << cases::run_case_to_toml(
        c, cases::to_toml(cases::make_provenance("hmlattice verify (lattice2d.insitu_injection), run " +
                                                 dir.filename().string())));
  });
  run.breakdown = recorder.breakdown();
  const l2::Lattice& l = model->lattice();
  run.stats = l2::compute_fracture_statistics(l, model->mechanics().states(), model->break_log());
  // Axial statistics (a fracture along theta is also along theta + pi): the mean of the doubled
  // angles of the broken beams' midpoints, halved.
  double cs = 0.0, sn = 0.0, n = 0.0;
  for (const l2::Fracture& f : run.stats.fractures) {
    if (f.kind != l2::FractureKind::radial) continue;
    for (int e : f.beams) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      const Eigen::Vector2d x = 0.5 * (l.points.col(i) + l.points.col(j));
      const double a = 2.0 * std::atan2(x.y(), x.x());
      cs += std::cos(a);
      sn += std::sin(a);
      n += 1.0;
    }
  }
  run.orientation = n > 0 ? std::fmod(0.5 * std::atan2(sn, cs) + std::numbers::pi, std::numbers::pi) : 0.0;
  run.concentration = n > 0 ? std::hypot(cs, sn) / n : 0.0;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

// Breakdown against the rate under the isotropic field: the lattice's first break, the 1D model's
// first wall failure from the same rest state, and the closed forms (rate-free limits).
// Fills `worst_rate_ratio` with the largest |ln(lattice / 1D)| over the rates.
Table isotropic_breakdown_by_rate(const BenchmarkContext& ctx, const std::filesystem::path& cases_dir,
                                  double& worst_rate_ratio) {
  const l2::ElasticConstants cal = l2::calibrated_continuum();
  Table by_rate{
      "Isotropic field S_H = S_h = 2e-4: breakdown against the injection rate (lattice N = 3000, seed 1, "
      "run to its first break; 1D: Appendix A from the same rest state, first wall failure)",
      {"Q", "lattice p_h before / at first break", "1D p_h at wall failure", "lattice / 1D", "Haimson-Fairhurst",
       "Hubbert-Willis"},
      {}};
  worst_rate_ratio = 0.0;
  for (double Q : {0.003, 0.01, 0.03}) {
    cases::RunCase c = cases::read_run_case(cases_dir / "insitu_isotropic_quick.toml");
    c.physics.parameters.Q = Q;
    c.output.vtk = false;
    const InjectionRun r = run_injection(c, ctx.data_dir / ("insitu_isotropic_Q" + fmt(Q)), true);
    const fdm1d::Fdm1dResult ref = borehole_fracture::run_reference(c);
    an::DimensionlessParameters p1d = c.physics.parameters;
    p1d.material.nu = cal.poisson_ratio;
    const fdm1d::WallFailure wall = fdm1d::first_wall_failure(ref, p1d);
    const an::BreakdownParameters material{.T_u = c.physics.parameters.tensile_strength,
                                           .p0 = 0.0,
                                           .b = c.physics.parameters.material.b,
                                           .nu = cal.poisson_ratio};
    const an::FarFieldStress far = c.insitu.far_field();
    const double ratio = r.breakdown.p_first / wall.p_h;
    worst_rate_ratio = std::max(worst_rate_ratio, std::abs(std::log(ratio)));
    by_rate.rows.push_back({fmt(Q), fmt(r.breakdown.p_before) + " / " + fmt(r.breakdown.p_first), fmt(wall.p_h),
                            fmt(ratio), fmt(an::haimson_fairhurst_breakdown(far, material).p_w),
                            fmt(an::hubbert_willis_breakdown(far, material).p_w)});
  }
  return by_rate;
}

// The injection's metrics: the rate series against the 1D model (shown), the first break and the
// fractures on the S_H axis, fewer arms under the deviatoric field.
void add_insitu_injection_metrics(double worst_rate_ratio, double worst_first_angle, double worst_orientation,
                                  double arms_ratio, std::vector<Metric>& metrics) {
  metrics.push_back({.name = "largest |ln(lattice p_h at first break / 1D p_h at wall failure)|, isotropic, 3 rates",
                     .value = worst_rate_ratio,
                     .tolerance = 0.5,
                     .comparison = Comparison::at_most,
                     .justification = "information: the unconfined lattice's wall over-read and single-beam "
                                      "scatter (lattice2d.insitu_dry) put its first break below the continuum's",
                     .gating = false});
  metrics.push_back({.name = "largest angle of the first broken beam from the S_H axis [deg], S_H = 3 S_h",
                     .value = worst_first_angle / degree,
                     .tolerance = 20.0,
                     .comparison = Comparison::at_most,
                     .justification = "the wall's hoop stress is largest on the S_H axis (Kirsch, the annulus); "
                                      "the wall has ~25 segments at N = 3000 (15 degrees each) and the particle "
                                      "stress scatters by ~25%: 20 degrees"});
  metrics.push_back({.name = "largest |axial mean direction of the radial fractures - theta_H| [deg], S_H = 3 S_h",
                     .value = worst_orientation / degree,
                     .tolerance = 15.0,
                     .comparison = Comparison::at_most,
                     .justification = "hydraulic fractures open against the least stress and grow along S_H; "
                                      "15 degrees: a secondary radial crack off the axis (one of three in the "
                                      "quick run) pulls the beam-weighted axial mean by ~7 degrees"});
  metrics.push_back({.name = "arms under S_H = 3 S_h over arms under S_H = S_h (same mean stress)",
                     .value = arms_ratio,
                     .tolerance = 0.75,
                     .comparison = Comparison::at_most,
                     .justification = "a deviatoric far field selects the S_H direction: fewer arms than the "
                                      "isotropic field's, which leaves every direction equal; 0.75 asks for a "
                                      "clear fall, not a number"});
}

BenchmarkResult insitu_injection(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  namespace fs = std::filesystem;
  const fs::path cases_dir = fs::path(HM_SOURCE_DIR) / "cases";
  const std::vector<std::uint64_t> seeds =
      ctx.tier == Tier::paper ? std::vector<std::uint64_t>{1, 2, 3} : std::vector<std::uint64_t>{1};
  Table table{"Borehole injection (the Fig. 12 quick case: b = 0.2, Q = 0.01, flux-boundary borehole, N = " +
                  std::string(ctx.tier == Tier::paper ? "2e4" : "3000") +
                  ") from rest under the far field, to t* = 0.0272; "
                  "breakdown against Hubbert-Willis (jacketed) and Haimson-Fairhurst (penetrating) with the "
                  "case's b and nu, p0 = 0",
              {"case", "seed", "S_H", "S_h", "first break: angle from S_H [deg]", "p_h before / at first break",
               "Hubbert-Willis", "Haimson-Fairhurst", "annulus (jacketed)", "arms", "radial fractures (reaching r = 1)",
               "fracture orientation - theta_H [deg]", "concentration", "s"},
              {}};
  double worst_first_angle = 0.0, worst_orientation = 0.0;
  double arms_isotropic = 0.0, arms_anisotropic = 0.0;
  for (const std::string name : {"insitu_isotropic_quick", "insitu_anisotropic_quick"}) {
    for (std::uint64_t seed : seeds) {
      cases::RunCase c = cases::read_run_case(cases_dir / (name + ".toml"));
      c.lattice.seed = seed;
      c.strength.seed = seed;
      c.output.vtk = false;
      if (ctx.tier == Tier::paper) c.lattice.n_particles = 20000;
      const InjectionRun r = run_injection(c, ctx.data_dir / (name + "_seed" + std::to_string(seed)));
      const an::FarFieldStress far = c.insitu.far_field();
      const an::BreakdownParameters material{.T_u = c.physics.parameters.tensile_strength,
                                             .p0 = 0.0,
                                             .b = c.physics.parameters.material.b,
                                             .nu = c.physics.parameters.material.nu};
      const bool anisotropic = far.S_H > far.S_h;
      const double first_psi = std::abs(
          std::remainder(std::atan2(r.breakdown.y_first, r.breakdown.x_first) - far.theta_H, std::numbers::pi));
      const double orientation = std::abs(std::remainder(r.orientation - far.theta_H, std::numbers::pi));
      (anisotropic ? arms_anisotropic : arms_isotropic) += r.stats.n_arms / static_cast<double>(seeds.size());
      if (anisotropic) {
        worst_first_angle = std::max(worst_first_angle, first_psi);
        worst_orientation = std::max(worst_orientation, orientation);
      }
      table.rows.push_back(
          {name, std::to_string(seed), fmt(far.S_H), fmt(far.S_h),
           anisotropic ? fmt(first_psi / degree) : "(isotropic)",
           fmt(r.breakdown.p_before) + " / " + fmt(r.breakdown.p_first),
           fmt(an::hubbert_willis_breakdown(far, material).p_w),
           fmt(an::haimson_fairhurst_breakdown(far, material).p_w),
           fmt(an::annulus_jacketed_breakdown(far, material, c.physics.parameters.R_i).p_w),
           std::to_string(r.stats.n_arms),
           std::to_string(r.stats.n_radial) + " (" + std::to_string(r.stats.n_radial_reaching_outer) + ")",
           anisotropic ? fmt(orientation / degree) : "(isotropic)", fmt(r.concentration), fmt(r.seconds)});
    }
  }
  res.tables.push_back(table);

  double worst_rate_ratio = 0.0;
  res.tables.push_back(isotropic_breakdown_by_rate(ctx, cases_dir, worst_rate_ratio));
  add_insitu_injection_metrics(worst_rate_ratio, worst_first_angle, worst_orientation,
                               arms_anisotropic / std::max(arms_isotropic, 1.0), res.metrics);
  res.figures.push_back({"verify_insitu_injection.py", "verify_insitu_injection.png",
                         "Injection from rest under an isotropic and an anisotropic far field: broken beams (colour: "
                         "time of breaking) with the S_H direction, and the borehole pressure with each field's "
                         "Hubbert-Willis pressure.",
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
  into.push_back({"lattice2d.insitu_injection",
                  "Borehole injection under an in-situ far field: where and which way it breaks",
                  "cases/insitu_isotropic_quick.toml (S_H = S_h = 2e-4) and cases/insitu_anisotropic_quick.toml "
                  "(S_H = 3e-4, S_h = 1e-4 at 30 degrees): the coupled lattice from rest, fracture on. The first "
                  "break's angle and the radial fractures' direction against the S_H axis, the number of arms of "
                  "the two fields, and the breakdown pressure beside Hubbert-Willis and Haimson-Fairhurst. Quick: "
                  "N = 3000, seed 1; paper: N = 2e4, seeds 1-3.",
                  Tier::quick, insitu_injection});
}

}  // namespace hm::verification
