// Speed of a whole coupled fracture run: the Fig. 12 setting (borehole annulus,
// Q = 0.01, b = 0.2, iota = 1, flux-boundary borehole, undrained split Psi = 1.3 with Anderson
// acceleration, tolerances 1e-4, fracture on with +-5% strengths) from t* = 0 to 2.72e-2 — what
// cases/fig12_b0.2_quick.toml and cases/paper/fig12_b0.2.toml run — at N particles (default 1e4).
// Prints the wall time and its split: set-up (lattice, factorisations with the Eq. 20 springs),
// mechanical solves, stresses and failure checks, factor downdates, deformed geometry, flow.
//   build/bench/bench_coupled_fracture            # N = 1e4
//   build/bench/bench_coupled_fracture 100000     # the paper's resolution (~30 min on 2 cores)
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"

using namespace hm::lattice2d;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  const long long n = argc > 1 ? std::atoll(argv[1]) : 10000;
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
  CouplingOptions coupling;
  coupling.relaxation = CouplingRelaxation::anderson;
  coupling.anderson_depth = 10;
  coupling.pressure_tolerance = coupling.displacement_tolerance = 1e-4;
  const Lattice lattice = generate_lattice(spec);
  CoupledModel model(lattice, calibrated_beam_parameters(), BoundaryConditions{}, MechanicsOptions{}, flow, coupling);
  model.enable_fracture(draw_beam_strengths(StrengthSpec{}, lattice.n_beams()));
  const double setup = seconds_since(start);

  TimeStepping stepping;
  stepping.dt_initial = 1e-5;
  stepping.dt_growth = 1.2;
  stepping.dt_max = 5e-4;
  stepping.t_end = 0.0272;
  const CoupledRunSummary run = model.run(stepping);
  const double total = seconds_since(start);
  std::printf("Fig. 12 b = 0.2 to t* = 0.0272 at N = %d particles: %s, %d steps, %d passes, %d beams broken\n",
              lattice.n_particles(), hm::core::name_of(run.status).c_str(), run.n_steps, run.total_iterations,
              model.n_broken());
  std::printf("  %-40s %9s %7s\n", "part", "seconds", "share");
  const double parts[] = {
      setup, run.mechanics_seconds, run.stress_seconds, run.break_seconds, run.geometry_seconds, run.flow_seconds,
      total};
  const char* names[] = {"set-up (lattice, factorisations)",
                         "mechanical solves",
                         "stresses and failure checks",
                         "factor downdates (breaks)",
                         "deformed geometry",
                         "flow (factorise/refine, solve)",
                         "whole run"};
  for (int k = 0; k < 7; ++k) std::printf("  %-40s %9.2f %6.1f%%\n", names[k], parts[k], 100.0 * parts[k] / total);
  return run.is_ok() ? 0 : 1;
}
