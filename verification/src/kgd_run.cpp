#include "kgd_run.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "crack_growth.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/fracture_pressure.hpp"
#include "hm/case/run_output.hpp"

namespace hm::verification {

namespace {

namespace l2 = hm::lattice2d;

double fed_crack_half_length(const l2::CoupledModel& m) {
  const int source = m.flow().source_triangle();
  for (const std::vector<int>& mode : m.flow().crack_modes())
    if (std::find(mode.begin(), mode.end(), source) != mode.end()) return crack_half_length(m.reference_dual(), mode);
  return 0.0;
}

}  // namespace

KgdRun run_kgd(const cases::RunCase& c) {
  KgdRun r;
  const auto model = cases::make_coupled_model(c);
  const l2::CoupledRunSummary run =
      model->run(c.stepping, [&](const l2::CoupledModel& m, const l2::CoupledStepSummary& s, bool) {
        if (m.time() <= 0.0) return;
        const l2::FlowTotals& totals = m.flow().totals();
        const double suction = cases::fracture_pressure(m).negative_area_fraction;
        r.points.push_back({m.time(), totals.injected, totals.deformation, cases::injection_pressure(m),
                            fed_crack_half_length(m), m.n_broken(), s.n_breaks + s.n_teeth,
                            std::isnan(suction) ? 0.0 : suction});
      });
  r.ok = run.is_ok();
  r.message = run.message;
  r.n_steps = run.n_steps;
  r.passes = run.total_iterations;
  r.seconds = run.seconds;
  r.max_balance = run.max_balance_error;
  return r;
}

const KgdPoint& kgd_state_at(const KgdRun& run, double t) {
  assert(!run.points.empty() && "kgd_state_at: a run with states");
  // Step ends land on t up to round-off of the accumulated step sizes.
  const auto after = std::upper_bound(run.points.begin(), run.points.end(), t * (1 + 1e-9),
                                      [](double time, const KgdPoint& p) { return time < p.t; });
  return after == run.points.begin() ? run.points.front() : *(after - 1);
}

}  // namespace hm::verification
