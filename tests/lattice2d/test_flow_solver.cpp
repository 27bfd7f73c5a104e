// The flow network's sparse factorisation (flow_network.cpp, FlowNetwork::Solver) against a dense
// solve of the same Eqs. 15-16, assembled here independently from the lattice and its dual graph:
// a step, a step after new geometry and broken beams (numeric refactorisation on the same pattern),
// the reuse_factorisation path and the steady state, on the annulus (borehole node) and the disk
// (point source).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/flow/flow_network.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::make_lattice;

namespace {

// The dense matrix of FlowNetwork's doc comment: (storage_scale E/M) V on the diagonal (the
// borehole's only with biot-modulus storage), dt iota_e A/d per connection.
Eigen::MatrixXd dense_flow_matrix(const Lattice& lattice, const DualGraph& dual, const FlowNetwork& network, double dt,
                                  double storage_scale) {
  const FlowParameters& parameters = network.parameters();
  const int n = network.n_unknowns(), h = network.borehole_index();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int s = 0; s < network.n_triangles(); ++s) a(s, s) = storage_scale * parameters.E_over_M * dual.triangle_area[s];
  if (h >= 0 && parameters.borehole_storage == BoreholeStorage::biot_modulus)
    a(h, h) = storage_scale * parameters.E_over_M * network.borehole_volume();
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [s, other] = lattice.beam_triangles[static_cast<std::size_t>(e)];
    const bool wall = lattice.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::inner;
    const int t = other >= 0 ? other : (wall ? h : -1);
    // Rock and crack side by side on the facet: (1 - w) of the rock's conductance and w of iota times it.
    const double w = network.crack_weights()[e];
    const double g = dt * dual.conductance[e] * ((1.0 - w) + w * parameters.iota);
    a(s, s) += g;
    if (t >= 0) {
      a(t, t) += g;
      a(s, t) -= g;
      a(t, s) -= g;
    }
  }
  return a;
}

// p^{n+1} of one implicit Euler step from p^n = network.pressure() with volume change dV.
Eigen::VectorXd dense_step(const Lattice& lattice, const DualGraph& dual, const FlowNetwork& network, double dt,
                           const Eigen::VectorXd& dV) {
  const FlowParameters& parameters = network.parameters();
  const int h = network.borehole_index();
  const Eigen::MatrixXd a = dense_flow_matrix(lattice, dual, network, dt, 1.0);
  Eigen::VectorXd storage = Eigen::VectorXd::Zero(network.n_unknowns());
  for (int s = 0; s < network.n_triangles(); ++s) storage[s] = parameters.E_over_M * dual.triangle_area[s];
  if (h >= 0 && parameters.borehole_storage == BoreholeStorage::biot_modulus)
    storage[h] = parameters.E_over_M * network.borehole_volume();
  Eigen::VectorXd deformation = parameters.b * dV;
  if (h >= 0 && parameters.borehole_deformation == BoreholeDeformation::none) deformation[h] = 0.0;
  Eigen::VectorXd rhs = storage.cwiseProduct(network.pressure()) - deformation;
  rhs[h >= 0 ? h : network.source_triangle()] += parameters.Q * dt;
  return a.llt().solve(rhs);
}

double relative_difference(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
  return (x - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

// Every `every`-th beam broken, every (3 every)-th one after it softening (a crack weight between 0
// and 1), and the particles moved by up to `amplitude` (domain radius 1).
void crack_and_deform(const Lattice& lattice, FlowNetwork& network, DualGraph& dual, std::size_t every,
                      double amplitude) {
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(lattice.n_beams());
  for (Eigen::Index e = 0; e < weights.size(); e += static_cast<Eigen::Index>(every)) weights[e] = 1.0;
  for (Eigen::Index e = 1; e < weights.size(); e += static_cast<Eigen::Index>(3 * every))
    weights[e] = 0.3 + 0.002 * (e % 300);
  network.set_crack_weights(weights);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> shift(-amplitude, amplitude);
  Eigen::Matrix2Xd positions = lattice.points;
  for (Eigen::Index i = 0; i < positions.cols(); ++i) positions.col(i) += Eigen::Vector2d(shift(rng), shift(rng));
  dual = build_dual_graph(lattice, positions);
  network.update_geometry(dual, positions);
}

// The reuse_factorisation tests' flow: b = 0.2, broken segments 5x as conductive (so breaks change the
// matrix), the factor kept across geometry changes.
FlowParameters reusing_parameters() {
  FlowParameters parameters;
  parameters.b = 0.2;
  parameters.iota = 5.0;
  parameters.reuse_factorisation = true;
  return parameters;
}

}  // namespace

TEST_CASE("The flow network's sparse factorisation agrees with a dense solve to round-off", "[lattice2d][flow]") {
  const DomainShape shape = GENERATE(DomainShape::annulus, DomainShape::disk);
  const BoreholeStorage storage = GENERATE(BoreholeStorage::biot_modulus, BoreholeStorage::none);
  CAPTURE(static_cast<int>(shape), hm::core::name_of(storage));
  const Lattice lattice = make_lattice(shape, 600);
  DualGraph dual = build_dual_graph(lattice);
  FlowParameters parameters;
  parameters.Q = 0.01;
  parameters.b = 0.2;
  parameters.iota = 5.0;
  parameters.borehole_storage = storage;
  FlowNetwork network(lattice, dual, parameters);
  // Measured: <= 1.4e-15 for the steps, 1.2e-14 for the steady state (CHOLMOD simplicial LDL' with
  // nested dissection, and Eigen's SimplicialLDLT before it); the bound leaves room for other orderings.
  const double tolerance = 1e-12;

  // Two steps with dt = 1e-4, the second with a volume change.
  const double dt = 1e-4;
  Eigen::VectorXd reference = dense_step(lattice, dual, network, dt, Eigen::VectorXd::Zero(network.n_unknowns()));
  FlowStepSummary summary = network.step(dt);
  REQUIRE(summary.is_ok());
  CHECK(summary.factorised);
  CHECK(relative_difference(network.pressure(), reference) <= tolerance);
  Eigen::VectorXd dV = Eigen::VectorXd::Zero(network.n_unknowns());
  for (Eigen::Index k = 0; k < dV.size(); k += 3) dV[k] = 1e-7;
  reference = dense_step(lattice, dual, network, dt, dV);
  summary = network.step(dt, dV);
  REQUIRE(summary.is_ok());  // same dt, nothing changed: the factor is reused
  CHECK_FALSE(summary.factorised);
  CHECK(relative_difference(network.pressure(), reference) <= tolerance);

  // New values on the same pattern: broken beams (iota = 5) and moved particles, then a new dt.
  crack_and_deform(lattice, network, dual, 7, 1e-3);
  for (const double step_dt : {dt, 3e-4}) {
    reference = dense_step(lattice, dual, network, step_dt, dV);
    summary = network.step(step_dt, dV);
    REQUIRE(summary.is_ok());
    CHECK(summary.factorised);
    CHECK(summary.balance_error <= 1e-10);
    CHECK(relative_difference(network.pressure(), reference) <= tolerance);
  }

  // Steady state: no storage, K p = Q at the source.
  const FlowSteadyState steady = network.solve_steady_state();
  REQUIRE(steady.solved);
  Eigen::VectorXd source = Eigen::VectorXd::Zero(network.n_unknowns());
  source[network.has_borehole() ? network.borehole_index() : network.source_triangle()] = parameters.Q;
  const Eigen::VectorXd steady_reference = dense_flow_matrix(lattice, dual, network, 1.0, 0.0).llt().solve(source);
  CHECK(relative_difference(steady.pressure, steady_reference) <= tolerance);
}

TEST_CASE("reuse_factorisation: CG on the new matrix, preconditioned by the old factor, reaches the dense solve",
          "[lattice2d][flow]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 600);
  DualGraph dual = build_dual_graph(lattice);
  const FlowParameters parameters = reusing_parameters();
  FlowNetwork network(lattice, dual, parameters);
  const double dt = 1e-4;
  REQUIRE(network.step(dt).is_ok());
  // A small change (a few broken beams, 1e-5 moves), as between two passes of the coupling loop.
  crack_and_deform(lattice, network, dual, 50, 1e-5);
  const Eigen::VectorXd reference = dense_step(lattice, dual, network, dt, Eigen::VectorXd::Zero(network.n_unknowns()));
  const FlowStepSummary summary = network.step(dt);
  REQUIRE(summary.is_ok());
  CAPTURE(summary.refinements);
  CHECK_FALSE(summary.factorised);
  CHECK(summary.refinements >= 1);
  // ||rhs - A p|| <= 1e-10 ||rhs|| (refinement_tolerance), times the condition number: measured 3e-10.
  CHECK(relative_difference(network.pressure(), reference) <= 1e-8);
}

TEST_CASE("reuse_factorisation: a solve slower than refresh_after_refinements refactorises at the next one",
          "[lattice2d][flow]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 600);
  DualGraph dual = build_dual_graph(lattice);
  FlowParameters parameters = reusing_parameters();
  parameters.refresh_after_refinements = 0;  // any refinement at all asks for a fresh factor
  FlowNetwork network(lattice, dual, parameters);
  const double dt = 1e-4;
  REQUIRE(network.step(dt).is_ok());
  crack_and_deform(lattice, network, dual, 50, 1e-5);
  const FlowStepSummary refined = network.step(dt);
  REQUIRE(refined.is_ok());
  CHECK_FALSE(refined.factorised);
  REQUIRE(refined.refinements >= 1);                   // > 0 = refresh_after_refinements
  crack_and_deform(lattice, network, dual, 50, 2e-5);  // the geometry moves again
  const Eigen::VectorXd reference = dense_step(lattice, dual, network, dt, Eigen::VectorXd::Zero(network.n_unknowns()));
  const FlowStepSummary refreshed = network.step(dt);
  REQUIRE(refreshed.is_ok());
  CHECK(refreshed.factorised);  // refactorised, not refined
  CHECK(refreshed.refinements == 0);
  // A fresh factorisation is a direct solve: round-off (measured <= 1.4e-15 against the dense solve in
  // the factorisation test above); 1e-10 leaves room for other orderings.
  CHECK(relative_difference(network.pressure(), reference) <= 1e-10);
  // The default (4) keeps the factor while the refinement is fast: with iota = 1 (the Fig. 12 cases) a
  // break changes no conductance, and the 1e-5 moves need 1-4 iterations; a second move is refined too.
  FlowParameters lenient = parameters;
  lenient.iota = 1.0;
  lenient.refresh_after_refinements = FlowParameters{}.refresh_after_refinements;
  DualGraph kept_dual = build_dual_graph(lattice);
  FlowNetwork kept(lattice, kept_dual, lenient);
  REQUIRE(kept.step(dt).is_ok());
  crack_and_deform(lattice, kept, kept_dual, 50, 1e-5);
  const FlowStepSummary first = kept.step(dt);
  REQUIRE(first.refinements >= 1);
  REQUIRE(first.refinements <= lenient.refresh_after_refinements);
  crack_and_deform(lattice, kept, kept_dual, 50, 2e-5);
  const FlowStepSummary second = kept.step(dt);
  CHECK_FALSE(second.factorised);
  CHECK(second.refinements >= 1);
  parameters.refresh_after_refinements = -1;
  CHECK_THROWS_AS(parameters.validate(), hm::InputError);
}
