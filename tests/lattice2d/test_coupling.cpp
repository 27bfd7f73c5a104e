#include <catch2/catch.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/coupled/coupling.hpp"
#include "hm/lattice2d/flow/flow_network.hpp"
#include "hm/lattice2d/fracture/notch.hpp"
#include "hm/lattice2d/linalg/spd_solver.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::make_lattice;

namespace {

// A disk of 3000 particles cut along y = 0, |x| < 0.8: the cut beams have crack weight 1.
struct StraightCut {
  Lattice lattice = make_lattice(DomainShape::disk, 3000);
  DualGraph dual = build_dual_graph(lattice);
  std::vector<int> beams = beams_crossing(lattice, NotchSegment{{-0.8, 0.0}, {0.8, 0.0}});
  Eigen::VectorXd weight = weights_of(lattice, beams);

  static Eigen::VectorXd weights_of(const Lattice& lattice, const std::vector<int>& beams) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(lattice.n_beams());
    for (const int e : beams) w[e] = 1.0;
    return w;
  }
  // The half above moved by `jump`, and the whole disk moved rigidly (a translation and a rotation
  // omega, the particles turning with it), which opens and slides no facet.
  Eigen::VectorXd moved_by(const Eigen::Vector2d& jump) const {
    const double omega = 2e-4;
    Eigen::VectorXd u(3 * lattice.n_particles());
    for (int i = 0; i < lattice.n_particles(); ++i) {
      const Eigen::Vector2d x = lattice.points.col(i);
      const Eigen::Vector2d above = x.y() > 0.0 ? jump : Eigen::Vector2d::Zero();
      u.segment<3>(3 * i) << 3e-4 - omega * x.y() + above.x(), -1e-4 + omega * x.x() + above.y(), omega;
    }
    return u;
  }
};

// Net pressure force on particle i against the continuum body force -xi b V_i grad p.
struct GradientError {
  double max_relative = 0.0;   // max_i |F_i + b V_i g| / (b V_i |g|)
  double mean_relative = 0.0;  // sum_i |F_i + b V_i g| / sum_i b V_i |g|
  double sum_relative = 0.0;   // |sum_i (F_i + b V_i g)| / sum_i b V_i |g|  (the global balance)
};

GradientError gradient_force_error(const Lattice& lattice, const DualGraph& dual, const Eigen::Matrix2Xd& sample_points,
                                   const Eigen::Vector2d& g, double b, const CouplingTerms& terms = {}) {
  Eigen::VectorXd p(lattice.n_triangles());
  for (int s = 0; s < lattice.n_triangles(); ++s) p[s] = 0.3 + g.dot(sample_points.col(s));
  const Eigen::VectorXd f = pressure_forces(lattice, dual, p, b, terms);
  GradientError out;
  double num = 0.0, den = 0.0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int i = 0; i < lattice.n_particles(); ++i) {
    if (lattice.boundary[static_cast<std::size_t>(i)] != BoundaryTag::interior) continue;
    const Eigen::Vector2d body = -terms.xi * b * dual.particle_area[i] * g;
    const Eigen::Vector2d err = Eigen::Vector2d(f[dof_index(i, 0)], f[dof_index(i, 1)]) - body;
    out.max_relative = std::max(out.max_relative, err.norm() / body.norm());
    num += err.norm();
    den += body.norm();
    sum += err;
  }
  out.mean_relative = num / den;
  out.sum_relative = sum.norm() / den;
  return out;
}

}  // namespace

TEST_CASE("The default coupling parameters are valid and each bad value is rejected", "[lattice2d]") {
  // xi and Psi are the coupling terms' own; b and E/M are the material's, validated with the flow.
  CouplingTerms cp;
  FlowParameters material;
  REQUIRE_NOTHROW(cp.validate());
  REQUIRE_NOTHROW(material.validate());
  SECTION("b") {
    material.b = 1.5;
    REQUIRE_THROWS_AS(material.validate(), hm::InputError);
  }
  SECTION("xi") {
    cp.xi = 0.0;
    REQUIRE_THROWS_AS(cp.validate(), hm::InputError);
  }
  SECTION("psi") {
    cp.psi = -1.0;
    REQUIRE_THROWS_AS(cp.validate(), hm::InputError);
  }
  SECTION("E_over_M") {
    material.E_over_M = 0.0;
    REQUIRE_THROWS_AS(material.validate(), hm::InputError);
  }
}

TEST_CASE("A linear pressure at the dual points gives the continuum body force -b V_i grad p on interior particles",
          "[lattice2d]") {
  // By the divergence theorem on the closed Voronoi cell of an interior particle, sum_st d_st p_st n_ij
  // = integral of p n over the cell boundary = V_i grad p when p_st is p at the segment midpoint, which
  // the mean of two dual-point values is for a linear p. So xi = 1 holds to round-off.
  const double b = 0.7;
  for (long long n : {2000LL, 8000LL, 32000LL}) {
    const Lattice lattice = make_lattice(DomainShape::disk, n);
    const DualGraph dual = build_dual_graph(lattice);
    for (const Eigen::Vector2d& g : {Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(-0.4, 2.5)}) {
      const GradientError e = gradient_force_error(lattice, dual, dual.dual_point, g, b);
      std::printf("dual-point sampling, N = %lld: max %.3g, mean %.3g\n", n, e.max_relative, e.mean_relative);
      // Round-off: the net force b V_i |g| ~ b h^2 is a cancellation of six terms ~ b h |p|, so the
      // relative error is ~ 1e-16 |p| / (h |g|), measured <= 2e-12 up to N = 32000 (h ~ 0.01).
      CHECK(e.max_relative < 1e-10);
    }
  }
}

TEST_CASE(
    "A linear pressure at the triangle centroids gives the body force on average, with a per-particle error "
    "that does not vanish on a random lattice",
    "[lattice2d]") {
  // Centroid sampling puts p_st at the mean of two centroids instead of the segment midpoint, an O(h)
  // offset, so each particle's force is off by O(h^2 |g|), the size of the force itself: O(1) relative
  // per particle, cancelling over many particles. Measured (seed 1, g = (1, 0)):
  //   N = 2000: max 0.54, mean 0.128, global 2.0e-3;  N = 8000: max 0.63, mean 0.127, global 9.5e-4;
  //   N = 32000: max 0.53, mean 0.126, global 4.9e-4 (first order in h ~ N^-1/2).
  // This is why the pressures live at the dual points (Section 2.2, "the Voronoi connection point").
  double previous_sum = 1.0;
  for (long long n : {2000LL, 8000LL, 32000LL}) {
    const Lattice lattice = make_lattice(DomainShape::disk, n);
    const DualGraph dual = build_dual_graph(lattice);
    const GradientError e = gradient_force_error(lattice, dual, dual.centroid, Eigen::Vector2d(1.0, 0.0), 0.5);
    std::printf("centroid sampling, N = %lld: max %.3g, mean %.3g, global %.3g\n", n, e.max_relative, e.mean_relative,
                e.sum_relative);
    CHECK(e.mean_relative < 0.2);          // the O(1) per-particle scatter, measured 0.13
    CHECK(e.sum_relative < previous_sum);  // the global balance improves with N
    previous_sum = e.sum_relative;
  }
}

TEST_CASE("A uniform pressure gives zero net force on every interior particle", "[lattice2d]") {
  for (DomainShape shape : {DomainShape::disk, DomainShape::annulus}) {
    const Lattice lattice = make_lattice(shape, 2000);
    const DualGraph dual = build_dual_graph(lattice);
    const bool annulus = shape == DomainShape::annulus;
    Eigen::VectorXd p = Eigen::VectorXd::Constant(lattice.n_triangles() + (annulus ? 1 : 0), 0.25);
    const Eigen::VectorXd f = pressure_forces(lattice, dual, p, 0.5, CouplingTerms{});
    double max_interior = 0.0;
    for (int i = 0; i < lattice.n_particles(); ++i)
      if (lattice.boundary[static_cast<std::size_t>(i)] == BoundaryTag::interior)
        max_interior = std::max(max_interior, std::hypot(f[dof_index(i, 0)], f[dof_index(i, 1)]));
    // Round-off of six terms b d p ~ 0.5 * 0.04 * 0.25.
    CHECK(max_interior < 1e-15);
    // Rotational components are never loaded.
    for (int i = 0; i < lattice.n_particles(); ++i) CHECK(f[dof_index(i, 2)] == 0.0);
  }
}

TEST_CASE("With the wall traction, a uniform pressure in an annulus and its borehole pushes the wall with (1 - b) p",
          "[lattice2d]") {
  // Continuum: total stress sigma = sigma' - b p I equals -p on the wall, so the skeleton feels (1 - b) p.
  // Discretely: the open boundary cells carry -b p times the missing facet, the wall traction +p.
  const Lattice lattice = make_lattice(DomainShape::annulus, 2000);
  const DualGraph dual = build_dual_graph(lattice);
  const double b = 0.6;
  const double p = 0.1;
  const Eigen::VectorXd f =
      pressure_forces(lattice, dual, Eigen::VectorXd::Constant(lattice.n_triangles() + 1, p), b, CouplingTerms{});
  // Sum of the radial force over the wall particles = (1 - b) p times the wall polygon's perimeter.
  double radial = 0.0, perimeter = 0.0;
  for (int i = 0; i < lattice.n_particles(); ++i)
    if (lattice.boundary[static_cast<std::size_t>(i)] == BoundaryTag::inner) {
      const Eigen::Vector2d r = lattice.points.col(i).normalized();
      radial += r.x() * f[dof_index(i, 0)] + r.y() * f[dof_index(i, 1)];
    }
  // Each chord's push (1 - b) p L, half at each end, leans from the end's radius by half the chord's
  // angle phi, sin(phi/2) = L / (2 R_i): the radial sum is (1 - b) p sum L cos(phi/2) (~1% below
  // (1 - b) p sum L at N = 2000), exact up to round-off and the wall particles' placement on the circle.
  for (int e = 0; e < lattice.n_beams(); ++e)
    if (lattice.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::inner) {
      const double half_chord = lattice.length[e] / (2.0 * lattice.spec.inner_radius);
      perimeter += lattice.length[e] * std::sqrt(1.0 - half_chord * half_chord);
    }
  CHECK(radial == Approx((1.0 - b) * p * perimeter).epsilon(1e-9));
}

TEST_CASE("The undrained spring is Psi xi b^2 (M/E) d_st/L_ij per beam and zero for the drained split", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 1000);
  const DualGraph dual = build_dual_graph(lattice);
  CouplingTerms cp;
  cp.psi = 2.0;
  cp.xi = 1.5;
  const double b = 0.4, E_over_M = 0.8;
  const Eigen::VectorXd k = undrained_spring_stiffness(lattice, dual, b, E_over_M, cp);
  for (int e = 0; e < lattice.n_beams(); e += 17)
    CHECK(k[e] == hm::test::roundoff(2.0 * 1.5 * 0.16 / 0.8 * std::max(dual.dual_length[e], 0.0) / lattice.length[e]));
  CHECK(k.minCoeff() >= 0.0);
  cp.psi = 0.0;
  CHECK(undrained_spring_stiffness(lattice, dual, b, E_over_M, cp).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("Springs relaxed at the drained solution leave it unchanged: (K + K_psi) u = f + K_psi u_drained",
          "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 1500);
  const DualGraph dual = build_dual_graph(lattice);
  CouplingTerms cp;
  cp.psi = 1.3;
  const double b = 0.5, E_over_M = 0.75;
  // A pressure bump around the centre.
  Eigen::VectorXd p(lattice.n_triangles());
  for (int s = 0; s < lattice.n_triangles(); ++s) p[s] = 1e-3 * std::exp(-dual.dual_point.col(s).squaredNorm() / 0.05);
  const Eigen::VectorXd f = pressure_forces(lattice, dual, p, b, cp);

  BeamMechanics drained(lattice, BeamParameters{}, BoundaryConditions{});
  drained.set_external_forces(f);
  REQUIRE(drained.solve().is_converged());
  const Eigen::VectorXd u_drained = drained.displacement();

  BeamMechanics undrained(lattice, BeamParameters{}, BoundaryConditions{});
  const Eigen::VectorXd k = undrained_spring_stiffness(lattice, dual, b, E_over_M, cp);
  undrained.set_normal_springs(k);
  SECTION("relaxed at the drained solution: the same solution") {
    undrained.set_external_forces(f + spring_preload(lattice, k, u_drained));
    const MechanicsSummary summary = undrained.solve();
    REQUIRE(summary.is_converged());
    CHECK(summary.equilibrium_residual < 1e-10);  // the residual includes the springs: round-off
    // Round-off of two factorisations relative to max |u|.
    CHECK((undrained.displacement() - u_drained).cwiseAbs().maxCoeff() < 1e-10 * u_drained.cwiseAbs().maxCoeff());
  }
  SECTION("relaxed at zero: a stiffer response") {
    undrained.set_external_forces(f);
    REQUIRE(undrained.solve().is_converged());
    const Eigen::VectorXd u = undrained.displacement();
    CHECK(u.cwiseAbs().maxCoeff() < u_drained.cwiseAbs().maxCoeff());
    CHECK(u.cwiseAbs().maxCoeff() > 0.1 * u_drained.cwiseAbs().maxCoeff());
  }
  SECTION("a dropped spring goes with its beam: the downdated factor solves as one assembled without it") {
    // Five beams near the centre, where the pressure bump loads the lattice.
    std::vector<int> cut;
    for (int e = 0; e < lattice.n_beams() && cut.size() < 5; ++e)
      if (lattice.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::interior &&
          0.5 * (lattice.points.col(lattice.beams[static_cast<std::size_t>(e)][0]) +
                 lattice.points.col(lattice.beams[static_cast<std::size_t>(e)][1]))
                      .norm() <
              0.1)
        cut.push_back(e);
    REQUIRE(cut.size() == 5);
    BeamMechanics dropping(lattice, BeamParameters{}, BoundaryConditions{});
    dropping.set_normal_springs(k, BrokenBeamSpring::drop);
    dropping.set_external_forces(f);
    REQUIRE(dropping.solve().is_converged());
    for (int e : cut) dropping.break_beam(e);
    REQUIRE(dropping.solve().is_converged());
    // Broken first, springs set afterwards: assembled and factorised afresh without the five springs.
    BeamMechanics assembled(lattice, BeamParameters{}, BoundaryConditions{});
    assembled.set_external_forces(f);
    for (int e : cut) assembled.break_beam(e);
    assembled.set_normal_springs(k, BrokenBeamSpring::drop);
    REQUIRE(assembled.solve().is_converged());
    for (int e : cut) CHECK(dropping.normal_springs()[e] == 0.0);
    CHECK(dropping.normal_springs() == assembled.normal_springs());
    const double scale = assembled.displacement().cwiseAbs().maxCoeff();
    // Round-off of a rank-1 downdate against a fresh factorisation, relative to max |u|.
    CHECK((dropping.displacement() - assembled.displacement()).cwiseAbs().maxCoeff() < 1e-10 * scale);
    // Kept springs hold the cut closer: a different displacement, by far more than round-off.
    undrained.set_external_forces(f);
    REQUIRE(undrained.solve().is_converged());
    for (int e : cut) undrained.break_beam(e);
    REQUIRE(undrained.solve().is_converged());
    CHECK(undrained.normal_springs() == k);
    CHECK((undrained.displacement() - assembled.displacement()).cwiseAbs().maxCoeff() > 1e-4 * scale);
  }
  SECTION("bad springs are rejected") {
    Eigen::VectorXd bad = k;
    bad[3] = -1.0;
    REQUIRE_THROWS_AS(undrained.set_normal_springs(bad), hm::InputError);
    REQUIRE_THROWS_AS(undrained.set_normal_springs(Eigen::VectorXd::Zero(5)), hm::InputError);
  }
}

TEST_CASE("Timing: the Eq. 20 springs by refactorisation against a rank-n_beams CHOLMOD update", "[lattice2d][slow]") {
  // The measurement behind docs/coupling.md, section 2 ("Implementation"). Prints, asserts only that
  // both routes give the same matrix.
  const Lattice lattice = make_lattice(DomainShape::disk, 10000);
  const DualGraph dual = build_dual_graph(lattice);
  const BeamMechanics mechanics(lattice, BeamParameters{}, BoundaryConditions{});
  const Eigen::VectorXd k = undrained_spring_stiffness(lattice, dual, 0.5, 0.75, CouplingTerms{});
  std::vector<int> free_index(static_cast<std::size_t>(3 * lattice.n_particles()), -1);
  int n_free = 0;
  for (std::size_t d = 0; d < free_index.size(); ++d)
    if (!mechanics.held_dofs()[d]) free_index[d] = n_free++;
  std::vector<Eigen::Triplet<double>> w;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const Eigen::Vector2d n = lattice.direction.col(e);
    const double s = std::sqrt(k[e]);
    const std::array<std::pair<int, double>, 4> entries = {std::pair{dof_index(i, 0), -s * n.x()},
                                                           {dof_index(i, 1), -s * n.y()},
                                                           {dof_index(j, 0), s * n.x()},
                                                           {dof_index(j, 1), s * n.y()}};
    for (const auto& [dof, value] : entries)
      if (free_index[static_cast<std::size_t>(dof)] >= 0)
        w.emplace_back(free_index[static_cast<std::size_t>(dof)], e, value);
  }
  SpdSolver::Matrix W(n_free, lattice.n_beams());
  W.setFromTriplets(w.begin(), w.end());
  const SpdSolver::Matrix A = mechanics.solver().matrix();
  auto seconds = [](auto&& f) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  CholmodSolver refactor, update;
  const SpdSolver::Matrix AW = A + SpdSolver::Matrix(W * W.transpose());
  const double t_factor = seconds([&] { refactor.compute(AW); });
  update.compute(A);
  const double t_update = seconds([&] { update.modify(W, 1); });
  std::printf("N = 1e4: springs by a new factorisation %.3f s, by a rank-%d update %.3f s\n", t_factor,
              lattice.n_beams(), t_update);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n_free);
  const Eigen::VectorXd x1 = refactor.solve(b), x2 = update.solve(b);
  CHECK((x1 - x2).cwiseAbs().maxCoeff() < 1e-8 * x1.cwiseAbs().maxCoeff());
}

TEST_CASE("Crack faces flagged for the full pressure carry (1 - b) p more than Eq. 17's b p", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 1500);
  const DualGraph dual = build_dual_graph(lattice);
  const double b = 0.2, p = 3e-4;
  const Eigen::VectorXd uniform = Eigen::VectorXd::Constant(lattice.n_triangles(), p);
  int e = 0;  // an interior beam
  while (lattice.beam_boundary[static_cast<std::size_t>(e)] != BoundaryTag::interior) ++e;
  Eigen::VectorXd flags = Eigen::VectorXd::Zero(lattice.n_beams());
  flags[e] = 1.0;
  const Eigen::VectorXd rock = pressure_forces(lattice, dual, uniform, b, CouplingTerms{});
  const Eigen::VectorXd crack = pressure_forces(lattice, dual, uniform, b, CouplingTerms{}, flags);
  // Only the flagged segment changes: by -(1 - b) d p n on i and the opposite on j.
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
  const Eigen::Vector2d extra = -(1.0 - b) * dual.dual_length[e] * p * lattice.direction.col(e);
  Eigen::VectorXd expected = rock;
  expected.segment<2>(3 * i) += extra;
  expected.segment<2>(3 * j) -= extra;
  CHECK((crack - expected).cwiseAbs().maxCoeff() < 1e-15 * p);  // a few round-offs of p d
  CHECK(extra.norm() > 0.1 * p * dual.dual_length[e]);
  // No flags: Eq. 17 as printed, bit for bit.
  CHECK(pressure_forces(lattice, dual, uniform, b, CouplingTerms{}, Eigen::VectorXd::Zero(flags.size())) == rock);
  // A softening facet of damage w: the share b + (1 - b) w, continuous between the rock's and the crack's.
  flags[e] = 0.25;
  const Eigen::VectorXd softening = pressure_forces(lattice, dual, uniform, b, CouplingTerms{}, flags);
  CHECK((softening - rock - 0.25 * (crack - rock)).cwiseAbs().maxCoeff() < 1e-15 * p);
}

TEST_CASE("A crack's opening volume is work-conjugate to the full pressure on its faces", "[lattice2d]") {
  // sum_s p_s V_s(u) = f(p) . u for pressures on the crack's triangles (b = 0: only the broken faces are
  // pushed), whatever u: the flow charges the crack the volume the mechanics' forces open.
  const Lattice lattice = make_lattice(DomainShape::disk, 1500);
  const DualGraph dual = build_dual_graph(lattice);
  // Broken beams (weight 1), softening ones (damage between 0 and 1) and rock; boundary beams too.
  Eigen::VectorXd broken = Eigen::VectorXd::Zero(lattice.n_beams());
  for (int e = 0; e < lattice.n_beams(); e += 7) broken[e] = 1.0;
  for (int e = 3; e < lattice.n_beams(); e += 11) broken[e] = 0.5 + 0.4 * std::sin(e);
  const Eigen::VectorXd u = Eigen::VectorXd::Random(3 * lattice.n_particles()) * 1e-3;
  const Eigen::VectorXd p = Eigen::VectorXd::Random(lattice.n_triangles()) * 1e-4;
  const Eigen::VectorXd f = pressure_forces(lattice, dual, p, 0.0, CouplingTerms{}, broken);
  const Eigen::VectorXd volumes = crack_opening_volumes(lattice, dual, broken, u);
  // The forces push the faces apart (-p d n on i, +p d n on j): their work is f . u.
  const double work = f.dot(u), scale = p.cwiseAbs().dot(volumes.cwiseAbs());
  CHECK(std::abs(p.dot(volumes) - work) < 1e-13 * scale);  // a sum of ~1e4 products: round-off
  CHECK(scale > 0.0);
  // One beam opened by w: its two triangles hold w d / 2 each (an interior beam).
  int e = 0;
  while (lattice.beam_boundary[static_cast<std::size_t>(e)] != BoundaryTag::interior) ++e;
  Eigen::VectorXd one = Eigen::VectorXd::Zero(lattice.n_beams());
  one[e] = 1.0;
  Eigen::VectorXd opened = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
  opened.segment<2>(3 * j) = 2e-4 * lattice.direction.col(e);
  const Eigen::VectorXd v = crack_opening_volumes(lattice, dual, one, opened);
  for (const int t : lattice.beam_triangles[static_cast<std::size_t>(e)])
    CHECK(v[t] == Approx(0.5 * 2e-4 * dual.dual_length[e]).epsilon(1e-14));
  CHECK(v.cwiseAbs().sum() == Approx(2e-4 * dual.dual_length[e]).epsilon(1e-14));
  // Opening it sideways (along the facet) holds no fluid.
  opened.segment<2>(3 * j) = 2e-4 * Eigen::Vector2d(-lattice.direction(1, e), lattice.direction(0, e));
  opened.segment<2>(3 * i) = opened.segment<2>(3 * j);
  CHECK(crack_opening_volumes(lattice, dual, one, opened).cwiseAbs().maxCoeff() < 1e-20);
}

TEST_CASE("A straight cut opened by w: each open facet's jump is w, its axial opening w cos(theta)", "[lattice2d]") {
  const StraightCut straight;
  const auto& [lattice, dual, cut, weight] = straight;
  REQUIRE(cut.size() > 80);
  const double w = 1e-3;
  const auto opened_by = [&](double opening) { return straight.moved_by({0.0, opening}); };
  const Eigen::VectorXd u = opened_by(w);
  const Eigen::VectorXd axial = crack_facet_openings(lattice, dual, weight, u, CrackAperture::axial);
  const Eigen::VectorXd jump = crack_facet_openings(lattice, dual, weight, u, CrackAperture::jump);
  double least_cosine = 1.0;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (weight[e] == 0.0) {
      CHECK(axial[e] == 0.0);
      CHECK(jump[e] == 0.0);
      continue;
    }
    const double cosine = std::abs(lattice.direction(1, e));
    least_cosine = std::min(least_cosine, cosine);
    // Differences of displacements ~1e-3 formed from terms ~1e-4 of the rigid motion: round-off ~1e-19.
    CHECK(axial[e] == Approx(w * cosine).margin(1e-17));
    // The jump's length from two components formed with that round-off: relative ~1e-16 of w, 1e-12 with room.
    CHECK(jump[e] == Approx(w).epsilon(1e-12));
  }
  // The cut has facets far from normal to the opening, where the two definitions differ most.
  CHECK(least_cosine < 0.3);
  // Pushed together instead, every facet is closed: both are the (negative) axial opening.
  const Eigen::VectorXd shut = opened_by(-w);
  CHECK(crack_facet_openings(lattice, dual, weight, shut, CrackAperture::jump) ==
        crack_facet_openings(lattice, dual, weight, shut, CrackAperture::axial));
  const Eigen::VectorXd shut_axial = crack_facet_openings(lattice, dual, weight, shut, CrackAperture::axial);
  for (const int e : cut) CHECK(shut_axial[e] == Approx(-w * std::abs(lattice.direction(1, e))).margin(1e-17));
}

TEST_CASE(
    "A straight cut's local crack normal leans less than its facets, its aperture is ~w opened and "
    "~the axial opening slid",
    "[lattice2d]") {
  const StraightCut straight;
  const auto& [lattice, dual, cut, weight] = straight;
  REQUIRE(cut.size() > 80);
  double facet_tilt = 0.0, crack_tilt = 0.0;
  for (const int e : cut) {
    const Eigen::Vector2d normal = local_crack_normal(lattice, dual, weight, e);
    CHECK(normal.norm() == Approx(1.0).epsilon(1e-14));
    CHECK(normal.dot(lattice.direction.col(e)) >= 0.0);
    facet_tilt += std::abs(lattice.direction(0, e));
    crack_tilt += std::abs(normal.x());
  }
  // The cut's facets lean 0.50 from its normal on average (|n_x|), the chord through three of them 0.25
  // on this lattice: a bound halfway between that and no gain.
  CHECK(crack_tilt < 0.75 * facet_tilt);
  // The half above moved by w up (opened) or along the cut (slid), the whole disk moved rigidly.
  const double w = 1e-3;
  const auto mean_over_cut = [&](const Eigen::VectorXd& a) {
    double sum = 0.0;
    for (const int e : cut) sum += a[e];
    return sum / static_cast<double>(cut.size());
  };
  const Eigen::VectorXd opened = straight.moved_by({0.0, w}), slid = straight.moved_by({w, 0.0});
  const Eigen::VectorXd a_open = crack_facet_openings(lattice, dual, weight, opened, CrackAperture::crack_normal);
  const Eigen::VectorXd axial_open = crack_facet_openings(lattice, dual, weight, opened, CrackAperture::axial);
  for (const int e : cut) {
    // The jump is w ŷ: its component along a unit normal is at most w (round-off as the jump test).
    CHECK(a_open[e] <= w * (1 + 1e-12));
    CHECK(a_open[e] >= axial_open[e]);
  }
  const Eigen::VectorXd a_slid = crack_facet_openings(lattice, dual, weight, slid, CrackAperture::crack_normal);
  const Eigen::VectorXd axial_slid = crack_facet_openings(lattice, dual, weight, slid, CrackAperture::axial);
  const Eigen::VectorXd jump_slid = crack_facet_openings(lattice, dual, weight, slid, CrackAperture::jump);
  const auto clamped_excess = [&](const Eigen::VectorXd& a) {  // mean of max(a, 0) - max(axial, 0), slid
    double sum = 0.0;
    for (const int e : cut) sum += std::max(a[e], 0.0) - std::max(axial_slid[e], 0.0);
    return sum / static_cast<double>(cut.size());
  };
  // Opened, the facets' mean aperture is 0.965 w on this lattice (the axial opening's 0.79 w); slid, it
  // exceeds the (clamped) axial opening, the zig-zag's dilation, by 0.066 w on average, the jump by 0.21 w.
  // Bounds halfway between the measured value and the other definition's.
  CHECK(mean_over_cut(a_open) > 0.9 * w);
  CHECK(mean_over_cut(axial_open) < 0.8 * w);
  CHECK(clamped_excess(a_slid) < 0.13 * w);
  CHECK(clamped_excess(jump_slid) > 0.2 * w);
  // A facet with no cracked neighbour is its own crack: its aperture is its axial opening.
  Eigen::VectorXd alone = Eigen::VectorXd::Zero(lattice.n_beams());
  alone[cut[cut.size() / 2]] = 1.0;
  const int e = cut[cut.size() / 2];
  // Its chord is its own Voronoi segment, normal to the beam to round-off.
  CHECK((local_crack_normal(lattice, dual, alone, e) - lattice.direction.col(e)).norm() < 1e-12);
  CHECK(crack_facet_openings(lattice, dual, alone, slid, CrackAperture::crack_normal)[e] ==
        Approx(axial_slid[e]).margin(1e-18));
}

TEST_CASE("The borehole's volume gradient is the wall traction per unit pressure and the wall polygon's area change",
          "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 2000);
  const DualGraph dual = build_dual_graph(lattice);
  const Eigen::VectorXd g = borehole_volume_gradient(lattice);
  // The wall traction of a unit borehole pressure with b = 0 (no Voronoi-segment forces): the same bits.
  Eigen::VectorXd unit_hole = Eigen::VectorXd::Zero(lattice.n_triangles() + 1);
  unit_hole[lattice.n_triangles()] = 1.0;
  CHECK(g == pressure_forces(lattice, dual, unit_hole, 0.0, CouplingTerms{}));
  // The area of the wall polygon (the flow's V_h) moved by eps du changes by eps g.du + O(eps^2).
  FlowParameters parameters;
  parameters.Q = 0.1;
  parameters.b = 0.5;
  FlowNetwork flow(lattice, dual, parameters);
  const double V0 = flow.borehole_volume();
  Eigen::VectorXd du = Eigen::VectorXd::Zero(g.size());
  for (int i = 0; i < lattice.n_particles(); ++i) {  // a smooth field that stretches, shears and turns the wall
    const Eigen::Vector2d x = lattice.points.col(i);
    du[dof_index(i, 0)] = 0.3 * x.x() + 0.2 * x.y() + std::sin(7.0 * x.y());
    du[dof_index(i, 1)] = -0.1 * x.x() + 0.4 * x.y() + std::cos(5.0 * x.x());
  }
  for (const double eps : {1e-4, 1e-5}) {
    Eigen::Matrix2Xd x = lattice.points;
    for (int i = 0; i < lattice.n_particles(); ++i)
      x.col(i) += eps * Eigen::Vector2d(du[dof_index(i, 0)], du[dof_index(i, 1)]);
    flow.update_geometry(build_dual_graph(lattice, x), x);
    const double dV = flow.borehole_volume() - V0;
    // The polygon's area is quadratic in the positions: the error is O(eps^2 |du|^2), here < 1e-3
    // of the first-order term at eps = 1e-4.
    CHECK(dV == Approx(eps * g.dot(du)).epsilon(10.0 * eps));
  }
  // A rigid motion leaves the hole's volume alone: g is orthogonal to translations and rotations.
  double tx = 0.0, ty = 0.0, turn = 0.0, scale = 0.0;
  for (int i = 0; i < lattice.n_particles(); ++i) {
    tx += g[dof_index(i, 0)];
    ty += g[dof_index(i, 1)];
    turn += -lattice.points(1, i) * g[dof_index(i, 0)] + lattice.points(0, i) * g[dof_index(i, 1)];
    scale += std::abs(g[dof_index(i, 0)]) + std::abs(g[dof_index(i, 1)]);
  }
  CHECK(std::abs(tx) < 1e-14 * scale);
  CHECK(std::abs(ty) < 1e-14 * scale);
  CHECK(std::abs(turn) < 1e-14 * scale);
}

TEST_CASE("The borehole's undrained spring is beta_h / s_h g g^T, and refused where the hole's volume sets no pressure",
          "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 1000);
  const RankOneStiffness spring = borehole_spring(lattice, 0.25, 0.5);
  CHECK(spring.stiffness() == 2.0);
  CHECK(spring.vector() == borehole_volume_gradient(lattice));
  REQUIRE_THROWS_WITH(borehole_spring(lattice, 0.0, 1.0),
                      Catch::Contains("coupling.borehole_spring") && Catch::Contains("borehole_storage"));
  REQUIRE_THROWS_AS(borehole_spring(lattice, 1.0, 0.0), hm::InputError);
}

TEST_CASE("A rank-1 stiffness solved by Sherman-Morrison equals the assembled matrix's solve, through breaks",
          "[lattice2d]") {
  // The annulus pressed from its borehole, with the hole's spring k g g^T (k of the order of a water-filled
  // hole's beta_h / s_h = K_w / (E V_h)), against an independent sparse LDL' of K_ff + k g_f g_f^T.
  const Lattice lattice = make_lattice(DomainShape::annulus, 1500);
  const DualGraph dual = build_dual_graph(lattice);
  const Eigen::VectorXd g = borehole_volume_gradient(lattice);
  const double k = 1.0 / (4.5 * 0.06);
  BoundaryConditions bc;
  bc.inner_pressure = 1e-4;
  bc.outer = BoundarySupport::fixed;  // no pin: the reported displacement is the solved one
  BeamMechanics mechanics(lattice, BeamParameters{}, bc);
  mechanics.set_rank_one_stiffness(RankOneStiffness(g, k));
  // K_ff + k g_f g_f^T assembled (dense) from the solver's matrix, and the displacement and the loads
  // on the free dofs: an independent check of the Sherman-Morrison solve (held dofs are at 0 here).
  const auto assembled_residual = [&] {
    std::vector<int> free;
    for (int d = 0; d < g.size(); ++d)
      if (!mechanics.held_dofs()[static_cast<std::size_t>(d)]) free.push_back(d);
    const auto n = static_cast<Eigen::Index>(free.size());
    Eigen::VectorXd gf(n), uf(n), ff(n);
    const Eigen::VectorXd f = mechanics.loads();
    for (Eigen::Index a = 0; a < n; ++a) {
      gf[a] = g[free[static_cast<std::size_t>(a)]];
      uf[a] = mechanics.displacement()[free[static_cast<std::size_t>(a)]];
      ff[a] = f[free[static_cast<std::size_t>(a)]];
    }
    const Eigen::MatrixXd A = Eigen::MatrixXd(mechanics.solver().matrix()) + k * gf * gf.transpose();
    return (A * uf - ff).cwiseAbs().maxCoeff() / ff.cwiseAbs().maxCoeff();
  };
  MechanicsSummary solved = mechanics.solve();
  REQUIRE(solved.is_converged());
  // reactions() includes the term: the free dofs balance to round-off; so does the assembled matrix.
  CHECK(solved.equilibrium_residual < 1e-10);
  CHECK(assembled_residual() < 1e-10);
  // The spring resists the hole's growth: less opening than the beams alone.
  BeamMechanics beams_only(lattice, BeamParameters{}, bc);
  REQUIRE(beams_only.solve().is_converged());
  const double opening = g.dot(mechanics.displacement()), opening_beams = g.dot(beams_only.displacement());
  CHECK(opening > 0.0);
  CHECK(opening < 0.8 * opening_beams);
  // Exactly as much less as the rank-1 term says: the hole's opening with the spring is the beams'
  // opening over 1 + k g.K^-1 g (Sherman-Morrison on g.u), to round-off.
  const Eigen::VectorXd K_inv_g = beams_only.linear_response(g);
  CHECK(opening == Approx(opening_beams / (1.0 + k * g.dot(K_inv_g))).epsilon(1e-9));
  // After breaks at the wall (the factor downdated: K^-1 g must be solved again) the same identities.
  // Hoop beams crossing y = 0 just outside the wall: in hoop tension, so they open in both models
  // (the same matrix K).
  std::vector<int> cut;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const Eigen::Vector2d mid = 0.5 * (lattice.points.col(i) + lattice.points.col(j));
    if (lattice.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::interior && mid.x() > 0.0 &&
        mid.x() < lattice.spec.inner_radius + 0.08 && std::abs(mid.y()) < 0.03 &&
        std::abs(lattice.direction(1, e)) > 0.7)
      cut.push_back(e);
  }
  REQUIRE(cut.size() >= 2);
  for (int e : cut) {
    mechanics.break_beam(e);
    beams_only.break_beam(e);
  }
  solved = mechanics.solve();
  REQUIRE(solved.is_converged());
  REQUIRE(beams_only.solve().is_converged());
  CHECK(mechanics.states() == beams_only.states());  // the same open and contact beams: the same K
  CHECK(solved.equilibrium_residual < 1e-10);
  const double opening_cut = g.dot(mechanics.displacement()), opening_beams_cut = g.dot(beams_only.displacement());
  CHECK(opening_beams_cut > opening_beams);  // the breaks soften the wall
  CHECK(opening_cut == Approx(opening_beams_cut / (1.0 + k * g.dot(beams_only.linear_response(g)))).epsilon(1e-9));
  // The kept K^-1 g was solved again for the downdated factor: the assembled matrix agrees.
  CHECK(assembled_residual() < 1e-10);
}
