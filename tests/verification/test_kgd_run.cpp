// The KGD benchmarks' reading of a run's states at a time.
#include <catch2/catch.hpp>

#include "kgd_run.hpp"

using namespace hm::verification;

TEST_CASE("kgd_state_at takes the last state at or before t, forgiving the step sizes' round-off", "[verification]") {
  KgdRun run;
  for (const double t : {1e-5, 2e-5, 2.9999999999999997e-5, 4e-5})
    run.points.push_back({.t = t, .half_length = t * 1e4});
  CHECK(kgd_state_at(run, 2.5e-5).t == 2e-5);
  CHECK(kgd_state_at(run, 3e-5).t == 2.9999999999999997e-5);
  // 3e-5 reached as 3.0000000000000004e-5 by summed steps is still the state at 3e-5.
  run.points[2].t = 3.0000000000000004e-5;
  CHECK(kgd_state_at(run, 3e-5).t == 3.0000000000000004e-5);
  CHECK(kgd_state_at(run, 1e-3).t == 4e-5);
  CHECK(kgd_state_at(run, 1e-6).t == 1e-5);  // before the first state: the first
}
