#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"

using namespace hm::lattice2d;

namespace {

Lattice annulus(long long n = 2000, std::uint64_t seed = 3) {
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.n_particles = n;
  spec.seed = seed;
  return generate_lattice(spec);
}

Lattice rectangle(long long n = 1500) {
  LatticeSpec spec;
  spec.domain = DomainShape::rectangle;
  spec.n_particles = n;
  spec.seed = 5;
  return generate_lattice(spec);
}

double max_abs_force(const std::vector<BeamForce>& forces) {
  double m = 0.0;
  for (const auto& f : forces)
    m = std::max({m, f.force_on_i.cwiseAbs().maxCoeff(), std::abs(f.moment_i), std::abs(f.moment_j)});
  return m;
}

// The interior beam closest to the centre whose direction is within 30 degrees of x.
int central_x_beam(const Lattice& l) {
  int best = -1;
  double best_r = 1e9;
  for (int e = 0; e < l.n_beams(); ++e) {
    const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
    if (l.boundary[i] != BoundaryTag::interior || l.boundary[j] != BoundaryTag::interior) continue;
    if (std::abs(l.direction(0, e)) < std::cos(M_PI / 6)) continue;
    const double r = (0.5 * (l.points.col(i) + l.points.col(j))).norm();
    if (r < best_r) {
      best_r = r;
      best = e;
    }
  }
  return best;
}

}  // namespace

TEST_CASE("Mechanics inputs: defaults valid, bad boundary conditions rejected naming the field", "[lattice2d]") {
  const Lattice l = annulus(600);
  REQUIRE_NOTHROW(BoundaryConditions{}.validate(l));
  REQUIRE_NOTHROW(MechanicsOptions{}.validate());
  BoundaryConditions bc;
  bc.prescribed.push_back({l.n_particles(), 0, 0.0});
  CHECK_THROWS_WITH(bc.validate(l),
                    Catch::Contains("boundary_conditions.prescribed[0].particle = " + std::to_string(l.n_particles())));
  bc.prescribed = {{0, 3, 0.0}};
  CHECK_THROWS_WITH(bc.validate(l), Catch::Contains("prescribed[0].component = 3"));
  bc.prescribed = {{0, 1, NAN}};
  CHECK_THROWS_AS(bc.validate(l), hm::InputError);
  bc = BoundaryConditions{};
  bc.inner_pressure = INFINITY;
  CHECK_THROWS_WITH(bc.validate(l), Catch::Contains("boundary_conditions.inner_pressure = inf"));
  bc = BoundaryConditions{};
  bc.inner_pressure = 0.1;
  CHECK_THROWS_WITH(bc.validate(rectangle(600)),
                    Catch::Contains("inner_pressure = 0.1, allowed: 0 unless domain = annulus"));
  bc = BoundaryConditions{};
  bc.prescribe_boundary_strain = true;
  bc.outer = BoundarySupport::fixed;
  CHECK_THROWS_WITH(bc.validate(l), Catch::Contains("prescribe_boundary_strain"));
  bc = BoundaryConditions{};
  bc.prescribe_boundary_strain = true;
  bc.boundary_strain << 0.0, 1e-3, 0.0, 0.0;
  CHECK_THROWS_WITH(bc.validate(l), Catch::Contains("boundary_strain(0,1) = 0.001"));
  // Held degrees of freedom that leave a rotation free: only x, y of one particle.
  bc = BoundaryConditions{};
  bc.prescribed = {{0, 0, 0.0}, {0, 1, 0.0}};
  CHECK_THROWS_WITH(BeamMechanics(l, BeamParameters{}, bc), Catch::Contains("rigid-body motion"));
  MechanicsOptions o;
  o.max_contact_iterations = 0;
  CHECK_THROWS_WITH(o.validate(), Catch::Contains("mechanics_options.max_contact_iterations = 0"));
  BeamMechanics m(l, BeamParameters{}, BoundaryConditions{});
  CHECK_THROWS_WITH(m.break_beam(l.n_beams()), Catch::Contains("beam = " + std::to_string(l.n_beams())));
}

TEST_CASE("Rigid-body motions carry no force", "[lattice2d]") {
  const Lattice l = annulus();
  const std::vector<BeamState> intact(static_cast<std::size_t>(l.n_beams()), BeamState::intact);
  SECTION("forces of a rigid displacement field") {
    Eigen::VectorXd u(3 * l.n_particles());
    for (int p = 0; p < l.n_particles(); ++p)
      u.segment<3>(3 * p) << 0.3 - 0.01 * l.points(1, p), -0.2 + 0.01 * l.points(0, p), 0.01;
    // round-off: u = O(0.3), stiffness O(1); cancellation of O(1) terms
    CHECK(max_abs_force(connection_forces(l, BeamParameters{}, intact, u)) < 1e-14);
  }
  SECTION("a rigid motion prescribed on the boundary moves the whole lattice rigidly") {
    BoundaryConditions bc;
    for (int p = 0; p < l.n_particles(); ++p) {
      if (l.boundary[static_cast<std::size_t>(p)] == BoundaryTag::interior) continue;
      bc.prescribed.push_back({p, 0, 1e-3 - 2e-3 * l.points(1, p)});
      bc.prescribed.push_back({p, 1, 2e-3 * l.points(0, p)});
    }
    BeamMechanics m(l, BeamParameters{}, bc);
    const MechanicsSummary s = m.solve();
    REQUIRE(s.is_converged());
    CHECK(max_abs_force(m.beam_forces()) < 1e-15);  // round-off of 1e-3 displacements
    for (int p = 0; p < l.n_particles(); ++p)
      CHECK(m.displacement()[3 * p + 2] == Approx(2e-3).epsilon(1e-9));  // round-off x cond
  }
}

TEST_CASE("A homogeneous boundary strain stretches every beam and leaves the free DOFs in equilibrium", "[lattice2d]") {
  const Lattice l = rectangle();
  for (double e : {1e-3, -1e-3}) {
    BoundaryConditions bc;
    bc.prescribe_boundary_strain = true;
    bc.boundary_strain = e * Eigen::Matrix2d::Identity();
    BeamMechanics m(l, BeamParameters{}, bc);
    const MechanicsSummary s = m.solve();
    REQUIRE(s.is_converged());
    // round-off: reaction sums of O(1e-3) forces; cond ~ 2e4 (test_spd_solver)
    CHECK(s.equilibrium_residual < 1e-10);
    int wrong = 0;
    double n_min = INFINITY, n_max = -INFINITY;
    for (const BeamForce& f : m.beam_forces()) {
      if (f.normal * e <= 0.0) ++wrong;
      n_min = std::min(n_min, f.normal);
      n_max = std::max(n_max, f.normal);
    }
    std::cout << "[mechanics] isotropic strain " << e << ": beam normal forces in [" << n_min << ", " << n_max
              << "], equilibrium residual " << s.equilibrium_residual << "\n";
    CHECK(wrong == 0);
  }
}

TEST_CASE("Pressure on the borehole wall moves the wall radially outward", "[lattice2d]") {
  const Lattice l = annulus(3000);
  for (BoundarySupport outer : {BoundarySupport::free, BoundarySupport::fixed}) {
    BoundaryConditions bc;
    bc.outer = outer;
    bc.inner_pressure = 1e-3;
    BeamMechanics m(l, BeamParameters{}, bc);
    CHECK(m.is_pinned() == (outer == BoundarySupport::free));
    const MechanicsSummary s = m.solve();
    REQUIRE(s.is_converged());
    CHECK(s.equilibrium_residual < 1e-10);  // round-off, as above
    double ur_min = INFINITY, ur_outer = 0.0;
    for (int p = 0; p < l.n_particles(); ++p) {
      const Eigen::Vector2d r = l.points.col(p).normalized();
      const double ur = r.dot(m.displacement().segment<2>(3 * p));
      if (l.boundary[static_cast<std::size_t>(p)] == BoundaryTag::inner) ur_min = std::min(ur_min, ur);
      if (l.boundary[static_cast<std::size_t>(p)] == BoundaryTag::outer) ur_outer = std::max(ur_outer, std::abs(ur));
    }
    std::cout << "[mechanics] borehole pressure 1e-3, outer " << hm::core::name_of(outer) << ": min wall u_r " << ur_min
              << ", max |u_r| outer " << ur_outer << "\n";
    CHECK(ur_min > 0.0);
    if (outer == BoundarySupport::fixed) CHECK(ur_outer == 0.0);
    if (outer == BoundarySupport::free) {
      CHECK(ur_outer > 0.0);
      // The pin carries nothing: pressure on a closed polygon has zero resultant and moment.
      const Eigen::VectorXd r = m.reactions();
      const double f_max = m.loads().cwiseAbs().maxCoeff();
      CHECK(r.segment<3>(3 * m.pinned_particle()).cwiseAbs().maxCoeff() < 1e-10 * f_max);  // round-off x cond
    }
  }
}

TEST_CASE("A broken beam pushed together is a compression-only contact: pulled apart it carries nothing",
          "[lattice2d]") {
  const Lattice l = rectangle();
  BoundaryConditions bc;
  bc.outer_pressure = 1e-3;  // pure traction, compression (pinned automatically)
  for (SpdSolverKind kind : {SpdSolverKind::cholmod, SpdSolverKind::pcg}) {
    MechanicsOptions options;
    options.solver = kind;
    BeamMechanics m(l, BeamParameters{}, bc, options);
    REQUIRE(m.solve().is_converged());
    const int e = central_x_beam(l);
    CHECK(m.break_beam(e) == BeamState::contact);  // shortened now: becomes a contact at once
    MechanicsSummary s = m.solve();
    REQUIRE(s.is_converged());
    CHECK(m.states()[static_cast<std::size_t>(e)] == BeamState::contact);
    BeamForce f = m.beam_forces()[static_cast<std::size_t>(e)];
    CHECK(f.normal < 0.0);
    CHECK(std::abs(f.shear) < 1e-12 * std::abs(f.normal));  // round-off of n.s = 0 in the rotation
    CHECK(f.moment_i == 0.0);
    // Reverse the load: the boundary now pulls, the contact opens and carries nothing.
    m.set_external_forces(-2.0 * m.loads());
    s = m.solve();
    REQUIRE(s.is_converged());
    CHECK(s.n_contact_changes >= 1);
    CHECK(m.states()[static_cast<std::size_t>(e)] == BeamState::open);
    f = m.beam_forces()[static_cast<std::size_t>(e)];
    CHECK(f.force_on_i.norm() == 0.0);
    const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
    CHECK((m.displacement().segment<2>(3 * j) - m.displacement().segment<2>(3 * i)).dot(l.direction.col(e)) > 0.0);
    // And back: closes again.
    m.set_external_forces(Eigen::VectorXd::Zero(3 * l.n_particles()));
    REQUIRE(m.solve().is_converged());
    CHECK(m.states()[static_cast<std::size_t>(e)] == BeamState::contact);
    CHECK(m.beam_forces()[static_cast<std::size_t>(e)].normal < 0.0);
  }
  SECTION("an active set still changing at the iteration cap is reported, not hidden") {
    MechanicsOptions options;
    options.max_contact_iterations = 1;
    BeamMechanics m(l, BeamParameters{}, bc, options);
    m.solve();
    const int e = central_x_beam(l);
    m.break_beam(e);
    m.set_external_forces(-2.0 * m.loads());  // the contact must open: one switch after the only solve
    const MechanicsSummary s = m.solve();
    CHECK(s.info == Eigen::Success);
    CHECK_FALSE(s.contact_converged);
    CHECK_FALSE(s.is_converged());
    CHECK_THAT(s.message, Catch::Contains("max_contact_iterations"));
  }
}

TEST_CASE("Fifty breaks with factor downdates agree with PCG on the same broken lattice", "[lattice2d]") {
  const Lattice l = annulus(2000);
  BoundaryConditions bc;
  bc.outer = BoundarySupport::fixed;
  bc.inner_pressure = 1e-3;
  MechanicsOptions chol, pcg;
  pcg.solver = SpdSolverKind::pcg;
  pcg.solver_options.cg_tolerance = 1e-12;
  BeamMechanics a(l, BeamParameters{}, bc, chol), b(l, BeamParameters{}, bc, pcg);
  REQUIRE(a.solve().is_converged());
  REQUIRE(b.solve().is_converged());
  int broken = 0;
  for (int e = 0; e < l.n_beams() && broken < 50; e += 53, ++broken) {
    a.break_beam(e);
    b.break_beam(e);
    REQUIRE(a.solve().is_converged());
  }
  const MechanicsSummary sb = b.solve();
  REQUIRE(sb.is_converged());
  CHECK(a.states() == b.states());
  const double diff = (a.displacement() - b.displacement()).norm() / a.displacement().norm();
  std::cout << "[mechanics] 50 breaks: |u_cholmod - u_pcg|/|u| = " << diff << ", detached " << a.n_detached_particles()
            << ", factorisations " << a.solver().report().n_factorizations << "\n";
  // Error bound cond * PCG residual: cond ~ 2e4 at N = 2000 (measured in test_spd_solver), tolerance 1e-12.
  CHECK(diff < 1e-7);
}

TEST_CASE("A particle or cluster that loses its anchoring is frozen rigidly, not left singular", "[lattice2d]") {
  const Lattice l = annulus(2000);
  BoundaryConditions bc;
  bc.outer = BoundarySupport::fixed;
  bc.inner_pressure = 1e-3;
  BeamMechanics m(l, BeamParameters{}, bc);
  REQUIRE(m.solve().is_converged());
  // An interior particle near r = 0.5: break all its beams.
  int p = 0;
  double best = 1e9;
  for (int q = 0; q < l.n_particles(); ++q)
    if (std::abs(l.points.col(q).norm() - 0.5) < best) {
      best = std::abs(l.points.col(q).norm() - 0.5);
      p = q;
    }
  std::vector<int> ring;  // its beams
  for (int e = 0; e < l.n_beams(); ++e)
    if (l.beams[static_cast<std::size_t>(e)][0] == p || l.beams[static_cast<std::size_t>(e)][1] == p) ring.push_back(e);
  for (int e : ring) m.break_beam(e);
  CHECK(m.detached_particles()[static_cast<std::size_t>(p)]);
  CHECK(m.n_detached_particles() == 1);
  MechanicsSummary s = m.solve();
  REQUIRE(s.is_converged());
  CHECK(s.equilibrium_residual < 1e-10);  // round-off, as above
  CHECK(m.displacement().allFinite());
  for (int e : ring) CHECK(m.beam_forces()[static_cast<std::size_t>(e)].force_on_i.norm() == 0.0);

  SECTION("breaks after the re-assembly (fewer free DOFs) still update the factor, not rebuild it") {
    const int factorisations = m.solver().report().n_factorizations;
    int broken = 0;
    for (int e = 0; e < l.n_beams() && broken < 5; e += 97) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      if (i == p || j == p || l.boundary[i] != BoundaryTag::interior || l.boundary[j] != BoundaryTag::interior)
        continue;
      m.break_beam(e);
      ++broken;
      REQUIRE(m.solve().is_converged());  // the forward solution exists again before the next break
    }
    REQUIRE(broken == 5);
    INFO(m.solver().report().last_update_failure);
    CHECK(m.solver().report().n_update_failures == 0);
    CHECK(m.n_detached_particles() == 1);  // no break above detached anything: no re-assembly
    CHECK(m.solver().report().n_factorizations == factorisations);
  }
  SECTION("a fixed boundary particle with no intact beam left: its free rotation would be singular") {
    int b = 0;
    while (l.boundary[static_cast<std::size_t>(b)] != BoundaryTag::outer) ++b;
    const int before = m.n_detached_particles();
    for (int e = 0; e < l.n_beams(); ++e)
      if (l.beams[static_cast<std::size_t>(e)][0] == b || l.beams[static_cast<std::size_t>(e)][1] == b) m.break_beam(e);
    CHECK(m.detached_particles()[static_cast<std::size_t>(b)]);
    CHECK(m.n_detached_particles() == before + 1);
    CHECK(m.held_dofs()[static_cast<std::size_t>(3 * b + 2)]);
    REQUIRE(m.solve().is_converged());
    CHECK(m.displacement().allFinite());
  }
  SECTION("a cluster: the particle's neighbours with it, cut off by breaking the beams around them") {
    std::vector<char> in(static_cast<std::size_t>(l.n_particles()), 0);
    int q = -1;  // a neighbour of p
    for (int e : ring)
      q = l.beams[static_cast<std::size_t>(e)][0] == p ? l.beams[static_cast<std::size_t>(e)][1]
                                                       : l.beams[static_cast<std::size_t>(e)][0];
    // Cluster {q and its neighbours except p}: break every beam leaving it.
    in[static_cast<std::size_t>(q)] = 1;
    for (int e = 0; e < l.n_beams(); ++e) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      if (i == q && j != p) in[static_cast<std::size_t>(j)] = 1;
      if (j == q && i != p) in[static_cast<std::size_t>(i)] = 1;
    }
    int n_cluster = 0;
    for (char c : in) n_cluster += c;
    for (int e = 0; e < l.n_beams(); ++e) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      if (in[static_cast<std::size_t>(i)] != in[static_cast<std::size_t>(j)]) m.break_beam(e);
    }
    CHECK(m.n_detached_particles() == 1 + n_cluster);
    s = m.solve();
    REQUIRE(s.is_converged());
    CHECK(s.equilibrium_residual < 1e-10);  // round-off, as above
    // The frozen cluster moves rigidly: its intact beams carry no force.
    const auto forces = m.beam_forces();
    double f_cluster = 0.0;
    for (int e = 0; e < l.n_beams(); ++e) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      if (in[static_cast<std::size_t>(i)] && in[static_cast<std::size_t>(j)])
        f_cluster = std::max(f_cluster, forces[static_cast<std::size_t>(e)].force_on_i.norm());
    }
    CHECK(f_cluster < 1e-15);  // round-off of 1e-3-scale displacements
  }
}

TEST_CASE("At N = 1e5, twenty breaks with factor downdates keep every solve in equilibrium", "[lattice2d][slow]") {
  const Lattice l = annulus(100000, 1);
  BoundaryConditions bc;
  bc.outer = BoundarySupport::fixed;
  bc.inner_pressure = 1e-3;
  BeamMechanics m(l, BeamParameters{}, bc);
  REQUIRE(m.solve().is_converged());
  // Beams at the borehole wall, where the first breaks happen: adjacent ones, so contacts and a crack form.
  std::vector<int> wall;
  for (int e = 0; e < l.n_beams() && wall.size() < 20; ++e) {
    const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
    if (l.points.col(i).norm() < 0.16 && l.points(0, i) > 0.0 && std::abs(l.direction(1, e)) > 0.7) wall.push_back(e);
  }
  double worst = 0.0, slowest = 0.0;
  for (int e : wall) {
    m.break_beam(e);
    const MechanicsSummary s = m.solve();
    REQUIRE(s.is_converged());
    worst = std::max(worst, s.equilibrium_residual);
    slowest = std::max(slowest, s.solve_seconds);
  }
  std::cout << "[mechanics] N = 1e5, " << wall.size() << " breaks: worst equilibrium residual " << worst
            << ", slowest solve " << slowest << " s, factorisations " << m.solver().report().n_factorizations << "\n";
  // The equilibrium residual re-evaluates every beam from its state, independently of the modified
  // factor; round-off of the solve (cond grows like N: ~1e6 here) times the 1e-3 load scale.
  CHECK(worst < 1e-9);
}

TEST_CASE("Pure traction: a pinned particle that loses its last intact beam hands the pin on, not singular",
          "[lattice2d]") {
  // The automatic pin sits at the particle nearest the centroid: on an annulus, a borehole-wall particle,
  // where fluid-driven fractures start (Fig. 12 at N = 600 broke all five beams of its pin in the first
  // step). Springs and contacts carry no moment and all point at the pin, so the rest of the lattice
  // could turn about it for free; without springs the detachment search froze the whole body.
  const Lattice l = annulus(2000);
  BoundaryConditions bc;
  bc.inner_pressure = 1e-3;  // outer free: pure traction, pinned automatically
  auto break_pin = [&](BeamMechanics& m) {
    const int pin = m.pinned_particle();
    for (int e = 0; e < l.n_beams(); ++e)
      if (l.beams[static_cast<std::size_t>(e)][0] == pin || l.beams[static_cast<std::size_t>(e)][1] == pin)
        m.break_beam(e);
    return pin;
  };
  auto check_new_pin = [&](const BeamMechanics& m, int old_pin) {
    REQUIRE(m.is_pinned());
    const int pin = m.pinned_particle();
    CHECK(pin != old_pin);
    CHECK_FALSE(m.detached_particles()[static_cast<std::size_t>(pin)]);
    for (int k = 0; k < 3; ++k) CHECK(m.held_dofs()[static_cast<std::size_t>(3 * pin + k)]);
  };
  // The wall moves outward and the new pin carries no more than the loads lost on frozen particles
  // (the boundary pressure is self-equilibrated): it is a gauge.
  auto check_solution = [&](const BeamMechanics& m, const MechanicsSummary& s, int old_pin) {
    REQUIRE(s.is_converged());
    CHECK(s.equilibrium_residual < 1e-10);  // round-off, as above
    CHECK(m.displacement().allFinite());
    double ur_min = INFINITY;
    for (int p = 0; p < l.n_particles(); ++p)
      if (p != old_pin && l.boundary[static_cast<std::size_t>(p)] == BoundaryTag::inner)
        ur_min = std::min(ur_min, l.points.col(p).normalized().dot(m.displacement().segment<2>(3 * p)));
    CHECK(ur_min > 0.0);
    const double f_max = m.loads().cwiseAbs().maxCoeff();
    const Eigen::VectorXd r = m.reactions();
    Eigen::Vector2d resultant = r.segment<2>(3 * m.pinned_particle());
    if (m.detached_particles()[static_cast<std::size_t>(old_pin)]) resultant += r.segment<2>(3 * old_pin);
    CHECK(resultant.cwiseAbs().maxCoeff() < 1e-10 * f_max);  // round-off x cond
  };
  SECTION("dry lattice: only the old pin is loose (frozen), the body keeps deforming") {
    BeamMechanics m(l, BeamParameters{}, bc);
    REQUIRE(m.solve().is_converged());
    const int old_pin = break_pin(m);
    check_new_pin(m, old_pin);
    CHECK(m.detached_particles()[static_cast<std::size_t>(old_pin)]);
    CHECK(m.n_detached_particles() == 1);  // was n - 1: the whole body frozen, the pin left as "the" body
    check_solution(m, m.solve(), old_pin);
  }
  SECTION("with the undrained split's normal springs: the old pin hangs on its springs, rotation held") {
    BeamMechanics m(l, BeamParameters{}, bc);
    m.set_normal_springs(Eigen::VectorXd::Constant(l.n_beams(), 0.05));  // ~ Psi xi b^2 (M/E) d/L of Fig. 12
    REQUIRE(m.solve().is_converged());
    const int old_pin = break_pin(m);
    check_new_pin(m, old_pin);
    CHECK(m.n_detached_particles() == 0);
    CHECK_FALSE(m.held_dofs()[static_cast<std::size_t>(3 * old_pin)]);
    CHECK_FALSE(m.held_dofs()[static_cast<std::size_t>(3 * old_pin + 1)]);
    CHECK(m.held_dofs()[static_cast<std::size_t>(3 * old_pin + 2)]);
    check_solution(m, m.solve(), old_pin);  // was: LDL' pivot ~1e-16, the body's rotation about the old pin
  }
}

TEST_CASE("Contacts switched one at a time reach the active set that switching all at once reaches", "[lattice2d]") {
  // A zig-zag crack, pressed shut by the outer pressure and pushed open by a pressure on its faces, with
  // softened beams beside it: some faces close, some open, some softened beams close. The contact
  // problem is convex (compression-only springs and closing softened springs on a positive definite
  // lattice), so its solution is unique: one switch per iteration (contact_switches_at_once = 0, the
  // fallback against cycling) must end where all-at-once ends.
  const Lattice l = rectangle();
  const DualGraph dual = build_dual_graph(l);
  std::vector<int> crack = beams_crossing_segment(l, {-0.3, -0.1}, {0.0, 0.1});
  for (int e : beams_crossing_segment(l, {0.0, 0.1}, {0.3, -0.05})) crack.push_back(e);
  std::sort(crack.begin(), crack.end());
  crack.erase(std::unique(crack.begin(), crack.end()), crack.end());
  REQUIRE(crack.size() >= 10);
  const std::vector<int> beside = beams_crossing_segment(l, {0.3, -0.05}, {0.45, -0.2});  // the tip's process zone
  REQUIRE(beside.size() >= 2);
  BoundaryConditions bc;
  bc.outer_pressure = 1e-4;
  struct Solved {
    std::vector<BeamState> states;
    std::vector<bool> closed;  // of the softened beams beside the tip
    Eigen::VectorXd displacement;
    int iterations = 0;
  };
  const auto solve = [&](int at_once) {
    MechanicsOptions options;
    options.contact_switches_at_once = at_once;
    options.max_contact_iterations = 400;
    BeamMechanics m(l, BeamParameters{}, bc, options);
    for (int e : crack) m.break_beam(e);
    for (int e : beside) m.soften_beam(e, 0.25);
    // Faces pressed unevenly: a pressure rising along the crack from 0 to 3 times the outer pressure.
    std::vector<double> weights;
    for (int e : crack) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      weights.push_back(1.5 * (1.0 + (l.points(0, i) + l.points(0, j)) / 0.6));
    }
    m.set_external_forces(crack_face_forces(l, dual, crack, 2e-4, weights));
    const MechanicsSummary s = m.solve();
    REQUIRE(s.is_converged());
    CHECK(s.equilibrium_residual < 1e-10);
    Solved out{m.states(), {}, m.displacement(), s.contact_iterations};
    for (int e : beside) out.closed.push_back(m.is_closed(e));
    return out;
  };
  const Solved all = solve(10), one = solve(0);
  int contacts = 0, open = 0;
  for (int e : crack) (all.states[static_cast<std::size_t>(e)] == BeamState::contact ? contacts : open)++;
  INFO("contacts " << contacts << ", open " << open << "; iterations " << all.iterations << " at once, "
                   << one.iterations << " one by one");
  CHECK(contacts > 0);
  CHECK(open > 0);  // both kinds, or the test would not switch anything
  CHECK(one.states == all.states);
  CHECK(one.closed == all.closed);
  CHECK(one.iterations >= all.iterations);
  // Same active set, same linear system: the same displacement to the factor updates' round-off.
  CHECK((one.displacement - all.displacement).cwiseAbs().maxCoeff() <= 1e-9 * all.displacement.cwiseAbs().maxCoeff());
}
