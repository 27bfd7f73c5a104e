#pragma once
/// \file
/// The pressure in the fractures at one time (docs/borehole_fracture.md): the area-weighted mean over
/// the "fracture triangles", those with a broken beam among their three beams (the fluid cells that
/// hold the open volume). `away` excludes the triangles that have a borehole-wall beam: their pressure
/// is tied to p_h through the wall segment (flow_network.hpp), so they show the borehole, not the
/// fracture. RunRecorder writes it at the output times (fracture_pressure.csv).
#include <limits>

#include "hm/lattice2d/coupled/coupled_model.hpp"

namespace hm::cases {

struct FracturePressure {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double mean_all = none, mean_away = none, min_away = none;  ///< NaN without fracture triangles
  int n_all = 0, n_away = 0;                                    ///< fracture triangles, all and away from the wall
  double negative_area_fraction = none;  ///< of the `away` triangles' area, the part with p < 0
};

FracturePressure fracture_pressure(const hm::lattice2d::CoupledModel& m);

}  // namespace hm::cases
