// The saw-tooth law in the lattice: a softened beam's stiffness through the kept factor, and one beam
// taken through its teeth by displacement control doing the work G_f d that the law books for it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/sawtooth_law.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "lattice_fixtures.hpp"

using namespace hm::lattice2d;

namespace {

Lattice square() { return hm::test::make_lattice(DomainShape::rectangle, 800, 3); }

// The interior beam nearest the centre.
int central_beam(const Lattice& lattice) {
  int best = -1;
  double best_r = 1e300;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (lattice.beam_boundary[static_cast<std::size_t>(e)] != BoundaryTag::interior) continue;
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const double r = (0.5 * (lattice.points.col(i) + lattice.points.col(j))).norm();
    if (r < best_r) best_r = r, best = e;
  }
  return best;
}

}  // namespace

TEST_CASE("A softened beam's rank-3 downdate leaves the factor equal to the assembled stiffness",
          "[lattice2d][fracture]") {
  const Lattice lattice = square();
  BoundaryConditions bc;
  bc.outer_pressure = -1e-4;  // all-round tension, pure traction
  BeamMechanics mechanics(lattice, calibrated_beam_parameters(), bc);
  const MechanicsSummary before = mechanics.solve();
  const int e = central_beam(lattice);
  const double n_before = mechanics.beam_forces()[static_cast<std::size_t>(e)].normal;
  // Three beams around the centre softened in steps, one of them broken afterwards (its contact, if
  // closed, has the unsoftened k_n).
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
  std::vector<int> soft = {e};
  for (int f = 0; f < lattice.n_beams() && soft.size() < 3; ++f) {
    const auto& b = lattice.beams[static_cast<std::size_t>(f)];
    if (f != e && (b[0] == i || b[1] == i)) soft.push_back(f);
  }
  for (int f : soft) mechanics.soften_beam(f, 0.5);
  mechanics.soften_beam(e, 0.125);
  CHECK(mechanics.stiffness_factor(e) == 0.125);
  const MechanicsSummary softened = mechanics.solve();
  REQUIRE(softened.is_converged());
  // The equilibrium residual re-evaluates every beam from its (softened) constants, independent of
  // the factor the solve used: round-off of the solve (~1e-13 before any update) shows it agrees.
  CHECK(softened.equilibrium_residual < 1e-10);
  CHECK(before.equilibrium_residual < 1e-10);
  // A softer beam carries less of the same all-round tension (it was stretched: n_before > 0).
  REQUIRE(n_before > 0.0);
  CHECK(mechanics.beam_forces()[static_cast<std::size_t>(e)].normal < 0.5 * n_before);
  mechanics.break_beam(soft[1]);
  CHECK(mechanics.stiffness_factor(soft[1]) == 1.0);
  const MechanicsSummary broken = mechanics.solve();
  REQUIRE(broken.is_converged());
  CHECK(broken.equilibrium_residual < 1e-10);

  // All-round compression instead: the softened beams are shortened, so they close (their normal
  // springs unsoftened by rank-1 updates); the factor still agrees with the beams' constants.
  BoundaryConditions compressed = bc;
  compressed.outer_pressure = 1e-4;
  BeamMechanics squeezed(lattice, calibrated_beam_parameters(), compressed);
  REQUIRE(squeezed.solve().is_converged());
  for (int f : soft) squeezed.soften_beam(f, 0.5);
  const MechanicsSummary closed = squeezed.solve();
  REQUIRE(closed.is_converged());
  CHECK(closed.equilibrium_residual < 1e-10);
  for (int f : soft) CHECK(squeezed.is_closed(f));
  squeezed.soften_beam(e, 0.125);  // a closed beam softens in bending only
  squeezed.break_beam(soft[1]);    // a closed beam breaks into a contact
  const MechanicsSummary after = squeezed.solve();
  REQUIRE(after.is_converged());
  CHECK(after.equilibrium_residual < 1e-10);

  CHECK_THROWS_AS(mechanics.soften_beam(e, 0.25), hm::InputError);       // would stiffen it
  CHECK_THROWS_AS(mechanics.soften_beam(e, 0.0), hm::InputError);        // zero is a break
  CHECK_THROWS_AS(mechanics.soften_beam(soft[1], 0.1), hm::InputError);  // broken
  CHECK_THROWS_AS(mechanics.soften_beam(-1, 0.1), hm::InputError);
}

TEST_CASE("One beam pulled through its teeth does the work G_f d that the law dissipates", "[lattice2d][fracture]") {
  // Every particle's x, y held; beam e's particle j moves by lambda delta along the beam, its other
  // beams cut beforehand, so e's elongation is exactly lambda delta and only e is stressed (rotations
  // are free and stay 0: no chord rotation). The work of its
  // normal force sum (1/2)(N(lambda_a) + N(lambda_b))(lambda_b - lambda_a) delta between the loads of
  // successive teeth, from the mechanics' forces, is what the beam dissipated once it is broken.
  const Lattice lattice = square();
  const DualGraph dual = build_dual_graph(lattice);
  const BeamParameters parameters = calibrated_beam_parameters();
  const int e = central_beam(lattice);
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
  const double delta = 1e-3;
  BoundaryConditions bc;
  for (int p = 0; p < lattice.n_particles(); ++p)
    for (int c = 0; c < 2; ++c) bc.prescribed.push_back({p, c, p == j ? delta * lattice.direction(c, e) : 0.0});
  BeamStrengths strengths;
  strengths.tensile = Eigen::VectorXd::Constant(lattice.n_beams(), 1e3);  // only beam e can fail
  strengths.compressive = Eigen::VectorXd::Constant(lattice.n_beams(), 1e3);
  const double f_t = 2e-4;
  strengths.tensile[e] = f_t;

  const double length = lattice.length[e];
  const double e_n = std::sqrt(3.0) * parameters.normal_stiffness;  // voronoi_facet: every beam's modulus
  const double critical = 2.0 * e_n / (f_t * f_t);                  // critical length per unit G_f
  // Ten times shorter than its critical length (ten teeth), and twice as long (one reduced tooth).
  for (const double g_f : {0.1 * length / critical, 2.0 * length / critical}) {
    INFO("G_f = " << g_f << ", critical length " << g_f * critical << ", L = " << length);
    BeamMechanics mechanics(lattice, parameters, bc);
    for (int f = 0; f < lattice.n_beams(); ++f) {
      const auto& b = lattice.beams[static_cast<std::size_t>(f)];
      if (f != e && (b[0] == j || b[1] == j)) mechanics.break_beam(f);
    }
    SawtoothLawOptions options;
    options.fracture_energy = g_f;
    SawtoothLaw law(lattice, dual, parameters, strengths, options);
    const double d = law.section(e);
    CHECK(d == Approx(std::max(dual.dual_length[e], parameters.facet_floor * length)).epsilon(1e-12));
    const bool brittle = g_f * critical <= length;
    CHECK(law.n_brittle_beams() >= (brittle ? 1 : 0));
    std::vector<BreakEvent> breaks;
    std::vector<ToothEvent> teeth;
    double load = 0.0, normal_before = 0.0, work = 0.0;
    for (int round = 0; round < 100 && breaks.empty(); ++round) {
      const BreakLoopSummary s = break_until_stable(mechanics, dual, strengths, law, {}, load, breaks, teeth, load);
      REQUIRE(s.status == BreakLoopStatus::stable);
      if (!breaks.empty()) break;
      // The next tooth's load (homogeneity: judged ratio = load x reference ratio), 1e-9 past it.
      const double next = (1.0 / s.max_reference_ratio) * (1.0 + 1e-9);
      const double normal_reference = mechanics.beam_forces()[static_cast<std::size_t>(e)].normal;  // at load 1
      work += 0.5 * (normal_before + next * normal_reference) * (next - load) * delta;
      normal_before = 0.0;  // set below from the state after the next load's events
      load = next;
      // The force at `next` after its events is that of the softened beam: the next segment starts there.
      const BreakLoopSummary after = break_until_stable(mechanics, dual, strengths, law, {}, load, breaks, teeth, load);
      REQUIRE(after.status == BreakLoopStatus::stable);
      normal_before = load * mechanics.beam_forces()[static_cast<std::size_t>(e)].normal;
    }
    REQUIRE(breaks.size() == 1u);
    CHECK(breaks[0].beam == e);
    REQUIRE(teeth.size() == (brittle ? 1u : static_cast<std::size_t>(options.teeth.n_teeth)));
    double booked = 0.0;
    for (std::size_t k = 0; k < teeth.size(); ++k) {
      CHECK(teeth[k].beam == e);
      CHECK(teeth[k].tooth == static_cast<int>(k));
      CHECK(teeth[k].ratio >= 1.0);
      CHECK(teeth[k].ratio < 1.0 + 1e-8);  // snapped to the tooth's load
      booked += teeth[k].energy;
    }
    CHECK(teeth.back().stiffness_factor == 0.0);  // the last tooth is the break
    // Each tooth reached 1e-9 past its strength: the work exceeds G_f d by ~2e-9 relative.
    CHECK(law.dissipated_energy() == Approx(g_f * d).epsilon(1e-12));
    CHECK(booked == Approx(g_f * d).epsilon(1e-12));
    CHECK(work == Approx(g_f * d).epsilon(1e-7));
  }
}

TEST_CASE("A softened beam that is shortened closes: its normal stiffness is unsoftened, its bending stays softened",
          "[lattice2d][fracture]") {
  // Every dof held (rotations too, but for one far particle's: the system must not be empty), beam e's
  // particle j moved by (along, across) delta in the beam's axes and its other beams cut: e's end
  // displacements are exactly prescribed, so its normal force is
  // k delta along and its shear proportional to k_omega delta across. Against the unsoftened beam at
  // the same displacement: a closed (shortened) beam has the full normal force and s times the shear,
  // an open (lengthened) one s times both. The equilibrium residual re-evaluates every beam from its
  // constants, independently of the factor the solve used: round-off shows the rank-1 updates of each
  // closing and opening agree with them (the factor itself is checked under all-round compression below).
  const Lattice lattice = square();
  const BeamParameters parameters = calibrated_beam_parameters();
  const int e = central_beam(lattice);
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
  const Eigen::Vector2d n = lattice.direction.col(e), t(-n.y(), n.x());
  const double delta = 1e-4;
  const auto forces = [&](double along, double across, const std::vector<double>& factors, bool break_it) {
    BoundaryConditions bc;
    const Eigen::Vector2d u = delta * (along * n + across * t);
    const int far = (i == 0 || j == 0) ? 1 + std::max(i, j) : 0;
    for (int p = 0; p < lattice.n_particles(); ++p)
      for (int c = 0; c < 3; ++c)
        if (p != far || c < 2) bc.prescribed.push_back({p, c, p == j && c < 2 ? u[c] : 0.0});
    BeamMechanics mechanics(lattice, parameters, bc);
    for (int f = 0; f < lattice.n_beams(); ++f) {
      const auto& b = lattice.beams[static_cast<std::size_t>(f)];
      if (f != e && (b[0] == j || b[1] == j)) mechanics.break_beam(f);
    }
    // Softened in steps, solved after each (so later steps may soften a closed beam), broken last.
    for (double s : factors) {
      mechanics.soften_beam(e, s);
      REQUIRE(mechanics.solve().equilibrium_residual < 1e-10);
    }
    if (break_it) mechanics.break_beam(e);
    const MechanicsSummary solved = mechanics.solve();
    REQUIRE(solved.is_converged());
    CHECK(solved.equilibrium_residual < 1e-10);
    if (!factors.empty() && !break_it) CHECK(mechanics.is_closed(e) == (along < 0.0));
    return mechanics.beam_forces()[static_cast<std::size_t>(e)];
  };
  for (const double along : {-1.0, 1.0}) {
    INFO((along < 0 ? "shortened" : "lengthened"));
    const BeamForce unsoftened = forces(along, 0.5, {}, false);
    REQUIRE(std::abs(unsoftened.shear) > 1e-3 * std::abs(unsoftened.normal));
    const double s = 0.125;
    const BeamForce softened = forces(along, 0.5, {0.5, 0.25, s}, false);
    CHECK(softened.normal == Approx((along < 0 ? 1.0 : s) * unsoftened.normal).epsilon(1e-10));
    CHECK(softened.shear == Approx(s * unsoftened.shear).epsilon(1e-10));
    // Broken after softening: a contact (shortened) has the unsoftened normal spring, an open beam nothing.
    const BeamForce broken = forces(along, 0.5, {0.5, s}, true);
    CHECK(broken.normal == Approx(along < 0 ? unsoftened.normal : 0.0).epsilon(1e-10));
    CHECK(std::abs(broken.shear) < 1e-12 * std::abs(unsoftened.normal));  // a contact pushes along the beam only
  }
}

TEST_CASE("The saw-tooth law refuses a fracture energy or strength factor that is not positive",
          "[lattice2d][fracture]") {
  SawtoothLawOptions options;
  for (double bad : {0.0, -1e-9, std::nan("")}) {
    options.fracture_energy = bad;
    CHECK_THROWS_WITH(options.validate(), Catch::Contains("sawtooth_law.fracture_energy"));
  }
  options.fracture_energy = 1e-9;
  options.strength_factor = 0.0;
  CHECK_THROWS_WITH(options.validate(), Catch::Contains("sawtooth_law.strength_factor = 0"));
  options.strength_factor = 1.0;
  options.teeth.n_teeth = 0;
  CHECK_THROWS_WITH(options.validate(), Catch::Contains("sawtooth_law.sawtooth.n_teeth"));
}
