// Cost of one iteration of the break loop ("break one beam, re-solve, re-check"), fracture.hpp's
// break_until_stable, at N particles (default 1e5, the paper's resolution): the annulus of
// cases/paper/fig12_b0.2.toml (R_i = 0.138, seed 1, free outer boundary) with calibrated_beam_parameters(),
// the undrained split's normal springs of that case (b = 0.2, Psi = 1.3, Table 1's E/M) in the matrix as in
// CoupledModel, +-5% strengths, and a borehole-wall pressure as the (reference) load. The load factor is
// snapped to the next break (as run_load_stepping does) until `breaks` beams are broken.
// Prints
//   1. break_until_stable's own split per break (solve, stresses + failure check, downdate), i.e. what
//      the coupled runs pay, and
//   2. a finer split of the same work through the public pieces: break_beam, solve, the equilibrium-
//      residual pass inside solve (reactions()), solve(false) without it, beam_forces() (fresh and into
//      a reused buffer), the BeamForces copy,
//      compute_particle_stress, find_crack_tip_beams, compute_beam_stress, select_beam_to_break.
//   build/bench/bench_break_iteration               # N = 1e5, 40 breaks
//   build/bench/bench_break_iteration 20000 100     # N, breaks
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/lattice2d/coupled/coupling.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"

using namespace hm::lattice2d;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double median(std::vector<double> t) {
  std::sort(t.begin(), t.end());
  return t.empty() ? 0.0 : t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const long long n = argc > 1 ? std::atoll(argv[1]) : 100000;
  const int n_target = argc > 2 ? std::atoi(argv[2]) : 40;
  double t0 = now();
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.inner_radius = 0.138;
  spec.n_particles = n;
  spec.seed = 1;
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  BoundaryConditions bc;
  bc.inner_pressure = 1e-3;  // reference load; the loop scales it (homogeneity, fracture.hpp)
  BeamMechanics mechanics(lattice, calibrated_beam_parameters(), bc);
  CouplingTerms coupling;
  coupling.psi = 1.3;
  mechanics.set_normal_springs(
      undrained_spring_stiffness(lattice, dual, 0.2, hm::analytic::E_over_M_table1(0.2, 0.25), coupling));
  const BeamStrengths strengths = draw_beam_strengths(StrengthSpec{}, lattice.n_beams());
  std::printf("N = %d particles, %d beams; set-up %.2f s\n", lattice.n_particles(), lattice.n_beams(), now() - t0);

  // 1. break_until_stable as the coupled model calls it, with the load snapped to each next break.
  BreakLoopOptions options;
  std::vector<BreakEvent> log;
  double lambda = 0.0, solve_s = 0.0, stress_s = 0.0, break_s = 0.0, loop_s = 0.0;
  int solves = 0, breaks = 0;
  while (breaks < n_target) {
    options.max_breaks = n_target - breaks;
    const BreakLoopSummary s = break_until_stable(mechanics, dual, strengths, options, lambda, log, lambda);
    if (s.status == BreakLoopStatus::solve_failed) {
      std::printf("solve failed: %s\n", s.message.c_str());
      return 1;
    }
    solve_s += s.solve_seconds;
    stress_s += s.stress_seconds;
    break_s += s.break_seconds;
    loop_s += s.seconds;
    solves += s.n_solves;
    breaks += s.n_breaks;
    if (!(s.max_reference_ratio > 0.0)) break;
    lambda = std::max(lambda, (1.0 / s.max_reference_ratio) * (1.0 + 1e-9));
  }
  std::printf("\n1. break_until_stable: %d breaks, %d solves (load factor now %.4g)\n", breaks, solves, lambda);
  std::printf("   %-42s %9s\n", "per solve / per break", "ms");
  std::printf("   %-42s %9.2f\n", "solve (per solve)", 1e3 * solve_s / solves);
  std::printf("   %-42s %9.2f\n", "stresses + failure check (per solve)", 1e3 * stress_s / solves);
  std::printf("   %-42s %9.2f\n", "break_beam: downdate (per break)", 1e3 * break_s / std::max(breaks, 1));
  std::printf("   %-42s %9.2f\n", "whole loop per break", 1e3 * loop_s / std::max(breaks, 1));
  // Sequence fingerprint, to compare builds.
  unsigned long long h = 1469598103934665603ULL;
  for (const BreakEvent& e : log) h = (h ^ static_cast<unsigned long long>(e.beam)) * 1099511628211ULL;
  std::printf("   break sequence hash %016llx (first %d, last %d)\n", h, log.empty() ? -1 : log.front().beam,
              log.empty() ? -1 : log.back().beam);

  // 2. Finer split, through the public pieces (the pre-optimisation path of current_beam_stress).
  const int reps = 10;
  std::vector<BeamForce> reused;
  std::vector<double> t_solve_lean, t_forces_reused;
  std::vector<double> t_break, t_solve, t_reactions, t_forces, t_copy, t_particle, t_tip, t_beam, t_select, t_cbs;
  for (int r = 0; r < reps; ++r) {
    double a = now();
    const MechanicsSummary ms = mechanics.solve();
    t_solve.push_back(now() - a);
    if (!ms.is_converged()) break;
    a = now();
    const MechanicsSummary again = mechanics.solve(false);  // the break loop's re-solve: no equilibrium residual
    t_solve_lean.push_back(now() - a);
    (void)again;
    a = now();
    const Eigen::VectorXd reactions = mechanics.reactions();
    t_reactions.push_back(now() - a);
    a = now();
    const std::vector<BeamForce> connection = mechanics.beam_forces();
    t_forces.push_back(now() - a);
    a = now();
    mechanics.beam_forces(reused);
    t_forces_reused.push_back(now() - a);
    a = now();
    BeamForces forces{Eigen::Matrix2Xd(2, lattice.n_beams()), Eigen::Matrix2Xd(2, lattice.n_beams())};
    for (int e = 0; e < lattice.n_beams(); ++e) {
      const BeamForce& f = connection[static_cast<std::size_t>(e)];
      forces.force.col(e) = f.force_on_i;
      forces.moment.col(e) = Eigen::Vector2d(f.moment_i, f.moment_j);
    }
    t_copy.push_back(now() - a);
    a = now();
    const ParticleStress ps = compute_particle_stress(lattice, dual, forces);
    t_particle.push_back(now() - a);
    a = now();
    const std::vector<bool> tip = find_crack_tip_beams(lattice, mechanics.states());
    t_tip.push_back(now() - a);
    a = now();
    const BeamStress bs = compute_beam_stress(lattice, ps, mechanics.states(), options.crack_tip);
    t_beam.push_back(now() - a);
    a = now();
    const BreakCandidate c = select_beam_to_break(bs, strengths, mechanics.states());
    t_select.push_back(now() - a);
    a = now();
    const BeamStress cbs = current_beam_stress(mechanics, dual, options.crack_tip, lambda);
    t_cbs.push_back(now() - a);
    // Break the intact beam most loaded relative to its strength (the loop's next break at its load).
    const FailureField field = evaluate_failure(bs, strengths, mechanics.states());
    Eigen::Index worst = 0;
    field.ratio.maxCoeff(&worst);
    a = now();
    mechanics.break_beam(static_cast<int>(worst));
    t_break.push_back(now() - a);
    (void)reactions;
    (void)tip;
    (void)cbs;
    (void)c;
  }
  std::printf("\n2. finer split (median of %d iterations), ms\n", reps);
  const std::vector<std::pair<const char*, double>> rows = {
      {"break_beam (downdate, detachment check)", median(t_break)},
      {"solve (incl. residual + gauge)", median(t_solve)},
      {"  of it: reactions() (equilibrium residual)", median(t_reactions)},
      {"solve(false) (no equilibrium residual)", median(t_solve_lean)},
      {"beam_forces() (connection_forces)", median(t_forces)},
      {"beam_forces(reused buffer)", median(t_forces_reused)},
      {"copy into BeamForces", median(t_copy)},
      {"compute_particle_stress", median(t_particle)},
      {"find_crack_tip_beams", median(t_tip)},
      {"compute_beam_stress (incl. tips)", median(t_beam)},
      {"select_beam_to_break", median(t_select)},
      {"current_beam_stress (whole, scaled)", median(t_cbs)},
  };
  for (const auto& [name, t] : rows) std::printf("   %-44s %9.2f\n", name, 1e3 * t);
  return 0;
}
