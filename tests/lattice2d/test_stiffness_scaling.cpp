// Tests of the two lattice options against the dry lattice's defects (docs/lattice.md, "Stiffness
// scaling and boundary spacing: measurements"): BeamParameters::stiffness_scaling = voronoi_facet
// (k_n,ij = k_n sqrt(3) max(d/L, floor)) and LatticeSpec::boundary_spacing_factor. The comparison table
// of the docs is re-measured by studies/stiffness_scaling.cpp.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/geometry/mesh_quality.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"

using namespace hm::lattice2d;

namespace {

Lattice make_lattice(DomainShape domain, long long n, std::uint64_t seed, double boundary_factor = 1.0) {
  LatticeSpec spec;
  spec.domain = domain;
  spec.n_particles = n;
  spec.seed = seed;
  spec.boundary_spacing_factor = boundary_factor;
  return generate_lattice(spec);
}

BeamParameters facet_beams(double aspect) {
  BeamParameters p;
  p.aspect = aspect;
  p.stiffness_scaling = StiffnessScaling::voronoi_facet;
  return p;
}

double polygon_area(const Lattice& l) {
  double a = 0.0;
  for (const auto& t : l.triangles) {
    const Eigen::Vector2d u = l.points.col(t[1]) - l.points.col(t[0]), v = l.points.col(t[2]) - l.points.col(t[0]);
    a += 0.5 * (u.x() * v.y() - u.y() * v.x());
  }
  return a;
}

// Whole-lattice mean stress of the affine field u = eps x, omega = 0: the virial sum_e F_e (x) L_e
// over the polygon area (= sum_i V_i sigma_i / area, docs/lattice.md "Particle stress"), unsymmetrised.
Eigen::Matrix2d affine_mean_stress(const Lattice& l, const BeamParameters& p, const Eigen::Matrix2d& eps) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * l.n_particles());
  for (int i = 0; i < l.n_particles(); ++i) u.segment<2>(dof_index(i, 0)) = eps * l.points.col(i);
  const BeamForces f = compute_beam_forces(l, p, u);
  Eigen::Matrix2d v = Eigen::Matrix2d::Zero();
  for (int e = 0; e < l.n_beams(); ++e) v += f.force.col(e) * (l.length[e] * l.direction.col(e)).transpose();
  return v / polygon_area(l);
}

}  // namespace

TEST_CASE("facet_ratios equal the dual graph's exact d/L", "[lattice2d]") {
  for (DomainShape d : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle}) {
    const Lattice l = make_lattice(d, 2000, 1);
    const DualGraph g = build_dual_graph(l);
    const Eigen::VectorXd r = facet_ratios(l);
    for (int e = 0; e < l.n_beams(); ++e)
      // Two formulas for the same number (cotangents vs circumcentre distance): round-off of O(1) values,
      // with an absolute floor for the near-co-circular pairs (d/L ~ 1e-6, cancellation in the cot sum).
      REQUIRE(r[e] == Approx(g.dual_length[e] / l.length[e]).epsilon(1e-10).margin(1e-12));
  }
}

TEST_CASE("voronoi_facet: affine bulk response is exact, shear decoupled", "[lattice2d]") {
  // sum_beams d L n (x) n = A I exactly (the Voronoi cells tile the polygon; divergence theorem per cell),
  // so under eps = e I (no chord rotation: the bending terms vanish whatever a) the mean stress is
  // sqrt(3) k_n e I on ANY lattice, and a traceless eps gives a traceless mean stress.
  // Tolerance 1e-12: round-off of ~6000 O(1) terms (hm::test::roundoff).
  for (DomainShape d : {DomainShape::disk, DomainShape::annulus}) {
    const Lattice l = make_lattice(d, 2000, 2);
    for (double aspect : {0.05, 1.0}) {
      const BeamParameters p = facet_beams(aspect);
      const Eigen::Matrix2d s = affine_mean_stress(l, p, Eigen::Matrix2d::Identity());
      CHECK(s(0, 0) == hm::test::roundoff(std::sqrt(3.0)));
      CHECK(s(1, 1) == hm::test::roundoff(std::sqrt(3.0)));
      CHECK(std::abs(s(0, 1)) < 1e-12);
      CHECK(std::abs(s(1, 0)) < 1e-12);
      Eigen::Matrix2d dev;
      dev << 1.0, 0.3, 0.3, -1.0;
      CHECK(std::abs(affine_mean_stress(l, p, dev).trace()) < 1e-12);
    }
    // The uniform lattice has no such identity: sum L^2 n (x) n is only statistically isotropic.
    BeamParameters uniform;
    const Eigen::Matrix2d su = affine_mean_stress(l, uniform, Eigen::Matrix2d::Identity());
    CHECK(std::abs(su(0, 0) - su(1, 1)) > 1e-6 * su(0, 0));
  }
}

TEST_CASE("voronoi_facet: affine field of central springs is isotropic with nu = 1/4", "[lattice2d]") {
  // With k_omega -> 0 (a = 1e-3: k_omega/k_n = 5e-7) C_ijkl = sqrt(3) k_n sum d L n_i n_j n_k n_l / A is
  // fully symmetric with an exact trace (test above), so C11 = C22 and C16 = -C26 exactly; what remains
  // is the cos 4theta / sin 4theta moment of the facet-weighted orientations, a sampling fluctuation.
  // Plane-strain nu = C12/(C11 + C12) = 1/4 when it vanishes. Tolerances: exact parts 1e-12 (round-off),
  // nu within 0.01 (measured |nu - 1/4| = 1e-3...3e-3 at N = 1e4 for seeds 1-3, ~1/sqrt(n_beams)).
  const Lattice l = make_lattice(DomainShape::disk, 10000, 1);
  const BeamParameters p = facet_beams(1e-3);
  Eigen::Matrix3d C;
  const Eigen::Matrix2d unit[3] = {(Eigen::Matrix2d() << 1, 0, 0, 0).finished(),
                                   (Eigen::Matrix2d() << 0, 0, 0, 1).finished(),
                                   (Eigen::Matrix2d() << 0, 0.5, 0.5, 0).finished()};
  for (int k = 0; k < 3; ++k) {
    const Eigen::Matrix2d s = affine_mean_stress(l, p, unit[k]);
    C.col(k) << s(0, 0), s(1, 1), 0.5 * (s(0, 1) + s(1, 0));
  }
  CHECK(C(0, 0) == hm::test::roundoff(C(1, 1)));
  CHECK(std::abs(C(2, 0) + C(2, 1)) < 1e-12);
  const double c11 = C(0, 0), c12 = 0.5 * (C(0, 1) + C(1, 0));
  const double nu = c12 / (c11 + c12);
  CHECK(std::abs(nu - 0.25) < 0.01);
  // Full symmetry C1212 = C1122 holds for central forces; the residual bending (k_omega/k_n = 5e-7,
  // C66 - C12 ~ 2 rho k_omega / 4 ~ 1e-6 with rho ~ 2 sqrt(3)) is the only difference: allow 1e-5.
  CHECK(std::abs(C(2, 2) - c12) < 1e-5);
}

TEST_CASE("voronoi_facet: symmetric stiffness, rigid-body modes carry no force", "[lattice2d]") {
  const Lattice l = make_lattice(DomainShape::annulus, 2000, 3);
  for (double floor : {0.0, 0.05}) {
    BeamParameters p = facet_beams(0.05);
    p.facet_floor = floor;
    const Eigen::SparseMatrix<double> K = assemble_stiffness(l, p);
    const Eigen::SparseMatrix<double> Kt = K.transpose();
    CHECK((K - Kt).norm() <= 1e-14 * K.norm());
    const int n = l.n_particles();
    Eigen::VectorXd tx = Eigen::VectorXd::Zero(3 * n), ty = tx, rot = tx;
    for (int i = 0; i < n; ++i) {
      tx[dof_index(i, 0)] = 1.0;
      ty[dof_index(i, 1)] = 1.0;
      rot[dof_index(i, 0)] = -l.points(1, i);
      rot[dof_index(i, 1)] = l.points(0, i);
      rot[dof_index(i, 2)] = 1.0;
    }
    // Round-off of K's O(k_n) entries against O(1) modes: 1e-12 of the largest entry.
    const double scale = K.coeffs().cwiseAbs().maxCoeff();
    CHECK((K * tx).cwiseAbs().maxCoeff() < 1e-12 * scale);
    CHECK((K * ty).cwiseAbs().maxCoeff() < 1e-12 * scale);
    CHECK((K * rot).cwiseAbs().maxCoeff() < 1e-12 * scale);
    // Factors are >= 0 and >= sqrt(3) floor; uniform gives 1.
    for (int e = 0; e < l.n_beams(); ++e) {
      REQUIRE(beam_stiffness_factor(l, p, e) >= std::sqrt(3.0) * floor);
      REQUIRE(beam_stiffness_factor(l, BeamParameters{}, e) == 1.0);
    }
  }
}

TEST_CASE("boundary_spacing_factor keeps the lattice's invariants", "[lattice2d]") {
  for (DomainShape d : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle}) {
    for (double factor : {1.0, 1.3, 1.35}) {
      const Lattice l = make_lattice(d, 3000, 4, factor);
      const DualGraph g = build_dual_graph(l);
      const MeshQuality q = mesh_quality(l, g);
      // The package's promises (test_lattice.cpp): min angle >= 20 deg, sum V_i = polygon area (round-off),
      // boundary circumcentres inside: d_su/L >= (1/2) cot(86 deg) = 0.035 at factor 1.35 (lattice.hpp).
      CHECK(q.triangle_angle_deg.min >= 20.0);
      CHECK(q.sum_particle_area == Approx(q.sum_triangle_area).epsilon(1e-12));
      CHECK(q.surface_ratio.min >= 0.035);
      CHECK(q.dual_ratio.min >= 0.0);
      // Count within 1% of the target (the r fit compensates for the sparser boundary row).
      CHECK(std::abs(l.n_particles() - 3000) <= 30);
      // Consecutive boundary particles are at least factor * r_min apart (chord spacing in [h, 1.01 h]).
      double min_gap = std::numeric_limits<double>::infinity();
      for (int e = 0; e < l.n_beams(); ++e)
        if (l.is_boundary_beam(e)) min_gap = std::min(min_gap, l.length[e]);
      CHECK(min_gap >= factor * l.min_spacing * (1 - 1e-12));
    }
  }
}

TEST_CASE("boundary_spacing_factor: same seed gives the identical lattice", "[lattice2d]") {
  const Lattice a = make_lattice(DomainShape::annulus, 2000, 9, 1.3),
                b = make_lattice(DomainShape::annulus, 2000, 9, 1.3);
  CHECK(a.points == b.points);
  CHECK(a.beams == b.beams);
  const Lattice c = make_lattice(DomainShape::annulus, 2000, 9, 1.0);
  CHECK((c.n_particles() != a.n_particles() || c.points != a.points));
}

TEST_CASE("bad stiffness-scaling and boundary-spacing values are rejected", "[lattice2d]") {
  using Catch::Matchers::Contains;
  LatticeSpec spec;
  for (double bad : {0.9, 1.5, std::numeric_limits<double>::quiet_NaN()}) {
    spec.boundary_spacing_factor = bad;
    CHECK_THROWS_AS(spec.validate(), hm::InputError);
    CHECK_THROWS_WITH(spec.validate(), Contains("boundary_spacing_factor"));
  }
  BeamParameters p;
  for (double bad : {-0.1, 0.6, std::numeric_limits<double>::quiet_NaN()}) {
    p.facet_floor = bad;
    CHECK_THROWS_AS(p.validate(), hm::InputError);
    CHECK_THROWS_WITH(p.validate(), Contains("facet_floor"));
  }
  p = BeamParameters{};
  p.stiffness_scaling = static_cast<StiffnessScaling>(7);
  CHECK_THROWS_WITH(p.validate(), Contains("stiffness_scaling"));
  const Lattice l = make_lattice(DomainShape::disk, 600, 1);
  CHECK_THROWS_AS(assemble_stiffness(l, p), hm::InputError);
}
