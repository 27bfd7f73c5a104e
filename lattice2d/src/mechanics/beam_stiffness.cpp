#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include <Eigen/Cholesky>

#include "hm/core/validation.hpp"
#include "hm/core/input_error.hpp"

namespace hm::lattice2d {

void BeamParameters::validate() const {
  using namespace hm::core;
  require_positive(normal_stiffness, "normal_stiffness");
  require_positive(aspect, "aspect");
  require_open(beam_poisson, "beam_poisson", -1.0, 0.5);
  const int scaling = static_cast<int>(stiffness_scaling);
  if (scaling < 0 || scaling > static_cast<int>(StiffnessScaling::voronoi_facet))
    throw InputError("stiffness_scaling = " + std::to_string(scaling) + ", allowed: uniform, voronoi_facet");
  require_closed(facet_floor, "facet_floor", 0.0, 1.0 / std::sqrt(3.0));
}

namespace {

// cot of the angle at vertex k of triangle t (the angle opposite its beam k).
double opposite_cot(const Lattice& l, int t, int k) {
  const auto& tri = l.triangles[static_cast<std::size_t>(t)];
  auto vertex = [&](int m) { return l.points.col(tri[static_cast<std::size_t>(m % 3)]); };
  const Eigen::Vector2d a = vertex(k + 1) - vertex(k), b = vertex(k + 2) - vertex(k);
  return a.dot(b) / std::abs(a.x() * b.y() - a.y() * b.x());
}

double facet_ratio(const Lattice& l, int beam) {
  double sum_cot = 0.0;
  for (int t : l.beam_triangles[static_cast<std::size_t>(beam)]) {
    if (t < 0) continue;
    const auto& tb = l.triangle_beams[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k)
      if (tb[static_cast<std::size_t>(k)] == beam) sum_cot += opposite_cot(l, t, k);
  }
  return 0.5 * sum_cot;  // d / L = (cot a_s + cot a_t) / 2
}

}  // namespace

Eigen::VectorXd facet_ratios(const Lattice& lattice) {
  Eigen::VectorXd r(lattice.n_beams());
  for (int e = 0; e < lattice.n_beams(); ++e) r[e] = facet_ratio(lattice, e);
  return r;
}

double beam_stiffness_factor(const Lattice& lattice, const BeamParameters& parameters, int beam) {
  if (parameters.stiffness_scaling == StiffnessScaling::uniform) return 1.0;
  return std::sqrt(3.0) * std::max(facet_ratio(lattice, beam), parameters.facet_floor);
}

BeamParameters beam_parameters_for(const Lattice& lattice, const BeamParameters& parameters, int beam) {
  BeamParameters q = parameters;
  q.normal_stiffness *= beam_stiffness_factor(lattice, parameters, beam);
  return q;
}

double BeamParameters::rotational_stiffness() const {
  return normal_stiffness / (2.0 / (aspect * aspect) + 4.0 * (1.0 + beam_poisson));
}

double BeamParameters::gamma() const { return aspect * aspect * (1.0 + beam_poisson) / 6.0; }

Matrix6d beam_element_stiffness(double length, double angle, const BeamParameters& p, BeamState state) {
  Matrix6d local = Matrix6d::Zero();  // (u_n,i, u_s,i, omega_i, u_n,j, u_s,j, omega_j)
  if (state != BeamState::open) {
    const double k_n = p.normal_stiffness;
    local(0, 0) = local(3, 3) = k_n;
    local(0, 3) = local(3, 0) = -k_n;
  }
  if (state == BeamState::intact) {
    const double k_w = p.rotational_stiffness(), g = p.gamma(), L = length;
    Eigen::Matrix2d D;
    D << g + 1.0 / 3.0, 1.0 / 6.0 - g, 1.0 / 6.0 - g, g + 1.0 / 3.0;
    D *= 2.0 * k_w * L * L;
    // theta_i = omega_i - (u_s,j - u_s,i)/L, theta_j = omega_j - (u_s,j - u_s,i)/L.
    Eigen::Matrix<double, 2, 6> B;
    B << 0, 1 / L, 1, 0, -1 / L, 0,  //
        0, 1 / L, 0, 0, -1 / L, 1;
    local += B.transpose() * D * B;
  }
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;  // global (x, y, omega) -> local (n, s, omega)
  R << c, s, 0, -s, c, 0, 0, 0, 1;
  Matrix6d T = Matrix6d::Zero();
  T.topLeftCorner<3, 3>() = R;
  T.bottomRightCorner<3, 3>() = R;
  return T.transpose() * local * T;
}

Matrix63d beam_element_factor(double length, double angle, const BeamParameters& p, BeamState state) {
  Matrix63d V = Matrix63d::Zero();
  const double c = std::cos(angle), s = std::sin(angle);
  if (state != BeamState::open) {
    const double r = std::sqrt(p.normal_stiffness);
    V.col(0) << -r * c, -r * s, 0.0, r * c, r * s, 0.0;
  }
  if (state == BeamState::intact) {
    const double k_w = p.rotational_stiffness(), g = p.gamma(), L = length;
    Eigen::Matrix2d D;
    D << g + 1.0 / 3.0, 1.0 / 6.0 - g, 1.0 / 6.0 - g, g + 1.0 / 3.0;
    D *= 2.0 * k_w * L * L;
    const Eigen::Matrix2d C = D.llt().matrixL();
    Eigen::Matrix<double, 2, 6> B;  // as in beam_element_stiffness, local (n, s, omega) components
    B << 0, 1 / L, 1, 0, -1 / L, 0,  //
        0, 1 / L, 0, 0, -1 / L, 1;
    Eigen::Matrix3d R;  // global (x, y, omega) -> local (n, s, omega)
    R << c, s, 0, -s, c, 0, 0, 0, 1;
    Matrix6d T = Matrix6d::Zero();
    T.topLeftCorner<3, 3>() = R;
    T.bottomRightCorner<3, 3>() = R;
    V.rightCols<2>() = T.transpose() * B.transpose() * C;
  }
  return V;
}

Eigen::SparseMatrix<double> assemble_stiffness(const Lattice& lattice, const BeamParameters& parameters,
                                               const std::vector<BeamState>& states) {
  parameters.validate();
  assert((states.empty() || static_cast<int>(states.size()) == lattice.n_beams()) && "one state per beam");
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(36 * static_cast<std::size_t>(lattice.n_beams()));
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const BeamState state = states.empty() ? BeamState::intact : states[static_cast<std::size_t>(e)];
    if (state == BeamState::open) continue;
    const Matrix6d k =
        beam_element_stiffness(lattice.length[e], lattice.angle[e], beam_parameters_for(lattice, parameters, e), state);
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const int dofs[6] = {dof_index(i, 0), dof_index(i, 1), dof_index(i, 2),
                         dof_index(j, 0), dof_index(j, 1), dof_index(j, 2)};
    // All 36 entries, zeros included: the sparsity pattern then depends only on the beam states,
    // not on beam angles, which keeps a symbolic factorisation reusable.
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b) triplets.emplace_back(dofs[a], dofs[b], k(a, b));
  }
  const int n = 3 * lattice.n_particles();
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

std::vector<bool> broken_flags(const std::vector<BeamState>& states) {
  std::vector<bool> broken(states.size());
  for (std::size_t e = 0; e < states.size(); ++e) broken[e] = states[e] != BeamState::intact;
  return broken;
}

}  // namespace hm::lattice2d
