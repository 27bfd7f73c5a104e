#pragma once
// A fluid-driven crack run through the coupled model, recorded after every accepted step: what the KGD
// benchmarks (lattice2d.kgd_toughness, lattice2d.kgd_transition) measure.
#include <string>
#include <vector>

#include "hm/case/run_case.hpp"

namespace hm::verification {

/// One state of the fluid-driven crack: after an accepted step.
struct KgdPoint {
  double t = 0.0, injected = 0.0, crack_volume = 0.0, pressure = 0.0, half_length = 0.0;
  int n_broken = 0;
  int events = 0;        ///< breaks and teeth in the step that ended here
  double suction = 0.0;  ///< the share of the fractures' area whose fluid is below 0 (isolated, unfed parts)
};

struct KgdRun {
  std::vector<KgdPoint> points;
  bool ok = false;
  std::string message;
  int n_steps = 0, passes = 0;
  double seconds = 0.0, max_balance = 0.0;
};

/// Runs case `c` to its t_end. half_length is that of the crack the source feeds (half its extent in x,
/// crack_half_length), crack_volume the solid's volume change (the flow's deformation total).
KgdRun run_kgd(const cases::RunCase& c);

/// The last recorded state at or before t (the first state if none is).
const KgdPoint& kgd_state_at(const KgdRun& run, double t);

}  // namespace hm::verification
