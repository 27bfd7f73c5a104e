#pragma once
/// \file
/// A stiffness k g g^T on top of a factorised matrix K, relaxed at a reference displacement u_r (its
/// force k g g^T (u - u_r): zero where u = u_r), applied without entering the factor (Sherman-Morrison):
/// with x = K^-1 b and z = K^-1 g,
///   (K + k g g^T)^-1 (b + k g g^T u_r) = x - z k g.(x - u_r) / (1 + k g.z).
/// For a term that couples many degrees of freedom at once, such as a borehole's fluid pushing on its
/// whole wall, which inside a sparse factor would fill a dense block. The correction vanishes as x
/// approaches u_r, so an iteration that relaxes the term at its last iterate converges to round-off
/// (taken as a preload k g g^T u_r in b, the correction would take back several times the answer and
/// leave ~1e-8 of noise). Costs one extra solve (z) whenever K changes; z is kept with the matrix
/// revision it belongs to (SpdSolveReport).
#include <vector>

#include <Eigen/Core>

#include "hm/core/state_archive.hpp"
#include "hm/lattice2d/linalg/spd_solver.hpp"

namespace hm::lattice2d {

class RankOneStiffness {
 public:
  RankOneStiffness() = default;
  /// g: one entry per degree of freedom (3 n_particles); k >= 0, finite. k = 0: none.
  RankOneStiffness(Eigen::VectorXd g, double k);

  bool is_active() const { return k_ > 0.0; }
  const Eigen::VectorXd& vector() const { return g_; }
  double stiffness() const { return k_; }
  /// The reference displacement u_r (all degrees of freedom); empty: 0.
  void set_reference(const Eigen::VectorXd& u_reference);
  /// x_free = K^-1 b on the free degrees of freedom (free_dofs: their indices into g) becomes the
  /// solution with the term: with u the displacement of x_free and the held values u_h (`held_value`,
  /// all degrees of freedom, 0 where free), x_free - z k (g.u - g.u_r) / (1 + k g_f.z). Without
  /// held values (nullptr) the response to forces alone: u_h and u_r taken as 0. Solves for z with
  /// `solver` when K changed since the last call. False if that solve failed (solver.info() says
  /// why); x_free is then unchanged.
  bool correct(SpdSolver& solver, const std::vector<int>& free_dofs, const Eigen::VectorXd* held_value,
               Eigen::VectorXd& x_free);
  /// Its force k g g.(u - u_r) at displacement u (all degrees of freedom), for reactions.
  Eigen::VectorXd force(const Eigen::VectorXd& u) const;

  /// z with its matrix revision, and u_r: a restored solver state continues with the same z bit for bit.
  void save_state(core::StateWriter& w) const;
  void restore_state(core::StateReader& r);

 private:
  Eigen::VectorXd g_;
  double k_ = 0.0;
  double reference_volume_ = 0.0;  // g.u_r
  Eigen::VectorXd z_;              // K^-1 g on the free degrees of freedom
  int z_revision_ = -1;            // SpdSolveReport::matrix_revision of K when z was solved
};

}  // namespace hm::lattice2d
