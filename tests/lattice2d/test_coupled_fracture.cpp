// Fracture inside the coupled step (Fig. 5's grey boxes): CoupledModel::enable_fracture.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::make_lattice;

namespace {

// Borehole injection as Fig. 12 (b = 0.2, Eq. 16's borehole node) but 3x the rate, so that a coarse
// annulus (N = 2000) breaks within a few steps.
CouplingOptions aitken_coupling() {
  CouplingOptions options;
  options.relaxation = CouplingRelaxation::aitken;  // Eq. 16's borehole: the plain loop diverges
  return options;
}

std::unique_ptr<CoupledModel> make_fracturing_model(const Lattice& lattice, std::uint64_t strength_seed = 1,
                                                    const CouplingOptions& options = aitken_coupling()) {
  FlowParameters flow;
  flow.Q = 0.03;
  flow.b = 0.2;
  flow.E_over_M = hm::analytic::E_over_M_table1(0.2, 0.25);
  auto model = std::make_unique<CoupledModel>(lattice, calibrated_beam_parameters(), BoundaryConditions{},
                                              MechanicsOptions{}, flow, options);
  StrengthSpec strength;
  strength.seed = strength_seed;
  model->enable_fracture(draw_beam_strengths(strength, lattice.n_beams()));
  return model;
}

struct FractureRun {
  std::vector<CoupledStepSummary> steps;
  std::vector<std::vector<BeamState>> states;  // after each step
};

FractureRun run_steps(CoupledModel& model, int n_steps, double dt) {
  FractureRun run;
  for (int n = 0; n < n_steps; ++n) {
    run.steps.push_back(model.step(dt));
    const auto& s = run.steps.back();
    if (!s.is_ok()) {
      std::string h;
      for (double r : s.pressure_history) h += std::to_string(r) + " ";
      INFO("step " << n << ": " << s.message << "; breaks " << s.n_breaks << "; residuals " << h);
      REQUIRE(s.is_ok());
    }
    run.states.push_back(model.mechanics().states());
  }
  return run;
}

}  // namespace

TEST_CASE("Coupled fracture: strengths must be one per beam", "[lattice2d][coupled_fracture]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 700);
  FlowParameters flow;
  CoupledModel model(lattice, calibrated_beam_parameters(), BoundaryConditions{}, MechanicsOptions{}, flow,
                     CouplingOptions{});
  CHECK_FALSE(model.fracture_enabled());
  CHECK_THROWS_WITH(model.enable_fracture(draw_beam_strengths(StrengthSpec{}, lattice.n_beams() - 1)),
                    Catch::Contains("one per beam"));
  BreakLoopOptions bad;
  bad.max_breaks = 0;
  CHECK_THROWS_AS(model.enable_fracture(draw_beam_strengths(StrengthSpec{}, lattice.n_beams()), bad), hm::InputError);
  model.enable_fracture(draw_beam_strengths(StrengthSpec{}, lattice.n_beams()));
  CHECK(model.fracture_enabled());
}

TEST_CASE("Coupled fracture: radial cracks from the wall, never healed, logged in time order",
          "[lattice2d][coupled_fracture]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 2000);
  const auto owner = make_fracturing_model(lattice);
  CoupledModel& model = *owner;
  const FractureRun run = run_steps(model, 12, 1e-4);
  const auto& log = model.break_log();
  INFO("beams broken: " << log.size());
  // Something must break for the test to mean anything (measured: the first break in step 2).
  REQUIRE(log.size() >= 5);
  CHECK(static_cast<int>(log.size()) == model.n_broken());

  // The first break is tensile, at the borehole wall (the hoop stress peaks there: Section 3.2).
  CHECK(log.front().mode == FailureMode::tensile);
  // Beams with an end on the wall have their midpoint within L/2 of R_i (a wall chord's inside it by L^2/(8 R_i)).
  CHECK(log.front().position.norm() == Approx(0.138).margin(0.5 * lattice.length.maxCoeff()));

  // Never healed: the broken set only grows, step after step.
  for (std::size_t n = 1; n < run.states.size(); ++n)
    for (int e = 0; e < lattice.n_beams(); ++e)
      if (run.states[n - 1][static_cast<std::size_t>(e)] != BeamState::intact)
        CHECK(run.states[n][static_cast<std::size_t>(e)] != BeamState::intact);

  // The log is in breaking order, its times are the steps' end times and never decrease; each beam once.
  std::vector<int> beams;
  for (std::size_t k = 0; k < log.size(); ++k) {
    CHECK(log[k].sequence == static_cast<int>(k));
    if (k > 0) CHECK(log[k].load >= log[k - 1].load);
    CHECK(log[k].ratio >= 1.0);
    beams.push_back(log[k].beam);
  }
  std::sort(beams.begin(), beams.end());
  CHECK(std::adjacent_find(beams.begin(), beams.end()) == beams.end());

  // The flow network sees the same broken set (iota applies to exactly these segments).
  for (int e = 0; e < lattice.n_beams(); ++e)
    CHECK(model.flow().crack_weights()[e] ==
          (model.mechanics().states()[static_cast<std::size_t>(e)] != BeamState::intact ? 1.0 : 0.0));

  // A pass that broke a beam never ends the iteration (Fig. 5): every breaking step took >= 2 passes,
  // and the step still converged to the coupling tolerances.
  for (const auto& s : run.steps) {
    if (s.n_breaks > 0) CHECK(s.iterations >= 2);
    CHECK(s.pressure_residual <= model.options().pressure_tolerance);
  }
}

TEST_CASE("Coupled fracture: the same seeds give the identical break sequence", "[lattice2d][coupled_fracture]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 2000);
  const auto pa = make_fracturing_model(lattice), pb = make_fracturing_model(lattice);
  CoupledModel &a = *pa, &b = *pb;
  run_steps(a, 8, 1e-4);
  run_steps(b, 8, 1e-4);
  REQUIRE(a.break_log().size() == b.break_log().size());
  REQUIRE(!a.break_log().empty());
  for (std::size_t k = 0; k < a.break_log().size(); ++k) {
    CHECK(a.break_log()[k].beam == b.break_log()[k].beam);
    CHECK(a.break_log()[k].load == b.break_log()[k].load);
    CHECK(a.break_log()[k].sigma_1 == b.break_log()[k].sigma_1);  // bitwise: the same arithmetic
  }
  CHECK((a.pressure() - b.pressure()).cwiseAbs().maxCoeff() == 0.0);
  // Another strength seed gives another sequence (the test above can fail).
  const auto pc = make_fracturing_model(lattice, 2);
  CoupledModel& c = *pc;
  run_steps(c, 8, 1e-4);
  bool differs = c.break_log().size() != a.break_log().size();
  for (std::size_t k = 0; !differs && k < a.break_log().size(); ++k)
    differs = c.break_log()[k].beam != a.break_log()[k].beam;
  CHECK(differs);
}

TEST_CASE("Coupled fracture checked at convergence: the break sequence does not depend on the iteration path",
          "[lattice2d][coupled_fracture]") {
  // Anderson's mixing factor changes the path of the passes, not their fixed point. Checked at every
  // pass, beams can break on the path's overshoots (N = 1e4 Fig. 12: 813 / 818 / 942 breaks for
  // mixing 0.5 / 0.8 / 1.0); checked at convergence only, the same beams break at the same times.
  const Lattice lattice = make_lattice(DomainShape::annulus, 2000);
  const auto run = [&](double mixing) {
    CouplingOptions options;
    options.relaxation = CouplingRelaxation::anderson;
    options.anderson_depth = 10;
    options.initial_relaxation = mixing;
    options.fracture_check = FractureCheck::at_convergence;
    auto model = make_fracturing_model(lattice, 1, options);
    const FractureRun r = run_steps(*model, 8, 1e-4);
    int passes = 0;
    for (const auto& s : r.steps) passes += s.iterations;
    return std::make_pair(model->break_log(), passes);
  };
  const auto [slow, slow_passes] = run(0.5);
  const auto [fast, fast_passes] = run(1.0);
  REQUIRE(!slow.empty());
  CHECK(slow_passes != fast_passes);  // the paths differ (else the test could not fail)
  REQUIRE(slow.size() == fast.size());
  for (std::size_t k = 0; k < slow.size(); ++k) {
    CHECK(slow[k].beam == fast[k].beam);
    CHECK(slow[k].load == fast[k].load);
  }
}

TEST_CASE("Coupled fracture: a step whose first break overshoots ends at that check, leaving no trace",
          "[lattice2d][coupled_fracture]") {
  // The step is retried whatever its later passes would do, so it stops at its first failure check
  // instead of converging the broken state: the passes after that check are saved, the outcome is
  // the same (the state of t^n, status overshoot).
  const Lattice lattice = make_lattice(DomainShape::annulus, 2000);
  CouplingOptions options;
  options.relaxation = CouplingRelaxation::anderson;
  options.anderson_depth = 10;
  options.fracture_check = FractureCheck::at_convergence;
  const double dt = 8e-4;  // eight of the steps that break above: the first break goes far past its threshold
  auto whole = make_fracturing_model(lattice, 1, options);
  const CoupledStepSummary taken = whole->step(dt);
  REQUIRE(taken.is_ok());
  REQUIRE(taken.n_breaks > 0);
  REQUIRE(taken.first_event_ratio > 1.02);

  auto retried = make_fracturing_model(lattice, 1, options);
  const CoupledStepSummary stopped = retried->step(dt, 0.02);
  CHECK(stopped.status == CoupledStatus::overshoot);
  CHECK(stopped.first_event_ratio == taken.first_event_ratio);
  // The first check's breaks only: the broken state was never re-converged.
  CHECK(stopped.iterations < taken.iterations);
  CHECK(stopped.n_breaks <= taken.n_breaks);
  CHECK(retried->time() == 0.0);
  CHECK(retried->n_broken() == 0);
  CHECK(retried->break_log().empty());
  // And the same step taken after it is the step taken in the first place.
  const CoupledStepSummary again = retried->step(dt);
  REQUIRE(again.is_ok());
  CHECK(again.iterations == taken.iterations);
  REQUIRE(retried->break_log().size() == whole->break_log().size());
  for (std::size_t k = 0; k < whole->break_log().size(); ++k)
    CHECK(retried->break_log()[k].beam == whole->break_log()[k].beam);
}
