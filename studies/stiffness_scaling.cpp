// Study (an executable, not a test; it asserts nothing): the dry lattice's stiffness-scaling and
// boundary-spacing options side by side, the measurement behind docs/lattice.md's table in "Stiffness
// scaling and boundary spacing: measurements" (which also holds its findings and the decision for the
// default lattice).
// Run: build/studies/study_stiffness_scaling (one table row per option and seed on stdout; ~25 s per
// seed at N = 1e4).
// Knobs (environment): HM_MEASURE_N particles (default 10000), HM_MEASURE_SEEDS seeds 1..n (default 1),
// HM_MEASURE_ONLY one option by name, HM_MEASURE_CALIBRATE (set: run calibrate_beams for the facet-scaled
// beams instead), HM_MEASURE_FACET_ASPECTS (e.g. "0.5,1": facet and uniform rows at these aspects instead).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <Eigen/Core>

#include "hm/analytic/lame.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/io/radial_average.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"

using namespace hm::lattice2d;

// Per option and seed: relaxed nu ceiling (a = 0.05, nu0 = 0.25, the stored constants' shape) and E on
// the calibration square; k_n = 1/E (calibrated E = 1); particle scatter sd/mean of sigma_xx under
// eps_xx; the annulus R_i = 0.138 under internal pressure: wall beams' sigma_1 over Lame's hoop stress,
// the first break / p_crit (the cylinder benchmark's loop, uniform +-5% strengths and none) and the Lame
// u_r error (16 shells, free outer, the option's own calibrated nu); factorisation + solve time.
namespace {

struct Option {
  const char* name;
  StiffnessScaling scaling;
  double floor;
  double boundary_factor;
  double aspect = 0.05;
};

void measure(const Option& o, long long n, std::uint64_t seed) {
  BeamParameters p;
  p.aspect = o.aspect;
  p.stiffness_scaling = o.scaling;
  p.facet_floor = o.floor;
  LatticeSpec rect = calibration_rectangle(n, 2.0, seed);
  rect.boundary_spacing_factor = o.boundary_factor;
  const ElasticProperties e = measure_elastic_properties(generate_lattice(rect), p);
  p.normal_stiffness = 1.0 / e.youngs_modulus;
  const double nu = e.poisson_ratio;

  const double r_i = 0.138;
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.inner_radius = r_i;
  spec.n_particles = n;
  spec.seed = seed;
  spec.boundary_spacing_factor = o.boundary_factor;
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  BoundaryConditions bc;
  bc.inner_pressure = 1.0;
  const StrengthSpec strength_spec;
  const double hoop = (1 + r_i * r_i) / (1 - r_i * r_i), p_crit = strength_spec.tensile_strength / hoop;
  double first[2] = {0, 0}, wall_mean = 0, wall_max = 0, solve_s = 0;
  for (int k = 0; k < 2; ++k) {
    StrengthSpec s = strength_spec;
    s.distribution = k == 0 ? StrengthDistribution::uniform : StrengthDistribution::none;
    const auto t0 = std::chrono::steady_clock::now();
    BeamMechanics m(lattice, p, bc);
    m.solve();
    solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const BeamStress st = current_beam_stress(m, dual);
    int nw = 0;
    wall_mean = wall_max = 0;
    for (int b = 0; b < lattice.n_beams(); ++b)
      if (lattice.beam_boundary[static_cast<std::size_t>(b)] == BoundaryTag::inner)
        wall_mean += st.sigma_1[b], wall_max = std::max(wall_max, st.sigma_1[b]), ++nw;
    wall_mean /= nw * hoop;
    wall_max /= hoop;
    LoadSteppingOptions opt;
    opt.load_increment = 0.05 * p_crit;
    opt.max_load = 3 * p_crit;
    opt.max_breaks = 1;
    const auto r = run_load_stepping(m, dual, draw_beam_strengths(s, lattice.n_beams()), opt, {});
    first[k] = r.breaks.empty() ? 0.0 : r.breaks.front().load / p_crit;
  }
  // Lame u_r, free outer boundary, p = 1e-4, the option's calibrated (E = 1, nu).
  const double pr = 1e-4;
  bc.inner_pressure = pr;
  BeamMechanics m(lattice, p, bc);
  m.solve();
  const Eigen::VectorXd& u = m.displacement();
  const int np = lattice.n_particles();
  Eigen::VectorXd ur(np), ue(np);
  const hm::analytic::LameCylinder lame(pr, 0.0, r_i, 1.0, nu);
  for (int i = 0; i < np; ++i) {
    const Eigen::Vector2d x = lattice.points.col(i), er = x.normalized();
    ur[i] = u.segment<2>(dof_index(i, 0)).dot(er);
    ue[i] = lame.state(x.norm()).u_r;
  }
  const auto edges = uniform_shell_edges(r_i, 1.0, 16);
  const auto a = radial_average(lattice.points, dual.particle_area, ur, edges);
  const auto b = radial_average(lattice.points, dual.particle_area, ue, edges);
  double err = 0;
  for (std::size_t k = 0; k < a.shells.size(); ++k)
    err = std::max(err, std::abs(a.shells[k].mean - b.shells[k].mean) / std::abs(b.shells.front().mean));
  std::printf(
      "| %s, a = %g | %lld | %llu | %.4f | %.4f | %.3f | %.1f%% | %.2f | %.2f | %.3f | %.3f | %.1f%% | %.3f |\n",
      o.name, o.aspect, n, static_cast<unsigned long long>(seed), nu, e.youngs_modulus, e.shear_isotropy_error,
      100 * e.scatter(0, 0) / e.stiffness(0, 0), wall_mean, wall_max, first[0], first[1], 100 * err, solve_s);
}

void measure_all() {
  const char* env = std::getenv("HM_MEASURE_N");
  const long long n = env ? std::atoll(env) : 10000;
  const char* seeds_env = std::getenv("HM_MEASURE_SEEDS");
  const int n_seeds = seeds_env ? std::atoi(seeds_env) : 1;
  std::printf(
      "| option | N | seed | nu (a=0.05) | E (k_n=1) | C66 err | scatter | wall mean | wall max | first/p_crit (+-5%%) "
      "| first (none) | Lame u_r err | solve s |\n");
  const Option options[] = {{"uniform", StiffnessScaling::uniform, 0.0, 1.0},
                            {"facet", StiffnessScaling::voronoi_facet, 0.0, 1.0},
                            {"facet floor 0.05", StiffnessScaling::voronoi_facet, 0.05, 1.0},
                            {"boundary 1.3", StiffnessScaling::uniform, 0.0, 1.3},
                            {"facet + boundary 1.3", StiffnessScaling::voronoi_facet, 0.0, 1.3},
                            // a from calibrate_beams with voronoi_facet (nu = 0.2500 over seeds 1-3, N = 1e4)
                            {"facet calibrated", StiffnessScaling::voronoi_facet, 0.0, 1.0, 0.506},
                            {"facet calibrated + boundary 1.3", StiffnessScaling::voronoi_facet, 0.0, 1.3, 0.506}};
  const char* only = std::getenv("HM_MEASURE_ONLY");  // one option by name
  if (std::getenv("HM_MEASURE_CALIBRATE")) {          // calibrate_beams with voronoi_facet, seeds 1-3
    CalibrationSpec spec;
    spec.n_particles = n;
    spec.stiffness_scaling = StiffnessScaling::voronoi_facet;
    const Calibration c = calibrate_beams(spec);
    std::printf("facet calibration: %s; k_n = %.16g, a = %.16g, %d measurements, %.1f s\n", c.message.c_str(),
                c.beams.normal_stiffness, c.beams.aspect, c.n_measurements, c.seconds);
    for (const auto& e : c.per_seed)
      std::printf("  E = %.4f nu = %.4f C66 err = %.4f reactions E = %.4f nu = %.4f scatter = %.3f\n", e.youngs_modulus,
                  e.poisson_ratio, e.shear_isotropy_error, e.boundary_youngs_modulus, e.boundary_poisson_ratio,
                  e.scatter(0, 0) / e.stiffness(0, 0));
    return;
  }
  const char* aspects_env = std::getenv("HM_MEASURE_FACET_ASPECTS");  // e.g. "0.5,1": facet rows at these a
  if (aspects_env) {
    std::string list = aspects_env;
    for (std::size_t pos = 0; pos < list.size();) {
      const std::size_t end = std::min(list.find(',', pos), list.size());
      const double a = std::atof(list.substr(pos, end - pos).c_str());
      for (int s = 1; s <= n_seeds; ++s) {
        measure({"facet", StiffnessScaling::voronoi_facet, 0.0, 1.0, a}, n, static_cast<std::uint64_t>(s));
        measure({"uniform", StiffnessScaling::uniform, 0.0, 1.0, a}, n, static_cast<std::uint64_t>(s));
      }
      pos = end + 1;
    }
    return;
  }
  for (const Option& o : options) {
    if (only && std::string(only) != o.name) continue;
    for (int s = 1; s <= n_seeds; ++s) measure(o, n, static_cast<std::uint64_t>(s));
  }
}

}  // namespace

int main() {
  measure_all();
  return 0;
}
