#pragma once
/// \file
/// The paper's Section 3.2 "insights from 1D", measured on a run_fdm1d result: the approach of the
/// borehole pressure to steady state, the transient negative (Mandel-Cryer) pressure of Fig. 10D,
/// and the ratio sigma_CC/sigma_1 at the borehole wall that decides whether the first failure is
/// tensile or shear. Dimensionless; tension positive.
#include <vector>

#include "hm/fdm1d/fdm1d.hpp"

namespace hm::fdm1d {

/// Steady borehole pressure of Eq. 23 (= B3 at r = R_i): p_h = -(Q/2pi) ln R_i.
double steady_borehole_pressure(double Q, double R_i);

/// First time at which p_h reaches `fraction` of p_h_steady, linearly interpolated between steps.
/// NaN if it is never reached within the run (or p_h_steady <= 0).
double time_to_fraction(const Fdm1dResult& result, double p_h_steady, double fraction = 0.99);

/// How the pressure at one probe goes below zero.
struct ProbeNegativePressure {
  double r = 0.0;
  double p_min = 0.0;            ///< smallest p at the probe (0 if never negative)
  double t_min = 0.0;            ///< when
  double time_negative = 0.0;    ///< total time with p < 0 (zero crossings interpolated)
  double last_negative_t = 0.0;  ///< end of the last interval with p < 0 (0 if none)
};

/// sigma_CC/sigma_1 at the wall. Failure is by shear before tension when C_u/T_u is below it
/// (sigma_CC/C_u > sigma_1/T_u), so it is the C_u/T_u threshold of Section 3.2 (paper: ~5.5).
/// Only defined while sigma_1 > 0; NaN otherwise.
double wall_coulomb_ratio(const BoreholeSample& wall);

struct Section32Diagnostics {
  double p_h_steady = 0.0;       ///< Eq. 23
  double t_99 = 0.0;             ///< time_to_fraction(0.99); NaN if not reached
  PressureMinimum min_pressure;  ///< over every step and node (copied from the result)
  std::vector<ProbeNegativePressure> probes;
  double wall_ratio_steady = 0.0;  ///< of the analytic steady state (Appendix B, SteadyBorehole)
  double wall_ratio_final = 0.0;   ///< at the last step (the steady value if the run reached it)
  /// Extremes over the steps with sigma_1 > 0. The first steps count too, where the wall field is
  /// barely resolved: an extreme at t ~ dt_initial depends on n_r and dt_initial.
  double wall_ratio_min = 0.0, t_wall_ratio_min = 0.0;
  double wall_ratio_max = 0.0, t_wall_ratio_max = 0.0;
};

/// All of the above for one run. `params` must be the parameters of the run.
Section32Diagnostics section32_diagnostics(const Fdm1dResult& result,
                                           const hm::analytic::DimensionlessParameters& params);

}  // namespace hm::fdm1d
