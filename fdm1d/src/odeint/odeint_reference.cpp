#include "hm/fdm1d/odeint_reference.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseLU>
#include <boost/numeric/odeint.hpp>
#include <chrono>
#include <utility>

#include "discretisation.hpp"  // fdm1d/src
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::fdm1d {

namespace an = hm::analytic;

void OdeintTolerances::validate() const {
  core::require_positive(absolute, "absolute");
  core::require_positive(relative, "relative");
}

namespace {

namespace ublas = boost::numeric::ublas;
namespace odeint = boost::numeric::odeint;
using State = ublas::vector<double>;
using Matrix = ublas::matrix<double>;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Why eliminate u: the mechanics rows carry no time derivative, so the semi-discrete system is an
// index-1 DAE, which Odeint's steppers cannot take. The mechanics rows are linear and homogeneous,
// K_uu u + K_up p = 0, so u = G p with G = -K_uu^{-1} K_up exactly (no approximation), and the
// fluid rows become the linear ODE  S dp/dt = s - A p  with S = storage + strain G. It is stiff
// (|lambda|max ~ 1/(S h^2)), so an explicit method would need ~h^2 steps: rosenbrock4 (L-stable,
// order 4, embedded error estimate) with the constant Jacobian J = -S^{-1} A is the natural choice.
struct LinearOde {
  const RowMatrix* J;
  const Eigen::VectorXd* c;
  void operator()(const State& x, State& dxdt, double /*t*/) const {
    const auto n = static_cast<Eigen::Index>(x.size());
    Eigen::Map<const Eigen::VectorXd> xv(&x[0], n);
    Eigen::Map<Eigen::VectorXd> dv(&dxdt[0], n);
    dv.noalias() = (*J) * xv + (*c);
  }
};

struct ConstantJacobian {
  const Matrix* J;
  void operator()(const State& /*x*/, Matrix& jac, double /*t*/, State& dfdt) const {
    jac = *J;
    for (auto& v : dfdt) v = 0.0;
  }
};

}  // namespace

Fdm1dOdeintResult run_fdm1d_odeint(const an::DimensionlessParameters& params, const Fdm1dNumerics& numerics,
                                   const OdeintTolerances& tolerances) {
  params.validate();
  if (!(params.R_i > 0.0))
    throw InputError("R_i = " + core::format_value(params.R_i) +
                     ", allowed: 0 < R_i < 1 (the 1D model needs a borehole)");
  numerics.validate(params.R_i);
  if (numerics.n_r > 2000)
    throw InputError("n_r = " + std::to_string(numerics.n_r) + ", allowed: n_r <= 2000 for the dense Odeint reference");
  tolerances.validate();
  const auto start = std::chrono::steady_clock::now();

  // 1. The same operators as the implicit-Euler solver, for the unit rate Q = 1 (p is linear in Q).
  const detail::RadialGrid grid(numerics.n_r, params.R_i);
  const int n = grid.n;
  an::DimensionlessParameters unit = params;
  unit.Q = 1.0;
  const detail::Blocks blk = detail::assemble(unit, grid);

  // 2. u = G p from the mechanics rows; only p_0..p_{n-1} are free (p_n = 0).
  Eigen::SparseLU<detail::SparseMatrix> mech(blk.mech_u);
  const Eigen::MatrixXd G = -mech.solve(Eigen::MatrixXd(blk.mech_p));
  const Eigen::MatrixXd strain = Eigen::MatrixXd(blk.strain);
  const Eigen::MatrixXd flux = Eigen::MatrixXd(blk.flux);
  Eigen::MatrixXd S = strain.topRows(n) * G.leftCols(n);
  S.diagonal() += blk.storage.head(n);
  const Eigen::PartialPivLU<Eigen::MatrixXd> S_lu(S);
  const RowMatrix J = -S_lu.solve(flux.topLeftCorner(n, n));
  const Eigen::VectorXd c = S_lu.solve(blk.source.head(n));
  Matrix J_ublas(static_cast<std::size_t>(n), static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) J_ublas(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) = J(i, j);

  // 3. Integrate p/Q, observing at 0 and every output time.
  std::vector<double> times{0.0};
  times.insert(times.end(), numerics.output_times.begin(), numerics.output_times.end());
  if (times.back() < numerics.t_end) times.push_back(numerics.t_end);
  State x(static_cast<std::size_t>(n), 0.0);
  std::vector<Eigen::VectorXd> observed;
  auto observer = [&observed, n](const State& s, double) {
    observed.emplace_back(Eigen::Map<const Eigen::VectorXd>(&s[0], n));
  };
  Fdm1dOdeintResult res;
  res.n_steps = static_cast<long>(odeint::integrate_times(
      odeint::make_dense_output(tolerances.absolute, tolerances.relative, odeint::rosenbrock4<double>()),
      std::make_pair(LinearOde{&J, &c}, ConstantJacobian{&J_ublas}), x, times.begin(), times.end(), numerics.dt_initial,
      observer));

  // 4. Back to p = Q (p/Q), u = G p, and the same post-processing as run_fdm1d.
  res.r.resize(static_cast<std::size_t>(n + 1));
  for (int i = 0; i <= n; ++i) res.r[static_cast<std::size_t>(i)] = grid.r(i);
  for (std::size_t k = 1; k < observed.size() && k < times.size(); ++k) {
    Eigen::VectorXd p = Eigen::VectorXd::Zero(n + 1);
    p.head(n) = params.Q * observed[k];
    const Eigen::VectorXd u = G * p;
    res.snapshots.push_back(detail::make_snapshot(u, p, grid, params, times[k]));
  }
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace hm::fdm1d
