#include "discretisation.hpp"

#include <array>
#include <cassert>
#include <numbers>
#include <vector>

#include "hm/analytic/failure_criteria.hpp"

namespace hm::fdm1d::detail {

namespace {
constexpr double pi = std::numbers::pi;
using Triplets = std::vector<Eigen::Triplet<double>>;

SparseMatrix from_triplets(int rows, int cols, const Triplets& t) {
  SparseMatrix m(rows, cols);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}
}  // namespace

Blocks assemble(const hm::analytic::DimensionlessParameters& params, const RadialGrid& grid) {
  const auto& mat = params.material;
  const int n = grid.n;
  const double h = grid.h;
  const double nu = mat.nu;
  const double b = mat.b;
  const double lambda = nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double oedometric = (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));  // lambda + 2G, E = 1
  // A3's right-hand side factor. The printed A4 writes it b(nu+1)(2nu-1)/(nu-1), which is the same.
  const double c = b * hm::analytic::oedometric_compliance(nu);
  const double f_b = hm::analytic::vol_strain_factor(mat.vol_strain) * b;

  Blocks blk;
  Triplets mu, mp, st, fl;

  // Mechanics. Interior rows: A4 times h^2, so every row is O(1).
  for (int i = 1; i < n; ++i) {
    const double r = grid.r(i);
    mu.emplace_back(i, i + 1, 1.0 + h / (2.0 * r));
    mu.emplace_back(i, i, -(2.0 + h * h / (r * r)));
    mu.emplace_back(i, i - 1, 1.0 - h / (2.0 * r));
    mp.emplace_back(i, i + 1, -0.5 * c * h);
    mp.emplace_back(i, i - 1, 0.5 * c * h);
  }
  // Stress rows times h: sigma_mr = (lambda + 2G) du/dr + lambda u/r = -(1 - b) p at both ends.
  // One-sided second-order du/dr keeps the row local to nodal values; a ghost node would need a
  // ghost pressure for A4's dp/dr at the wall as well.
  mu.emplace_back(0, 0, -1.5 * oedometric + lambda * h / grid.R_i);
  mu.emplace_back(0, 1, 2.0 * oedometric);
  mu.emplace_back(0, 2, -0.5 * oedometric);
  mp.emplace_back(0, 0, (1.0 - b) * h);
  mu.emplace_back(n, n, 1.5 * oedometric + lambda * h);
  mu.emplace_back(n, n - 1, -2.0 * oedometric);
  mu.emplace_back(n, n - 2, 0.5 * oedometric);
  mp.emplace_back(n, n, (1.0 - b) * h);

  // Fluid rings. Face i + 1/2 sits at r_face(i); the end rings are half rings.
  blk.storage.resize(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double r_in = i == 0 ? grid.R_i : grid.r_face(i - 1);
    const double r_out = i == n ? 1.0 : grid.r_face(i);
    blk.storage[i] = mat.E_over_M * pi * (r_out * r_out - r_in * r_in);
    // E_i = 2 pi (r_out u(r_out) - r_in u(r_in)); u at a wall face is the nodal value.
    if (i == 0) {
      st.emplace_back(i, i, -f_b * 2.0 * pi * r_in);
    } else {
      st.emplace_back(i, i - 1, -f_b * pi * r_in);
      st.emplace_back(i, i, -f_b * pi * r_in);
    }
    if (i == n) {
      st.emplace_back(i, i, f_b * 2.0 * pi * r_out);
    } else {
      st.emplace_back(i, i, f_b * pi * r_out);
      st.emplace_back(i, i + 1, f_b * pi * r_out);
    }
  }
  for (int i = 0; i < n; ++i) {
    const double g_out = 2.0 * pi * grid.r_face(i) / h;
    fl.emplace_back(i, i, g_out);
    fl.emplace_back(i, i + 1, -g_out);
    if (i > 0) {  // no flux through the wall: the injection enters as the source of ring 0
      const double g_in = 2.0 * pi * grid.r_face(i - 1) / h;
      fl.emplace_back(i, i, g_in);
      fl.emplace_back(i, i - 1, -g_in);
    }
  }
  blk.outer_face_conductance = 2.0 * pi * grid.r_face(n - 1) / h;

  blk.mech_u = from_triplets(n + 1, n + 1, mu);
  blk.mech_p = from_triplets(n + 1, n + 1, mp);
  blk.strain = from_triplets(n + 1, n + 1, st);
  blk.flux = from_triplets(n + 1, n + 1, fl);
  blk.source = Eigen::VectorXd::Zero(n + 1);
  blk.source[0] = params.Q;
  return blk;
}

SparseMatrix implicit_euler_matrix(const Blocks& blk, double dt) {
  const int n = static_cast<int>(blk.storage.size()) - 1;
  Triplets t;
  t.reserve(static_cast<std::size_t>(16 * (n + 1)));
  auto add = [&t](const SparseMatrix& m, int row_stride_offset, int col_offset, double scale, int last_row) {
    for (int k = 0; k < m.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(m, k); it; ++it)
        if (it.row() <= last_row)
          t.emplace_back(2 * it.row() + row_stride_offset, 2 * it.col() + col_offset, scale * it.value());
  };
  add(blk.mech_u, 0, 0, 1.0, n);
  add(blk.mech_p, 0, 1, 1.0, n);
  add(blk.strain, 1, 0, 1.0, n - 1);
  add(blk.flux, 1, 1, dt, n - 1);
  for (int i = 0; i < n; ++i) t.emplace_back(2 * i + 1, 2 * i + 1, blk.storage[i]);
  t.emplace_back(2 * n + 1, 2 * n + 1, 1.0);  // Dirichlet p = 0 at r = 1
  return from_triplets(2 * (n + 1), 2 * (n + 1), t);
}

double radial_strain(const Eigen::VectorXd& u, const RadialGrid& grid, int i) {
  const int n = grid.n;
  assert(u.size() == n + 1 && "radial_strain: u has the wrong size");
  if (i == 0) return (-3.0 * u[0] + 4.0 * u[1] - u[2]) / (2.0 * grid.h);
  if (i == n) return (3.0 * u[n] - 4.0 * u[n - 1] + u[n - 2]) / (2.0 * grid.h);
  return (u[i + 1] - u[i - 1]) / (2.0 * grid.h);
}

hm::analytic::RadialState node_state(const Eigen::VectorXd& u, const Eigen::VectorXd& p, const RadialGrid& grid, int i,
                                     double nu, const hm::analytic::LameCylinder* rest) {
  hm::analytic::RadialState s;
  s.p = p[i];
  s.u_r = u[i];
  hm::analytic::set_plane_strain_stresses(s, nu, radial_strain(u, grid, i), u[i] / grid.r(i));
  if (rest) {
    const hm::analytic::RadialState r = rest->state(grid.r(i));
    s.u_r += r.u_r;
    s.sigma_r += r.sigma_r;
    s.sigma_theta += r.sigma_theta;
    s.sigma_z += r.sigma_z;
  }
  return s;
}

double coulomb_of(const hm::analytic::RadialState& s, double friction) {
  const auto mm = hm::analytic::major_minor({s.sigma_r, s.sigma_theta, s.sigma_z});
  return hm::analytic::coulomb_stress(mm.sigma_1, mm.sigma_3, friction);
}

Fdm1dSnapshot make_snapshot(const Eigen::VectorXd& u, const Eigen::VectorXd& p, const RadialGrid& grid,
                            const hm::analytic::DimensionlessParameters& params, double t,
                            const hm::analytic::LameCylinder* rest) {
  Fdm1dSnapshot snap;
  snap.t = t;
  const auto n_nodes = static_cast<std::size_t>(grid.n + 1);
  for (auto* v : {&snap.p, &snap.u_r, &snap.sigma_r, &snap.sigma_theta, &snap.sigma_z, &snap.coulomb})
    v->reserve(n_nodes);
  for (int i = 0; i <= grid.n; ++i) {
    const auto s = node_state(u, p, grid, i, params.material.nu, rest);
    snap.p.push_back(s.p);
    snap.u_r.push_back(s.u_r);
    snap.sigma_r.push_back(s.sigma_r);
    snap.sigma_theta.push_back(s.sigma_theta);
    snap.sigma_z.push_back(s.sigma_z);
    snap.coulomb.push_back(coulomb_of(s, params.friction));
  }
  return snap;
}

}  // namespace hm::fdm1d::detail
