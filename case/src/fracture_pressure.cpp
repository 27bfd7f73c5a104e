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
