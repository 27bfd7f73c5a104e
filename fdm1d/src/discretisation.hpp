#pragma once
// The spatial discretisation of Appendix A, shared by the implicit-Euler solver and the Odeint
// reference so that both integrate exactly the same semi-discrete system.
//
// Grid: r_i = R_i + i h, h = (1 - R_i)/n, i = 0..n. Unknowns u_i and p_i at every node; p_n = 0.
//
// Mechanics (one row per node, all homogeneous in (u, p)):
//   interior: A4 (= A3 by centred differences), multiplied by h^2;
//   i = 0:    sigma_mr(R_i) + (1 - b) p_0 = 0, i.e. the total radial stress equals -p_h;
//   i = n:    sigma_mr(1) + (1 - b) p_n = 0;
//   du/dr at both ends by the one-sided second-order formula, multiplied by h.
// Fluid (finite-volume rings [r_{i-1/2}, r_{i+1/2}] clipped to [R_i, 1], half rings at both ends):
//   (E/M) V_i dp_i/dt + f b dE_i(u)/dt + F_{i+1/2} - F_{i-1/2} = Q delta_{i0},
//   V_i = exact ring area, F_{i+1/2} = -2 pi r_{i+1/2} (p_{i+1} - p_i)/h, F_{-1/2} = 0,
//   E_i(u) = 2 pi (r_{i+1/2} u_{i+1/2} - r_{i-1/2} u_{i-1/2}) = ring integral of eps_r + eps_theta
//   (exact for the face values; u at interior faces by the mean of its two nodes).
//   E_i telescopes, so the sum over rings is 2 pi (u_n - R_i u_0), the area change of the annulus:
//   the scheme is conservative and the volume balance closes to round-off.
//   (A6 instead takes the centred nodal eps_v times V_i = 2 pi r_i dr; that differs by
//   dr (u_{i+1} - 2u_i + u_{i-1})/4 per ring, still second order but not telescoping.)
// Borehole node: the borehole itself stores no fluid, as in A6 (the paper's 2D Eq. 16 gives it a
//   volume V_h; A6 has no such term). Node 0 is the wall; its half ring receives the whole injection,
//   no flux crosses r = R_i otherwise. A fluid-filled borehole would add (E/K_w) pi R_i^2 dp_0/dt +
//   2 pi R_i du_0/dt to ring 0 and slow the early transient; we follow A6 so the numbers are the paper's.
#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hm/analytic/lame.hpp"
#include "hm/analytic/physical_parameters.hpp"
#include "hm/analytic/radial_state.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace hm::fdm1d::detail {

using SparseMatrix = Eigen::SparseMatrix<double>;

struct RadialGrid {
  int n = 0;  ///< intervals
  double R_i = 0.0;
  double h = 0.0;
  RadialGrid(int n_r, double inner_radius) : n(n_r), R_i(inner_radius), h((1.0 - inner_radius) / n_r) {}
  double r(int i) const { return i == n ? 1.0 : R_i + i * h; }
  /// Face between node i and i + 1.
  double r_face(int i) const { return R_i + (i + 0.5) * h; }
};

/// The operators of the semi-discrete system, each (n+1) x (n+1): rows are equations (node i),
/// columns unknowns (u_j or p_j).
struct Blocks {
  SparseMatrix mech_u, mech_p;          ///< mechanics rows: mech_u u + mech_p p = 0
  Eigen::VectorXd storage;              ///< (E/M) V_i, including the Dirichlet half ring i = n
  SparseMatrix strain;                  ///< f b E_i(u), rows 0..n
  SparseMatrix flux;                    ///< F_{i+1/2} - F_{i-1/2} for rows 0..n-1; row n empty
  Eigen::VectorXd source;               ///< Q at row 0
  double outer_face_conductance = 0.0;  ///< 2 pi r_{n-1/2}/h: F_{n-1/2} = this (p_{n-1} - p_n)
};

Blocks assemble(const hm::analytic::DimensionlessParameters& params, const RadialGrid& grid);

/// Implicit-Euler matrix of size 2(n+1), unknowns interleaved [u_0, p_0, u_1, p_1, ...] (narrow band):
/// mechanics rows as in Blocks, fluid rows storage + strain + dt flux, the last fluid row p_n = 0.
SparseMatrix implicit_euler_matrix(const Blocks& blocks, double dt);

/// du/dr at node i: centred inside, one-sided second order at the ends.
double radial_strain(const Eigen::VectorXd& u, const RadialGrid& grid, int i);

/// Effective stresses at node i from u (plane strain), with p and u_r filled in; plus the rest
/// state's u_r and stresses at r_i when `rest` is given (RestState).
hm::analytic::RadialState node_state(const Eigen::VectorXd& u, const Eigen::VectorXd& p, const RadialGrid& grid, int i,
                                     double nu, const hm::analytic::LameCylinder* rest = nullptr);

/// sigma_CC of Eq. 11 with sigma_1, sigma_3 = max, min of the three effective stresses.
double coulomb_of(const hm::analytic::RadialState& s, double friction);

/// Whole profiles at time t from nodal u and p.
Fdm1dSnapshot make_snapshot(const Eigen::VectorXd& u, const Eigen::VectorXd& p, const RadialGrid& grid,
                            const hm::analytic::DimensionlessParameters& params, double t,
                            const hm::analytic::LameCylinder* rest = nullptr);

}  // namespace hm::fdm1d::detail
