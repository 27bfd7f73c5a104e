#include "hm/lattice2d/mechanics/rank_one_stiffness.hpp"

#include <cmath>
#include <utility>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

RankOneStiffness::RankOneStiffness(Eigen::VectorXd g, double k) : g_(std::move(g)), k_(k) {
  if (!(k >= 0.0 && std::isfinite(k)))
    throw hm::InputError("rank-one stiffness k = " + core::format_value(k) + ", allowed: >= 0, finite");
  if (!g_.allFinite()) throw hm::InputError("rank-one stiffness vector: not finite, allowed: finite entries");
}

void RankOneStiffness::set_reference(const Eigen::VectorXd& u_reference) {
  reference_volume_ = u_reference.size() == 0 ? 0.0 : g_.dot(u_reference);
}

bool RankOneStiffness::correct(SpdSolver& solver, const std::vector<int>& free_dofs, const Eigen::VectorXd* held_value,
                               Eigen::VectorXd& x_free) {
  if (!is_active()) return true;
  const auto n = static_cast<Eigen::Index>(free_dofs.size());
  Eigen::VectorXd g(n);
  for (Eigen::Index a = 0; a < n; ++a) g[a] = g_[free_dofs[static_cast<std::size_t>(a)]];
  if (z_revision_ != solver.report().matrix_revision || z_.size() != n) {
    Eigen::VectorXd z = solver.solve(g);
    if (solver.info() != Eigen::Success) return false;
    z_ = std::move(z);
    z_revision_ = solver.report().matrix_revision;
  }
  // g.u - g.u_r; held_value is 0 at the free degrees of freedom.
  const double excess = held_value ? g.dot(x_free) + g_.dot(*held_value) - reference_volume_ : g.dot(x_free);
  x_free -= z_ * (k_ * excess / (1.0 + k_ * g.dot(z_)));
  return true;
}

Eigen::VectorXd RankOneStiffness::force(const Eigen::VectorXd& u) const {
  if (!is_active()) return Eigen::VectorXd::Zero(u.size());
  return k_ * (g_.dot(u) - reference_volume_) * g_;
}

void RankOneStiffness::save_state(core::StateWriter& w) const {
  w.put("rank_one.z", z_);
  w.put("rank_one.z_revision", z_revision_);
  w.put("rank_one.reference_volume", reference_volume_);
}

void RankOneStiffness::restore_state(core::StateReader& r) {
  r.get("rank_one.z", z_);
  r.get("rank_one.z_revision", z_revision_);
  r.get("rank_one.reference_volume", reference_volume_);
}

}  // namespace hm::lattice2d
