#pragma once
/// \file
/// Brittle failure of beams (Section 2.1, Eq. 11, Fig. 3): the per-beam failure check against the
/// beam's own strengths, the choice of the one beam to break next, and the break log.
/// Dimensionless (stresses over E). Tension positive.
///
/// The loop "break the selected beam, re-solve, select again until none fails" belongs to the caller
/// (it needs the mechanical solver); a step of it reads:
///   forces = compute_beam_forces(...); stress = compute_beam_stress(lattice,
///       compute_particle_stress(lattice, dual, forces), states, tip);
///   candidate = select_beam_to_break(stress, strengths, states);
///   if (!candidate.found()) break;
///   log.push_back(make_break_event(lattice, stress, candidate, load, log.size()));
///   states[candidate.beam] = BeamState::open;  // or contact, per the active-set rule; then re-solve
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hm/analytic/failure_criteria.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"

namespace hm::lattice2d {

using hm::analytic::FailureMode;

/// hm::analytic::check_failure with Eq. 11's friction factor [(1 + mu_i^2)^(1/2) + mu_i]^2 formed once
/// instead of per call: bitwise the same ratio and mode (the same operations in the same order), for
/// loops over every beam (evaluate_failure, the break loop of fracture.hpp).
class FailureCriterion {
 public:
  explicit FailureCriterion(double friction) : k_squared_(hm::analytic::coulomb_factor(friction)) {}
  /// max(sigma_1 / T_u, sigma_CC / C_u); mode none below 1, else the larger criterion (tensile on a tie).
  hm::analytic::FailureCheck check(double sigma_1, double sigma_3, double tensile_strength,
                                   double compressive_strength) const {
    return combine(sigma_1 / tensile_strength, shear_ratio(sigma_1, sigma_3, compressive_strength));
  }
  /// sigma_CC / C_u of Eq. 11 alone.
  double shear_ratio(double sigma_1, double sigma_3, double compressive_strength) const {
    return (k_squared_ * sigma_1 - sigma_3) / compressive_strength;
  }
  /// The check from a tensile and a shear ratio (the saw-tooth law drives tension by the beam's own
  /// axial stress): their maximum, mode as check().
  static hm::analytic::FailureCheck combine(double tensile, double shear) {
    const double ratio = std::max(tensile, shear);
    if (ratio < 1.0) return {FailureMode::none, ratio};
    return {tensile >= shear ? FailureMode::tensile : FailureMode::shear, ratio};
  }

 private:
  double k_squared_ = 0.0;
};

/// Failure check of every beam: ratio = max(sigma_1 / T_u, sigma_CC / C_u) with sigma_CC of Eq. 11
/// (hm::analytic::check_failure), mode tensile or shear where ratio >= 1 (the larger of the two
/// wins; tensile on an exact tie), none elsewhere. Broken beams get mode none and ratio 0.
struct FailureField {
  Eigen::VectorXd ratio;
  std::vector<FailureMode> mode;
};
FailureField evaluate_failure(const BeamStress& stress, const BeamStrengths& strengths,
                              const std::vector<BeamState>& states = {});

/// The beam to break next.
struct BreakCandidate {
  int beam = -1;  ///< -1 if no intact beam has ratio >= 1
  FailureMode mode = FailureMode::none;
  double ratio = 0.0;      ///< its failure ratio (>= 1 when found)
  double max_ratio = 0.0;  ///< largest ratio over the intact beams (< 1 when none found)

  bool found() const { return beam >= 0; }
};

/// Among the intact beams, the one most over its threshold: largest ratio >= 1, ties broken by the
/// lowest beam index (deterministic). `states` empty = all intact.
BreakCandidate select_beam_to_break(const BeamStress& stress, const BeamStrengths& strengths,
                                    const std::vector<BeamState>& states = {});

/// One line of the break log.
struct BreakEvent {
  int sequence = 0;     ///< 0, 1, ... in the order of breaking
  int beam = -1;        ///< beam index
  int particle_i = -1;  ///< its particles (i < j)
  int particle_j = -1;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< beam midpoint, undeformed, over R
  double load = 0.0;     ///< load factor or time (t/t_s) at the break; the caller's choice
  double sigma_1 = 0.0;  ///< beam stress at breaking (crack-tip factor included)
  double sigma_3 = 0.0;
  double ratio = 0.0;             ///< failure ratio, >= 1
  double crack_tip_factor = 1.0;  ///< 1 unless the beam was at a crack tip
  FailureMode mode = FailureMode::none;
};

/// The log record for a found candidate (precondition: candidate.found()).
BreakEvent make_break_event(const Lattice& lattice, const BeamStress& stress, const BreakCandidate& candidate,
                            double load, int sequence);
/// The same record from the candidate beam's own stresses and crack-tip factor (for callers that do
/// not keep a BeamStress of every beam, e.g. the break loop).
BreakEvent make_break_event(const Lattice& lattice, const BreakCandidate& candidate, double sigma_1, double sigma_3,
                            double crack_tip_factor, double load, int sequence);

}  // namespace hm::lattice2d
