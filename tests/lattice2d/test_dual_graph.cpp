#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::spec_of;

namespace {

// Shoelace area of the boundary polygon(s), from the boundary particles, which are generated in
// counter-clockwise order on each curve: outer polygon minus the borehole polygon.
double polygon_area(const Lattice& lattice) {
  return hm::test::ring_area(lattice, BoundaryTag::outer) - hm::test::ring_area(lattice, BoundaryTag::inner);
}

}  // namespace

TEST_CASE("Default dual-graph options are valid, a zero floor is rejected", "[lattice2d]") {
  REQUIRE_NOTHROW(DualGraphOptions{}.validate());
  DualGraphOptions options;
  options.min_dual_ratio = 0.0;
  CHECK_THROWS_WITH(options.validate(), Catch::Contains("min_dual_ratio = 0"));
  CHECK_THROWS_AS(options.validate(), hm::InputError);
}

TEST_CASE("Particle areas and triangle areas both tile the polygonal domain", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle})
    for (long long n : {700LL, 5000LL}) {
      DYNAMIC_SECTION(hm::core::name_of(shape) << " n = " << n) {
        const Lattice lattice = generate_lattice(spec_of(shape, n, 9));
        const DualGraph dual = build_dual_graph(lattice);
        const double polygon = polygon_area(lattice);
        // Round-off: both are sums of ~1e4 positive O(1/n) terms; 1e-12 relative is the project's
        // round-off bound and leaves two orders of magnitude to the measured 1e-14.
        CHECK(dual.particle_area.sum() == hm::test::roundoff(polygon));
        CHECK(dual.triangle_area.sum() == hm::test::roundoff(polygon));
        CHECK(dual.particle_area.minCoeff() > 0.0);
        CHECK(dual.triangle_area.minCoeff() > 0.0);
        // The polygon through the boundary particles differs from the curved domain by the chord
        // segments: at most (2 pi R) h^2 / (12 R) per circle with h ~ 1.01 r_min.
        const double h = 1.01 * lattice.min_spacing;
        const double chord_loss = 2.0 * std::numbers::pi * h * h / 12.0 * (1.0 + 1.0);
        CHECK(std::abs(polygon - domain_area(lattice.spec)) <= chord_loss);
      }
    }
}

TEST_CASE("Dual lengths and conductances are strictly positive and bounded", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle})
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      DYNAMIC_SECTION(hm::core::name_of(shape) << " seed " << seed) {
        const Lattice lattice = generate_lattice(spec_of(shape, 4000, seed));
        const DualGraph dual = build_dual_graph(lattice);
        const double ratio = dual.options.min_dual_ratio;
        int n_negative = 0;
        for (int e = 0; e < lattice.n_beams(); ++e) {
          const double length = lattice.length[e];
          // Delaunay: d_st = L/2 (cot a_s + cot a_t) >= 0; round-off of the circumcentres only.
          if (dual.dual_length[e] < -1e-12 * length) ++n_negative;
          CHECK(dual.flow_distance[e] >= ratio * length);
          CHECK(dual.flow_distance[e] >= dual.dual_length[e]);
          CHECK(dual.conductance[e] > 0.0);
          // Bound 1/min_dual_ratio by construction of the floor (+ round-off of L / (ratio L)).
          CHECK(dual.conductance[e] <= (1.0 / ratio) * (1.0 + 1e-12));
          if (lattice.is_boundary_beam(e)) {
            // d_su = L/2 cot(a), the opposite angle a bounded by the boundary spacing (lattice_fixtures.hpp):
            // 0.070 L at the default spacing factor 1.3; 0.9 of it leaves margin. The floor never acts.
            CHECK(dual.dual_length[e] >=
                  0.9 * hm::test::min_boundary_dual_ratio(lattice.spec.boundary_spacing_factor) * length);
            CHECK_FALSE(dual.is_floored[static_cast<std::size_t>(e)]);
          }
        }
        CHECK(n_negative == 0);
      }
    }
}

TEST_CASE("Voronoi cells of interior particles close: a uniform pressure gives zero net force", "[lattice2d]") {
  // Eq. 17 with p_st = 1 summed over the Voronoi segments around particle i: sum_j d_ij n_ij = 0
  // exactly when the dual segments are perpendicular to the beams and form a closed polygon.
  const Lattice lattice = generate_lattice(spec_of(DomainShape::annulus, 3000, 4));
  const DualGraph dual = build_dual_graph(lattice);
  Eigen::Matrix2Xd force = Eigen::Matrix2Xd::Zero(2, lattice.n_particles());
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    force.col(i) -= dual.dual_length[e] * lattice.direction.col(e);
    force.col(j) += dual.dual_length[e] * lattice.direction.col(e);
  }
  double worst = 0.0;
  for (int i = 0; i < lattice.n_particles(); ++i)
    if (lattice.boundary[static_cast<std::size_t>(i)] == BoundaryTag::interior)
      worst = std::max(worst, force.col(i).norm());
  // Round-off: a handful of O(1e-2) terms computed from O(1) coordinates, ~1e-16 each.
  CHECK(worst < 1e-14);
}

TEST_CASE("Particle area matches the Voronoi polygon for an interior particle", "[lattice2d]") {
  // Independent check of V_i: shoelace of the circumcentres of the triangles around particle i,
  // ordered by angle (the Voronoi cell of a Delaunay vertex is the convex polygon through them).
  const Lattice lattice = generate_lattice(spec_of(DomainShape::disk, 1000, 8));
  const DualGraph dual = build_dual_graph(lattice);
  int n_checked = 0;
  for (int i = 0; i < lattice.n_particles() && n_checked < 50; i += 7) {
    if (lattice.boundary[static_cast<std::size_t>(i)] != BoundaryTag::interior) continue;
    std::vector<std::pair<double, int>> around;
    for (int s = 0; s < lattice.n_triangles(); ++s) {
      const auto& t = lattice.triangles[static_cast<std::size_t>(s)];
      if (t[0] == i || t[1] == i || t[2] == i) {
        const Eigen::Vector2d d = dual.centroid.col(s) - lattice.points.col(i);
        around.emplace_back(std::atan2(d.y(), d.x()), s);
      }
    }
    std::sort(around.begin(), around.end());
    double twice = 0.0;
    for (std::size_t k = 0; k < around.size(); ++k) {
      const Eigen::Vector2d a = dual.dual_point.col(around[k].second);
      const Eigen::Vector2d b = dual.dual_point.col(around[(k + 1) % around.size()].second);
      twice += a.x() * b.y() - a.y() * b.x();
    }
    // 1e-10 relative: the shoelace of O(1) coordinates for an O(1e-3) area cancels ~3 digits.
    CHECK(dual.particle_area[i] == Approx(0.5 * twice).epsilon(1e-10));
    ++n_checked;
  }
  CHECK(n_checked > 20);
}

TEST_CASE("The dual graph follows given particle positions", "[lattice2d]") {
  // A uniform dilation by (1 + eps) scales lengths by (1 + eps) and areas by (1 + eps)^2.
  const Lattice lattice = generate_lattice(spec_of(DomainShape::rectangle, 800, 2));
  const DualGraph dual0 = build_dual_graph(lattice);
  const double scale = 1.01;
  const DualGraph dual1 = build_dual_graph(lattice, Eigen::Matrix2Xd(scale * lattice.points));
  for (int e = 0; e < lattice.n_beams(); e += 13)
    CHECK(dual1.dual_length[e] == Approx(scale * dual0.dual_length[e]).epsilon(1e-12).margin(1e-14));
  CHECK(dual1.particle_area.sum() == hm::test::roundoff(scale * scale * dual0.particle_area.sum()));
}
