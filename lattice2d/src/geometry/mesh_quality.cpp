#include "hm/lattice2d/geometry/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <ostream>

namespace hm::lattice2d {
namespace {

class RangeBuilder {
 public:
  void add(double v) {
    lo_ = std::min(lo_, v);
    hi_ = std::max(hi_, v);
    sum_ += v;
    ++n_;
  }
  Range range() const { return n_ == 0 ? Range{} : Range{lo_, hi_, sum_ / static_cast<double>(n_)}; }

 private:
  double lo_ = std::numeric_limits<double>::infinity(), hi_ = -std::numeric_limits<double>::infinity(), sum_ = 0.0;
  long long n_ = 0;
};

}  // namespace

MeshQuality mesh_quality(const Lattice& lattice, const DualGraph& dual) {
  MeshQuality q;
  q.n_particles = lattice.n_particles();
  q.n_boundary_particles = static_cast<int>(std::count_if(lattice.boundary.begin(), lattice.boundary.end(),
                                                          [](BoundaryTag t) { return t != BoundaryTag::interior; }));
  q.n_beams = lattice.n_beams();
  q.n_triangles = lattice.n_triangles();
  q.min_spacing = lattice.min_spacing;
  q.domain_area = domain_area(lattice.spec);

  RangeBuilder angle, area_s, length, d_st, d_su, ratio_st, ratio_su, cond, area_i;
  for (int s = 0; s < lattice.n_triangles(); ++s) {
    const auto& t = lattice.triangles[static_cast<std::size_t>(s)];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d a = lattice.points.col(t[static_cast<std::size_t>((k + 1) % 3)]) -
                                lattice.points.col(t[static_cast<std::size_t>(k)]);
      const Eigen::Vector2d b = lattice.points.col(t[static_cast<std::size_t>((k + 2) % 3)]) -
                                lattice.points.col(t[static_cast<std::size_t>(k)]);
      angle.add(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)) * 180.0 / std::numbers::pi);
    }
    area_s.add(dual.triangle_area[s]);
    q.sum_triangle_area += dual.triangle_area[s];
  }
  for (int e = 0; e < lattice.n_beams(); ++e) {
    length.add(lattice.length[e]);
    (lattice.is_boundary_beam(e) ? d_su : d_st).add(dual.dual_length[e]);
    (lattice.is_boundary_beam(e) ? ratio_su : ratio_st).add(dual.dual_length[e] / lattice.length[e]);
    cond.add(dual.conductance[e]);
    if (lattice.is_boundary_beam(e)) ++q.n_boundary_beams;
    if (dual.is_floored[static_cast<std::size_t>(e)]) ++q.n_floored;
  }
  for (int i = 0; i < lattice.n_particles(); ++i) {
    area_i.add(dual.particle_area[i]);
    q.sum_particle_area += dual.particle_area[i];
  }
  q.triangle_angle_deg = angle.range();
  q.triangle_area = area_s.range();
  q.beam_length = length.range();
  q.dual_length = d_st.range();
  q.surface_distance = d_su.range();
  q.dual_ratio = ratio_st.range();
  q.surface_ratio = ratio_su.range();
  q.conductance = cond.range();
  q.particle_area = area_i.range();
  return q;
}

std::string to_string(const MeshQuality& q) {
  char buf[2048];
  auto row = [](const char* name, const Range& r) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-22s min %.4e  max %.4e  mean %.4e\n", name, r.min, r.max, r.mean);
    return std::string(line);
  };
  std::snprintf(buf, sizeof buf,
                "particles %d (boundary %d), beams %d (boundary %d), triangles %d, min spacing %.4e\n"
                "  floored flow distances %d, sum V_i %.15g, sum V_s %.15g, domain area %.15g\n",
                q.n_particles, q.n_boundary_particles, q.n_beams, q.n_boundary_beams, q.n_triangles, q.min_spacing,
                q.n_floored, q.sum_particle_area, q.sum_triangle_area, q.domain_area);
  return std::string(buf) + row("triangle angle [deg]", q.triangle_angle_deg) + row("beam length L", q.beam_length) +
         row("d_st (interior)", q.dual_length) + row("d_su (boundary)", q.surface_distance) +
         row("d_st / L", q.dual_ratio) + row("d_su / L", q.surface_ratio) + row("conductance A/d", q.conductance) +
         row("particle area V_i", q.particle_area) + row("triangle area V_s", q.triangle_area);
}

std::ostream& operator<<(std::ostream& out, const MeshQuality& q) { return out << to_string(q); }

}  // namespace hm::lattice2d
