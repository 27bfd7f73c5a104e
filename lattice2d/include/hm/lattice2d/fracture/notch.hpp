#pragma once
/// \file
/// Pre-cut cracks: the beams that a straight notch cuts, broken before the first step (the starting
/// crack of a propagation benchmark, e.g. Griffith's crack under face pressure). Lengths over R.
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/geometry/lattice.hpp"

namespace hm::lattice2d {

/// A straight notch from `a` to `b` in the lattice's plane (over R).
struct NotchSegment {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  /// Throws hm::InputError unless both ends are finite and distinct.
  void validate() const;
};

/// Every beam whose centre line (particle i to particle j, undeformed) meets the segment, touching
/// included, in ascending order. A beam meets it when each of the two segments has the other's ends
/// on opposite sides (or one on it): the orientation test on the exact double arithmetic.
std::vector<int> beams_crossing(const Lattice& lattice, const NotchSegment& notch);

/// The union of beams_crossing over `notches`, ascending, each beam once.
std::vector<int> beams_crossing(const Lattice& lattice, const std::vector<NotchSegment>& notches);

}  // namespace hm::lattice2d
