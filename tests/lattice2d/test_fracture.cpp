#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"

using namespace hm::lattice2d;

namespace {

// A small square pulled in y: u_y = +-strain/2 on the top/bottom rows (reference strain `strain`), u_x
// held at one bottom particle only (free lateral contraction, uniaxial stress).
BoundaryConditions uniaxial_pull(const Lattice& lattice, double strain) {
  BoundaryConditions bc;
  const double half = 0.5 * lattice.spec.height, tol = 1e-9;
  int pin = -1;
  for (int p = 0; p < lattice.n_particles(); ++p) {
    const double y = lattice.points(1, p);
    if (std::abs(y - half) < tol) bc.prescribed.push_back({p, 1, 0.5 * strain * lattice.spec.height});
    if (std::abs(y + half) < tol) {
      bc.prescribed.push_back({p, 1, -0.5 * strain * lattice.spec.height});
      if (pin < 0 || std::abs(lattice.points(0, p)) < std::abs(lattice.points(0, pin))) pin = p;
    }
  }
  bc.prescribed.push_back({pin, 0, 0.0});
  return bc;
}

Lattice square(std::uint64_t seed = 3, long long n = 800) {
  LatticeSpec spec;
  spec.domain = DomainShape::rectangle;
  spec.n_particles = n;
  spec.seed = seed;
  return generate_lattice(spec);
}

StrengthSpec strength_spec(std::uint64_t seed = 5) {
  StrengthSpec s;
  s.seed = seed;
  return s;
}

struct PullRun {
  LoadingResult result;
  std::vector<std::vector<BeamState>> states_per_step;
};

// Pull until 40 beams are broken (the crack runs well into the square at N = 800).
PullRun pull(std::uint64_t lattice_seed, std::uint64_t strength_seed, bool snap = true) {
  const Lattice lattice = square(lattice_seed);
  BeamMechanics mechanics(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
  const DualGraph dual = build_dual_graph(lattice);
  const BeamStrengths strengths = draw_beam_strengths(strength_spec(strength_seed), lattice.n_beams());
  LoadSteppingOptions options;
  options.load_increment = 2e-5;
  options.max_load = 1e-2;
  options.max_breaks = 40;
  options.snap_to_breaks = snap;
  PullRun run;
  run.result = run_load_stepping(mechanics, dual, strengths, options, [&](const LoadStep&, const BeamMechanics& m) {
    run.states_per_step.push_back(m.states());
    return true;
  });
  return run;
}

}  // namespace

TEST_CASE("Load stepping breaks beams in load order and never heals one", "[lattice2d]") {
  const PullRun run = pull(3, 5);
  const auto& r = run.result;
  REQUIRE(r.status == LoadingStatus::break_cap);  // the cap of 40 ends the run
  REQUIRE(r.breaks.size() == 40u);
  for (std::size_t k = 0; k < r.breaks.size(); ++k) {
    CHECK(r.breaks[k].sequence == static_cast<int>(k));
    CHECK(r.breaks[k].ratio >= 1.0);
    if (k > 0) CHECK(r.breaks[k].load >= r.breaks[k - 1].load);
  }
  for (std::size_t s = 1; s < r.steps.size(); ++s) CHECK(r.steps[s].load >= r.steps[s - 1].load);
  // Once broken, a beam stays broken (contact <-> open is allowed, intact never comes back).
  for (std::size_t s = 1; s < run.states_per_step.size(); ++s)
    for (std::size_t e = 0; e < run.states_per_step[s].size(); ++e)
      if (run.states_per_step[s - 1][e] != BeamState::intact) CHECK(run.states_per_step[s][e] != BeamState::intact);
  // The crack-tip factor enters the loop: the first break has none (no crack yet), later tip beams have
  // (L/2L_m)^(1/2) > 1 (L ~ 0.04 at N = 800 against 2 L_m = 6.3e-3).
  CHECK(r.breaks.front().crack_tip_factor == 1.0);
  bool tip_seen = false;
  for (const auto& ev : r.breaks) tip_seen = tip_seen || ev.crack_tip_factor > 1.0;
  CHECK(tip_seen);
  // Every logged beam is broken at the end.
  for (const auto& ev : r.breaks)
    CHECK(run.states_per_step.back()[static_cast<std::size_t>(ev.beam)] != BeamState::intact);
}

TEST_CASE("A pulled square fails completely: the crack crosses it and the load drops to zero", "[lattice2d]") {
  const Lattice lattice = square();
  BoundaryConditions bc = uniaxial_pull(lattice, 1.0);
  std::vector<int> top;
  for (const auto& pd : bc.prescribed)
    if (pd.component == 1 && pd.value > 0) top.push_back(pd.particle);
  BeamMechanics mechanics(lattice, BeamParameters{}, bc);
  const DualGraph dual = build_dual_graph(lattice);
  const BeamStrengths strengths = draw_beam_strengths(strength_spec(), lattice.n_beams());
  LoadSteppingOptions options;
  options.load_increment = 2e-5;
  options.max_load = 1e-2;
  double peak = 0, last = 0;
  const LoadingResult r =
      run_load_stepping(mechanics, dual, strengths, options, [&](const LoadStep& s, const BeamMechanics& m) {
        const Eigen::VectorXd reaction = m.reactions();
        double force = 0;
        for (int p : top) force += reaction[3 * p + 1];
        last = s.load * force;
        peak = std::max(peak, last);
        return !(s.n_breaks_total > 0 && last < 1e-3 * peak);
      });
  INFO(r.message);
  REQUIRE(r.status == LoadingStatus::stopped);  // by the observer, not a cap or a failed solve
  CHECK(peak > 0);
  CHECK(std::abs(last) < 1e-3 * peak);
  double x_lo = 1, x_hi = -1;
  for (const auto& ev : r.breaks) x_lo = std::min(x_lo, ev.position.x()), x_hi = std::max(x_hi, ev.position.x());
  CHECK(x_hi - x_lo > 0.8);  // across the unit width, up to a spacing (~0.04) at each side
}

TEST_CASE("Same seeds give an identical break sequence, other strength seeds a different one", "[lattice2d]") {
  const PullRun a = pull(3, 5), b = pull(3, 5), c = pull(3, 6);
  REQUIRE(a.result.breaks.size() == b.result.breaks.size());
  for (std::size_t k = 0; k < a.result.breaks.size(); ++k) {
    CHECK(a.result.breaks[k].beam == b.result.breaks[k].beam);
    CHECK(a.result.breaks[k].load == b.result.breaks[k].load);  // bitwise: same operations in the same order
    CHECK(a.result.breaks[k].sigma_1 == b.result.breaks[k].sigma_1);
  }
  bool differs = false;
  for (std::size_t k = 0; k < std::min(a.result.breaks.size(), c.result.breaks.size()); ++k)
    differs = differs || a.result.breaks[k].beam != c.result.breaks[k].beam;
  CHECK(differs);
}

TEST_CASE("Snapped loading finds the first break at the load the intact solution predicts", "[lattice2d]") {
  const Lattice lattice = square();
  BeamMechanics intact(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
  const DualGraph dual = build_dual_graph(lattice);
  const BeamStrengths strengths = draw_beam_strengths(strength_spec(), lattice.n_beams());
  std::vector<BreakEvent> none;
  const BreakLoopSummary at_zero = break_until_stable(intact, dual, strengths, {}, 0.0, none, 0.0);
  REQUIRE(at_zero.is_stable());
  CHECK(at_zero.n_breaks == 0);
  CHECK(at_zero.max_ratio == 0.0);
  const double predicted = 1.0 / at_zero.max_reference_ratio;

  const PullRun snapped = pull(3, 5, true), stepped = pull(3, 5, false);
  // Snap: exact up to its 1 + 1e-9 margin (fracture.hpp).
  CHECK(snapped.result.breaks.front().load == Approx(predicted).epsilon(2e-9));
  CHECK(snapped.result.breaks.front().ratio == Approx(1.0).epsilon(2e-9));
  // Fixed steps of 2e-5 (0.1 T_u in strain with E ~ O(1)): found up to one step late, never early.
  CHECK(stepped.result.breaks.front().load >= predicted);
  CHECK(stepped.result.breaks.front().load < predicted + 2e-5 * (1 + 1e-12));
  CHECK(stepped.result.breaks.front().beam == snapped.result.breaks.front().beam);
}

TEST_CASE("The load factor convention equals solving at the scaled load", "[lattice2d]") {
  // Homogeneity (fracture.hpp): judging lambda x the reference solution must give the same breaks as a
  // mechanics that holds lambda x the load, through contacts and crack-tip factors.
  const Lattice lattice = square();
  const DualGraph dual = build_dual_graph(lattice);
  const BeamStrengths strengths = draw_beam_strengths(strength_spec(), lattice.n_beams());
  BreakLoopOptions options;
  options.max_breaks = 25;
  const double lambda = 4e-4;  // ~2x the first-break strain: the loop runs into the cap
  BeamMechanics reference(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
  BeamMechanics actual(lattice, BeamParameters{}, uniaxial_pull(lattice, lambda));
  std::vector<BreakEvent> log_ref, log_act;
  const auto s_ref = break_until_stable(reference, dual, strengths, options, lambda, log_ref, lambda);
  const auto s_act = break_until_stable(actual, dual, strengths, options, lambda, log_act, 1.0);
  CHECK(s_ref.status == BreakLoopStatus::break_cap);
  CHECK(s_act.status == BreakLoopStatus::break_cap);
  REQUIRE(log_ref.size() == log_act.size());
  for (std::size_t k = 0; k < log_ref.size(); ++k) {
    CHECK(log_ref[k].beam == log_act[k].beam);
    // Different right-hand sides through the same factor: agreement to the solver's round-off.
    CHECK(log_ref[k].sigma_1 == Approx(log_act[k].sigma_1).epsilon(1e-8));
  }
}

TEST_CASE("current_beam_stress equals the compute_beam_forces path on a cracked lattice", "[lattice2d]") {
  // It takes the forces from BeamMechanics::beam_forces (local frames) instead of compute_beam_forces.
  const Lattice lattice = square();
  const DualGraph dual = build_dual_graph(lattice);
  const BeamStrengths strengths = draw_beam_strengths(strength_spec(), lattice.n_beams());
  BeamMechanics m(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
  BreakLoopOptions options;
  options.max_breaks = 25;
  std::vector<BreakEvent> log;
  break_until_stable(m, dual, strengths, options, 4e-4, log, 4e-4);
  m.solve();
  int n_broken = 0;
  for (BeamState s : m.states()) n_broken += s != BeamState::intact;
  REQUIRE(n_broken == 25);
  const BeamStress fast = current_beam_stress(m, dual, {}, 2.0);
  const BeamForces forces = compute_beam_forces(lattice, m.parameters(), m.displacement(), m.states());
  const BeamStress slow = compute_beam_stress(lattice, compute_particle_stress(lattice, dual, forces), m.states());
  const double scale = slow.stress.cwiseAbs().maxCoeff();
  CHECK((fast.stress - 2.0 * slow.stress).cwiseAbs().maxCoeff() <= 1e-12 * scale);  // round-off
  CHECK((fast.crack_tip_factor - slow.crack_tip_factor).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("The break loop stops only when no intact beam reaches its threshold", "[lattice2d]") {
  const Lattice lattice = square();
  const DualGraph dual = build_dual_graph(lattice);
  const BeamStrengths strengths = draw_beam_strengths(strength_spec(), lattice.n_beams());
  SECTION("below the first-break load nothing breaks") {
    BeamMechanics m(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
    std::vector<BreakEvent> log;
    const auto s = break_until_stable(m, dual, strengths, {}, 1e-5, log, 1e-5);
    CHECK(s.is_stable());
    CHECK(s.n_breaks == 0);
    CHECK(s.n_solves == 1);
    CHECK(s.max_ratio < 1.0);
    CHECK(log.empty());
  }
  SECTION("above it the loop breaks until stable, and a fresh check finds no candidate") {
    // A moderate overload, 2% above the first-break load, without the tip factor: measured one break,
    // then the loop ends stable (seeds 3/5, N = 800).
    BeamMechanics m(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
    std::vector<BreakEvent> log;
    std::vector<BreakEvent> none;
    const double first = 1.0 / break_until_stable(m, dual, strengths, {}, 0.0, none, 0.0).max_reference_ratio;
    BreakLoopOptions options;
    options.crack_tip.enabled = false;
    const auto s = break_until_stable(m, dual, strengths, options, 1.02 * first, log, 1.02 * first);
    INFO("breaks " << s.n_breaks);
    REQUIRE(s.is_stable());
    CHECK(s.n_breaks >= 1);
    CHECK(s.n_solves == s.n_breaks + 1);
    CHECK(s.max_ratio < 1.0);
    const BeamStress now = current_beam_stress(m, dual, options.crack_tip, 1.02 * first);
    CHECK_FALSE(select_beam_to_break(now, strengths, m.states()).found());
  }
  SECTION("a cap ends the loop with a status, not an exception") {
    BeamMechanics m(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
    std::vector<BreakEvent> log;
    BreakLoopOptions options;
    options.max_breaks = 3;
    const auto s = break_until_stable(m, dual, strengths, options, 1.0, log, 1.0);  // 5000 x T_u in strain
    CHECK(s.status == BreakLoopStatus::break_cap);
    CHECK(s.n_breaks == 3);
    CHECK(log.size() == 3u);
    CHECK(s.max_ratio >= 1.0);
    CHECK(s.message.find("max_breaks") != std::string::npos);
  }
}

TEST_CASE("Crack-face pressure is self-equilibrated and opens the crack", "[lattice2d]") {
  LatticeSpec spec;
  spec.n_particles = 3000;
  spec.seed = 7;
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  const std::vector<int> crack = beams_crossing_segment(lattice, {-0.3, 0.0}, {0.3, 0.0});
  // ~0.6 / (mean spacing ~0.03) crossings, at least one per spacing.
  REQUIRE(crack.size() >= 15u);
  for (int e : crack) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    CHECK(lattice.points(1, i) * lattice.points(1, j) < 0.0);
  }
  const double p = 1e-3;
  const Eigen::VectorXd f = crack_face_forces(lattice, dual, crack, p);
  Eigen::Vector3d net = Eigen::Vector3d::Zero();  // (f_x, f_y, moment about the origin)
  double scale = 0;
  for (int q = 0; q < lattice.n_particles(); ++q) {
    const Eigen::Vector2d fq = f.segment<2>(3 * q), x = lattice.points.col(q);
    net += Eigen::Vector3d(fq.x(), fq.y(), x.x() * fq.y() - x.y() * fq.x());
    scale = std::max(scale, fq.norm());
    CHECK(f[3 * q + 2] == 0.0);
  }
  CHECK(net.norm() <= 1e-14 * scale * crack.size());  // round-off
  // The upper face is pushed up with p times the crack's projected length (divergence theorem on the
  // Voronoi polyline, whose ends lie within one spacing of +-0.3).
  double up = 0;
  for (int e : crack) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const double to_upper = lattice.points(1, j) > 0 ? 1.0 : -1.0;  // force on the upper particle: +-p d n
    up += to_upper * p * dual.dual_length[e] * lattice.direction(1, e);
  }
  CHECK(up == Approx(p * 0.6).epsilon(0.15));
  // Weights scale each beam's push: all 1 is the unweighted load bit for bit, and one beam at weight 0.25
  // leaves a quarter of its push.
  CHECK(crack_face_forces(lattice, dual, crack, p, std::vector<double>(crack.size(), 1.0)) == f);
  std::vector<double> weights(crack.size(), 1.0);
  weights[0] = 0.25;
  const Eigen::VectorXd g = crack_face_forces(lattice, dual, crack, p, weights);
  const Eigen::VectorXd alone = crack_face_forces(lattice, dual, {crack[0]}, p);
  // Round-off of the particles' sums of a few pushes: 1e-12 of one push.
  CHECK((f - g - 0.75 * alone).cwiseAbs().maxCoeff() <= 1e-12 * alone.cwiseAbs().maxCoeff());
  CHECK_THROWS_AS(crack_face_forces(lattice, dual, crack, p, {1.0}), hm::InputError);

  BeamMechanics m(lattice, BeamParameters{}, BoundaryConditions{});
  for (int e : crack) CHECK(m.break_beam(e) == BeamState::open);
  m.set_external_forces(f);
  const MechanicsSummary s = m.solve();
  REQUIRE(s.is_converged());
  CHECK(s.n_contacts == 0);
  for (const CrackOpening& o : crack_opening(lattice, m.displacement(), crack)) {
    CHECK(o.normal_opening > 0.0);
    // The faces separate across the crack line: the jump points from the lower to the upper particle.
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(o.beam)];
    const double sign = lattice.points(1, j) > lattice.points(1, i) ? 1.0 : -1.0;
    CHECK(sign * o.jump.y() > 0.0);
  }
}

TEST_CASE("Fracture inputs are rejected with the field named", "[lattice2d]") {
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const hm::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  auto contains = [](const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; };
  SECTION("defaults are valid") {
    CHECK_NOTHROW(BreakLoopOptions{}.validate());
    CHECK_NOTHROW(LoadSteppingOptions{}.validate());
  }
  SECTION("break loop options") {
    BreakLoopOptions o;
    o.max_breaks = 0;
    CHECK(contains(message([&] { o.validate(); }), "break_loop.max_breaks = 0"));
    o = {};
    o.crack_tip.material_length = -1;
    CHECK(contains(message([&] { o.validate(); }), "break_loop.crack_tip.material_length"));
  }
  SECTION("load stepping options") {
    LoadSteppingOptions o;
    o.load_increment = 0;
    CHECK(contains(message([&] { o.validate(); }), "load_stepping.load_increment = 0"));
    o = {};
    o.initial_load = -1;
    CHECK(contains(message([&] { o.validate(); }), "load_stepping.initial_load = -1"));
    o = {};
    o.initial_load = 2;
    o.max_load = 1;
    CHECK(contains(message([&] { o.validate(); }), "load_stepping.max_load = 1"));
    o = {};
    o.max_steps = 0;
    CHECK(contains(message([&] { o.validate(); }), "load_stepping.max_steps = 0"));
    o = {};
    o.max_breaks = -3;
    CHECK(contains(message([&] { o.validate(); }), "load_stepping.max_breaks = -3"));
    o = {};
    o.break_loop.max_breaks = 0;
    CHECK(contains(message([&] { o.validate(); }), "load_stepping.break_loop.max_breaks = 0"));
    o = {};
    o.max_load = std::nan("");
    CHECK(contains(message([&] { o.validate(); }), "load_stepping.max_load"));
  }
  SECTION("break loop arguments, crack beams and pressure") {
    const Lattice lattice = square(3, 600);
    const DualGraph dual = build_dual_graph(lattice);
    BeamMechanics m(lattice, BeamParameters{}, uniaxial_pull(lattice, 1.0));
    std::vector<BreakEvent> log;
    const BeamStrengths good = draw_beam_strengths({}, lattice.n_beams()), short_one = draw_beam_strengths({}, 3);
    CHECK(contains(message([&] { break_until_stable(m, dual, good, {}, 0.0, log, -1.0); }), "stress_scale = -1"));
    CHECK(contains(message([&] { break_until_stable(m, dual, short_one, {}, 0.0, log, 1.0); }), "strengths"));
    CHECK(contains(message([&] {
                     crack_face_forces(lattice, dual, {0, lattice.n_beams()}, 1.0);
                   }),
                   "crack_beams[1] = " + std::to_string(lattice.n_beams())));
    CHECK(contains(message([&] { crack_face_forces(lattice, dual, {0}, INFINITY); }), "pressure = "));
    CHECK(contains(message([&] { crack_opening(lattice, m.displacement(), {-1}); }), "beams[0] = -1"));
  }
}
