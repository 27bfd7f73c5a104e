// Speed of the flow network's linear solve (Section 2.2, Eqs. 15-16). The implicit Euler matrix
// (E/M) V + dt K of the Fig. 12 annulus (cases/paper/fig12_b0.2.toml: R_i = 0.138, seed 1, the
// borehole as one node without storage) is refactorised with new values on the same pattern on every
// coupling pass (deformed areas and conductances, broken beams). Times, on that pattern, the numeric
// factorisation and the solve of
//   - Eigen::SimplicialLDLT (its AMD ordering): the flow network's factorisation before CHOLMOD,
//   - CHOLMOD through Eigen's CholmodSupport: symbolic analysis once, then cholmod_factorize with new
//     values per repeat, supernodal LL' and simplicial LDL', each with nested dissection and AMD, and
//     CHOLMOD's own supernodal/simplicial choice,
//   - linalg's CholmodSolver with the flow network's options (its front end today), beside Eigen's
//     CholmodSupport simplicial LDL' (its front end before), the ratio printed,
// and a whole FlowNetwork::solve after update_geometry() (assembly, factorisation and solve with
// whatever flow_network.cpp uses). Medians over the repeats, in seconds; OpenBLAS with its default
// threads (the supernodal factorisation's BLAS-3 kernels).
//   build/bench/bench_flow_solve                   # N = 1e4 and 1e5, 7 repeats
//   build/bench/bench_flow_solve 100000 [repeats]  # one N
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/lattice2d/flow/flow_network.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/linalg/spd_solver.hpp"

using namespace hm::lattice2d;
using Matrix = Eigen::SparseMatrix<double>;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// The flow matrix as FlowNetwork assembles it (both triangles): storage (E/M) V_s on the triangles'
// diagonal (none on the borehole node, borehole_storage = "none"), dt A/d per connection times
// `scale` (new values on the same pattern for every repeat).
Matrix flow_matrix(const Lattice& lattice, const DualGraph& dual, double E_over_M, double dt,
                   const std::vector<double>& scale) {
  const int nt = lattice.n_triangles(), h = nt;
  std::vector<Eigen::Triplet<double>> t;
  for (int s = 0; s < nt; ++s) t.emplace_back(s, s, E_over_M * dual.triangle_area[s]);
  t.emplace_back(h, h, 0.0);
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [s, other] = lattice.beam_triangles[static_cast<std::size_t>(e)];
    const bool wall = lattice.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::inner;
    const int u = other >= 0 ? other : (wall ? h : -1);
    const double g = dt * dual.conductance[e] * scale[static_cast<std::size_t>(e)];
    t.emplace_back(s, s, g);
    if (u >= 0) {
      t.emplace_back(u, u, g);
      t.emplace_back(s, u, -g);
      t.emplace_back(u, s, -g);
    }
  }
  Matrix a(nt + 1, nt + 1);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

struct Timing {
  double analyse = 0.0, factorise = 0.0, solve = 0.0, residual = 0.0, factor_nnz = 0.0;
};

void print(const char* name, const Timing& t) {
  std::printf("  %-36s %8.4f %10.4f %9.5f %9.1e %9.3g\n", name, t.analyse, t.factorise, t.solve, t.residual,
              t.factor_nnz);
}

// Analyse the first matrix once, then factorise + solve every matrix (same pattern, new values).
template <typename Solver, typename Configure, typename Nnz>
Timing time_solver(const std::vector<Matrix>& matrices, const Eigen::VectorXd& b, Configure configure, Nnz nnz) {
  Timing t;
  std::vector<double> fac, sol;
  Solver solver;
  configure(solver);
  auto t0 = std::chrono::steady_clock::now();
  solver.analyzePattern(matrices[0]);
  t.analyse = seconds_since(t0);
  for (const Matrix& a : matrices) {
    t0 = std::chrono::steady_clock::now();
    solver.factorize(a);
    fac.push_back(seconds_since(t0));
    if (solver.info() != Eigen::Success) std::printf("  factorisation failed\n");
    t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd x = solver.solve(b);
    sol.push_back(seconds_since(t0));
    t.residual = std::max(t.residual, (a * x - b).norm() / b.norm());
  }
  t.factorise = median(fac);
  t.solve = median(sol);
  t.factor_nnz = nnz(solver);
  return t;
}

// The flow network's front end, linalg's CholmodSolver with the flow's options (simplicial LDL',
// nested dissection, solves on all threads), in Eigen's calls: compute() is its analysis (with a first
// factorisation), update_values() its factorisation with new values.
struct FlowFront {
  hm::lattice2d::CholmodSolver solver{flow_solver_options()};
  void analyzePattern(const Matrix& a) { solver.compute(a); }
  void factorize(const Matrix& a) { solver.update_values(a); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) { return solver.solve(b); }
  Eigen::ComputationInfo info() const { return solver.info(); }
};

template <typename Solver>
void cholmod_ordering(Solver& s, int ordering) {
  s.cholmod().nmethods = 1;
  s.cholmod().method[0].ordering = ordering;
  s.cholmod().postorder = 1;
}

template <typename Solver>
double cholmod_nnz(Solver& s) {
  return s.cholmod().lnz;
}

void run(long long n_particles, int repeats) {
  auto t0 = std::chrono::steady_clock::now();
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.inner_radius = 0.138;
  spec.n_particles = n_particles;
  spec.seed = 1;
  spec.boundary_spacing_factor = 1.0;  // explicit: the bench must not follow a changed default
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  const double lattice_seconds = seconds_since(t0);

  const double E_over_M = hm::analytic::E_over_M_table1(0.2, 0.25);
  const double dt = 1e-4;  // between dt_initial = 1e-5 and dt_max = 5e-4
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> jitter(0.9, 1.1);
  std::vector<Matrix> matrices;
  for (int r = 0; r < repeats; ++r) {
    std::vector<double> scale(static_cast<std::size_t>(lattice.n_beams()));
    for (double& s : scale) s = r == 0 ? 1.0 : jitter(rng);
    matrices.push_back(flow_matrix(lattice, dual, E_over_M, dt, scale));
  }
  Eigen::VectorXd b = Eigen::VectorXd::Zero(matrices[0].rows());
  b[b.size() - 1] = 0.01 * dt;  // Q dt into the borehole node
  b.head(b.size() - 1).setConstant(1e-9);
  std::printf(
      "N = %lld particles: %d particles, %d triangles, %lld unknowns, %lld nonzeros (both triangles);"
      " lattice %.1f s; %d repeats\n",
      n_particles, lattice.n_particles(), lattice.n_triangles(), static_cast<long long>(matrices[0].rows()),
      static_cast<long long>(matrices[0].nonZeros()), lattice_seconds, repeats);
  std::printf("  %-36s %8s %10s %9s %9s %9s\n", "solver", "analyse", "factorise", "solve", "max res", "nnz(L)");

  using EigenLdlt = Eigen::SimplicialLDLT<Matrix>;
  // nnz(L) with its diagonal, as CHOLMOD counts it (Eigen stores the unit diagonal implicitly).
  auto eigen_nnz = [](EigenLdlt& s) { return double(s.matrixL().nestedExpression().nonZeros() + s.rows()); };
  print("Eigen SimplicialLDLT (AMD)", time_solver<EigenLdlt>(
                                          matrices, b, [](EigenLdlt&) {}, eigen_nnz));
  using Super = Eigen::CholmodSupernodalLLT<Matrix>;
  using Simplicial = Eigen::CholmodSimplicialLDLT<Matrix>;
  print("CHOLMOD supernodal LL' (NESDIS)",
        time_solver<Super>(
            matrices, b, [](Super& s) { cholmod_ordering(s, CHOLMOD_NESDIS); }, cholmod_nnz<Super>));
  print("CHOLMOD supernodal LL' (AMD)",
        time_solver<Super>(
            matrices, b, [](Super& s) { cholmod_ordering(s, CHOLMOD_AMD); }, cholmod_nnz<Super>));
  const Timing eigen_front = time_solver<Simplicial>(
      matrices, b, [](Simplicial& s) { cholmod_ordering(s, CHOLMOD_NESDIS); }, cholmod_nnz<Simplicial>);
  print("CHOLMOD simplicial LDL' (NESDIS)", eigen_front);
  const Timing flow_front = time_solver<FlowFront>(
      matrices, b, [](FlowFront&) {}, [](FlowFront& f) { return f.solver.factor_nonzeros(); });
  print("  the same, linalg's CholmodSolver", flow_front);
  std::printf(
      "  (the flow's front end, linalg's CholmodSolver, over Eigen's CholmodSupport before it: factorise %.2fx, "
      "solve %.2fx, its solves on all threads against CHOLMOD's one)\n",
      flow_front.factorise / eigen_front.factorise, flow_front.solve / eigen_front.solve);
  print("CHOLMOD simplicial LDL' (AMD)",
        time_solver<Simplicial>(
            matrices, b, [](Simplicial& s) { cholmod_ordering(s, CHOLMOD_AMD); }, cholmod_nnz<Simplicial>));
  // CHOLMOD's own choice: supernodal when flops / nnz(L) >= supernodal_switch (40), else simplicial.
  using Auto = Eigen::CholmodDecomposition<Matrix>;
  double flops_per_nnz = 0.0;
  print("CHOLMOD auto (NESDIS)", time_solver<Auto>(
                                     matrices, b, [](Auto& s) { cholmod_ordering(s, CHOLMOD_NESDIS); },
                                     [&](Auto& s) {
                                       flops_per_nnz = s.cholmod().fl / s.cholmod().lnz;
                                       return s.cholmod().lnz;
                                     }));
  std::printf("  (NESDIS: %.0f flops per nonzero of L; CHOLMOD goes supernodal above %.0f)\n", flops_per_nnz, 40.0);

  // The flow network itself: update_geometry() marks the factor stale, so every solve() assembles,
  // refactorises and solves (reuse_factorisation off, the default).
  FlowParameters flow;
  flow.Q = 0.01;
  flow.b = 0.2;
  flow.E_over_M = E_over_M;
  flow.borehole_storage = BoreholeStorage::none;
  flow.borehole_deformation = BoreholeDeformation::none;
  t0 = std::chrono::steady_clock::now();
  FlowNetwork network(lattice, dual, flow);
  const double construct = seconds_since(t0);
  std::vector<double> pass;
  double balance = 0.0;
  for (int r = 0; r < repeats; ++r) {
    network.update_geometry(dual, lattice.points);
    t0 = std::chrono::steady_clock::now();
    const FlowStepSummary s = network.step(dt);
    pass.push_back(seconds_since(t0));
    if (!s.is_ok()) std::printf("  FlowNetwork::step: %s\n", s.message.c_str());
    balance = std::max(balance, s.balance_error);
  }
  std::printf(
      "  FlowNetwork: construction %.4f s (the analysis comes with the first factorisation), step after "
      "update_geometry %.4f s (median), "
      "balance error <= %.1e, p_h = %.6e\n",
      construct, median(pass), balance, network.borehole_pressure());
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 7;
  if (argc > 1) {
    run(std::atoll(argv[1]), repeats);
  } else {
    run(10000, repeats);
    run(100000, repeats);
  }
  return 0;
}
