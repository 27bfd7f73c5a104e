#include "geometry/point_sampling.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <random>

namespace hm::lattice2d::detail {
namespace {

// Uniform [0, 1) from the top 53 bits: std::uniform_real_distribution is not bitwise portable.
class UniformRng {
 public:
  explicit UniformRng(std::uint64_t seed) : engine_(seed) {}
  double next() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  // Index in [0, n); the modulo bias (n / 2^64) is far below anything measurable.
  std::size_t index(std::size_t n) { return static_cast<std::size_t>(engine_() % n); }

 private:
  std::mt19937_64 engine_;
};

struct Box {
  double x0, y0, x1, y1;
};

Box bounding_box(const LatticeSpec& spec) {
  if (spec.domain == DomainShape::rectangle)
    return {-0.5 * spec.width, -0.5 * spec.height, 0.5 * spec.width, 0.5 * spec.height};
  return {-1.0, -1.0, 1.0, 1.0};
}

// Open domain: candidates strictly inside; the spacing test keeps them ~0.87 r from the boundary.
bool is_inside(const LatticeSpec& spec, const Eigen::Vector2d& p) {
  const double rr = p.squaredNorm();
  switch (spec.domain) {
    case DomainShape::disk: return rr < 1.0;
    case DomainShape::annulus: return rr < 1.0 && rr > spec.inner_radius * spec.inner_radius;
    case DomainShape::rectangle: return std::abs(p.x()) < 0.5 * spec.width && std::abs(p.y()) < 0.5 * spec.height;
  }
  return false;
}

// Points on a circle with chord spacing >= r: n = floor(pi / asin(r / 2R)).
void add_circle(double radius, double r, BoundaryTag tag, PointSet& out) {
  const int n = static_cast<int>(std::floor(std::numbers::pi / std::asin(std::min(1.0, 0.5 * r / radius))));
  assert(n >= 3 && "boundary circle too coarse for the spacing");
  for (int k = 0; k < n; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / n;
    out.points.emplace_back(radius * std::cos(phi), radius * std::sin(phi));
    out.tags.push_back(tag);
  }
}

// Rectangle sides with spacing >= r, corners included once, counter-clockwise from (-w/2, -h/2).
void add_rectangle(double w, double h, double r, PointSet& out) {
  const int nx = std::max(1, static_cast<int>(std::floor(w / r)));
  const int ny = std::max(1, static_cast<int>(std::floor(h / r)));
  auto add = [&](double x, double y) {
    out.points.emplace_back(x, y);
    out.tags.push_back(BoundaryTag::outer);
  };
  for (int k = 0; k < nx; ++k) add(-0.5 * w + w * k / nx, -0.5 * h);
  for (int k = 0; k < ny; ++k) add(0.5 * w, -0.5 * h + h * k / ny);
  for (int k = 0; k < nx; ++k) add(0.5 * w - w * k / nx, 0.5 * h);
  for (int k = 0; k < ny; ++k) add(-0.5 * w, 0.5 * h - h * k / ny);
}

// Background grid for the spacing test. Cell diagonal slightly below r, so a cell holds at most one
// point and the neighbours within r lie in the 5 x 5 block around a cell.
class SpacingGrid {
 public:
  SpacingGrid(const Box& box, double r)
      : box_(box),
        r2_(r * r),
        cell_(0.999 * r / std::numbers::sqrt2),
        nx_(static_cast<int>(std::ceil((box.x1 - box.x0) / cell_)) + 1),
        ny_(static_cast<int>(std::ceil((box.y1 - box.y0) / cell_)) + 1),
        cells_(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), -1) {}

  bool is_free(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& points) const {
    const int cx = cx_of(p.x()), cy = cy_of(p.y());
    for (int j = std::max(0, cy - 2); j <= std::min(ny_ - 1, cy + 2); ++j)
      for (int i = std::max(0, cx - 2); i <= std::min(nx_ - 1, cx + 2); ++i) {
        const int q = cells_[at(i, j)];
        if (q >= 0 && (points[static_cast<std::size_t>(q)] - p).squaredNorm() < r2_) return false;
      }
    return true;
  }
  void insert(const Eigen::Vector2d& p, int index) {
    int& slot = cells_[at(cx_of(p.x()), cy_of(p.y()))];
    assert(slot < 0 && "two points closer than the cell diagonal");
    slot = index;
  }

 private:
  int cx_of(double x) const { return std::clamp(static_cast<int>((x - box_.x0) / cell_), 0, nx_ - 1); }
  int cy_of(double y) const { return std::clamp(static_cast<int>((y - box_.y0) / cell_), 0, ny_ - 1); }
  std::size_t at(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
  }
  Box box_;
  double r2_, cell_;
  int nx_, ny_;
  std::vector<int> cells_;
};

}  // namespace

double initial_spacing_guess(const LatticeSpec& spec) {
  // Bridson with 30 darts stops short of saturation: measured ~0.62 points per r^2 at n = 1e5
  // (a saturated random sequential packing has ~0.70). The fit in generate_lattice corrects the rest.
  return std::sqrt(0.62 * domain_area(spec) / static_cast<double>(spec.n_particles));
}

PointSet sample_points(const LatticeSpec& spec, double r, std::uint64_t stream_seed) {
  PointSet out;
  // Boundary spacing h = boundary_spacing_factor * r (>= r, so the interior's spacing test still holds
  // against boundary particles; default 1 = spacing in [r, ~1.01 r]).
  const double h = spec.boundary_spacing_factor * r;
  switch (spec.domain) {
    case DomainShape::disk: add_circle(1.0, h, BoundaryTag::outer, out); break;
    case DomainShape::annulus:
      add_circle(1.0, h, BoundaryTag::outer, out);
      add_circle(spec.inner_radius, h, BoundaryTag::inner, out);
      break;
    case DomainShape::rectangle: add_rectangle(spec.width, spec.height, h, out); break;
  }

  const Box box = bounding_box(spec);
  SpacingGrid grid(box, r);
  std::vector<int> active;
  for (std::size_t k = 0; k < out.points.size(); ++k) {
    grid.insert(out.points[k], static_cast<int>(k));
    active.push_back(static_cast<int>(k));
  }
  auto add = [&](const Eigen::Vector2d& p) {
    const int index = static_cast<int>(out.points.size());
    out.points.push_back(p);
    out.tags.push_back(BoundaryTag::interior);
    grid.insert(p, index);
    active.push_back(index);
  };

  UniformRng rng(stream_seed);
  // One uniformly placed interior seed; growth also starts from every boundary particle.
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const Eigen::Vector2d p(box.x0 + (box.x1 - box.x0) * rng.next(), box.y0 + (box.y1 - box.y0) * rng.next());
    if (is_inside(spec, p) && grid.is_free(p, out.points)) {
      add(p);
      break;
    }
  }

  // Bridson (2007): darts uniform in the ring r <= |d| < 2r around a random active point, drawn by
  // rejection from the square (no sin/cos, so the stream is bitwise portable).
  while (!active.empty()) {
    const std::size_t a = rng.index(active.size());
    const Eigen::Vector2d centre = out.points[static_cast<std::size_t>(active[a])];
    bool found = false;
    for (int attempt = 0; attempt < spec.bridson_attempts && !found; ++attempt) {
      Eigen::Vector2d d;
      double dd;
      do {
        d = Eigen::Vector2d(4.0 * rng.next() - 2.0, 4.0 * rng.next() - 2.0);
        dd = d.squaredNorm();
      } while (dd < 1.0 || dd >= 4.0);
      const Eigen::Vector2d p = centre + r * d;
      if (is_inside(spec, p) && grid.is_free(p, out.points)) {
        add(p);
        found = true;
      }
    }
    if (!found) {
      active[a] = active.back();
      active.pop_back();
    }
  }
  return out;
}

}  // namespace hm::lattice2d::detail
