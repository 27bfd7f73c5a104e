#pragma once
/// \file
/// Anderson acceleration of a fixed-point iteration x = g(x) (Walker & Ni 2011, "type II"; in
/// fluid-structure coupling known as IQN-ILS): the next guess is the mixed step x + beta r corrected
/// by the least-squares combination of the last `depth` residual differences that best cancels the
/// current residual r = g(x) - x. Same fixed points as the plain iteration; far fewer passes when a
/// few slow modes dominate (the coupled lattice's crack openings, docs/coupling.md).
#include <deque>

#include <Eigen/Core>

namespace hm::lattice2d {

class AndersonAcceleration {
 public:
  /// depth: number of kept differences (>= 1); mixing: beta in (0, 1], the step along r when the
  /// history is empty and the mixing of the corrected step. Throws hm::InputError otherwise.
  AndersonAcceleration(int depth, double mixing);

  /// Forget the history (the map changed, e.g. a beam broke).
  void reset();

  /// The next guess after evaluating g at x (`g_of_x`, same size as x).
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& g_of_x);

  int history_size() const { return static_cast<int>(dx_.size()); }

 private:
  int depth_;
  double mixing_;
  std::deque<Eigen::VectorXd> dx_, dr_;  // x_k - x_{k-1}, r_k - r_{k-1}, newest last
  Eigen::MatrixXd gram_;                 // dr_i . dr_j
  Eigen::VectorXd x_prev_, r_prev_;
  bool has_prev_ = false;
};

}  // namespace hm::lattice2d
