#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::make_lattice;

namespace {

// Section 3.1's point injection: Q = 0.1, b = 0.5, E/M of Table 1 at b = 0.5, free outer boundary.
FlowParameters rudnicki_flow() {
  FlowParameters flow;
  flow.Q = 0.1;
  flow.b = 0.5;
  return flow;
}

// The annulus tests' borehole: Q = 0.01, b = 0.5, the paper's Eq. 16 node.
FlowParameters borehole_flow() {
  FlowParameters flow;
  flow.Q = 0.01;
  flow.b = 0.5;
  return flow;
}

CoupledModel make_model(const Lattice& lattice, CouplingOptions options,
                        BoundarySupport outer = BoundarySupport::free) {
  BoundaryConditions bc;
  bc.outer = outer;
  return CoupledModel(lattice, BeamParameters{}, bc, MechanicsOptions{}, rudnicki_flow(), options);
}

double max_abs(const Eigen::VectorXd& v) { return v.cwiseAbs().maxCoeff(); }

// One step on the disk iterated to 1e-10 with `relaxation` and with the plain loop: the same solution.
void check_same_step_as_plain_loop(CouplingOptions options, CouplingRelaxation relaxation) {
  const Lattice disk = make_lattice(DomainShape::disk, 2000);
  options.pressure_tolerance = options.displacement_tolerance = 1e-10;
  options.relaxation = CouplingRelaxation::none;
  CoupledModel plain = make_model(disk, options);
  options.relaxation = relaxation;
  CoupledModel relaxed = make_model(disk, options);
  const CoupledStepSummary a = plain.step(2e-5), b = relaxed.step(2e-5);
  REQUIRE(a.status == CoupledStatus::converged);
  REQUIRE(b.status == CoupledStatus::converged);
  INFO("disk, one step: plain " << a.iterations << " passes, " << hm::core::name_of(relaxation) << " " << b.iterations);
  // Both stop at a relative change of 1e-10 per pass (see the drained/undrained test).
  CHECK(max_abs(plain.pressure() - relaxed.pressure()) < 1e-8 * max_abs(plain.pressure()));
  CHECK(max_abs(plain.displacement() - relaxed.displacement()) < 1e-8 * max_abs(plain.displacement()));
}

}  // namespace

TEST_CASE("Coupling options and time stepping: defaults are valid, bad values are rejected", "[lattice2d]") {
  CouplingOptions o;
  REQUIRE_NOTHROW(o.validate());
  TimeStepping t;
  REQUIRE_NOTHROW(t.validate());
  SECTION("drained with Psi != 0") {
    o.split = CouplingSplit::drained;
    REQUIRE_THROWS_AS(o.validate(), hm::InputError);
  }
  SECTION("tolerance") {
    o.pressure_tolerance = 0.0;
    REQUIRE_THROWS_AS(o.validate(), hm::InputError);
  }
  SECTION("max_iterations") {
    o.max_iterations = 0;
    REQUIRE_THROWS_AS(o.validate(), hm::InputError);
  }
  SECTION("dt_growth") {
    t.dt_growth = 0.5;
    REQUIRE_THROWS_AS(t.validate(), hm::InputError);
  }
  SECTION("dt_initial > t_end") {
    t.dt_initial = 1.0;
    REQUIRE_THROWS_AS(t.validate(), hm::InputError);
  }
  SECTION("output times") {
    t.output_times = {2e-5, 1e-5};
    REQUIRE_THROWS_AS(t.validate(), hm::InputError);
  }
}

TEST_CASE("The undrained split with Psi = 0 is the drained split exactly", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 2000);
  CouplingOptions undrained;
  undrained.terms.psi = 0.0;
  CouplingOptions drained;
  drained.split = CouplingSplit::drained;
  drained.terms.psi = 0.0;
  CoupledModel a = make_model(lattice, undrained), b = make_model(lattice, drained);
  for (int n = 0; n < 3; ++n) {
    const CoupledStepSummary sa = a.step(1e-5), sb = b.step(1e-5);
    REQUIRE(sa.is_ok());
    CHECK(sa.iterations == sb.iterations);
  }
  CHECK(a.spring_stiffness().cwiseAbs().maxCoeff() == 0.0);
  CHECK((a.displacement() - b.displacement()).cwiseAbs().maxCoeff() == 0.0);  // bitwise: the same arithmetic
  CHECK((a.pressure() - b.pressure()).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("The iterated undrained and drained splits converge to the same solution of a time step", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 2000);
  CouplingOptions undrained;
  undrained.pressure_tolerance = undrained.displacement_tolerance = 1e-10;
  CouplingOptions drained = undrained;
  drained.split = CouplingSplit::drained;
  drained.terms.psi = 0.0;
  drained.max_iterations = 400;
  for (BoundarySupport outer : {BoundarySupport::free, BoundarySupport::fixed}) {
    CoupledModel a = make_model(lattice, undrained, outer), b = make_model(lattice, drained, outer);
    for (int n = 0; n < 2; ++n) {
      const CoupledStepSummary sa = a.step(2e-5), sb = b.step(2e-5);
      REQUIRE(sa.status == CoupledStatus::converged);
      REQUIRE(sb.status == CoupledStatus::converged);
      std::printf("%s boundary, step %d: iterations undrained (Psi = 1.3) %d, drained %d\n",
                  hm::core::name_of(outer).c_str(), n + 1, sa.iterations, sb.iterations);
    }
    // Both stop at a relative change of 1e-10 per pass; the fixed points agree to a few times that
    // (the contraction factor of the slower, drained iteration amplifies the last change).
    CHECK(max_abs(a.pressure() - b.pressure()) < 1e-8 * max_abs(a.pressure()));
    CHECK(max_abs(a.displacement() - b.displacement()) < 1e-8 * max_abs(a.displacement()));
  }
}

TEST_CASE("The fluid volume balance of every coupled step closes to 1e-8", "[lattice2d]") {
  // injected = storage + deformation + outflow per step (FlowStepSummary); the scheme is conservative,
  // so this is round-off of the flow solve, whatever the coupling iterate.
  for (DomainShape shape : {DomainShape::disk, DomainShape::annulus}) {
    const Lattice lattice = make_lattice(shape, 2000);
    CoupledModel model = make_model(lattice, CouplingOptions{});
    TimeStepping stepping;
    stepping.dt_initial = 2e-6;
    stepping.dt_growth = 1.5;
    stepping.t_end = 1e-4;
    double worst = 0.0, flow_seconds = 0.0;
    long long n_solves = 0;
    int n_observed = 0;
    const CoupledRunSummary run = model.run(stepping, [&](const CoupledModel&, const CoupledStepSummary& s, bool) {
      worst = std::max(worst, s.flow.balance_error);
      flow_seconds += s.flow_seconds;
      n_solves += s.n_mechanics_solves;
      ++n_observed;
    });
    REQUIRE(run.is_ok());
    CHECK(worst <= 1e-8);
    CHECK(run.max_balance_error == worst);
    // The run's time split and counters are the accepted steps' (the observer also sees t = 0, empty).
    CHECK(n_observed == run.n_steps + 1);
    CHECK(run.n_mechanics_solves == n_solves);
    CHECK(run.n_mechanics_solves >= run.total_iterations);  // one solve per pass at least
    CHECK(run.flow_seconds == flow_seconds);                // the same sums in the same order: exact
    // The totals add up as well.
    const FlowTotals& t = model.flow().totals();
    CHECK(std::abs(t.injected - t.storage - t.deformation - t.outflow) <= 1e-8 * t.injected);
    CHECK(t.injected == Approx(0.1 * 1e-4).epsilon(1e-12));
  }
}

TEST_CASE("A coupling loop that hits its iteration cap is reported, not thrown, and leaves the state at t^n",
          "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 1000);
  CouplingOptions options;
  options.max_iterations = 1;
  SECTION("a failed step") {
    CoupledModel model = make_model(lattice, options);
    const CoupledStepSummary s = model.step(1e-5);
    CHECK(s.status == CoupledStatus::not_converged);
    CHECK_FALSE(s.is_ok());
    CHECK(s.message.find("max_iterations") != std::string::npos);
    CHECK(model.time() == 0.0);
    CHECK(max_abs(model.displacement()) == 0.0);
    const CoupledRunSummary run = model.run(TimeStepping{});
    CHECK_FALSE(run.is_ok());
    CHECK(run.n_steps == 0);
  }
  SECTION("one pass accepted on request (the paper's 'one iteration of both systems')") {
    options.accept_unconverged = true;
    CoupledModel model = make_model(lattice, options);
    const CoupledStepSummary s = model.step(1e-5);
    CHECK(s.status == CoupledStatus::accepted_unconverged);
    CHECK(model.time() == 1e-5);
    // One pass: the mechanics saw p^n = 0, so the first step only moves the fluid; the second deforms.
    CHECK(max_abs(model.displacement()) == 0.0);
    CHECK(max_abs(model.pressure()) > 0.0);
    REQUIRE(model.step(1e-5).is_ok());
    CHECK(max_abs(model.displacement()) > 0.0);
  }
}

TEST_CASE("run() lands on the output times, grows dt geometrically and caps it", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 1000);
  CoupledModel model = make_model(lattice, CouplingOptions{});
  TimeStepping stepping;
  stepping.dt_initial = 1e-6;
  stepping.dt_growth = 2.0;
  stepping.dt_max = 8e-6;
  stepping.t_end = 4e-5;
  stepping.output_times = {5e-6, 2e-5};
  std::vector<double> outputs, dts;
  const CoupledRunSummary run = model.run(stepping, [&](const CoupledModel& m, const CoupledStepSummary& s, bool out) {
    if (out) outputs.push_back(m.time());
    if (s.dt > 0.0) dts.push_back(s.dt);
  });
  REQUIRE(run.is_ok());
  REQUIRE(outputs.size() == 4);
  CHECK(outputs[0] == 0.0);
  CHECK(outputs[1] == Approx(5e-6).epsilon(1e-12));
  CHECK(outputs[2] == Approx(2e-5).epsilon(1e-12));
  CHECK(outputs[3] == Approx(4e-5).epsilon(1e-12));
  // 1, 2, then 2 (shortened to hit 5e-6), 4, 8, 3 (to 2e-5), 8, 8, 4 (to 4e-5) in units of 1e-6.
  CHECK(dts.front() == Approx(1e-6));
  CHECK(*std::max_element(dts.begin(), dts.end()) <= 8e-6 * (1 + 1e-12));
  CHECK(run.n_steps == static_cast<int>(dts.size()));
}

TEST_CASE("The pass observer sees every pass of a step, the last one being the accepted state", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 1000);
  CoupledModel model = make_model(lattice, CouplingOptions{});
  int calls = 0;
  Eigen::VectorXd last_p;
  model.set_pass_observer([&](int pass, const Eigen::VectorXd& p, const Eigen::VectorXd&) {
    CHECK(pass == ++calls);
    last_p = p;
  });
  const CoupledStepSummary s = model.step(2e-5);
  REQUIRE(s.is_ok());
  CHECK(calls == s.iterations);
  CHECK(static_cast<int>(s.pressure_history.size()) == s.iterations);
  CHECK((last_p - model.pressure()).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE(
    "In a borehole the plain loop diverges and is reported: Aitken relaxation converges to the same kind of "
    "fixed point as the plain loop on the disk",
    "[lattice2d]") {
  // The borehole node's feedback: the wall traction p_h moves the wall, b dV_h changes p_h by
  // ~ b dV_h / ((E/M) V_h), a loop gain ~2 at Table 1's E/M (measured residual ratio 1.93 per pass).
  FlowParameters flow = borehole_flow();
  const Lattice annulus = make_lattice(DomainShape::annulus, 2000);
  CouplingOptions options;
  SECTION("plain: not converged, state kept") {
    options.max_iterations = 30;
    CoupledModel model(annulus, BeamParameters{}, BoundaryConditions{}, MechanicsOptions{}, flow, options);
    const CoupledStepSummary s = model.step(1e-5);
    CHECK(s.status == CoupledStatus::not_converged);
    CHECK(model.time() == 0.0);
  }
  SECTION("Aitken: converged, balance closed") {
    options.relaxation = CouplingRelaxation::aitken;
    CoupledModel model(annulus, BeamParameters{}, BoundaryConditions{}, MechanicsOptions{}, flow, options);
    for (int n = 0; n < 3; ++n) {
      const CoupledStepSummary s = model.step(1e-5 * (n + 1));
      REQUIRE(s.status == CoupledStatus::converged);
      CHECK(s.flow.balance_error <= 1e-8);
    }
    CHECK(model.flow().borehole_pressure() > 0.0);
  }
  SECTION("Aitken on the disk reaches the plain loop's solution") {
    check_same_step_as_plain_loop(options, CouplingRelaxation::aitken);
  }
  SECTION("a bad relaxation factor is rejected") {
    options.initial_relaxation = 1.5;
    REQUIRE_THROWS_AS(options.validate(), hm::InputError);
    options.initial_relaxation = 0.5;
    options.anderson_depth = 0;
    REQUIRE_THROWS_AS(options.validate(), hm::InputError);
  }
  SECTION("Anderson: converges the borehole and reaches the plain loop's solution on the disk") {
    options.relaxation = CouplingRelaxation::anderson;
    CoupledModel model(annulus, BeamParameters{}, BoundaryConditions{}, MechanicsOptions{}, flow, options);
    for (int n = 0; n < 3; ++n) REQUIRE(model.step(1e-5 * (n + 1)).status == CoupledStatus::converged);
    // Measured 15 and 18 passes on the disk: on its fast loop the mixing costs a few passes; Anderson's gain
    // is on the fractured borehole's slow crack modes (docs/coupling.md: 2865 -> 772 passes at N = 3000).
    check_same_step_as_plain_loop(options, CouplingRelaxation::anderson);
  }
}

TEST_CASE("The borehole's undrained spring converges the plain loop in a borehole, at the fixed point found without it",
          "[lattice2d]") {
  // The loop gain ~2 through the borehole (above) is the hole's undrained response missing from the
  // mechanics; with beta_h / s_h g g^T in it, relaxed at the iterate, the plain loop contracts.
  FlowParameters flow = borehole_flow();
  const Lattice annulus = make_lattice(DomainShape::annulus, 2000);
  CouplingOptions sprung;
  sprung.relaxation = CouplingRelaxation::none;
  sprung.terms.borehole_spring = BoreholeSpring::undrained;
  // This borehole's passes stall at a change of ~5e-9 with or without the spring (Aitken without it:
  // ~3e-9; the first steps' borehole pressure is ~1e-6): 1e-8 is reached.
  sprung.pressure_tolerance = sprung.displacement_tolerance = 1e-8;
  sprung.max_iterations = 60;
  CouplingOptions reference = sprung;
  reference.terms.borehole_spring = BoreholeSpring::none;
  reference.relaxation = CouplingRelaxation::anderson;
  reference.max_iterations = 200;
  CoupledModel a(annulus, BeamParameters{}, BoundaryConditions{}, MechanicsOptions{}, flow, sprung);
  CoupledModel b(annulus, BeamParameters{}, BoundaryConditions{}, MechanicsOptions{}, flow, reference);
  for (int n = 0; n < 3; ++n) {
    const CoupledStepSummary sa = a.step(1e-5 * (n + 1)), sb = b.step(1e-5 * (n + 1));
    REQUIRE(sa.status == CoupledStatus::converged);
    REQUIRE(sb.status == CoupledStatus::converged);
    CHECK(sa.flow.balance_error <= 1e-8);
    std::printf("borehole, step %d: plain loop with the borehole spring %d passes, Anderson without it %d\n", n + 1,
                sa.iterations, sb.iterations);
  }
  // Both stop at a relative change of 1e-8 per pass; the fixed points agree to a hundred times that
  // (the slower loop's contraction factor amplifies its last change).
  CHECK(max_abs(a.pressure() - b.pressure()) < 1e-6 * max_abs(a.pressure()));
  CHECK(max_abs(a.displacement() - b.displacement()) < 1e-6 * max_abs(a.displacement()));
  SECTION("refused without a borehole storage, whose volume then sets no pressure") {
    flow.borehole_storage = BoreholeStorage::none;
    flow.borehole_deformation = BoreholeDeformation::none;
    REQUIRE_THROWS_WITH(CoupledModel(annulus, BeamParameters{}, BoundaryConditions{}, MechanicsOptions{}, flow, sprung),
                        Catch::Contains("borehole_spring"));
  }
}

TEST_CASE("The linear predictor reaches the same states as the previous-state start, in fewer passes", "[lattice2d]") {
  // The borehole of Fig. 12 without fracture: continuous injection, Anderson as in the cases.
  FlowParameters flow;
  flow.Q = 0.01;
  flow.b = 0.2;
  const Lattice annulus = make_lattice(DomainShape::annulus, 2000);
  CouplingOptions options;
  options.relaxation = CouplingRelaxation::anderson;
  options.anderson_depth = 10;
  options.pressure_tolerance = options.displacement_tolerance = 1e-9;
  const auto run = [&](CouplingPredictor predictor, int& passes) {
    options.predictor = predictor;
    CoupledModel model(annulus, BeamParameters{}, BoundaryConditions{}, MechanicsOptions{}, flow, options);
    passes = 0;
    double dt = 1e-5;
    for (int n = 0; n < 8; ++n, dt *= 1.2) {
      const CoupledStepSummary s = model.step(dt);
      REQUIRE(s.status == CoupledStatus::converged);
      passes += s.iterations;
    }
    return std::pair{Eigen::VectorXd(model.pressure()), Eigen::VectorXd(model.displacement())};
  };
  int previous_passes = 0, linear_passes = 0;
  const auto [p0, u0] = run(CouplingPredictor::previous, previous_passes);
  const auto [p1, u1] = run(CouplingPredictor::linear, linear_passes);
  INFO("8 steps: previous " << previous_passes << " passes, linear " << linear_passes);
  // Both stop at a relative change of 1e-9 per pass; with a contraction rate of at most ~0.7 per pass the
  // distance to the fixed point is < 1e-9 / (1 - 0.7) ~ 3e-9 for each: 1e-7 leaves room for 8 steps.
  CHECK(max_abs(p1 - p0) < 1e-7 * max_abs(p0));
  CHECK(max_abs(u1 - u0) < 1e-7 * max_abs(u0));
  CHECK(linear_passes < previous_passes);
}
