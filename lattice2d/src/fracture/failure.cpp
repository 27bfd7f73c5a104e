#include "hm/lattice2d/fracture/failure.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "hm/core/file_output.hpp"

namespace hm::lattice2d {

namespace {

bool is_intact(const std::vector<BeamState>& states, int beam) {
  return states.empty() || states[static_cast<std::size_t>(beam)] == BeamState::intact;
}

}  // namespace

FailureField evaluate_failure(const BeamStress& stress, const BeamStrengths& strengths,
                              const std::vector<BeamState>& states) {
  const int n_beams = static_cast<int>(stress.sigma_1.size());
  assert(strengths.n_beams() == n_beams && "one strength per beam");
  assert((states.empty() || static_cast<int>(states.size()) == n_beams) && "one state per beam");
  FailureField out{Eigen::VectorXd::Zero(n_beams), std::vector<FailureMode>(static_cast<std::size_t>(n_beams))};
  const FailureCriterion criterion(strengths.friction);
  for (int e = 0; e < n_beams; ++e) {
    if (!is_intact(states, e)) continue;
    const auto check =
        criterion.check(stress.sigma_1[e], stress.sigma_3[e], strengths.tensile[e], strengths.compressive[e]);
    assert(!std::isnan(check.ratio) && "failure ratio is NaN: non-finite stress");
    out.ratio[e] = check.ratio;
    out.mode[static_cast<std::size_t>(e)] = check.mode;
  }
  return out;
}

BreakCandidate select_beam_to_break(const BeamStress& stress, const BeamStrengths& strengths,
                                    const std::vector<BeamState>& states) {
  // evaluate_failure's check, beam by beam, without its two per-beam arrays.
  const int n_beams = static_cast<int>(stress.sigma_1.size());
  assert(strengths.n_beams() == n_beams && "one strength per beam");
  assert((states.empty() || static_cast<int>(states.size()) == n_beams) && "one state per beam");
  const FailureCriterion criterion(strengths.friction);
  BreakCandidate best;
  bool any_intact = false;
  for (int e = 0; e < n_beams; ++e) {
    if (!is_intact(states, e)) continue;
    const auto check =
        criterion.check(stress.sigma_1[e], stress.sigma_3[e], strengths.tensile[e], strengths.compressive[e]);
    assert(!std::isnan(check.ratio) && "failure ratio is NaN: non-finite stress");
    const double r = check.ratio;
    if (!any_intact || r > best.max_ratio) best.max_ratio = r;
    any_intact = true;
    // Strictly greater: on equal ratios the lowest index, visited first, stays.
    if (r >= 1.0 && (!best.found() || r > best.ratio)) {
      best.beam = e;
      best.ratio = r;
      best.mode = check.mode;
    }
  }
  return best;
}

BreakEvent make_break_event(const Lattice& lattice, const BeamStress& stress, const BreakCandidate& candidate,
                            double load, int sequence) {
  assert(candidate.found() && "make_break_event: no beam selected");
  const int e = candidate.beam;
  return make_break_event(lattice, candidate, stress.sigma_1[e], stress.sigma_3[e], stress.crack_tip_factor[e], load,
                          sequence);
}

BreakEvent make_break_event(const Lattice& lattice, const BreakCandidate& candidate, double sigma_1, double sigma_3,
                            double crack_tip_factor, double load, int sequence) {
  assert(candidate.found() && "make_break_event: no beam selected");
  const int e = candidate.beam;
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
  BreakEvent event;
  event.sequence = sequence;
  event.beam = e;
  event.particle_i = i;
  event.particle_j = j;
  event.position = 0.5 * (lattice.points.col(i) + lattice.points.col(j));
  event.load = load;
  event.sigma_1 = sigma_1;
  event.sigma_3 = sigma_3;
  event.ratio = candidate.ratio;
  event.crack_tip_factor = crack_tip_factor;
  event.mode = candidate.mode;
  return event;
}

}  // namespace hm::lattice2d
