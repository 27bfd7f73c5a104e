#pragma once
/// \file
/// An independent time integration of the same semi-discrete system as run_fdm1d (same grid, same
/// operators), by Boost.Odeint's adaptive stiff Rosenbrock method of order 4. It exists to measure
/// implicit Euler's time error: at equal n_r the two differ only in the time integration.
#include <string>
#include <vector>

#include "hm/fdm1d/fdm1d.hpp"

namespace hm::fdm1d {

/// Error control of the Rosenbrock integrator. The state integrated is p/Q (u follows from p), so
/// both tolerances are independent of Q.
struct OdeintTolerances {
  /// Absolute error per step on p/Q. Allowed: > 0.
  double absolute = 1e-12;
  /// Relative error per step. Allowed: > 0.
  double relative = 1e-10;

  /// Throws hm::InputError "field = value, allowed: rule".
  void validate() const;
};

struct Fdm1dOdeintResult {
  std::vector<double> r;                 ///< grid nodes, as in Fdm1dResult
  std::vector<Fdm1dSnapshot> snapshots;  ///< at numerics.output_times, then t_end if not among them
  long n_steps = 0;                      ///< accepted Rosenbrock steps
  double wall_seconds = 0.0;
};

/// Integrates the Appendix A semi-discretisation from p = u = 0 to numerics.t_end with rosenbrock4.
/// Uses n_r, t_end, output_times of `numerics` (dt_initial only as the first trial step).
/// Limits: dense linear algebra, O(n_r^3) setup and per step; n_r <= 2000 (checked).
Fdm1dOdeintResult run_fdm1d_odeint(const hm::analytic::DimensionlessParameters& params, const Fdm1dNumerics& numerics,
                                   const OdeintTolerances& tolerances = {});

}  // namespace hm::fdm1d
