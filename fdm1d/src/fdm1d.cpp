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
  const an::LameCylinder* at_rest = rest_lame ? &*rest_lame : nullptr;

  // 1. Grid, operators, output schedule.
  const RadialGrid grid(numerics.n_r, params.R_i);
  const int n = grid.n;
  const Blocks blk = detail::assemble(params, grid);
  std::vector<double> targets = numerics.output_times;
  if (targets.empty() || targets.back() < numerics.t_end) targets.push_back(numerics.t_end);

  Fdm1dResult res;
  res.r.resize(static_cast<std::size_t>(n + 1));
  for (int i = 0; i <= n; ++i) res.r[static_cast<std::size_t>(i)] = grid.r(i);
  res.probe_radii = numerics.probe_radii;
  std::vector<Probe> probes;
  for (double r : numerics.probe_radii) probes.push_back(locate(r, grid));

  VectorXd u = VectorXd::Zero(n + 1), p = VectorXd::Zero(n + 1);
  double t = 0.0, outflow = 0.0;

  auto record = [&](double balance_error) {
    BoreholeSample s;
    s.t = t;
    s.p_h = p[0];
    s.injected = params.Q * t;
    s.stored = blk.storage.dot(p) + (blk.strain * u).sum();
    s.outflow = outflow;
    s.balance_error = balance_error;
    const auto wall = detail::node_state(u, p, grid, 0, params.material.nu, at_rest);
    s.sigma_r = wall.sigma_r;
    s.sigma_theta = wall.sigma_theta;
    s.sigma_z = wall.sigma_z;
    s.coulomb = detail::coulomb_of(wall, params.friction);
    res.borehole.push_back(s);
    std::vector<double> pp;
    pp.reserve(probes.size());
    for (const auto& pr : probes) pp.push_back((1.0 - pr.w) * p[pr.i] + pr.w * p[pr.i + 1]);
    res.probe_p.push_back(std::move(pp));
    Eigen::Index i_min = 0;
    const double p_min = p.minCoeff(&i_min);
    if (p_min < res.min_pressure.p) res.min_pressure = {p_min, grid.r(static_cast<int>(i_min)), t};
  };
  record(0.0);
  if (observer) observer(res);

  auto stop = [&]() -> Fdm1dResult {
    res.summary.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(res);
  };

  FactorCache nominal, landing;
  auto solver_for = [&](FactorCache& slot, double dt) -> Solver* {
    if (slot.dt == dt) return slot.solver.get();
    slot.solver = std::make_unique<Solver>();
    slot.solver->compute(detail::implicit_euler_matrix(blk, dt));
    slot.dt = dt;
    ++res.summary.n_factorisations;
    if (slot.solver->info() != Eigen::Success) {
      res.summary.status = Fdm1dSummary::Status::singular_matrix;
      res.summary.message =
          "sparse LU failed at dt = " + core::format_value(dt) + ": " + slot.solver->lastErrorMessage();
      return nullptr;
    }
    return slot.solver.get();
  };

  // 2. Time loop: implicit Euler, landing exactly on every output time.
  double dt_nominal = numerics.dt_initial;
  VectorXd rhs(2 * (n + 1)), x(2 * (n + 1));
  for (double target : targets) {
    while (t < target) {
      // Land on the target; when less than two nominal steps remain, halve the remainder instead of
      // leaving a sliver step (a sliver's volume change drowns in the round-off of the stored volume).
      const double remaining = target - t;
      double dt = dt_nominal;
      bool lands = false;
      if (remaining <= dt * (1.0 + 1e-10)) {
        dt = remaining;
        lands = true;
      } else if (remaining < 2.0 * dt) {
        dt = 0.5 * remaining;
      }
      FactorCache* slot = &nominal;
      // Within round-off of the nominal step: keep its factorisation (an O(1e-16 dt) time shift).
      if (std::abs(dt - dt_nominal) <= 1e-12 * dt_nominal) {
        dt = dt_nominal;
      } else {
        slot = &landing;
      }
      Solver* solver = solver_for(*slot, dt);
      if (!solver) return stop();

      // Mechanics rows: 0. Fluid rows: old storage + old strain + injected volume. Dirichlet row: 0.
      const VectorXd old_strain = blk.strain * u;
      for (int i = 0; i <= n; ++i) {
        rhs[2 * i] = 0.0;
        rhs[2 * i + 1] = i < n ? blk.storage[i] * p[i] + old_strain[i] + dt * blk.source[i] : 0.0;
      }
      x = solver->solve(rhs);
      if (solver->info() != Eigen::Success) {
        res.summary.status = Fdm1dSummary::Status::singular_matrix;
        res.summary.message = "sparse LU solve failed at t = " + core::format_value(t);
        return stop();
      }
      if (!x.allFinite()) {
        res.summary.status = Fdm1dSummary::Status::non_finite;
        res.summary.message = "the solution at t = " + core::format_value(t + dt) +
                              " is not finite (Q = " + core::format_value(params.Q) +
                              "): the inputs overflow double precision";
        return stop();
      }
      VectorXd u_new(n + 1), p_new(n + 1);
      for (int i = 0; i <= n; ++i) {
        u_new[i] = x[2 * i];
        p_new[i] = x[2 * i + 1];
      }

      // Fluid-volume balance of the whole annulus, from the fields (not from the matrix):
      // injected = d(stored) + outflow, the outflow being what crosses r_{n-1/2} minus what the
      // Dirichlet half ring at r = 1 stores by its own strain change.
      const VectorXd d_strain = blk.strain * (u_new - u);
      const double d_stored = blk.storage.dot(p_new - p) + d_strain.sum();
      const double d_out = dt * blk.outer_face_conductance * (p_new[n - 1] - p_new[n]) - d_strain[n] -
                           blk.storage[n] * (p_new[n] - p[n]);
      const double injected = params.Q * dt;
      const double scale = std::max({std::abs(injected), std::abs(d_stored), std::abs(d_out)});
      const double balance = scale > 0.0 ? std::abs(injected - d_stored - d_out) / scale : 0.0;

      u = std::move(u_new);
      p = std::move(p_new);
      outflow += d_out;
      t = lands ? target : t + dt;
      ++res.summary.n_steps;
      res.summary.max_balance_error = std::max(res.summary.max_balance_error, balance);
      record(balance);
      if (!(t < target)) res.snapshots.push_back(detail::make_snapshot(u, p, grid, params, t, at_rest));
      if (observer) observer(res);
      if (progress) progress(t, numerics.t_end);
      dt_nominal = std::min(dt_nominal * numerics.dt_growth, numerics.dt_max);
      if (stop_request && t < numerics.t_end && stop_request()) {
        res.summary.status = Fdm1dSummary::Status::interrupted;
        res.summary.message = "stopped on request at t = " + core::format_value(t);
        return stop();
      }
    }
  }

  return stop();
}

}  // namespace hm::fdm1d
