#pragma once
/// \file
/// The monolithic radial 1D poroelastic finite-difference model of the paper's Appendix A
/// (Eqs. A1-A6): displacement u and pore pressure p on the annulus R_i <= r <= 1, solved together
/// by implicit Euler, with continuous injection Q into the borehole (Section 3.2, Fig. 9).
///
/// Dimensionless as in the paper (lengths / R, stresses and pressures / E, time / t_s); tension
/// positive; stresses are effective (sigma_m of Eq. 1). Total stress = effective - b p.
/// Limits: radial symmetry and plane strain; unfractured (the model stops being valid at the first
/// fracture, Appendix A); a borehole is required (R_i > 0, no point injection).
#include <functional>
#include <string>
#include <vector>

#include "hm/analytic/physical_parameters.hpp"

namespace hm::fdm1d {

/// Numerical settings of the 1D model. Every field has its default here; validate() checks them.
struct Fdm1dNumerics {
  /// n_r, number of grid intervals on [R_i, 1] (nodes r_i = R_i + i dr, i = 0..n_r). Allowed: >= 8.
  /// Default 400: steady u and wall stresses within ~0.2% of Appendix B (tests/fdm1d/test_fdm1d.cpp).
  int n_r = 400;
  /// First time step (dimensionless t / t_s). Allowed: > 0.
  double dt_initial = 1e-5;
  /// Geometric growth factor of the time step, dt_{k+1} = min(dt_growth dt_k, dt_max). Allowed: >= 1.
  double dt_growth = 1.05;
  /// Largest time step. Allowed: >= dt_initial.
  double dt_max = 1e-3;
  /// End time of the run. Allowed: > 0.
  double t_end = 1.0;
  /// Times at which whole profiles are stored; steps are shortened to land on them exactly.
  /// t_end is always stored as well. Allowed: strictly increasing, each in (0, t_end].
  std::vector<double> output_times = {0.025, 0.05, 0.1, 0.25, 1.0};
  /// Radii at which p is recorded at every step (linear interpolation between nodes; Fig. 10C/D).
  /// Our choice of default (the paper does not give its 4 points). Allowed: each in [R_i, 1].
  std::vector<double> probe_radii = {0.2, 0.4, 0.6, 0.8};

  /// Throws hm::InputError "field = value, allowed: rule" for the first violated rule.
  /// R_i is the borehole radius the probes must lie outside of.
  void validate(double R_i) const;
};

/// Whole profiles at one output time, one value per grid node.
struct Fdm1dSnapshot {
  double t = 0.0;
  std::vector<double> p;            ///< pore pressure
  std::vector<double> u_r;          ///< radial displacement
  std::vector<double> sigma_r;      ///< effective radial stress
  std::vector<double> sigma_theta;  ///< effective hoop stress
  std::vector<double> sigma_z;      ///< effective axial stress (plane strain)
  std::vector<double> coulomb;      ///< sigma_CC of Eq. 11, sigma_1/sigma_3 = max/min of the three
};

/// The borehole and the fluid-volume balance after one time step (and at t = 0).
/// Volumes are per unit axial length (dimensionless, / R^2).
struct BoreholeSample {
  double t = 0.0;
  double p_h = 0.0;       ///< borehole pressure p at r = R_i
  double injected = 0.0;  ///< Q t
  /// Fluid stored in the annulus: sum over rings of (E/M) V_i p_i + f b (ring integral of eps_r + eps_theta).
  double stored = 0.0;
  double outflow = 0.0;  ///< cumulative volume that left through r = 1 (negative: backflow)
  /// |Q dt - d(stored) - d(outflow)| / max(Q dt, |d stored|, |d outflow|) of this step; 0 at t = 0.
  double balance_error = 0.0;
  /// Effective stresses and sigma_CC (Eq. 11) at the borehole wall r = R_i.
  double sigma_r = 0.0, sigma_theta = 0.0, sigma_z = 0.0, coulomb = 0.0;
};

/// The smallest pressure over all steps and nodes (the Mandel-Cryer dip of Fig. 10D).
struct PressureMinimum {
  double p = 0.0;  ///< value (0 if p never went below zero)
  double r = 0.0;  ///< where
  double t = 0.0;  ///< when
};

/// Outcome of a run: numerical trouble is reported here, never thrown.
struct Fdm1dSummary {
  /// non_finite: the solution overflowed (inputs beyond double precision, e.g. Q = 1e308).
  /// interrupted: stopped between two steps because the stop predicate said so (the result holds
  /// every step up to then).
  enum class Status { success, singular_matrix, non_finite, interrupted };
  Status status = Status::success;
  std::string message;             ///< human-readable; empty on success
  long n_steps = 0;                ///< time steps taken
  long n_factorisations = 0;       ///< sparse LU factorisations (one per distinct dt)
  double max_balance_error = 0.0;  ///< largest BoreholeSample::balance_error
  double wall_seconds = 0.0;
  bool is_success() const { return status == Status::success; }
};

struct Fdm1dResult {
  std::vector<double> r;                     ///< grid nodes, r[0] = R_i, r[n_r] = 1
  std::vector<Fdm1dSnapshot> snapshots;      ///< at output_times, then t_end if not among them
  std::vector<BoreholeSample> borehole;      ///< t = 0, then after every step
  std::vector<double> probe_radii;           ///< copy of Fdm1dNumerics::probe_radii
  std::vector<std::vector<double>> probe_p;  ///< probe_p[k][j]: p at probe j at time borehole[k].t
  PressureMinimum min_pressure;
  Fdm1dSummary summary;
};

/// Called after every step with the current time and t_end (e.g. for a progress bar).
using ProgressCallback = std::function<void(double t, double t_end)>;
/// Called with the result so far after t = 0 is recorded and after every accepted step (its new
/// borehole and probe row, and its snapshot if the step landed on an output time): to write as it goes.
using StepObserver = std::function<void(const Fdm1dResult& so_far)>;
/// Asked after every accepted step (and its observer); true stops the run there (status interrupted),
/// unless that step reached t_end.
using StopPredicate = std::function<bool()>;

/// The rock at rest before injection under an isotropic in-situ stress (the 1D model's only far
/// field: radial symmetry), in the deviation form of the lattice (docs/insitu.md): p is the deviation
/// from p0, so the rest state is Lame's cylinder in effective stress, wall pressure (1 - b) p0 and
/// outer pressure S - b p0, and every reported stress and u_r is the rest state plus the increment
/// (exact: the model is linear and its outer boundary is traction-free in the increment).
struct RestState {
  double S = 0.0;   ///< in-situ stress S/E, compression positive. Allowed: >= 0, finite.
  double p0 = 0.0;  ///< rest pore pressure p0/E. Allowed: >= 0, finite.
  bool is_zero() const { return S == 0.0 && p0 == 0.0; }
  /// Throws hm::InputError "field = value, allowed: rule".
  void validate() const;
};

/// Runs the Appendix A model from p = u = 0 at t = 0 to numerics.t_end.
/// Validates both inputs first (throws hm::InputError, also for R_i = 0). Cost: one banded sparse
/// solve of 2(n_r + 1) unknowns per step.
Fdm1dResult run_fdm1d(const hm::analytic::DimensionlessParameters& params, const Fdm1dNumerics& numerics,
                      const ProgressCallback& progress = {}, const StepObserver& observer = {},
                      const StopPredicate& stop = {});
/// The same from the rest state `rest` (its stresses and u_r added to every reported one).
Fdm1dResult run_fdm1d(const hm::analytic::DimensionlessParameters& params, const Fdm1dNumerics& numerics,
                      const RestState& rest, const ProgressCallback& progress = {}, const StepObserver& observer = {},
                      const StopPredicate& stop = {});

}  // namespace hm::fdm1d
