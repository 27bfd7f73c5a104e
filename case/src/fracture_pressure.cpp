#include "hm/case/fracture_pressure.hpp"

#include <algorithm>
#include <cmath>

namespace hm::cases {

FracturePressure fracture_pressure(const hm::lattice2d::CoupledModel& m) {
  const hm::lattice2d::Lattice& l = m.lattice();
  const auto& states = m.mechanics().states();
  const Eigen::VectorXd& area = m.current_dual().triangle_area;
  const Eigen::VectorXd& p = m.pressure();
  double a_all = 0.0, pa_all = 0.0, a_away = 0.0, pa_away = 0.0, a_neg = 0.0;
  FracturePressure f;
  if (l.n_triangles() > 0) {
    f.p_min = p.head(l.n_triangles()).minCoeff();
    f.p_max = p.head(l.n_triangles()).maxCoeff();
  }
  // beam_flow_rate's sign: into the borehole for a wall beam, out of the domain for an outer beam.
  const Eigen::VectorXd rate = m.flow().beam_flow_rate(p);
  double into_borehole = 0.0, into_domain = 0.0, into_mouths = 0.0;
  bool has_wall = false;
  for (int e = 0; e < l.n_beams(); ++e) {
    const auto tag = l.beam_boundary[static_cast<std::size_t>(e)];
    if (tag == hm::lattice2d::BoundaryTag::inner) has_wall = true, into_borehole += std::max(rate[e], 0.0);
    if (tag != hm::lattice2d::BoundaryTag::outer) continue;
    into_domain += std::max(-rate[e], 0.0);
    if (states[static_cast<std::size_t>(e)] != hm::lattice2d::BeamState::intact) into_mouths += std::max(-rate[e], 0.0);
  }
  if (has_wall) f.borehole_backflow = into_borehole;
  f.outer_inflow = into_domain;
  f.mouth_inflow = into_mouths;
  for (int s = 0; s < l.n_triangles(); ++s) {
    bool cracked = false, wall = false;
    for (int e : l.triangle_beams[static_cast<std::size_t>(s)]) {
      cracked = cracked || states[static_cast<std::size_t>(e)] != hm::lattice2d::BeamState::intact;
      wall = wall || l.beam_boundary[static_cast<std::size_t>(e)] == hm::lattice2d::BoundaryTag::inner;
    }
    if (!cracked) continue;
    ++f.n_all;
    a_all += area[s];
    pa_all += area[s] * p[s];
    if (wall) continue;
    ++f.n_away;
    a_away += area[s];
    pa_away += area[s] * p[s];
    if (p[s] < 0.0) a_neg += area[s];
    f.min_away = std::isnan(f.min_away) ? p[s] : std::min(f.min_away, p[s]);
  }
  if (f.n_all > 0) f.mean_all = pa_all / a_all;
  if (f.n_away > 0) f.mean_away = pa_away / a_away, f.negative_area_fraction = a_neg / a_away;
  return f;
}

}  // namespace hm::cases
