#include "hm/lattice2d/anderson_acceleration.hpp"

#include <cassert>
#include <string>

#include <Eigen/QR>

#include "hm/analytic/input_error.hpp"
#include "hm/analytic/validation.hpp"

namespace hm::lattice2d {

AndersonAcceleration::AndersonAcceleration(int depth, double mixing) : depth_(depth), mixing_(mixing) {
  if (depth < 1) throw hm::InputError("anderson_depth = " + std::to_string(depth) + ", allowed: >= 1");
  if (!(mixing > 0.0 && mixing <= 1.0))
    throw hm::InputError("initial_relaxation = " + hm::analytic::format_value(mixing) + ", allowed: 0 < value <= 1");
}

void AndersonAcceleration::reset() {
  dx_.clear();
  dr_.clear();
  has_prev_ = false;
}

Eigen::VectorXd AndersonAcceleration::next(const Eigen::VectorXd& x, const Eigen::VectorXd& g_of_x) {
  assert(x.size() == g_of_x.size() && "x and g(x) have one entry per unknown");
  const Eigen::VectorXd r = g_of_x - x;
  if (has_prev_) {
    dx_.push_back(x - x_prev_);
    dr_.push_back(r - r_prev_);
    if (static_cast<int>(dx_.size()) > depth_) {
      dx_.pop_front();
      dr_.pop_front();
    }
  }
  x_prev_ = x;
  r_prev_ = r;
  has_prev_ = true;
  if (dx_.empty()) return x + mixing_ * r;
  const Eigen::Index m = static_cast<Eigen::Index>(dx_.size());
  Eigen::MatrixXd R(x.size(), m), X(x.size(), m);
  for (Eigen::Index j = 0; j < m; ++j) {
    R.col(j) = dr_[static_cast<std::size_t>(j)];
    X.col(j) = dx_[static_cast<std::size_t>(j)];
  }
  // gamma = argmin |r - R gamma|: rank-revealing QR, so nearly dependent differences do no harm.
  const Eigen::VectorXd gamma = R.colPivHouseholderQr().solve(r);
  return x + mixing_ * r - (X + mixing_ * R) * gamma;
}

}  // namespace hm::lattice2d
