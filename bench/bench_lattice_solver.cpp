// Speed of the dry lattice's mechanical solve: the annulus R_i = 0.138 with a fixed
// outer boundary and a borehole pressure, at N particles. For each N it times
//   1. CHOLMOD analyse + factorise (nested dissection; supernodal, converted to simplicial LDL'),
//   2. a solve with that factor,
//   3. the re-solve after one broken beam: rank-3 downdate of the kept factor + solve (mean of 10 breaks),
//      with the triangular solves on all threads (SubtreeSolve, the default), CHOLMOD's one-thread
//      solves, and a full solve,
//   4. the same through BeamMechanics (break_beam + solve with contact check and equilibrium residual),
//   5. preconditioned CG (incomplete Cholesky): set-up + cold solve from x = 0, and the re-solve after
//      one break warm-started from the previous solution,
//   6. the memory floor of the triangular solves (L's bytes over one thread's read bandwidth) and each
//      solve's time over it,
// and prints seconds and the ratio to the cold CG solve. Also: the factorisation variants
// (simplicial vs supernodal, orderings) for the "which is faster overall" choice.
//   build/bench/bench_lattice_solver                 # N = 1e4 and 1e5
//   build/bench/bench_lattice_solver 20000 --quick   # one N, no variants
//   build/bench/bench_lattice_solver 100000 --no-pcg  # CHOLMOD only (e.g. to compare BLAS libraries)
// Wall times on whatever machine runs it; the target is step 3 <= 0.1 s at N = 1e5.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "hm/core/state_archive.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"

using namespace hm::lattice2d;

namespace {

// Median of a handful of timings (the machine is shared; the minimum is printed beside it).
double median(std::vector<double> t) {
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// Reading memory on one thread, bytes per second: the median of five sums over an array of `bytes`, larger
// than any cache, as a triangular solve streams its factor.
double read_bandwidth(std::size_t bytes) {
  std::vector<double> a(bytes / sizeof(double), 1.0);
  std::vector<double> t;
  volatile double sink = 0.0;
  for (int r = 0; r < 5; ++r) {
    const double t0 = now();
    double s[4] = {0.0, 0.0, 0.0, 0.0};  // four sums: the adds' latency must not be the limit
    for (std::size_t k = 0; k + 4 <= a.size(); k += 4)
      for (int q = 0; q < 4; ++q) s[q] += a[k + static_cast<std::size_t>(q)];
    t.push_back(now() - t0);
    sink = sink + s[0] + s[1] + s[2] + s[3];
  }
  return static_cast<double>(a.size() * sizeof(double)) / median(t);
}

// Rank-3 factor columns of beam e restricted to the free degrees of freedom of `m`.
SpdSolver::Matrix beam_columns(const BeamMechanics& m, const std::vector<int>& free_index, int e) {
  const Lattice& l = m.lattice();
  const Matrix63d V = beam_element_factor(l.length[e], l.angle[e], m.parameters());
  const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
  const int dofs[6] = {3 * i, 3 * i + 1, 3 * i + 2, 3 * j, 3 * j + 1, 3 * j + 2};
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < 3; ++c)
    for (int a = 0; a < 6; ++a)
      if (free_index[static_cast<std::size_t>(dofs[a])] >= 0)
        t.emplace_back(free_index[static_cast<std::size_t>(dofs[a])], c, V(a, c));
  SpdSolver::Matrix W(m.n_free_dofs(), 3);
  W.setFromTriplets(t.begin(), t.end());
  return W;
}

void run(long long n, bool variants, bool with_pcg) {
  // 1. The lattice and its mechanical system.
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.n_particles = n;
  double t0 = now();
  const Lattice lattice = generate_lattice(spec);
  const double t_lattice = now() - t0;
  BoundaryConditions bc;
  bc.outer = BoundarySupport::fixed;
  bc.inner_pressure = 1e-3;
  t0 = now();
  BeamMechanics mech(lattice, calibrated_beam_parameters(), bc);  // the toolkit's default beams
  const double t_setup = now() - t0;
  const SpdSolver::Matrix A = mech.solver().matrix();
  std::vector<int> free_index(mech.held_dofs().size(), -1);
  int k = 0;
  for (std::size_t d = 0; d < free_index.size(); ++d)
    if (!mech.held_dofs()[d]) free_index[d] = k++;
  Eigen::VectorXd b(mech.n_free_dofs());
  for (std::size_t d = 0; d < free_index.size(); ++d)
    if (free_index[d] >= 0) b[free_index[d]] = mech.loads()[static_cast<Eigen::Index>(d)];
  // Ten interior beams near r = 0.3, spread around, to break one at a time.
  std::vector<int> breaks;
  for (int e = 0; e < lattice.n_beams() && breaks.size() < 10; e += 1 + lattice.n_beams() / 4000) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const double r = lattice.points.col(i).norm();
    if (lattice.boundary[i] == BoundaryTag::interior && lattice.boundary[j] == BoundaryTag::interior && r > 0.25 &&
        r < 0.35)
      breaks.push_back(e);
  }
  std::printf("\nN = %d particles, %d beams, %d unknowns, nnz(A) = %ld; lattice %.2f s, BeamMechanics set-up %.2f s\n",
              lattice.n_particles(), lattice.n_beams(), mech.n_free_dofs(), static_cast<long>(A.nonZeros()), t_lattice,
              t_setup);

  // 2. CHOLMOD.
  CholmodSolver chol;
  t0 = now();
  chol.compute(A);
  const double t_factor = now() - t0;
  t0 = now();
  chol.refactorize();  // numeric factorisation (+ conversion to LDL') alone, ordering kept
  const double t_numeric = now() - t0;
  std::vector<double> solves, resolves, downdates;
  Eigen::VectorXd x;
  for (int r = 0; r < 5; ++r) {
    t0 = now();
    x = chol.solve(b);
    solves.push_back(now() - t0);
  }
  for (int e : breaks) {
    const SpdSolver::Matrix W = beam_columns(mech, free_index, e);
    t0 = now();
    chol.modify(W, -1);
    const double t1 = now();
    x = chol.solve(b);
    resolves.push_back(now() - t0);
    downdates.push_back(t1 - t0);
  }
  std::vector<double> residuals;
  for (int r = 0; r < 5; ++r) {
    t0 = now();
    volatile double rn = (A.transpose() * x - b).norm();
    (void)rn;
    residuals.push_back(now() - t0);
  }
  const double t_residual = median(residuals);
  const double t_first = solves.front();
  solves.erase(solves.begin());
  const double t_solve = median(solves), t_resolve = median(resolves), t_downdate = median(downdates);
  // The same re-solves with other solver options (median over the breaks).
  const auto resolve_with = [&](const SpdSolverOptions& o) {
    CholmodSolver other(o);
    other.compute(A);
    other.solve(b);
    std::vector<double> t;
    for (int e : breaks) {
      const SpdSolver::Matrix W = beam_columns(mech, free_index, e);
      t0 = now();
      other.modify(W, -1);
      other.solve(b);
      t.push_back(now() - t0);
    }
    return median(t);
  };
  SpdSolverOptions full_options, serial_options;
  full_options.reuse_forward_solve = false;  // full forward + backward solve each time (CHOLMOD's)
  full_options.parallel_triangular_solve = false;
  serial_options.parallel_triangular_solve = false;  // CHOLMOD's one-thread backward solve
  const double t_resolve_full = resolve_with(full_options), t_resolve_serial = resolve_with(serial_options);
  std::printf("  minimum over repeats: repeated solve %.4f s, re-solve %.4f s (4 solves, %d breaks; medians below)\n",
              *std::min_element(solves.begin(), solves.end()), *std::min_element(resolves.begin(), resolves.end()),
              static_cast<int>(breaks.size()));
  std::printf("  CHOLMOD ordering %s, nnz(L) = %.3g, residual after 10 downdates %.1e, info %d\n",
              chol.ordering_used().c_str(), chol.factor_nonzeros(), chol.report().relative_residual,
              static_cast<int>(chol.info()));
  // The floor of a triangular solve: it must read every entry of L once (a double and its row index).
  const double factor_bytes = chol.factor_nonzeros() * (sizeof(double) + sizeof(int));
  const double bandwidth = read_bandwidth(static_cast<std::size_t>(std::max(factor_bytes, 2.5e8)));
  const double floor_one = factor_bytes / bandwidth;
  std::printf(
      "  memory floor: L holds %.0f MB, read at %.1f GB/s (one thread): %.4f s a triangular solve; "
      "first solve (two) %.1fx it, repeated solve (one) %.1fx, re-solve %.1fx\n",
      factor_bytes / 1e6, bandwidth / 1e9, floor_one, t_first / (2 * floor_one), t_solve / floor_one,
      t_resolve / floor_one);

  // A step's snapshot restored, as a retried step does: in place into the solver that saved it (its
  // analysis and factor storage kept), against into a new solver (an analysis and a second factor's
  // storage: what every restore did before).
  const std::size_t snapshot_bytes = hm::core::StateWriter::measure(
      [&](hm::core::StateWriter& w) { chol.save_state(w, hm::lattice2d::StateScope::whole); });
  hm::core::StateWriter snapshot;
  chol.save_state(snapshot, hm::lattice2d::StateScope::whole);
  const auto restore_into = [&](CholmodSolver& solver) {
    hm::core::StateReader r = hm::core::StateReader::of_snapshot(snapshot, "the bench's snapshot");
    const double start = now();
    solver.restore_state(r);
    return now() - start;
  };
  const double t_in_place = restore_into(chol);
  CholmodSolver fresh;
  const double t_fresh = restore_into(fresh);
  std::printf("  snapshot restore (%.0f MB): in place %.3f s, into a new solver %.3f s: %.1fx\n",
              static_cast<double>(snapshot_bytes) / 1e6, t_in_place, t_fresh, t_fresh / t_in_place);

  // A failed step with ten breaks, returned to its start: the start's state with a copy of the factor
  // (saved whole, restored in place: what a step did before), against the start's state without it,
  // the factor's changes logged and undone by the solver (StateScope::step_start: what a step does).
  const std::vector<int> step_breaks(
      breaks.begin(), breaks.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(10, breaks.size())));
  // Each keeps its writer's memory from one step to the next, as a run keeps its snapshot's.
  hm::core::StateWriter whole_state, step_state;
  const auto failed_step = [&](hm::lattice2d::StateScope scope, hm::core::StateWriter& state) {
    const double start = now();
    if (scope == hm::lattice2d::StateScope::step_start) chol.begin_step();
    state.clear();
    chol.save_state(state, scope);
    for (int e : step_breaks) chol.modify(beam_columns(mech, free_index, e), -1);
    hm::core::StateReader r = hm::core::StateReader::of_snapshot(state, "the bench's step");
    chol.restore_state(r);
    return std::pair{now() - start, state.bytes().size()};
  };
  std::vector<double> t_whole, t_logged;
  std::size_t bytes_whole = 0, bytes_logged = 0;
  for (int r = 0; r < 5; ++r) {
    std::tie(t_whole.emplace_back(), bytes_whole) = failed_step(hm::lattice2d::StateScope::whole, whole_state);
    std::tie(t_logged.emplace_back(), bytes_logged) = failed_step(hm::lattice2d::StateScope::step_start, step_state);
  }
  std::printf(
      "  a failed step with %d breaks, back to its start (median of 5): factor copied %.3f s, state %.0f MB; "
      "factor's changes undone %.3f s, state %.0f MB: %.1fx the time, %.1fx the memory\n",
      static_cast<int>(step_breaks.size()), median(t_whole), static_cast<double>(bytes_whole) / 1e6, median(t_logged),
      static_cast<double>(bytes_logged) / 1e6, median(t_whole) / median(t_logged),
      static_cast<double>(bytes_whole) / static_cast<double>(bytes_logged));

  // 3. Through the mechanics (contact check, equilibrium residual, forces not included).
  mech.solve();
  std::vector<double> mechs;
  for (int e : breaks) {
    t0 = now();
    mech.break_beam(e);
    const MechanicsSummary s = mech.solve();
    mechs.push_back(now() - t0);
    if (!s.is_converged()) std::printf("  mechanics solve not converged: %s\n", s.message.c_str());
  }
  const double t_mech = median(mechs);

  std::printf("  %-58s %10s %8s\n", "step", "seconds", "/ CG");
  if (!with_pcg) {
    const auto line = [](const char* name, double t) { std::printf("  %-58s %10.4f\n", name, t); };
    line("CHOLMOD analyse + factorise", t_factor);
    line("  of which numeric (refactorize())", t_numeric);
    line("CHOLMOD first solve", t_first);
    line("CHOLMOD re-solve after one break", t_resolve);
    line("  same, CHOLMOD's one-thread solves", t_resolve_serial);
    line("BeamMechanics break_beam + solve", t_mech);
  }
  if (with_pcg) {
    // 4. PCG (incomplete Cholesky), cold and warm.
    SpdSolverOptions po;
    po.cg_tolerance = 1e-10;
    PcgSolver pcg(po);
    t0 = now();
    pcg.compute(A);
    const double t_ichol = now() - t0;
    t0 = now();
    pcg.solve(b);
    const double t_cg_cold = now() - t0;
    const int it_cold = pcg.report().iterations;
    const SpdSolver::Matrix W = beam_columns(mech, free_index, breaks[0]);
    t0 = now();
    pcg.modify(W, -1);
    pcg.solve(b);  // includes rebuilding the incomplete Cholesky preconditioner
    const double t_cg_warm = now() - t0;
    const int it_warm = pcg.report().iterations;

    const double cg = t_ichol + t_cg_cold;
    auto row = [&](const char* name, double t) { std::printf("  %-58s %10.4f %8.4f\n", name, t, t / cg); };
    row("CHOLMOD analyse + factorise", t_factor);
    row("  of which numeric (refactorize(): factorise + to LDL')", t_numeric);
    row("CHOLMOD first solve (forward + backward)", t_first);
    row("CHOLMOD repeated solve, same b (backward half)", t_solve);
    row("  of which the residual check ||A x - b||", t_residual);
    row("CHOLMOD re-solve after one break (rank-3 downdate + solve)", t_resolve);
    row("  of which the downdate (cholmod_updown_solve)", t_downdate);
    row("  same, full solve (reuse_forward_solve = false)", t_resolve_full);
    row("  same, CHOLMOD's one-thread solves (parallel_triangular_solve = false)", t_resolve_serial);
    row("BeamMechanics break_beam + solve", t_mech);
    row("PCG cold: ichol set-up + solve from 0 (= CG)", cg);
    std::printf("  %-58s %10.4f %8.4f   (%d iterations)\n", "  of which the CG iterations", t_cg_cold, t_cg_cold / cg,
                it_cold);
    std::printf("  %-58s %10.4f %8.4f   (%d iterations)\n", "PCG re-solve after one break, warm start (+ ichol)",
                t_cg_warm, t_cg_warm / cg, it_warm);
    std::printf("  speed-up of the CHOLMOD re-solve over warm PCG: %.0fx, over cold PCG: %.0fx\n",
                t_cg_warm / t_resolve, cg / t_resolve);
  }

  if (!variants) return;
  // 5. Factorisation variants: factorise + 10 downdate re-solves.
  struct Variant {
    const char* name;
    CholmodOrdering ordering;
    bool supernodal;
  };
  for (const Variant& v : {Variant{"nesdis, supernodal -> LDL'", CholmodOrdering::nested_dissection, true},
                           Variant{"nesdis, simplicial LDL'", CholmodOrdering::nested_dissection, false},
                           Variant{"metis, supernodal -> LDL'", CholmodOrdering::metis, true},
                           Variant{"amd, supernodal -> LDL'", CholmodOrdering::amd, true},
                           Variant{"automatic, supernodal -> LDL'", CholmodOrdering::automatic, true}}) {
    SpdSolverOptions o;
    o.ordering = v.ordering;
    o.supernodal_factorization = v.supernodal;
    CholmodSolver s(o);
    t0 = now();
    s.compute(A);
    const double tf = now() - t0;
    t0 = now();
    s.refactorize();
    const double tn = now() - t0;
    std::vector<double> tres;
    for (int e : breaks) {
      const SpdSolver::Matrix Wv = beam_columns(mech, free_index, e);
      t0 = now();
      s.modify(Wv, -1);
      s.solve(b);
      tres.push_back(now() - t0);
    }
    const double tr = median(tres);
    std::printf("  variant %-32s (%-6s) analyse+factorise %6.3f s, numeric %6.3f s, re-solve %7.4f s, nnz(L) %.3g\n",
                v.name, s.ordering_used().c_str(), tf, tn, tr, s.factor_nonzeros());
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<long long> sizes;
  bool variants = true, with_pcg = true;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--quick")
      variants = false;
    else if (arg == "--no-pcg")
      with_pcg = false;
    else
      sizes.push_back(std::atoll(arg.c_str()));
  }
  if (sizes.empty()) sizes = {10000, 100000};
  try {
    for (long long n : sizes) run(n, variants, with_pcg);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_lattice_solver: %s\n", e.what());
    return 1;
  }
  return 0;
}
