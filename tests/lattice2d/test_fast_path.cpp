// The per-solve fast path against the definitions it stands for, in the build CI runs (Release):
// BeamOperator's internal force against -K_e u_e of the element matrix, the factor columns against
// K_e, and the break loop's FailureScan against the public stress and failure functions at every break.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "approx.hpp"
#include "fracture/failure_scan.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;

namespace {

// Round-off of a 6 x 6 product against the structured evaluation: a few operations per entry on O(1)
// relative magnitudes (the tolerance is relative to ||K_e|| ||u_e||, the size of the terms summed).
constexpr double kRoundoff = 1e-12;

// Mixed states: about half intact, a quarter contact, a quarter open (seeded).
std::vector<BeamState> mixed_states(int n_beams, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<BeamState> states(static_cast<std::size_t>(n_beams));
  for (auto& s : states) {
    const auto draw = random() % 4;
    s = draw < 2 ? BeamState::intact : draw == 2 ? BeamState::contact : BeamState::open;
  }
  return states;
}

Eigen::VectorXd random_displacement(int n_particles, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd u(3 * n_particles);
  for (Eigen::Index k = 0; k < u.size(); ++k) u[k] = uniform(random);
  return u;
}

// Minus K_e u_e of every beam from the element matrices: the definition the fast forces stand for.
BeamForces element_matrix_forces(const Lattice& lattice, const BeamParameters& parameters,
                                 const std::vector<BeamState>& states, const Eigen::VectorXd& u) {
  BeamForces out{Eigen::Matrix2Xd(2, lattice.n_beams()), Eigen::Matrix2Xd(2, lattice.n_beams())};
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const Matrix6d K =
        beam_element_stiffness(lattice.length[e], lattice.angle[e], beam_parameters_for(lattice, parameters, e),
                               states[static_cast<std::size_t>(e)]);
    const Vector6d f = -K * element_displacements(lattice, e, u);
    out.force.col(e) = f.head<2>();
    out.moment.col(e) << f[2], f[5];
  }
  return out;
}

// Every boundary particle held at u = eps x: stretched in y, squeezed in x, so that some broken beams
// close into contacts.
BoundaryConditions stretch_and_squeeze() {
  BoundaryConditions bc;
  bc.prescribe_boundary_strain = true;
  bc.boundary_strain << -0.3, 0.0, 0.0, 1.0;
  return bc;
}

}  // namespace

TEST_CASE("Beam internal forces and factor columns equal the element stiffness they come from", "[lattice2d]") {
  const Lattice lattice = hm::test::make_lattice(DomainShape::disk, 800, 4);
  BeamParameters parameters;
  parameters.aspect = 0.8;
  parameters.beam_poisson = 0.1;
  parameters.stiffness_scaling = StiffnessScaling::voronoi_facet;
  const std::vector<BeamState> states = mixed_states(lattice.n_beams(), 11);
  const Eigen::VectorXd u = random_displacement(lattice.n_particles(), 12);
  double force_error = 0.0, factor_error = 0.0, strain_error = 0.0;
  int n_contact = 0, n_open = 0;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const BeamState state = states[static_cast<std::size_t>(e)];
    n_contact += state == BeamState::contact;
    n_open += state == BeamState::open;
    const BeamParameters p = beam_parameters_for(lattice, parameters, e);
    const Matrix6d K = beam_element_stiffness(lattice.length[e], lattice.angle[e], p, state);
    const Matrix63d V = beam_element_factor(lattice.length[e], lattice.angle[e], p, state);
    const BeamOperator op(lattice, e, p, state);
    const Vector6d u_e = element_displacements(lattice, e, u);
    if (state == BeamState::open) {
      CHECK(K.isZero(0.0));
      CHECK(V.isZero(0.0));
      CHECK(op.internal_force(u_e).isZero(0.0));
      continue;
    }
    const double scale = K.norm() * u_e.norm();
    force_error = std::max(force_error, (op.internal_force(u_e) - K * u_e).cwiseAbs().maxCoeff() / scale);
    factor_error = std::max(factor_error, (V * V.transpose() - K).cwiseAbs().maxCoeff() / K.norm());
    // The structured strains and resultants are B T u_e and D q.
    const Eigen::Vector3d q = op.strains(u_e);
    const Eigen::Vector3d q_dense = op.strain_matrix() * op.rotation() * u_e;
    strain_error = std::max(strain_error, (q - q_dense).cwiseAbs().maxCoeff() / u_e.norm() * lattice.length[e]);
    strain_error = std::max(strain_error, (op.resultants(q) - op.constitutive() * q).cwiseAbs().maxCoeff() /
                                              (op.constitutive().norm() * q.norm()));
  }
  REQUIRE(n_contact > 100);
  REQUIRE(n_open > 100);
  CAPTURE(force_error, factor_error, strain_error);
  CHECK(force_error < kRoundoff);
  CHECK(factor_error < kRoundoff);
  CHECK(strain_error < kRoundoff);

  // The two public force layouts are the same per-beam evaluation, bit for bit, and -K_e u_e to round-off.
  const std::vector<BeamForce> connection = connection_forces(lattice, parameters, states, u);
  const BeamForces forces = compute_beam_forces(lattice, parameters, u, states);
  const BeamForces reference = element_matrix_forces(lattice, parameters, states, u);
  double difference = 0.0;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const BeamForce& f = connection[static_cast<std::size_t>(e)];
    difference = std::max({difference, (forces.force.col(e) - f.force_on_i).cwiseAbs().maxCoeff(),
                           std::abs(forces.moment(0, e) - f.moment_i), std::abs(forces.moment(1, e) - f.moment_j)});
  }
  CHECK(difference == 0.0);
  const double force_scale = reference.force.cwiseAbs().maxCoeff();
  CHECK((forces.force - reference.force).cwiseAbs().maxCoeff() < kRoundoff * force_scale);
  CHECK((forces.moment - reference.moment).cwiseAbs().maxCoeff() < kRoundoff * reference.moment.cwiseAbs().maxCoeff());
}

TEST_CASE("The break loop's failure scan equals the public stress and failure path at every break", "[lattice2d]") {
  // Seeds 3/5, N = 800, the reference strain scaled by 4e-4: 30 breaks, with crack tips and contacts.
  const Lattice lattice = hm::test::make_lattice(DomainShape::rectangle, 800, 3);
  const DualGraph dual = build_dual_graph(lattice);
  StrengthSpec strength;
  strength.seed = 5;
  const BeamStrengths strengths = draw_beam_strengths(strength, lattice.n_beams());
  const BeamParameters parameters;
  const double scale = 4e-4;
  const CrackTipOptions crack_tip;
  BeamMechanics m(lattice, parameters, stretch_and_squeeze());
  FailureScan scan(lattice, dual, crack_tip, m.states());
  std::vector<int> sequence;
  double stress_error = 0.0, ratio_error = 0.0, equilibrium_error = 0.0;
  while (sequence.size() < 30) {
    REQUIRE(m.solve().is_converged());
    const FailureScan::Result fast = scan.run(m.beam_forces(), strengths, m.states(), scale);

    // The reference: forces from the element matrices, then the public functions from scratch.
    const BeamForces forces = element_matrix_forces(lattice, parameters, m.states(), m.displacement());
    const ParticleStress particle = compute_particle_stress(lattice, dual, forces);
    const BeamStress at_reference = compute_beam_stress(lattice, particle, m.states(), crack_tip);
    BeamStress judged = at_reference;
    judged.stress *= scale;
    judged.sigma_1 *= scale;
    judged.sigma_3 *= scale;
    const BreakCandidate expected = select_beam_to_break(judged, strengths, m.states());
    const double stress_scale = particle.stress.cwiseAbs().maxCoeff();
    stress_error =
        std::max(stress_error, (scan.particle_stress().stress - particle.stress).cwiseAbs().maxCoeff() / stress_scale);
    // current_beam_stress is the same path as the scan.
    const BeamStress current = current_beam_stress(m, dual, crack_tip, scale);
    stress_error =
        std::max(stress_error, (current.stress - judged.stress).cwiseAbs().maxCoeff() / (scale * stress_scale));
    CHECK((current.crack_tip_factor - judged.crack_tip_factor).cwiseAbs().maxCoeff() == 0.0);
    const double max_reference_ratio = select_beam_to_break(at_reference, strengths, m.states()).max_ratio;
    ratio_error = std::max({ratio_error, std::abs(fast.judged.max_ratio / expected.max_ratio - 1.0),
                            std::abs(fast.max_reference_ratio / max_reference_ratio - 1.0)});
    // The mechanics' reactions use the same internal force: K u - f with the assembled K of the states.
    const Eigen::VectorXd Ku = assemble_stiffness(lattice, parameters, m.states()) * m.displacement();
    equilibrium_error =
        std::max(equilibrium_error, (m.reactions() + m.loads() - Ku).cwiseAbs().maxCoeff() / Ku.cwiseAbs().maxCoeff());

    REQUIRE(fast.judged.beam == expected.beam);
    if (!expected.found()) break;
    const int e = expected.beam;
    CHECK(fast.judged.mode == expected.mode);
    CHECK(fast.judged.ratio == hm::test::roundoff(expected.ratio));
    CHECK(fast.sigma_1 == hm::test::roundoff(judged.sigma_1[e]));
    CHECK(fast.sigma_3 == hm::test::roundoff(judged.sigma_3[e]));
    CHECK(fast.crack_tip_factor == judged.crack_tip_factor[e]);
    sequence.push_back(e);
    m.break_beam(e);
    scan.beam_broken(e);
  }
  CAPTURE(stress_error, ratio_error, equilibrium_error);
  CHECK(stress_error < kRoundoff);
  CHECK(ratio_error < kRoundoff);
  CHECK(equilibrium_error < kRoundoff);
  REQUIRE(sequence.size() == 30u);
  int n_contact = 0, n_tip = 0;
  for (BeamState s : m.states()) n_contact += s == BeamState::contact;
  for (bool tip : find_crack_tip_beams(lattice, m.states())) n_tip += tip;
  CHECK(n_contact > 0);
  CHECK(n_tip > 0);

  // break_until_stable (which runs the scan) breaks the same beams in the same order.
  BeamMechanics fresh(lattice, parameters, stretch_and_squeeze());
  BreakLoopOptions options;
  options.max_breaks = 30;
  std::vector<BreakEvent> log;
  break_until_stable(fresh, dual, strengths, options, scale, log, scale);
  std::vector<int> logged;
  for (const BreakEvent& event : log) logged.push_back(event.beam);
  CHECK(logged == sequence);
}
