#pragma once
/// \file
/// The fluid at one time, as the paper's Figs. 12-20 describe it (docs/borehole_fracture.md):
/// - the pressure in the fractures: the area-weighted mean over the "fracture triangles", those with a
///   broken beam among their three beams (the fluid cells that hold the open volume). `away` excludes
///   the triangles that have a borehole-wall beam: their pressure is tied to p_h through the wall
///   segment (flow_network.hpp), so they show the borehole, not the fracture;
/// - the range of the pressure over all triangles (the colour bars of the paper's snapshots);
/// - backflow: fluid flowing back into the borehole through the wall segments whose triangle is above
///   p_h (Figs. 16-17: "fluid flows back into the borehole"), and into the domain through the outer
///   segments whose triangle is below p = 0: through all of them (the Mandel-Cryer suction draws
///   fluid in at the free boundary in every run), and through those of broken beams, the fracture
///   mouths (Fig. 16H: secondary fractures "connected to the boundary, causing a backflow of fluid
///   into the domain").
/// RunRecorder writes it at the output times (fracture_pressure.csv).
#include <limits>

#include "hm/lattice2d/coupled/coupled_model.hpp"

namespace hm::cases {

struct FracturePressure {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double mean_all = none, mean_away = none, min_away = none;  ///< NaN without fracture triangles
  int n_all = 0, n_away = 0;                                  ///< fracture triangles, all and away from the wall
  double negative_area_fraction = none;                       ///< of the `away` triangles' area, the part with p < 0
  double p_min = none, p_max = none;                          ///< over every triangle
  /// Volume per unit time (as Q): the sum of the wall segments' flow into the borehole where it is
  /// positive (0 when all the wall takes fluid from the borehole; NaN without a borehole), the sum
  /// of the outer segments' flow into the domain where it is positive, and its part through broken beams.
  double borehole_backflow = none, outer_inflow = none, mouth_inflow = none;
};

FracturePressure fracture_pressure(const hm::lattice2d::CoupledModel& m);

}  // namespace hm::cases
