#pragma once
// Reading a 1D (fdm1d) result where the 2D lattice is compared with it: the borehole pressure at any
// time and shell averages of a nodal profile. Shared by the lattice-vs-fdm1d and Fig. 12/13 benchmarks.
#include <vector>

#include "hm/fdm1d/fdm1d.hpp"

namespace hm::verification {

/// Linear interpolation of nodal values f on the increasing grid r (constant beyond its ends).
double interpolate(const std::vector<double>& r, const std::vector<double>& f, double x);

/// Area-weighted mean int f r dr / int r dr of the piecewise-linear nodal profile over r0 <= r <= r1
/// (trapezoid on 400 sub-intervals, far finer than the 1D grid).
double shell_mean(const std::vector<double>& r, const std::vector<double>& f, double r0, double r1);

/// The 1D borehole pressure at time t: linear between steps, exact where a step time coincides.
double borehole_pressure_at(const fdm1d::Fdm1dResult& result, double t);

}  // namespace hm::verification
