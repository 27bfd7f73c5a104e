#include "hm/lattice2d/fracture/fracture_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>

#include <Eigen/Geometry>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

void FractureStatisticsOptions::validate() const {
  hm::core::require_open(arm_radius_fraction, "fracture_statistics.arm_radius_fraction", 0.0, 1.0);
  hm::core::require_positive(arm_gap_beams, "fracture_statistics.arm_gap_beams");
  hm::core::require_finite(arm_gap, "fracture_statistics.arm_gap");
  hm::core::require_positive(arm_gap, "fracture_statistics.arm_gap");
  hm::core::require_non_negative(sizable_extent, "fracture_statistics.sizable_extent");
}

namespace {

constexpr double pi = 3.14159265358979323846;

void require_one_flag_per_beam(const Lattice& lattice, const std::vector<bool>& flags, const char* what = "broken") {
  if (static_cast<int>(flags.size()) != lattice.n_beams())
    throw hm::InputError(std::string("fracture_statistics: ") + what + " flags = " + std::to_string(flags.size()) +
                         ", allowed: one per beam (" + std::to_string(lattice.n_beams()) + ")");
}

// Union-find with path halving; the root is not the smallest index, which is why clusters are
// numbered afterwards by a scan in beam order.
struct DisjointSets {
  std::vector<int> parent;
  explicit DisjointSets(int n) : parent(static_cast<std::size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int a) {
    while (parent[static_cast<std::size_t>(a)] != a) {
      const auto ua = static_cast<std::size_t>(a);
      parent[ua] = parent[static_cast<std::size_t>(parent[ua])];
      a = parent[ua];
    }
    return a;
  }
  void unite(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

Eigen::Vector2d midpoint(const Lattice& lattice, int beam) {
  const auto& b = lattice.beams[static_cast<std::size_t>(beam)];
  return 0.5 * (lattice.points.col(b[0]) + lattice.points.col(b[1]));
}

// The failure mode of each beam from its first event in the log (none if not logged).
std::vector<FailureMode> logged_modes(const Lattice& lattice, const std::vector<BreakEvent>& log) {
  std::vector<FailureMode> mode(static_cast<std::size_t>(lattice.n_beams()), FailureMode::none);
  std::vector<bool> seen(mode.size(), false);
  for (const BreakEvent& ev : log) {
    if (ev.beam < 0 || ev.beam >= lattice.n_beams())
      throw hm::InputError("fracture_statistics: break log beam = " + std::to_string(ev.beam) +
                           ", allowed: 0 <= beam < " + std::to_string(lattice.n_beams()));
    const auto e = static_cast<std::size_t>(ev.beam);
    if (seen[e]) continue;
    seen[e] = true;
    mode[e] = ev.mode;
  }
  return mode;
}

}  // namespace

double arm_radius(const Lattice& lattice, const FractureStatisticsOptions& options) {
  const LatticeSpec& spec = lattice.spec;
  const double r_inner = spec.domain == DomainShape::annulus ? spec.inner_radius : 0.0;
  // The rectangle's inscribed circle stands in for the outer radius (its sides are "outer").
  const double r_outer = spec.domain == DomainShape::rectangle ? 0.5 * std::min(spec.width, spec.height) : 1.0;
  return r_inner + options.arm_radius_fraction * (r_outer - r_inner);
}

double arm_gap_of_beams(const Lattice& lattice, const FractureStatisticsOptions& options) {
  return options.arm_gap_beams * lattice.length.mean();
}

int count_crossings(const Lattice& lattice, const std::vector<bool>& broken, double radius, double max_gap) {
  require_one_flag_per_beam(lattice, broken);
  hm::core::require_positive(radius, "fracture_statistics.radius");
  hm::core::require_positive(max_gap, "fracture_statistics.arm_gap");
  std::vector<double> angles;  // where each straddling broken beam meets the circle, in [0, 2 pi)
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (!broken[static_cast<std::size_t>(e)]) continue;
    Eigen::Vector2d inside = lattice.points.col(lattice.beams[static_cast<std::size_t>(e)][0]);
    Eigen::Vector2d outside = lattice.points.col(lattice.beams[static_cast<std::size_t>(e)][1]);
    if (inside.norm() >= radius) std::swap(inside, outside);
    if (!(inside.norm() < radius && outside.norm() >= radius)) continue;
    // |inside + s d| = radius: with |inside| < radius the roots have opposite signs, so the larger
    // one is the single crossing in (0, 1].
    const Eigen::Vector2d d = outside - inside;
    const double a = d.squaredNorm(), b = inside.dot(d), c = inside.squaredNorm() - radius * radius;
    const double s = (-b + std::sqrt(b * b - a * c)) / a;
    const Eigen::Vector2d x = inside + s * d;
    double theta = std::atan2(x.y(), x.x());
    if (theta < 0.0) theta += 2.0 * pi;
    angles.push_back(theta);
  }
  if (angles.empty()) return 0;
  std::sort(angles.begin(), angles.end());
  // Groups on a circle = gaps wider than the threshold, counted around (the wrap-around gap included);
  // no wide gap means one group covering the whole circle.
  const double max_gap_angle = max_gap / radius;
  int n_wide = 0;
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double next = k + 1 < angles.size() ? angles[k + 1] : angles.front() + 2.0 * pi;
    if (next - angles[k] > max_gap_angle) ++n_wide;
  }
  return std::max(n_wide, 1);
}

namespace {

// The beams that connect fractures (broken, and softened ones with SoftenedBeams::link) joined by `link`.
DisjointSets linked_beams(const Lattice& lattice, const std::vector<bool>& linking, FractureLink link) {
  const auto links = [&](int e) { return linking[static_cast<std::size_t>(e)]; };
  DisjointSets sets(lattice.n_beams());
  if (link == FractureLink::shared_triangle) {
    // Two cracked edges of one triangle: their Voronoi segments meet at its dual point.
    for (const auto& edges : lattice.triangle_beams)
      for (int k = 0; k < 3; ++k)
        for (int m = k + 1; m < 3; ++m)
          if (links(edges[k]) && links(edges[m])) sets.unite(edges[k], edges[m]);
  } else {
    // Every cracked beam joins the first cracked beam seen at each of its particles.
    std::vector<int> first_at(static_cast<std::size_t>(lattice.n_particles()), -1);
    for (int e = 0; e < lattice.n_beams(); ++e) {
      if (!links(e)) continue;
      for (int i : lattice.beams[static_cast<std::size_t>(e)]) {
        int& first = first_at[static_cast<std::size_t>(i)];
        if (first < 0)
          first = e;
        else
          sets.unite(e, first);
      }
    }
  }
  return sets;
}

}  // namespace

FractureStatistics compute_fracture_statistics(const Lattice& lattice, const std::vector<bool>& broken,
                                               const std::vector<BreakEvent>& log,
                                               const FractureStatisticsOptions& options,
                                               const std::vector<bool>& softened) {
  options.validate();
  require_one_flag_per_beam(lattice, broken);
  if (!softened.empty()) require_one_flag_per_beam(lattice, softened, "softened");
  const std::vector<FailureMode> mode = logged_modes(lattice, log);
  const auto is_broken = [&](int e) { return broken[static_cast<std::size_t>(e)]; };

  std::vector<bool> linking = broken;
  if (options.softened == SoftenedBeams::link && !softened.empty())
    for (std::size_t e = 0; e < linking.size(); ++e) linking[e] = linking[e] || softened[e];
  DisjointSets sets = linked_beams(lattice, linking, options.link);

  FractureStatistics stats;
  std::vector<int> fracture_of_root(static_cast<std::size_t>(lattice.n_beams()), -1);
  std::vector<Eigen::Vector2d> direction_sum;
  std::vector<Eigen::AlignedBox2d> box;
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (!is_broken(e)) continue;
    int& id = fracture_of_root[static_cast<std::size_t>(sets.find(e))];
    if (id < 0) {  // first (smallest) beam of a new fracture: ids follow the smallest beam index
      id = static_cast<int>(stats.fractures.size());
      Fracture f;
      f.id = id;
      f.r_min = std::numeric_limits<double>::infinity();
      f.r_max = -std::numeric_limits<double>::infinity();
      stats.fractures.push_back(f);
      direction_sum.push_back(Eigen::Vector2d::Zero());
      box.emplace_back();
    }
    Fracture& f = stats.fractures[static_cast<std::size_t>(id)];
    f.beams.push_back(e);
    const BoundaryTag tag = lattice.beam_boundary[static_cast<std::size_t>(e)];
    f.connected_to_borehole = f.connected_to_borehole || tag == BoundaryTag::inner;
    f.reaches_outer = f.reaches_outer || tag == BoundaryTag::outer;
    const Eigen::Vector2d m = midpoint(lattice, e);
    const double r = m.norm();
    f.r_min = std::min(f.r_min, r);
    f.r_max = std::max(f.r_max, r);
    if (r > 0.0) direction_sum[static_cast<std::size_t>(id)] += m / r;
    box[static_cast<std::size_t>(id)].extend(m);
    const FailureMode how = mode[static_cast<std::size_t>(e)];
    f.n_tensile += how == FailureMode::tensile ? 1 : 0;
    f.n_shear += how == FailureMode::shear ? 1 : 0;
  }

  for (Fracture& f : stats.fractures) {
    f.kind = f.connected_to_borehole ? FractureKind::radial : FractureKind::secondary;
    f.length = f.r_max - f.r_min;
    f.extent = box[static_cast<std::size_t>(f.id)].diagonal().norm();
    const Eigen::Vector2d& dir = direction_sum[static_cast<std::size_t>(f.id)];
    double deg = std::atan2(dir.y(), dir.x()) * 180.0 / pi;
    if (deg < 0.0) deg += 360.0;
    f.angle_deg = deg >= 360.0 ? 0.0 : deg;  // -tiny + 360 rounds to 360

    stats.n_broken += f.n_beams();
    stats.n_tensile += f.n_tensile;
    stats.n_shear += f.n_shear;
    if (f.kind == FractureKind::radial) {
      ++stats.n_radial;
      stats.n_radial_reaching_outer += f.reaches_outer ? 1 : 0;
      stats.max_radial_extent = std::max(stats.max_radial_extent, f.r_max);
    } else {
      ++stats.n_secondary;
      stats.n_secondary_sizable += f.extent >= options.sizable_extent ? 1 : 0;
    }
  }
  stats.n_fractures = static_cast<int>(stats.fractures.size());
  stats.arm_radius = arm_radius(lattice, options);
  stats.n_arms = count_crossings(lattice, broken, stats.arm_radius, arm_gap_of_beams(lattice, options));
  stats.n_arms_fixed_gap = count_crossings(lattice, broken, stats.arm_radius, options.arm_gap);
  return stats;
}

std::vector<bool> softened_flags(const std::vector<ToothEvent>& teeth, int n_beams, double until) {
  std::vector<bool> softened(static_cast<std::size_t>(n_beams), false);
  for (const ToothEvent& ev : teeth) {
    if (ev.beam < 0 || ev.beam >= n_beams)
      throw hm::InputError("fracture_statistics: tooth log beam = " + std::to_string(ev.beam) +
                           ", allowed: 0 <= beam < " + std::to_string(n_beams));
    if (ev.load <= until) softened[static_cast<std::size_t>(ev.beam)] = true;
  }
  return softened;
}

FractureStatistics compute_fracture_statistics(const Lattice& lattice, const std::vector<BeamState>& states,
                                               const std::vector<BreakEvent>& log,
                                               const FractureStatisticsOptions& options) {
  return compute_fracture_statistics(lattice, broken_flags(states), log, options);
}

}  // namespace hm::lattice2d
