#pragma once
/// \file
/// CSV output of a 1D run, read by figures/fig10_*.py and fig11_*.py and by users:
///   borehole.csv  t, p_h, injected, stored, outflow, balance_error, wall stresses and sigma_CC
///   profiles.csv  t, r, p, u_r, sigma_r, sigma_theta, sigma_z, coulomb (one row per node and time)
///   probes.csv    t, p_r<radius> for each probe radius
///   steady_state.csv  r, p, u_r, sigma_r, sigma_theta, sigma_z, coulomb of the corrected Appendix B
///                     at the grid nodes: the state the run tends to (dashed in Figs. 10, 11)
#include <filesystem>

#include "hm/analytic/physical_parameters.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace hm::cases {

void write_fdm1d_results(const std::filesystem::path& dir, const hm::fdm1d::Fdm1dResult& result,
                         const hm::analytic::DimensionlessParameters& params);

}  // namespace hm::cases
