#include "hm/lattice2d/mechanics/far_field.hpp"

#include <algorithm>
#include <cmath>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

Eigen::Matrix2d far_field_tensor(const analytic::FarFieldStress& far) {
  // Written out so that the off-diagonal entries are one and the same number (symmetric exactly).
  const double c = std::cos(far.theta_H), s = std::sin(far.theta_H);
  const double xy = -(far.S_H - far.S_h) * c * s;
  Eigen::Matrix2d t;
  t << -(far.S_H * c * c + far.S_h * s * s), xy, xy, -(far.S_H * s * s + far.S_h * c * c);
  return t;
}

void add_far_field_loads(const analytic::FarFieldStress& far, double p0, double b, DomainShape domain,
                         BoundaryConditions& conditions) {
  far.validate();
  core::require_finite(p0, "p0");
  if (!(p0 >= 0.0)) throw hm::InputError("p0 = " + core::format_value(p0) + ", allowed: >= 0 (compression positive)");
  // A stress of E strains the rock by order one, far outside the small-strain lattice (a rock's in-situ
  // stresses are ~1e-3 E); 1e300 overflowed the loads into NaN at the first solve.
  if (far.S_H > 1.0)
    throw hm::InputError("S_H = " + core::format_value(far.S_H) +
                         ", allowed: <= 1 (over E; the lattice is small-strain)");
  if (p0 > 1.0)
    throw hm::InputError("p0 = " + core::format_value(p0) + ", allowed: <= 1 (over E; the lattice is small-strain)");
  if (!(b >= 0.0 && b <= 1.0)) throw hm::InputError("b = " + core::format_value(b) + ", allowed: 0 <= b <= 1");
  conditions.outer_stress += far_field_tensor(far) + b * p0 * Eigen::Matrix2d::Identity();
  if (domain == DomainShape::annulus) conditions.inner_pressure += (1.0 - b) * p0;
}

Eigen::VectorXd annulus_displacement(const Lattice& lattice, const analytic::InSituAnnulus& exact,
                                     double youngs_modulus) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  for (int i = 0; i < lattice.n_particles(); ++i) {
    const Eigen::Vector2d x = lattice.points.col(i);
    const double r = std::clamp(x.norm(), exact.inner_radius(), 1.0), theta = std::atan2(x.y(), x.x());
    const analytic::PolarState s = exact.state(r, theta);
    const Eigen::Vector2d er = x / x.norm(), et(-er.y(), er.x());
    u.segment<2>(dof_index(i, 0)) = (s.u_r * er + s.u_theta * et) / youngs_modulus;
  }
  return without_rigid_motion(lattice, u);
}

DisplacementError displacement_error(const Lattice& lattice, const Eigen::VectorXd& u, const Eigen::VectorXd& u_ref) {
  double sum = 0.0, largest = 0.0, scale = 0.0;
  for (int i = 0; i < lattice.n_particles(); ++i) {
    const double d = (u.segment<2>(dof_index(i, 0)) - u_ref.segment<2>(dof_index(i, 0))).norm();
    sum += d * d;
    largest = std::max(largest, d);
    scale = std::max(scale, u_ref.segment<2>(dof_index(i, 0)).norm());
  }
  return {std::sqrt(sum / lattice.n_particles()) / scale, largest / scale};
}

}  // namespace hm::lattice2d
