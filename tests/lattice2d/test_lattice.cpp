#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::spec_of;

namespace {

// The message of the hm::InputError thrown by `f`, or "" if none.
template <class F>
std::string input_error_of(F f) {
  try {
    f();
  } catch (const hm::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("The default lattice spec is valid", "[lattice2d]") { REQUIRE_NOTHROW(LatticeSpec{}.validate()); }

TEST_CASE("Bad lattice specs are rejected naming the field", "[lattice2d]") {
  SECTION("too few particles") {
    LatticeSpec spec;
    spec.n_particles = 100;
    CHECK_THAT(input_error_of([&] { generate_lattice(spec); }), Catch::Contains("n_particles = 100"));
  }
  SECTION("borehole as large as the domain") {
    LatticeSpec spec = spec_of(DomainShape::annulus, 1000);
    spec.inner_radius = 1.0;
    CHECK_THAT(input_error_of([&] { spec.validate(); }), Catch::Contains("inner_radius = 1"));
  }
  SECTION("negative borehole radius") {
    LatticeSpec spec = spec_of(DomainShape::annulus, 1000);
    spec.inner_radius = -0.1;
    CHECK_THAT(input_error_of([&] { spec.validate(); }), Catch::Contains("inner_radius = -0.1"));
  }
  SECTION("out-of-range domain value") {
    LatticeSpec spec;
    spec.domain = static_cast<DomainShape>(7);
    CHECK_THAT(input_error_of([&] { spec.validate(); }), Catch::Contains("domain = "));
  }
  SECTION("degenerate rectangle") {
    LatticeSpec spec = spec_of(DomainShape::rectangle, 1000);
    spec.width = 0.0;
    CHECK_THAT(input_error_of([&] { spec.validate(); }), Catch::Contains("width = 0"));
  }
  SECTION("too few Bridson attempts") {
    LatticeSpec spec;
    spec.bridson_attempts = 1;
    CHECK_THAT(input_error_of([&] { spec.validate(); }), Catch::Contains("bridson_attempts = 1"));
  }
}

TEST_CASE("The same seed gives a bitwise identical lattice, another seed a different one", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle}) {
    DYNAMIC_SECTION(hm::core::name_of(shape)) {
      const Lattice a = generate_lattice(spec_of(shape, 1500, 42));
      const Lattice b = generate_lattice(spec_of(shape, 1500, 42));
      const Lattice c = generate_lattice(spec_of(shape, 1500, 43));
      REQUIRE(a.points.cols() == b.points.cols());
      CHECK((a.points.array() == b.points.array()).all());  // bitwise, no tolerance
      CHECK(a.min_spacing == b.min_spacing);
      CHECK(a.triangles == b.triangles);
      CHECK(a.beams == b.beams);
      CHECK(a.beam_triangles == b.beam_triangles);
      const bool same_size = a.points.cols() == c.points.cols();
      CHECK((!same_size || !(a.points.array() == c.points.array()).all()));
    }
  }
}

TEST_CASE("The particle count meets the target", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle})
    for (long long n : {500LL, 700LL, 3000LL, 10000LL})
      for (std::uint64_t seed : {1u, 2u}) {
        const Lattice lattice = generate_lattice(spec_of(shape, n, seed));
        INFO(hm::core::name_of(shape) << " n = " << n << " seed " << seed << ": got " << lattice.n_particles());
        // 1%: the spacing is re-fitted until within 0.3%, best of 16 passes otherwise; measured worst
        // 0.4% over 120 specs (3 domains, n = 500..10000, 5 seeds), i.e. 2 particles at n = 500.
        CHECK(std::abs(lattice.n_particles() / static_cast<double>(n) - 1.0) < 0.01);
      }
}

TEST_CASE("Every pair of particles is at least the minimum spacing apart", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle}) {
    const Lattice lattice = generate_lattice(spec_of(shape, 1200, 7));
    double closest = 1e300;
    for (int i = 0; i < lattice.n_particles(); ++i)
      for (int j = i + 1; j < lattice.n_particles(); ++j)
        closest = std::min(closest, (lattice.points.col(i) - lattice.points.col(j)).norm());
    INFO(hm::core::name_of(shape) << ": closest " << closest << ", r_min " << lattice.min_spacing);
    // Round-off: boundary chords are 2R sin(pi/n) >= r_min in exact arithmetic.
    CHECK(closest >= lattice.min_spacing * (1.0 - 1e-12));
    // Maximality: Bridson leaves no big holes, so no particle is isolated beyond 2 r_min.
    CHECK(lattice.length.maxCoeff() < 2.0 * lattice.min_spacing * 1.5);
  }
}

TEST_CASE("Boundary particles lie on the domain boundary, interior ones strictly inside", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle}) {
    const LatticeSpec spec = spec_of(shape, 2000, 3);
    const Lattice lattice = generate_lattice(spec);
    for (int i = 0; i < lattice.n_particles(); ++i) {
      const Eigen::Vector2d p = lattice.points.col(i);
      const double r = p.norm();
      const BoundaryTag tag = lattice.boundary[static_cast<std::size_t>(i)];
      if (shape == DomainShape::rectangle) {
        const double gap = std::min(0.5 * spec.width - std::abs(p.x()), 0.5 * spec.height - std::abs(p.y()));
        if (tag == BoundaryTag::outer)
          CHECK(std::abs(gap) < 1e-15);  // round-off of w k / n
        else  // >= sqrt(1 - s^2/4) r_min for a side spacing s <= 1.2 factor r_min (0.63 at the default 1.3)
          CHECK(gap > std::sqrt(1.0 - std::pow(0.6 * spec.boundary_spacing_factor, 2)) * lattice.min_spacing);
        continue;
      }
      if (tag == BoundaryTag::outer) CHECK(r == hm::test::roundoff(1.0));
      if (tag == BoundaryTag::inner) CHECK(r == hm::test::roundoff(spec.inner_radius));
      if (tag == BoundaryTag::interior) {
        // sqrt(1 - 1.01^2/4) r_min ~ 0.86 r_min: the spacing to the two nearest boundary particles.
        CHECK(1.0 - r > 0.8 * lattice.min_spacing);
        if (shape == DomainShape::annulus) CHECK(r - spec.inner_radius > 0.8 * lattice.min_spacing);
      }
    }
  }
}

TEST_CASE("The triangulation is Delaunay and every beam has one or two triangles", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus, DomainShape::rectangle}) {
    const Lattice lattice = generate_lattice(spec_of(shape, 800, 11));
    const Eigen::Matrix2Xd& x = lattice.points;
    // Empty circumcircle, every triangle against every particle.
    int n_violations = 0;
    for (const auto& t : lattice.triangles) {
      const Eigen::Vector2d a = x.col(t[0]), u = x.col(t[1]) - a, v = x.col(t[2]) - a;
      const double cross = u.x() * v.y() - u.y() * v.x();
      REQUIRE(cross > 0.0);  // counter-clockwise, non-degenerate
      const Eigen::Vector2d c = a + Eigen::Vector2d(v.y() * u.squaredNorm() - u.y() * v.squaredNorm(),
                                                    u.x() * v.squaredNorm() - v.x() * u.squaredNorm()) /
                                        (2.0 * cross);
      const double rr = (c - a).squaredNorm();
      for (int p = 0; p < lattice.n_particles(); ++p)
        // 1e-9 relative: round-off of the circumcentre (well conditioned, angles > 20 deg) with a wide
        // margin; it still catches any point inside by more than a nanometre of the unit domain.
        if ((x.col(p) - c).squaredNorm() < rr * (1.0 - 1e-9)) ++n_violations;
    }
    CHECK(n_violations == 0);

    // Topology: every beam has one or two triangles, every triangle three distinct beams.
    int n_boundary_beams = 0;
    for (int e = 0; e < lattice.n_beams(); ++e) {
      const auto [s, t] = lattice.beam_triangles[static_cast<std::size_t>(e)];
      REQUIRE(s >= 0);
      CHECK(t != s);
      if (t < 0) {
        ++n_boundary_beams;
        CHECK(lattice.beam_boundary[static_cast<std::size_t>(e)] != BoundaryTag::interior);
      }
    }
    for (int s = 0; s < lattice.n_triangles(); ++s)
      for (int k = 0; k < 3; ++k) {
        const int e = lattice.triangle_beams[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)];
        REQUIRE(e >= 0);
        const auto& tb = lattice.beam_triangles[static_cast<std::size_t>(e)];
        CHECK((tb[0] == s || tb[1] == s));
      }
    // Each boundary curve is a closed polygon: as many boundary beams as boundary particles.
    int n_boundary_particles = 0;
    for (BoundaryTag tag : lattice.boundary) n_boundary_particles += tag != BoundaryTag::interior;
    CHECK(n_boundary_beams == n_boundary_particles);
    // Euler: V - E + F = 1 for a disk-like domain, 0 with one hole.
    const int euler = lattice.n_particles() - lattice.n_beams() + lattice.n_triangles();
    CHECK(euler == (shape == DomainShape::annulus ? 0 : 1));
  }
}

TEST_CASE("Beam geometry is consistent with the particle positions", "[lattice2d]") {
  const Lattice lattice = generate_lattice(spec_of(DomainShape::annulus, 1000, 5));
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    CHECK(i < j);
    const Eigen::Vector2d d = lattice.points.col(j) - lattice.points.col(i);
    CHECK(lattice.length[e] == hm::test::roundoff(d.norm()));
    CHECK(lattice.direction.col(e).norm() == hm::test::roundoff(1.0));
    CHECK(std::cos(lattice.angle[e]) == hm::test::roundoff(lattice.direction(0, e)));
    CHECK(std::sin(lattice.angle[e]) == hm::test::roundoff(lattice.direction(1, e)));
  }
}

TEST_CASE("Beam directions are isotropic (no grid-aligned bias)", "[lattice2d]") {
  const Lattice lattice = generate_lattice(spec_of(DomainShape::disk, 10000, 1));
  constexpr int n_bins = 12;
  std::array<int, n_bins> histogram{};
  for (int e = 0; e < lattice.n_beams(); ++e) {
    double phi = std::fmod(lattice.angle[e] + 2.0 * std::numbers::pi, std::numbers::pi);  // undirected
    histogram[static_cast<std::size_t>(std::min(n_bins - 1, static_cast<int>(phi / std::numbers::pi * n_bins)))]++;
  }
  const double expected = lattice.n_beams() / static_cast<double>(n_bins);
  // ~2450 beams per bin; 10% is about 5 standard deviations of a Poisson count: any lattice-direction
  // bias of a structured grid (60 or 90 degree peaks) would put whole bins at 0 or 2x.
  for (int count : histogram) CHECK(std::abs(count / expected - 1.0) < 0.10);
}
