#include "hm/lattice2d/fracture/notch.hpp"

#include <algorithm>
#include <cmath>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

namespace {

// Twice the signed area of (p, q, r): > 0 when r lies left of p -> q.
double orientation(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
  return (q.x() - p.x()) * (r.y() - p.y()) - (q.y() - p.y()) * (r.x() - p.x());
}

// r on the segment p -> q, given that the three are collinear.
bool within(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
  return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
         r.y() <= std::max(p.y(), q.y());
}

bool segments_meet(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& q1,
                   const Eigen::Vector2d& q2) {
  const double d1 = orientation(q1, q2, p1), d2 = orientation(q1, q2, p2);
  const double d3 = orientation(p1, p2, q1), d4 = orientation(p1, p2, q2);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && within(q1, q2, p1)) || (d2 == 0 && within(q1, q2, p2)) || (d3 == 0 && within(p1, p2, q1)) ||
         (d4 == 0 && within(p1, p2, q2));
}

}  // namespace

void NotchSegment::validate() const {
  if (!(a.allFinite() && b.allFinite()))
    throw hm::InputError("notch = [" + core::format_value(a.x()) + ", " + core::format_value(a.y()) + ", " +
                         core::format_value(b.x()) + ", " + core::format_value(b.y()) + "], allowed: finite ends");
  if (a == b)
    throw hm::InputError("notch = [" + core::format_value(a.x()) + ", " + core::format_value(a.y()) + ", " +
                         core::format_value(b.x()) + ", " + core::format_value(b.y()) +
                         "], allowed: two distinct ends");
}

std::vector<int> beams_crossing(const Lattice& lattice, const NotchSegment& notch) {
  notch.validate();
  std::vector<int> out;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    if (segments_meet(lattice.points.col(i), lattice.points.col(j), notch.a, notch.b)) out.push_back(e);
  }
  return out;
}

std::vector<int> beams_crossing(const Lattice& lattice, const std::vector<NotchSegment>& notches) {
  std::vector<int> out;
  for (const NotchSegment& n : notches) {
    const std::vector<int> cut = beams_crossing(lattice, n);
    out.insert(out.end(), cut.begin(), cut.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace hm::lattice2d
