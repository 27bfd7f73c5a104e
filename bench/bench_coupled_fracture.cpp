// Speed of a whole coupled fracture run: the Fig. 12 setting (borehole annulus,
// Q = 0.01, b = 0.2, iota = 1, flux-boundary borehole, undrained split Psi = 1.3 with Anderson
// acceleration, tolerances 1e-4, fracture on with +-5% strengths) from t* = 0 to 2.72e-2 — what
// cases/fig12_b0.2_quick.toml and cases/paper/fig12_b0.2.toml run — at N particles (default 1e4).
// Prints the wall time and its split: set-up (lattice, factorisations with the Eq. 20 springs),
// mechanical solves, stresses and failure checks, factor downdates, deformed geometry, flow.
//   build/bench/bench_coupled_fracture            # N = 1e4
//   build/bench/bench_coupled_fracture 100000     # the paper's resolution (~30 min on 2 cores)
//   build/bench/bench_coupled_fracture 10000 --versus-cg [t_end]
//       the same run with the paper's mechanics solver beside it (conjugate gradients, incomplete-Cholesky
//       preconditioned, warm-started from the last solution, its preconditioner rebuilt after each break)
//       to t_end (default t* = 4.5e-3, the paper's first snapshot: most breaks have happened), and the
//       ratio of the two runs' wall times (~6 min at N = 1e4 on one thread)
//   build/bench/bench_coupled_fracture 10000 --versus-cubic [t_end]
//       the same run with the cubic law for the cracks' flow (k/R^2 = 1e-14, Table 1's rock at R = 1 m)
//       beside the paper's constant iota = 1: their cost per coupling pass and per run (the two take
//       different fractures, so the per-pass ratio is the law's own cost)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"

using namespace hm::lattice2d;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Timing {
  CoupledRunSummary run;
  int n_broken = 0, n_particles = 0;
  double setup = 0.0, total = 0.0;
};

// The Fig. 12 b = 0.2 setting to t_end with the given mechanics solver and crack flow.
Timing run_fig12(long long n, double t_end, SpdSolverKind solver, const FractureFlowSpec& crack_flow = {}) {
  const auto start = std::chrono::steady_clock::now();
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.inner_radius = 0.138;
  spec.n_particles = n;
  spec.seed = 1;
  FlowParameters flow;
  flow.Q = 0.01;
  flow.b = 0.2;
  flow.E_over_M = hm::analytic::E_over_M_table1(0.2, 0.25);
  flow.borehole_storage = BoreholeStorage::none;
  flow.borehole_deformation = BoreholeDeformation::none;
  flow.fracture_flow = crack_flow;
  CouplingOptions coupling;
  coupling.relaxation = CouplingRelaxation::anderson;
  coupling.anderson_depth = 20;  // as the paper cases (docs/coupling.md)
  coupling.pressure_tolerance = coupling.displacement_tolerance = 1e-4;
  MechanicsOptions mechanics;
  mechanics.solver = solver;
  const Lattice lattice = generate_lattice(spec);
  CoupledModel model(lattice, calibrated_beam_parameters(), BoundaryConditions{}, mechanics, flow, coupling);
  model.enable_fracture(draw_beam_strengths(StrengthSpec{}, lattice.n_beams()));
  Timing t;
  t.setup = seconds_since(start);
  TimeStepping stepping;
  stepping.dt_initial = 1e-5;
  stepping.dt_growth = 1.2;
  stepping.dt_max = 5e-4;
  stepping.t_end = t_end;
  t.run = model.run(stepping);
  t.total = seconds_since(start);
  t.n_broken = model.n_broken();
  t.n_particles = lattice.n_particles();
  return t;
}

void print_split(const Timing& t) {
  std::printf("  %-40s %9s %7s\n", "part", "seconds", "share");
  const double parts[] = {t.setup,
                          t.run.mechanics_seconds,
                          t.run.stress_seconds,
                          t.run.break_seconds,
                          t.run.geometry_seconds,
                          t.run.flow_seconds,
                          t.total};
  const char* names[] = {"set-up (lattice, factorisations)",
                         "mechanical solves",
                         "stresses and failure checks",
                         "factor downdates (breaks)",
                         "deformed geometry",
                         "flow (factorise/refine, solve)",
                         "whole run"};
  for (int k = 0; k < 7; ++k) std::printf("  %-40s %9.2f %6.1f%%\n", names[k], parts[k], 100.0 * parts[k] / t.total);
}

}  // namespace

int main(int argc, char** argv) {
  const long long n = argc > 1 ? std::atoll(argv[1]) : 10000;
  const bool versus_cg = argc > 2 && std::strcmp(argv[2], "--versus-cg") == 0;
  const bool versus_cubic = argc > 2 && std::strcmp(argv[2], "--versus-cubic") == 0;
  const double t_end = versus_cg || versus_cubic ? (argc > 3 ? std::atof(argv[3]) : 4.5e-3) : 0.0272;
  const bool extra = argc > 2 && !versus_cg && !versus_cubic;
  if (n < 100 || extra || argc > 4 || !(t_end > 0.0)) {
    std::fprintf(stderr,
                 "bench_coupled_fracture: arguments [N >= 100] [--versus-cg | --versus-cubic [t_end > 0]]; "
                 "given N = %lld%s%s, t_end = %g\n",
                 n, extra ? ", unknown " : "", extra ? argv[2] : "", t_end);
    return 2;
  }
  const Timing chol = run_fig12(n, t_end, SpdSolverKind::cholmod);
  std::printf("Fig. 12 b = 0.2 to t* = %g at N = %d particles: %s, %d steps, %d passes, %d beams broken\n", t_end,
              chol.n_particles, hm::core::name_of(chol.run.status).c_str(), chol.run.n_steps, chol.run.total_iterations,
              chol.n_broken);
  print_split(chol);
  if (versus_cubic) {
    FractureFlowSpec cubic;
    cubic.law = FractureFlow::cubic;
    cubic.permeability = 1e-14;
    cubic.aperture = default_crack_aperture(FractureFlow::cubic);
    const Timing c = run_fig12(n, t_end, SpdSolverKind::cholmod, cubic);
    std::printf(
        "The same with the cubic law for the cracks (k/R^2 = 1e-14): %s, %d steps, %d passes, %d beams broken\n",
        hm::core::name_of(c.run.status).c_str(), c.run.n_steps, c.run.total_iterations, c.n_broken);
    print_split(c);
    const auto per_pass = [](const Timing& t, double seconds) { return seconds / std::max(1, t.run.total_iterations); };
    std::printf(
        "per coupling pass: flow %.2f ms (cubic) against %.2f ms (iota), ratio %.2f; whole run %.2f ms against "
        "%.2f ms, ratio %.2f; whole runs %.1f s against %.1f s, ratio %.2f\n",
        1e3 * per_pass(c, c.run.flow_seconds), 1e3 * per_pass(chol, chol.run.flow_seconds),
        per_pass(c, c.run.flow_seconds) / per_pass(chol, chol.run.flow_seconds), 1e3 * per_pass(c, c.total),
        1e3 * per_pass(chol, chol.total), per_pass(c, c.total) / per_pass(chol, chol.total), c.total, chol.total,
        c.total / chol.total);
    return chol.run.is_ok() && c.run.is_ok() ? 0 : 1;
  }
  if (!versus_cg) return chol.run.is_ok() ? 0 : 1;
  const Timing cg = run_fig12(n, t_end, SpdSolverKind::pcg);
  std::printf(
      "The same with warm-started preconditioned CG for the mechanics (the paper's approach): %s, %d steps, "
      "%d passes, %d beams broken\n",
      hm::core::name_of(cg.run.status).c_str(), cg.run.n_steps, cg.run.total_iterations, cg.n_broken);
  print_split(cg);
  std::printf("whole run: CG %.1f s, CHOLMOD with rank-3 downdates %.1f s: ratio %.1f; mechanical solves alone %.1f\n",
              cg.total, chol.total, cg.total / chol.total, cg.run.mechanics_seconds / chol.run.mechanics_seconds);
  return chol.run.is_ok() && cg.run.is_ok() ? 0 : 1;
}
