#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include <Eigen/Cholesky>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

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
  if (!(bending_factor > 0.0 && bending_factor <= 1.0))
    throw InputError("bending_factor = " + format_value(bending_factor) + ", allowed: 0 < bending_factor <= 1");
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
  return bending_factor * normal_stiffness / (2.0 / (aspect * aspect) + 4.0 * (1.0 + beam_poisson));
}

double BeamParameters::gamma() const { return aspect * aspect * (1.0 + beam_poisson) / 6.0; }

BeamOperator::BeamOperator(double c, double s, double length, const BeamParameters& p, BeamState state)
    : c_(c),
      s_(s),
      length_(length),
      normal_(state == BeamState::open ? 0.0 : p.normal_stiffness),
      bending_(state == BeamState::intact ? 2.0 * p.rotational_stiffness() * length * length : 0.0),
      diagonal_(p.gamma() + 1.0 / 3.0),
      off_diagonal_(1.0 / 6.0 - p.gamma()),
      state_(state) {}

BeamOperator::BeamOperator(const Lattice& lattice, int beam, const BeamParameters& p, BeamState state)
    : BeamOperator(lattice.direction(0, beam), lattice.direction(1, beam), lattice.length[beam], p, state) {}

Matrix6d BeamOperator::rotation() const {
  Eigen::Matrix3d R;  // global (x, y, omega) -> local (n, s, omega)
  R << c_, s_, 0, -s_, c_, 0, 0, 0, 1;
  Matrix6d T = Matrix6d::Zero();
  T.topLeftCorner<3, 3>() = R;
  T.bottomRightCorner<3, 3>() = R;
  return T;
}

Eigen::Matrix<double, 3, 6> BeamOperator::strain_matrix() const {
  // Local (u_n,i, u_s,i, omega_i, u_n,j, u_s,j, omega_j); theta = omega - (u_s,j - u_s,i) / L.
  const double L = length_;
  Eigen::Matrix<double, 3, 6> B;
  B << -1, 0, 0, 1, 0, 0,         //
      0, 1 / L, 1, 0, -1 / L, 0,  //
      0, 1 / L, 0, 0, -1 / L, 1;
  return B;
}

Eigen::Matrix3d BeamOperator::constitutive() const {
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  D(0, 0) = normal_;
  Eigen::Matrix2d Db;
  Db << diagonal_, off_diagonal_, off_diagonal_, diagonal_;
  D.bottomRightCorner<2, 2>() = Db * bending_;
  return D;
}

Eigen::Matrix3d BeamOperator::constitutive_factor() const {
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  C(0, 0) = std::sqrt(normal_);
  if (bending_ > 0.0) C.bottomRightCorner<2, 2>() = constitutive().bottomRightCorner<2, 2>().llt().matrixL();
  return C;
}

Matrix6d BeamOperator::stiffness() const {
  const Eigen::Matrix<double, 3, 6> B = strain_matrix();
  const Matrix6d T = rotation();
  const Matrix6d local = B.transpose() * constitutive() * B;
  return T.transpose() * local * T;
}

Matrix63d BeamOperator::factor() const {
  return rotation().transpose() * strain_matrix().transpose() * constitutive_factor();
}

BeamState contact_state(BeamState current, double elongation, double tolerance) {
  if (elongation < -tolerance) return BeamState::contact;
  if (elongation > tolerance || current == BeamState::intact) return BeamState::open;
  return current;
}

BeamForce beam_force(const Lattice& lattice, int beam, const BeamParameters& parameters, BeamState state,
                     const Eigen::VectorXd& u) {
  BeamForce F;
  if (state == BeamState::open) return F;
  // The force the beam exerts on its particles is minus its internal force K_e u_e.
  const Vector6d f =
      -BeamOperator(lattice, beam, parameters, state).internal_force(element_displacements(lattice, beam, u));
  F.force_on_i = f.head<2>();
  const Eigen::Vector2d n = lattice.direction.col(beam), s(-n.y(), n.x());
  F.normal = F.force_on_i.dot(n);
  F.shear = F.force_on_i.dot(s);
  F.moment_i = f[2];
  F.moment_j = f[5];
  return F;
}

Matrix6d beam_element_stiffness(double length, double angle, const BeamParameters& p, BeamState state) {
  return BeamOperator(std::cos(angle), std::sin(angle), length, p, state).stiffness();
}

Matrix63d beam_element_factor(double length, double angle, const BeamParameters& p, BeamState state) {
  return BeamOperator(std::cos(angle), std::sin(angle), length, p, state).factor();
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
