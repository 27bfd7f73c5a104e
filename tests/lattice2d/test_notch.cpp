// Pre-cut cracks: the beams a notch segment cuts, against an independent count of the beams whose
// centre line changes side across the notch's line within its extent.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/fracture/notch.hpp"

using namespace hm::lattice2d;

namespace {

Lattice disk(int n) {
  LatticeSpec spec;
  spec.domain = DomainShape::disk;
  spec.n_particles = n;
  return generate_lattice(spec);
}

// Beams crossing the horizontal segment y = 0, |x| <= half (no particle lies on y = 0 in a random
// lattice): ends on opposite sides, and the crossing point within the extent.
std::vector<int> crossing_y0(const Lattice& l, double half) {
  std::vector<int> out;
  for (int e = 0; e < l.n_beams(); ++e) {
    const Eigen::Vector2d p = l.points.col(l.beams[e][0]), q = l.points.col(l.beams[e][1]);
    if (p.y() * q.y() >= 0.0) continue;
    const double x = p.x() + (q.x() - p.x()) * (0.0 - p.y()) / (q.y() - p.y());
    if (std::abs(x) <= half) out.push_back(e);
  }
  return out;
}

}  // namespace

TEST_CASE("A notch cuts exactly the beams whose centre lines cross it", "[lattice2d][fracture]") {
  const Lattice l = disk(3000);
  const std::vector<int> cut = beams_crossing(l, NotchSegment{{-0.05, 0.0}, {0.05, 0.0}});
  CHECK(cut == crossing_y0(l, 0.05));
  // A notch of length 0.1 across beams of mean length ~0.03 (N = 3000 on the unit disk) cuts a few
  // beams per beam length: between 2 and 20, and a notch twice as long about twice as many.
  CHECK(cut.size() >= 2);
  CHECK(cut.size() <= 20);
  const std::vector<int> longer = beams_crossing(l, NotchSegment{{-0.1, 0.0}, {0.1, 0.0}});
  CHECK(longer == crossing_y0(l, 0.1));
  CHECK(longer.size() > cut.size());
  // Reversed ends, and the union of two halves, give the same set.
  CHECK(beams_crossing(l, NotchSegment{{0.05, 0.0}, {-0.05, 0.0}}) == cut);
  const std::vector<int> halves =
      beams_crossing(l, std::vector<NotchSegment>{{{-0.05, 0.0}, {0.0, 0.0}}, {{0.0, 0.0}, {0.05, 0.0}}});
  CHECK(halves == cut);
  CHECK(std::is_sorted(halves.begin(), halves.end()));
  // Degenerate segments are refused.
  CHECK_THROWS_AS(beams_crossing(l, NotchSegment{{0.1, 0.1}, {0.1, 0.1}}), hm::InputError);
  CHECK_THROWS_AS(beams_crossing(l, NotchSegment{{NAN, 0.0}, {0.1, 0.0}}), hm::InputError);
}
