// The dry crack growth of lattice2d.griffith_growth on its two paths: the saw-tooth law's events one at
// a time, and the envelope the teeth approximate followed by secant iterations.
#include <catch2/catch.hpp>

#include <cmath>

#include "crack_growth.hpp"
#include "hm/lattice2d/fracture/strength.hpp"

using namespace hm::verification;

namespace {

CrackGrowthSpec small_growth(SofteningPath path) {
  CrackGrowthSpec spec;
  spec.n_particles = 2000;
  const double t_u = hm::lattice2d::StrengthSpec{}.tensile_strength;
  spec.fracture_energy = 0.04 * t_u * t_u;  // l_ch = 0.04 R, the benchmark's
  spec.faces = PressurisedFaces::with_softening;
  spec.path = path;
  spec.max_half_length = 0.2;
  return spec;
}

}  // namespace

TEST_CASE("Both softening paths start the growth at the same load, and the continuous one books its envelope",
          "[verification][fracture]") {
  const CrackGrowthRun teeth = grow_pressurised_crack(small_growth(SofteningPath::teeth));
  const CrackGrowthRun continuous = grow_pressurised_crack(small_growth(SofteningPath::continuous));
  REQUIRE(teeth.reached);
  REQUIRE(continuous.reached);
  REQUIRE(teeth.points.size() > 2);
  REQUIRE(continuous.points.size() > 2);
  // Until the first beam reaches its strength the lattice is linear: both paths find that load from one
  // solve at p = 1 (the teeth path's failure ratio, the continuous path's strain over the peak strain),
  // the teeth path 1e-9 past it.
  CHECK(continuous.points.front().pressure == Approx(teeth.points.front().pressure).epsilon(1e-8));
  CHECK(continuous.points.front().volume == Approx(teeth.points.front().volume).epsilon(1e-8));
  CHECK(continuous.points.front().booked == 0.0);
  double booked = 0.0, work = 0.0;
  for (const GrowthPoint& p : continuous.points) {
    CHECK(p.booked >= booked);  // damage only grows
    CHECK(p.work >= work);
    booked = p.booked, work = p.work;
  }
  // The crack's broken beams each booked G_f d in full, and softened beams beside it some: the booked
  // energy exceeds G_f times the broken facets' count times the shortest facet (a loose floor, 0.002 R
  // at N = 2000), which a path that booked nothing for its breaks would miss.
  CHECK(continuous.points.back().booked >
        small_growth(SofteningPath::continuous).fracture_energy * continuous.points.back().n_broken * 0.002);
}
