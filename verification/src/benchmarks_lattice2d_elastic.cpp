// Benchmarks of the dry lattice's elastic side: the calibration of the beam
// constants (measured E, nu per seed and density against the target), the patch test (mean interior
// particle stress under a homogeneous boundary strain against the calibrated continuum) and Lame's
// thick-walled cylinder (radially averaged u_r and sigma_theta, free and fixed outer boundary, two
// resolutions). Method and numbers: docs/lattice.md, "Calibration".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "hm/analytic/lame.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/io/radial_average.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"
#include "hm/verification/benchmark.hpp"
#include "report_writer.hpp"

namespace hm::verification {

using core::CsvWriter;

namespace {

namespace l2 = hm::lattice2d;

std::string pct(double x) { return format_number(100.0 * x) + "%"; }

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The calibration targets: E = 1 (the unit of stress) and Table 1's nu = 0.25 (plane strain), reached with
// the default facet-scaled beams.
constexpr double target_e = 1.0, target_nu = 0.25;
const char* target_reason =
    "the target E = 1, nu = 0.25 within 2%: the default facet-scaled beams are calibrated to nu = 0.25 "
    "(with the paper's uniform beams nu cannot exceed ~0.224, docs/lattice.md 'Calibration')";

// --- calibration --------------------------------------------------------------------------------

// The calibration's E and nu at N = 1e4 (means over seeds; E also at the other densities), against the
// targets and the documented constants, and the isotropy of the stiffness.
void add_calibration_metrics(double e_default, double nu_default, double iso_default,
                             const std::vector<std::pair<long long, double>>& e_by_density, double stored_nu,
                             std::vector<Metric>& metrics) {
  metrics.push_back({.name = "E, mean over seeds 1-3 at N = 1e4",
                     .value = e_default,
                     .reference = target_e,
                     .tolerance = 0.02,
                     .comparison = Comparison::rel_error,
                     .justification = "the calibration's 2% on E (k_n is scaled for E = 1 on exactly these "
                                      "lattices, so the check guards the stored constants)"});
  for (auto [n, em] : e_by_density)
    if (n != 10000)
      metrics.push_back({.name = "E at another density, N = " + std::to_string(n) + " (constants from N = 1e4)",
                         .value = em,
                         .reference = target_e,
                         .tolerance = 0.02,
                         .comparison = Comparison::rel_error,
                         .justification = "the calibration's 2% on E, on lattices it did not see; E is "
                                          "spacing-independent for per-beam k_n up to a measured drift of "
                                          "+0.6% (2.5e3) to -0.6% (1e5)"});
  metrics.push_back({.name = "nu, mean over seeds 1-3 at N = 1e4, against the target 0.25",
                     .value = nu_default,
                     .reference = target_nu,
                     .tolerance = 0.02,
                     .comparison = Comparison::abs_error,
                     .justification = "the calibration's 0.02 on nu (facet-scaled beams, calibrated to 0.25 on "
                                      "these lattices)"});
  metrics.push_back({.name = "nu, mean over seeds 1-3 at N = 1e4, against the documented value",
                     .value = nu_default,
                     .reference = stored_nu,
                     .tolerance = 0.005,
                     .comparison = Comparison::abs_error,
                     .justification = "regression on calibrated_continuum() (2026-11-22): 3x the seed sd 1.5e-3"});
  metrics.push_back({.name = "max |C66 - (C11-C12)/2| / ((C11-C12)/2), seeds 1-3 at N = 1e4",
                     .value = iso_default,
                     .tolerance = 0.03,
                     .comparison = Comparison::at_most,
                     .justification = "isotropy within the region mean's sampling error (~27%/sqrt(3500) per "
                                      "entry) and the measured systematic ~-1.5% (docs/lattice.md)"});
}

BenchmarkResult calibration(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const l2::BeamParameters beams = l2::calibrated_beam_parameters();
  const l2::ElasticConstants stored = l2::calibrated_continuum();
  Table per_seed{"Relaxed plane-strain constants with calibrated_beam_parameters() (k_n = " +
                     fmt(beams.normal_stiffness) + ", a = " + fmt(beams.aspect) + ", nu0 = " + fmt(beams.beam_poisson) +
                     "): squares of side 2 at the density of the unit disk of N particles, central region r <= 0.6",
                 {"N (disk)", "seed", "particles", "E", "nu", "C11", "C12", "C66", "(C11-C12)/2", "C66 error",
                  "E, nu from reactions", "particle scatter xx, xy (sd/mean)", "s"},
                 {}};
  Table by_density{"Seed means by point density (E independent of N for per-beam k_n)",
                   {"N (disk)", "seeds", "E mean", "E sd", "nu mean", "nu sd", "max |C66 error|"},
                   {}};
  const std::vector<long long> densities = ctx.tier == Tier::paper ? std::vector<long long>{2500, 10000, 40000, 100000}
                                                                   : std::vector<long long>{2500, 10000};
  double e_default = 0, nu_default = 0, iso_default = 0;
  std::vector<std::pair<long long, double>> e_by_density;
  for (long long n : densities) {
    const std::vector<std::uint64_t> seeds =
        n > 40000 ? std::vector<std::uint64_t>{1} : std::vector<std::uint64_t>{1, 2, 3};
    std::vector<double> e, nu;
    double worst_iso = 0;
    for (auto seed : seeds) {
      const l2::Lattice lattice = l2::generate_lattice(l2::calibration_rectangle(n, 2.0, seed));
      const l2::ElasticProperties p = l2::measure_elastic_properties(lattice, beams);
      e.push_back(p.youngs_modulus);
      nu.push_back(p.poisson_ratio);
      worst_iso = std::max(worst_iso, std::abs(p.shear_isotropy_error));
      per_seed.rows.push_back(
          {std::to_string(n), std::to_string(seed), std::to_string(lattice.n_particles()), fmt(p.youngs_modulus),
           fmt(p.poisson_ratio), fmt(p.c11), fmt(p.c12), fmt(p.c66), fmt(0.5 * (p.c11 - p.c12)),
           pct(p.shear_isotropy_error), fmt(p.boundary_youngs_modulus) + ", " + fmt(p.boundary_poisson_ratio),
           pct(p.scatter(0, 0) / p.stiffness(0, 0)) + ", " + pct(p.scatter(2, 2) / p.stiffness(2, 2)), fmt(p.seconds)});
    }
    double em = 0, nm = 0;
    for (std::size_t k = 0; k < e.size(); ++k) {
      em += e[k] / static_cast<double>(e.size());
      nm += nu[k] / static_cast<double>(nu.size());
    }
    double es = 0, ns = 0;
    for (std::size_t k = 0; k < e.size() && e.size() > 1; ++k) {
      es += (e[k] - em) * (e[k] - em) / static_cast<double>(e.size() - 1);
      ns += (nu[k] - nm) * (nu[k] - nm) / static_cast<double>(nu.size() - 1);
    }
    by_density.rows.push_back({std::to_string(n), std::to_string(seeds.size()), fmt(em), fmt(std::sqrt(es)), fmt(nm),
                               fmt(std::sqrt(ns)), pct(worst_iso)});
    e_by_density.emplace_back(n, em);
    if (n == 10000) {
      e_default = em;
      nu_default = nm;
      iso_default = worst_iso;
    }
  }
  res.tables.push_back(per_seed);
  res.tables.push_back(by_density);
  add_calibration_metrics(e_default, nu_default, iso_default, e_by_density, stored.poisson_ratio, res.metrics);
  if (ctx.tier == Tier::paper) {
    const auto& first = by_density.rows.front();
    const auto& last = by_density.rows.back();
    res.notes.push_back("Density dependence: E = " + first[2] + " at N = " + first[0] + " and " + last[2] +
                        " at N = " + last[0] + ".");
  }
  res.notes.push_back(
      "The calibration fixes nu0 = 0.25 and searches the aspect a (which spans k_omega/k_n from 0 to "
      "1/(4(1 + nu0))), then scales k_n for E = 1. With the default facet-scaled beams (k_n,ij = k_n sqrt(3) "
      "d_ij/L_ij) a in [0.05, 2] gives nu in [0.175, 0.323], and a = " +
      fmt(beams.aspect) + " gives the target 0.25; the lattice represents E = 1, nu = " + fmt(stored.poisson_ratio) +
      ", which every continuum comparison below uses (calibrated_continuum()). With the paper's uniform beams "
      "nu cannot exceed ~0.224 (docs/lattice.md).");
  return res;
}

// --- patch test -----------------------------------------------------------------------------------

// Plane-strain isotropic stress of a strain (tension positive): lambda tr(eps) I + 2 mu eps.
Eigen::Matrix2d continuum_stress(const Eigen::Matrix2d& eps, double e, double nu) {
  const double lambda = e * nu / ((1 + nu) * (1 - 2 * nu)), mu = e / (2 * (1 + nu));
  return lambda * eps.trace() * Eigen::Matrix2d::Identity() + 2 * mu * eps;
}

// The interior particles within `region` of the centre, their area-weighted mean stress and the
// particle-to-particle standard deviation (Voigt xx, yy, xy).
struct CentralStress {
  std::vector<int> particles;
  Eigen::Vector3d mean, sd;
};
CentralStress central_stress(const l2::Lattice& lattice, const l2::DualGraph& dual, const l2::ParticleStress& stress,
                             double region) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), plain = Eigen::Vector3d::Zero();
  double area = 0;
  std::vector<int> chosen;
  for (int i = 0; i < lattice.n_particles(); ++i)
    if (lattice.boundary[i] == l2::BoundaryTag::interior && lattice.points.col(i).norm() <= region) {
      chosen.push_back(i);
      mean += dual.particle_area[i] * stress.stress.col(i);
      plain += stress.stress.col(i);
      area += dual.particle_area[i];
    }
  mean /= area;
  plain /= static_cast<double>(chosen.size());
  Eigen::Vector3d sd = Eigen::Vector3d::Zero();
  for (int i : chosen) sd += (stress.stress.col(i) - plain).cwiseAbs2();
  sd = (sd / static_cast<double>(chosen.size())).cwiseSqrt();
  return {chosen, mean, sd};
}

// Histogram data for the patch test's scatter: one row per region particle, beside the continuum's stress.
void write_patch_stresses(const std::filesystem::path& path, const l2::Lattice& lattice,
                          const l2::ParticleStress& stress, const std::vector<int>& chosen,
                          const Eigen::Vector3d& expected) {
  core::write_file_atomically(path, [&](std::ostream& out) {
    CsvWriter csv(out, {"x", "y", "sigma_xx", "sigma_yy", "sigma_xy", "expected_xx", "expected_yy", "expected_xy"});
    for (int i : chosen)
      csv.row({lattice.points(0, i), lattice.points(1, i), stress.stress(0, i), stress.stress(1, i),
               stress.stress(2, i), expected[0], expected[1], expected[2]});
  });
}

BenchmarkResult patch_test(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const l2::BeamParameters beams = l2::calibrated_beam_parameters();
  const l2::ElasticConstants cal = l2::calibrated_continuum();
  // A disk, a seed the calibration did not use, and a general strain (both normal strains and shear).
  l2::LatticeSpec spec;
  spec.domain = l2::DomainShape::disk;
  spec.n_particles = ctx.tier == Tier::paper ? 100000 : 10000;
  spec.seed = 7;
  const l2::Lattice lattice = l2::generate_lattice(spec);
  const l2::DualGraph dual = l2::build_dual_graph(lattice);
  Eigen::Matrix2d eps;
  eps << 1e-3, 4e-4, 4e-4, -3e-4;
  l2::BoundaryConditions bc;
  bc.prescribe_boundary_strain = true;
  bc.boundary_strain = eps;
  const auto start = std::chrono::steady_clock::now();
  l2::BeamMechanics mechanics(lattice, beams, bc);
  const l2::MechanicsSummary summary = mechanics.solve();
  const l2::ParticleStress stress =
      l2::compute_particle_stress(lattice, dual, l2::compute_beam_forces(lattice, beams, mechanics.displacement()));
  const double solve_s = seconds_since(start);

  const auto [chosen, mean, sd] = central_stress(lattice, dual, stress, 0.6);

  auto voigt = [](const Eigen::Matrix2d& s) { return Eigen::Vector3d(s(0, 0), s(1, 1), s(0, 1)); };
  const Eigen::Vector3d expected = voigt(continuum_stress(eps, cal.youngs_modulus, cal.poisson_ratio));
  const Eigen::Vector3d target = voigt(continuum_stress(eps, target_e, target_nu));
  const double scale = expected.norm();
  const double error = (mean - expected).norm() / scale;
  const double error_target = (mean - target).norm() / target.norm();

  Table table{"Patch test: disk N = " + std::to_string(lattice.n_particles()) +
                  " (seed 7), boundary strain eps_xx = 1e-3, "
                  "eps_yy = -3e-4, eps_xy = 4e-4; " +
                  std::to_string(chosen.size()) + " interior particles with r <= 0.6",
              {"component", "lattice (area-weighted mean)", "continuum E = 1, nu = " + fmt(cal.poisson_ratio),
               "relative error", "continuum E = 1, nu = 0.25", "particle sd", "sd / |sigma|"},
              {}};
  const char* names[] = {"sigma_xx", "sigma_yy", "sigma_xy"};
  for (int k = 0; k < 3; ++k)
    table.rows.push_back({names[k], fmt(mean[k]), fmt(expected[k]), pct((mean[k] - expected[k]) / scale),
                          fmt(target[k]), fmt(sd[k]), pct(sd[k] / scale)});
  res.tables.push_back(table);

  write_patch_stresses(ctx.data_dir / "lattice_patch_test.csv", lattice, stress, chosen, expected);

  res.metrics.push_back({.name = "|mean interior stress - calibrated continuum| / |sigma|",
                         .value = error,
                         .tolerance = 0.02,
                         .comparison = Comparison::at_most,
                         .justification = "the calibration's 2% on E; the seed-to-seed scatter of the calibrated E "
                                          "is 0.4% and the region mean's sampling error ~27%/sqrt(n) < 1%"});
  res.metrics.push_back({.name = "|mean interior stress - continuum (E = 1, nu = 0.25)| / |sigma|",
                         .value = error_target,
                         .tolerance = 0.02,
                         .comparison = Comparison::at_most,
                         .justification = target_reason});
  res.metrics.push_back({.name = "solve converged (equilibrium residual)",
                         .value = summary.equilibrium_residual,
                         .tolerance = 1e-8,
                         .comparison = Comparison::at_most,
                         .justification = "direct sparse Cholesky: round-off"});
  res.notes.push_back("Particle-to-particle scatter (sd over the region, relative to |sigma|): " + pct(sd[0] / scale) +
                      ", " + pct(sd[1] / scale) + ", " + pct(sd[2] / scale) +
                      " for xx, yy, xy. A random lattice with uniform beam constants is not elastically uniform: "
                      "V_i and the neighbours' beam lengths vary from particle to particle, so single-particle "
                      "stresses scatter by ~25% around the continuum value although their mean matches it. Beam "
                      "stiffness is not scaled with the Voronoi facet (the paper's uniform k_n is kept). Solve " +
                      fmt(solve_s) + " s.");
  res.figures.push_back({"verify_lattice_patch.py", "verify_lattice_patch.png",
                         "Patch test: histogram of the interior particle stresses against the calibrated continuum "
                         "value (dashed) under a homogeneous boundary strain.",
                         ""});
  return res;
}

// --- Lame cylinder -----------------------------------------------------------------------------------

struct LameRun {
  long long n = 0;
  int particles = 0;
  std::string outer;
  double u_error = 0, sigma_error = 0, u_wall_error = 0, seconds = 0;
};

LameRun lame_case(const l2::Lattice& lattice, const l2::DualGraph& dual, l2::BoundarySupport outer, double p,
                  CsvWriter& csv, int outer_tag) {
  const auto start = std::chrono::steady_clock::now();
  const l2::BeamParameters beams = l2::calibrated_beam_parameters();
  const l2::ElasticConstants cal = l2::calibrated_continuum();
  const double r_i = lattice.spec.inner_radius;
  l2::BoundaryConditions bc;
  bc.outer = outer;
  bc.inner_pressure = p;
  l2::BeamMechanics mechanics(lattice, beams, bc);
  mechanics.solve();
  const Eigen::VectorXd& u = mechanics.displacement();
  const l2::ParticleStress stress =
      l2::compute_particle_stress(lattice, dual, l2::compute_beam_forces(lattice, beams, u));

  // Per particle: lattice u_r and sigma_theta, and the analytic values at the particle's own radius, so
  // both are averaged over exactly the same particles and weights (no shell-curvature bias).
  const int n = lattice.n_particles();
  Eigen::VectorXd ur(n), ur_exact(n), st(n), st_exact(n), area(n);
  std::vector<int> interior;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d x = lattice.points.col(i);
    const double r = x.norm();
    const Eigen::Vector2d er = x / r, et(-er.y(), er.x());
    const analytic::RadialState a = outer == l2::BoundarySupport::free
                                        ? analytic::LameCylinder(p, 0.0, r_i, 1.0, cal.poisson_ratio).state(r)
                                        : analytic::LameCylinderFixedOuter(p, r_i, 1.0, cal.poisson_ratio).state(r);
    ur[i] = u.segment<2>(l2::dof_index(i, 0)).dot(er);
    ur_exact[i] = a.u_r / cal.youngs_modulus;  // the analytic classes assume E = 1
    Eigen::Matrix2d s;
    s << stress.stress(0, i), stress.stress(2, i), stress.stress(2, i), stress.stress(1, i);
    st[i] = et.dot(s * et);
    st_exact[i] = a.sigma_theta;
    area[i] = dual.particle_area[i];
    if (lattice.boundary[i] == l2::BoundaryTag::interior) interior.push_back(i);
  }
  // sigma_theta: interior particles only (a boundary particle's stress is one-sided, not a continuum one).
  const int m = static_cast<int>(interior.size());
  Eigen::Matrix2Xd xi(2, m);
  Eigen::VectorXd ai(m), sti(m), sti_exact(m);
  for (int k = 0; k < m; ++k) {
    const int i = interior[k];
    xi.col(k) = lattice.points.col(i);
    ai[k] = area[i];
    sti[k] = st[i];
    sti_exact[k] = st_exact[i];
  }
  const int n_shells = 16;
  const auto edges = l2::uniform_shell_edges(r_i, 1.0, n_shells);
  const auto pu = l2::radial_average(lattice.points, area, ur, edges);
  const auto pue = l2::radial_average(lattice.points, area, ur_exact, edges);
  const auto ps = l2::radial_average(xi, ai, sti, edges);
  const auto pse = l2::radial_average(xi, ai, sti_exact, edges);

  LameRun run;
  run.particles = n;
  run.outer = outer == l2::BoundarySupport::free ? "free" : "fixed";
  const double u_scale = std::abs(pue.shells.front().mean);
  const double s_scale = std::abs(analytic::LameCylinder(p, 0.0, r_i, 1.0, cal.poisson_ratio).state(r_i).sigma_theta);
  for (int k = 0; k < n_shells; ++k) {
    const auto &a = pu.shells[k], &b = pue.shells[k], &c = ps.shells[k], &d = pse.shells[k];
    run.u_error = std::max(run.u_error, std::abs(a.mean - b.mean) / u_scale);
    run.sigma_error = std::max(run.sigma_error, std::abs(c.mean - d.mean) / s_scale);
    csv.row(
        {static_cast<double>(n), static_cast<double>(outer_tag), a.r_mean, a.mean, b.mean, c.r_mean, c.mean, d.mean});
  }
  run.u_wall_error = std::abs(pu.shells.front().mean - u_scale) / u_scale;
  run.seconds = seconds_since(start);
  return run;
}

// The Lame benchmark's gates, from its runs in the order [coarse free, coarse fixed, fine free, fine fixed].
void add_lame_metrics(const std::vector<LameRun>& runs, std::vector<Metric>& metrics) {
  const LameRun &coarse_free = runs[0], &coarse_fixed = runs[1], &fine_free = runs[2], &fine_fixed = runs[3];
  const std::string fine = std::to_string(fine_free.particles);
  // Observed order in the spacing h ~ N^-1/2 between the two resolutions.
  auto order = [&](const LameRun& c, const LameRun& f) {
    return std::log(c.u_error / f.u_error) / std::log(std::sqrt(static_cast<double>(f.particles) / c.particles));
  };
  const char* measured =
      "measured (2026-11-22, seed 1, facet-scaled beams, boundary spacing 1.3): max shell u_r "
      "error 7.0% / 2.65% / 1.16% (free) and 6.8% / 2.50% / 1.10% (fixed) at N = 2.5e3 / 1e4 / 1e5, "
      "first order in the spacing; the largest error sits in the innermost shell";
  metrics.push_back({.name = "max shell u_r error / u_r(R_i), free outer, N = " + fine + " (the issue's 3%)",
                     .value = fine_free.u_error,
                     .tolerance = 0.03,
                     .comparison = Comparison::at_most,
                     .justification = std::string("the target 3% at N >= 1e4 (free boundary); ") + measured});
  metrics.push_back(
      {.name = "max shell u_r error / u_r(R_i), fixed outer, N = " + fine,
       .value = fine_fixed.u_error,
       .tolerance = 0.03,
       .comparison = Comparison::at_most,
       .justification = std::string("the free boundary's 3%, applied to the fixed boundary too; ") + measured});
  metrics.push_back({.name = "observed order of the u_r error in the spacing (free)",
                     .value = order(coarse_free, fine_free),
                     .tolerance = 0.5,
                     .comparison = Comparison::at_least,
                     .justification = "the error must fall with the spacing: the wall row and the boundary layers "
                                      "of the lattice are O(spacing) thick (first order), and the random "
                                      "lattice's shell-mean scatter falls more slowly; measured 1.40 (2.5e3 -> "
                                      "1e4), 0.72 (1e4 -> 1e5)"});
  metrics.push_back({.name = "observed order of the u_r error in the spacing (fixed)",
                     .value = order(coarse_fixed, fine_fixed),
                     .tolerance = 0.5,
                     .comparison = Comparison::at_least,
                     .justification = "as for the free boundary; measured 1.40 (2.5e3 -> 1e4), 0.72 (1e4 -> 1e5)"});
  metrics.push_back({.name = "max shell sigma_theta error / sigma_theta(R_i), free outer, N = " + fine,
                     .value = fine_free.sigma_error,
                     .tolerance = 0.1,
                     .comparison = Comparison::at_most,
                     .justification = "particle stresses scatter by ~25% and the innermost shell holds the steepest "
                                      "gradient (sigma_theta ~ 1/r^2) over few particles; information beside u_r",
                     .gating = false});
}

BenchmarkResult lattice_lame(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const double p = 1e-4;
  const l2::ElasticConstants cal = l2::calibrated_continuum();
  const std::vector<long long> resolutions =
      ctx.tier == Tier::paper ? std::vector<long long>{10000, 100000} : std::vector<long long>{2500, 10000};
  const std::filesystem::path out_path = ctx.data_dir / "lattice_lame.csv";
  std::ofstream out = core::open_for_writing(out_path);
  CsvWriter csv(
      out, {"n_particles", "outer_fixed", "r_u", "u_r", "u_r_exact", "r_sigma", "sigma_theta", "sigma_theta_exact"});
  Table table{
      "Lame cylinder R_i = 0.138, p_i = 1e-4, calibrated beams; 16 radial shells; lattice against the "
      "plane-strain solution with E = 1, nu = " +
          fmt(cal.poisson_ratio) +
          " averaged over the same particles (u_r: all particles; sigma_theta: interior particles)",
      {"N", "outer boundary", "max shell |u_r error| / u_r(R_i)", "innermost shell u_r error",
       "max shell |sigma_theta error| / sigma_theta(R_i)", "s"},
      {}};
  std::vector<LameRun> runs;
  for (long long n : resolutions) {
    l2::LatticeSpec spec;
    spec.domain = l2::DomainShape::annulus;
    spec.inner_radius = 0.138;
    spec.n_particles = n;
    spec.seed = 1;
    const l2::Lattice lattice = l2::generate_lattice(spec);
    const l2::DualGraph dual = l2::build_dual_graph(lattice);
    for (auto outer : {l2::BoundarySupport::free, l2::BoundarySupport::fixed}) {
      LameRun run = lame_case(lattice, dual, outer, p, csv, outer == l2::BoundarySupport::fixed ? 1 : 0);
      run.n = n;
      table.rows.push_back({std::to_string(run.particles), run.outer, pct(run.u_error), pct(run.u_wall_error),
                            pct(run.sigma_error), fmt(run.seconds)});
      runs.push_back(run);
    }
  }
  res.tables.push_back(table);
  add_lame_metrics(runs, res.metrics);
  res.figures.push_back({"verify_lattice_lame.py", "verify_lattice_lame.png",
                         "Lame cylinder: radially averaged u_r and sigma_theta of the lattice (markers, two "
                         "resolutions) against the plane-strain solution with the calibrated E, nu (lines), free and "
                         "fixed outer boundary.",
                         ""});
  core::close_checked(out, out_path);
  return res;
}

}  // namespace

void add_lattice2d_elastic_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({"lattice2d.calibration", "Lattice: calibrated elastic constants (E, nu) per seed and density",
                  "Relaxed plane-strain E and nu of the lattice with the stored beam constants, measured by "
                  "homogeneous boundary-strain solves on squares of the same point density (seeds 1-3), against the "
                  "target E = 1, nu = 0.25 (Section 2.1, Table 1).",
                  Tier::quick, calibration});
  into.push_back({"lattice2d.patch_test", "Lattice: patch test under a homogeneous boundary strain",
                  "Mean interior particle stress of a disk under a prescribed homogeneous boundary strain against the "
                  "calibrated continuum; particle-to-particle scatter reported.",
                  Tier::quick, patch_test});
  into.push_back({"lattice2d.lame", "Lattice: Lame thick-walled cylinder, free and fixed outer boundary",
                  "Annulus R_i = 0.138 under internal pressure: radially averaged u_r and sigma_theta against Lame's "
                  "plane-strain solution with the calibrated E, nu, at two resolutions.",
                  Tier::quick, lattice_lame});
}

}  // namespace hm::verification
