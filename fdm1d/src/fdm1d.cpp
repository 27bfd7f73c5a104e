#include "hm/fdm1d/fdm1d.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "discretisation.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::fdm1d {

namespace an = hm::analytic;

void Fdm1dNumerics::validate(double R_i) const {
  // Measured 1.7 GB at n_r = 1e6 (the grid, its matrix and the stored profiles): above that a run
  // would exhaust memory before it produced anything.
  if (n_r < 8 || n_r > 1000000)
    throw InputError("n_r = " + std::to_string(n_r) + ", allowed: 8 <= n_r <= 1000000" +
                     (n_r > 1000000 ? " (about " + core::format_value(std::round(n_r * 1.7e3 / 1e8) / 10.0) +
                                          " GB at 1.7 kB per interval)"
                                    : std::string()));
  core::require_positive(dt_initial, "dt_initial");
  core::require_finite(dt_growth, "dt_growth");
  if (!(dt_growth >= 1.0))
    throw InputError("dt_growth = " + core::format_value(dt_growth) + ", allowed: dt_growth >= 1");
  core::require_positive(dt_max, "dt_max");
  if (!(dt_max >= dt_initial))
    throw InputError("dt_max = " + core::format_value(dt_max) + ", allowed: dt_max >= dt_initial (" +
                     core::format_value(dt_initial) + ")");
  core::require_positive(t_end, "t_end");
  core::require_feasible_stepping(dt_initial, dt_growth, dt_max, t_end);
  for (std::size_t k = 0; k < output_times.size(); ++k) {
    const std::string element = core::element_of(k);
    if (!(output_times[k] > 0.0 && output_times[k] <= t_end))
      throw FieldError("output_times", element, core::format_value(output_times[k]),
                       "0 < {} <= t_end (" + core::format_value(t_end) + ")");
    if (k > 0 && !(output_times[k] > output_times[k - 1]))
      throw FieldError("output_times", element, core::format_value(output_times[k]), "strictly increasing times");
  }
  for (std::size_t k = 0; k < probe_radii.size(); ++k)
    core::require_closed(probe_radii[k], "probe_radii[" + std::to_string(k) + "]", R_i, 1.0);
}

namespace {

using detail::Blocks;
using detail::RadialGrid;
using Eigen::VectorXd;
using Solver = Eigen::SparseLU<detail::SparseMatrix, Eigen::COLAMDOrdering<int>>;

/// One factorisation per distinct dt: the nominal (growing) step and the occasional shortened one
/// that lands on an output time each keep their own slot.
struct FactorCache {
  double dt = -1.0;
  std::unique_ptr<Solver> solver;
};

/// Linear interpolation weights of the probes in the uniform grid.
struct Probe {
  int i;     // left node
  double w;  // weight of node i + 1
};

Probe locate(double r, const RadialGrid& grid) {
  const double x = (r - grid.R_i) / grid.h;
  const int i = std::clamp(static_cast<int>(std::floor(x)), 0, grid.n - 1);
  return {i, x - i};
}

}  // namespace

void RestState::validate() const {
  core::require_finite(S, "S");
  core::require_finite(p0, "p0");
  if (!(S >= 0.0)) throw InputError("S = " + core::format_value(S) + ", allowed: >= 0 (compression positive)");
  if (!(p0 >= 0.0)) throw InputError("p0 = " + core::format_value(p0) + ", allowed: >= 0 (compression positive)");
}

Fdm1dResult run_fdm1d(const an::DimensionlessParameters& params, const Fdm1dNumerics& numerics,
                      const ProgressCallback& progress, const StepObserver& observer,
                      const StopPredicate& stop_request) {
  return run_fdm1d(params, numerics, RestState{}, progress, observer, stop_request);
}

namespace {

/// One run of the model: the grid and its operators, the fields, and what the run records.
class Fdm1dRun {
 public:
  Fdm1dRun(const an::DimensionlessParameters& params, const Fdm1dNumerics& numerics, const an::LameCylinder* at_rest)
      : params_(params), grid_(numerics.n_r, params.R_i), blk_(detail::assemble(params, grid_)), at_rest_(at_rest) {
    const int n = grid_.n;
    res_.r.resize(static_cast<std::size_t>(n + 1));
    for (int i = 0; i <= n; ++i) res_.r[static_cast<std::size_t>(i)] = grid_.r(i);
    res_.probe_radii = numerics.probe_radii;
    for (double r : numerics.probe_radii) probes_.push_back(locate(r, grid_));
    u_ = VectorXd::Zero(n + 1);
    p_ = VectorXd::Zero(n + 1);
    rhs_.resize(2 * (n + 1));
    record(0.0);
  }

  double time() const { return t_; }
  Fdm1dResult& result() { return res_; }

  /// One implicit Euler step of length dt, landing on `target` when `lands`; false (the summary
  /// says why) when the linear algebra fails or the solution is not finite.
  bool advance(double dt, bool lands, double target, bool nominal) {
    Solver* solver = solver_for(nominal ? nominal_ : landing_, dt);
    if (!solver) return false;
    const int n = grid_.n;
    // Mechanics rows: 0. Fluid rows: old storage + old strain + injected volume. Dirichlet row: 0.
    const VectorXd old_strain = blk_.strain * u_;
    for (int i = 0; i <= n; ++i) {
      rhs_[2 * i] = 0.0;
      rhs_[2 * i + 1] = i < n ? blk_.storage[i] * p_[i] + old_strain[i] + dt * blk_.source[i] : 0.0;
    }
    const VectorXd x = solver->solve(rhs_);
    if (solver->info() != Eigen::Success) {
      fail(Fdm1dSummary::Status::singular_matrix, "sparse LU solve failed at t = " + core::format_value(t_));
      return false;
    }
    if (!x.allFinite()) {
      fail(Fdm1dSummary::Status::non_finite, "the solution at t = " + core::format_value(t_ + dt) +
                                                 " is not finite (Q = " + core::format_value(params_.Q) +
                                                 "): the inputs overflow double precision");
      return false;
    }
    VectorXd u_new(n + 1), p_new(n + 1);
    for (int i = 0; i <= n; ++i) {
      u_new[i] = x[2 * i];
      p_new[i] = x[2 * i + 1];
    }
    const double balance = accept(dt, std::move(u_new), std::move(p_new));
    t_ = lands ? target : t_ + dt;
    ++res_.summary.n_steps;
    res_.summary.max_balance_error = std::max(res_.summary.max_balance_error, balance);
    record(balance);
    if (!(t_ < target)) res_.snapshots.push_back(detail::make_snapshot(u_, p_, grid_, params_, t_, at_rest_));
    return true;
  }

  void fail(Fdm1dSummary::Status status, std::string message) {
    res_.summary.status = status;
    res_.summary.message = std::move(message);
  }

 private:
  /// The step's new fields become the state; returns the fluid-volume balance of the whole annulus,
  /// from the fields (not from the matrix): injected = d(stored) + outflow, the outflow being what
  /// crosses r_{n-1/2} minus what the Dirichlet half ring at r = 1 stores by its own strain change.
  double accept(double dt, VectorXd u_new, VectorXd p_new) {
    const int n = grid_.n;
    const VectorXd d_strain = blk_.strain * (u_new - u_);
    const double d_stored = blk_.storage.dot(p_new - p_) + d_strain.sum();
    const double d_out = dt * blk_.outer_face_conductance * (p_new[n - 1] - p_new[n]) - d_strain[n] -
                         blk_.storage[n] * (p_new[n] - p_[n]);
    const double injected = params_.Q * dt;
    const double scale = std::max({std::abs(injected), std::abs(d_stored), std::abs(d_out)});
    u_ = std::move(u_new);
    p_ = std::move(p_new);
    outflow_ += d_out;
    return scale > 0.0 ? std::abs(injected - d_stored - d_out) / scale : 0.0;
  }

  /// The factorisation of the step dt in `slot`, made when dt changes; null after a failure.
  Solver* solver_for(FactorCache& slot, double dt) {
    if (slot.dt == dt) return slot.solver.get();
    slot.solver = std::make_unique<Solver>();
    slot.solver->compute(detail::implicit_euler_matrix(blk_, dt));
    slot.dt = dt;
    ++res_.summary.n_factorisations;
    if (slot.solver->info() != Eigen::Success) {
      fail(Fdm1dSummary::Status::singular_matrix,
           "sparse LU failed at dt = " + core::format_value(dt) + ": " + slot.solver->lastErrorMessage());
      return nullptr;
    }
    return slot.solver.get();
  }

  void record(double balance_error) {
    BoreholeSample s;
    s.t = t_;
    s.p_h = p_[0];
    s.injected = params_.Q * t_;
    s.stored = blk_.storage.dot(p_) + (blk_.strain * u_).sum();
    s.outflow = outflow_;
    s.balance_error = balance_error;
    const auto wall = detail::node_state(u_, p_, grid_, 0, params_.material.nu, at_rest_);
    s.sigma_r = wall.sigma_r;
    s.sigma_theta = wall.sigma_theta;
    s.sigma_z = wall.sigma_z;
    s.coulomb = detail::coulomb_of(wall, params_.friction);
    res_.borehole.push_back(s);
    std::vector<double> pp;
    pp.reserve(probes_.size());
    for (const auto& pr : probes_) pp.push_back((1.0 - pr.w) * p_[pr.i] + pr.w * p_[pr.i + 1]);
    res_.probe_p.push_back(std::move(pp));
    Eigen::Index i_min = 0;
    const double p_min = p_.minCoeff(&i_min);
    if (p_min < res_.min_pressure.p) res_.min_pressure = {p_min, grid_.r(static_cast<int>(i_min)), t_};
  }

  const an::DimensionlessParameters& params_;
  const RadialGrid grid_;
  const Blocks blk_;
  const an::LameCylinder* at_rest_;
  std::vector<Probe> probes_;
  Fdm1dResult res_;
  VectorXd u_, p_, rhs_;
  double t_ = 0.0, outflow_ = 0.0;
  FactorCache nominal_, landing_;  // the nominal (growing) step's and a shortened step's
};

/// The step towards `target` from `t`: the nominal one, or the remainder when it lands (`lands`);
/// when less than two nominal steps remain, half the remainder instead of leaving a sliver step (a
/// sliver's volume change drowns in the round-off of the stored volume).
double step_towards(double target, double t, double dt_nominal, bool& lands) {
  const double remaining = target - t;
  lands = remaining <= dt_nominal * (1.0 + 1e-10);
  if (lands) return remaining;
  if (remaining < 2.0 * dt_nominal) return 0.5 * remaining;
  return dt_nominal;
}

}  // namespace

Fdm1dResult run_fdm1d(const an::DimensionlessParameters& params, const Fdm1dNumerics& numerics, const RestState& rest,
                      const ProgressCallback& progress, const StepObserver& observer,
                      const StopPredicate& stop_request) {
  params.validate();
  rest.validate();
  if (!(params.R_i > 0.0))
    throw InputError("R_i = " + core::format_value(params.R_i) +
                     ", allowed: 0 < R_i < 1 (the 1D model needs a borehole)");
  numerics.validate(params.R_i);
  const auto start = std::chrono::steady_clock::now();
  // The rest state in effective stress (RestState): none when zero, so such runs are those without it.
  const double b = params.material.b;
  const std::optional<an::LameCylinder> rest_lame =
      rest.is_zero() ? std::nullopt
                     : std::optional<an::LameCylinder>(std::in_place, (1.0 - b) * rest.p0, rest.S - b * rest.p0,
                                                       params.R_i, 1.0, params.material.nu);
  std::vector<double> targets = numerics.output_times;
  if (targets.empty() || targets.back() < numerics.t_end) targets.push_back(numerics.t_end);

  Fdm1dRun run(params, numerics, rest_lame ? &*rest_lame : nullptr);
  Fdm1dResult& res = run.result();
  if (observer) observer(res);
  const auto finished = [&]() -> Fdm1dResult {
    res.summary.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(res);
  };

  // Implicit Euler, landing exactly on every output time.
  double dt_nominal = numerics.dt_initial;
  for (double target : targets) {
    while (run.time() < target) {
      bool lands = false;
      double dt = step_towards(target, run.time(), dt_nominal, lands);
      // Within round-off of the nominal step: keep its factorisation (an O(1e-16 dt) time shift).
      const bool nominal = std::abs(dt - dt_nominal) <= 1e-12 * dt_nominal;
      if (nominal) dt = dt_nominal;
      if (!run.advance(dt, lands, target, nominal)) return finished();
      if (observer) observer(res);
      if (progress) progress(run.time(), numerics.t_end);
      dt_nominal = std::min(dt_nominal * numerics.dt_growth, numerics.dt_max);
      if (stop_request && run.time() < numerics.t_end && stop_request()) {
        run.fail(Fdm1dSummary::Status::interrupted, "stopped on request at t = " + core::format_value(run.time()));
        return finished();
      }
    }
  }
  return finished();
}

}  // namespace hm::fdm1d
