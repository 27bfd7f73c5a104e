#pragma once
/// \file
/// How the coupling loop forms the next pass's guess from the last pass (Section 2.3, Fig. 5: the
/// mechanics sees the pressure guess p_g and relaxes the Eq. 20 springs at u_g; the flow then gives
/// p, the mechanics u). Every strategy has the plain loop's fixed point (p, u) = (p_g, u_g); they
/// differ in the path, which matters for the borehole's stiff feedback (docs/coupling.md, section 3).
#include <array>
#include <memory>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "hm/core/enum_names.hpp"

namespace hm::lattice2d {

/// How the pressure guess of the next pass is formed from the flow's result.
enum class CouplingRelaxation {
  none,      ///< the flow's pressure as it is (the paper's Fig. 5)
  aitken,    ///< Aitken's dynamic relaxation of the pressure update (same fixed point; our addition)
  anderson,  ///< Anderson acceleration of the pressure update (same fixed point; our addition)
};
constexpr auto enum_names(CouplingRelaxation) {
  return core::enum_table<CouplingRelaxation>({{CouplingRelaxation::none, "none"},
                                               {CouplingRelaxation::aitken, "aitken"},
                                               {CouplingRelaxation::anderson, "anderson"}});
}

/// One strategy, with the history it keeps within a time step.
class PassRelaxation {
 public:
  virtual ~PassRelaxation() = default;
  /// A new time step: no history.
  virtual void start_step() = 0;
  /// Beams broke after a converged pass (the fracture check at convergence): the map the history
  /// describes is gone, the loop starts again from the broken state.
  virtual void restart() = 0;
  /// The next guess (p_guess, u_guess) after a pass mapped it to (p, u). `beams_broke`: the pass itself
  /// broke beams, so its map differs from the previous passes'.
  virtual void next_guess(Eigen::VectorXd& p_guess, Eigen::VectorXd& u_guess, const Eigen::VectorXd& p,
                          const Eigen::VectorXd& u, bool beams_broke) = 0;
};

/// The strategy `kind`: initial_relaxation is Aitken's first factor and Anderson's mixing (0, 1];
/// anderson_depth the number of residual differences Anderson combines.
std::unique_ptr<PassRelaxation> make_pass_relaxation(CouplingRelaxation kind, double initial_relaxation,
                                                     int anderson_depth);

}  // namespace hm::lattice2d
