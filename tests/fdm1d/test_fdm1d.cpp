// Unit tests of the Appendix A solver (hm/fdm1d/fdm1d.hpp): input validation, the steady state
// against Appendix B with its observed order in dr, linearity in Q, the fluid-volume balance, the
// vol_strain variants, b = 0 decoupling and the Mandel-Cryer negative pressure of Fig. 10D.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "approx.hpp"
#include "hm/analytic/lame.hpp"
#include "hm/analytic/physical_parameters.hpp"
#include "hm/analytic/steady_borehole.hpp"
#include "hm/core/input_error.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace {

using hm::analytic::DimensionlessParameters;
using hm::analytic::VolStrain;
using hm::fdm1d::Fdm1dNumerics;
using hm::fdm1d::Fdm1dResult;
using hm::fdm1d::run_fdm1d;

/// Time steps that reach steady state: implicit Euler is L-stable, so steps growing to dt = 10 damp
/// every transient mode (slowest decay rate ~1, 1/(1 + 10) per step) far below round-off by t = 300.
Fdm1dNumerics steady_numerics(int n_r) {
  Fdm1dNumerics n;
  n.n_r = n_r;
  n.dt_initial = 1e-3;
  n.dt_growth = 2.0;
  n.dt_max = 10.0;
  n.t_end = 300.0;
  n.output_times = {};
  n.probe_radii = {};
  return n;
}

double max_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// Max-norm errors of the final snapshot against the steady state of Appendix B (corrected B6-B9):
/// p and u relative to their own max norm, the stresses relative to the largest stress, max |sigma_theta|
/// (sigma_z alone nearly vanishes for b = 0, so its own norm would be no scale).
struct SteadyErrors {
  double p, u, sigma_r, sigma_theta, sigma_z;
};
SteadyErrors steady_errors(const DimensionlessParameters& prm, int n_r) {
  const Fdm1dResult res = run_fdm1d(prm, steady_numerics(n_r));
  REQUIRE(res.summary.is_success());
  const auto& s = res.snapshots.back();
  const hm::analytic::SteadyBorehole exact(prm.Q, prm.material.b, prm.material.nu, prm.R_i);
  std::vector<double> ep, eu, er, et, ez, xp, xu, xt;
  for (std::size_t i = 0; i < res.r.size(); ++i) {
    const auto e = exact.state(res.r[i]);
    ep.push_back(s.p[i] - e.p), xp.push_back(e.p);
    eu.push_back(s.u_r[i] - e.u_r), xu.push_back(e.u_r);
    er.push_back(s.sigma_r[i] - e.sigma_r);
    et.push_back(s.sigma_theta[i] - e.sigma_theta), xt.push_back(e.sigma_theta);
    ez.push_back(s.sigma_z[i] - e.sigma_z);
  }
  const double stress = max_abs(xt);
  return {max_abs(ep) / max_abs(xp), max_abs(eu) / max_abs(xu), max_abs(er) / stress, max_abs(et) / stress,
          max_abs(ez) / stress};
}

void require_second_order(double e_coarse, double e_mid, double e_fine) {
  // Grids halve dr; the expected order of the centred scheme and of the one-sided boundary
  // differences is 2. Floor 1.8 and band 0.3 as in PorePy's convergence tests.
  for (const double order : {std::log2(e_coarse / e_mid), std::log2(e_mid / e_fine)}) {
    CAPTURE(e_coarse, e_mid, e_fine, order);
    CHECK(order >= 1.8);
    CHECK(std::abs(order - 2.0) <= 0.3);
  }
}

}  // namespace

TEST_CASE("Default 1D numerics are valid", "[fdm1d]") { REQUIRE_NOTHROW(Fdm1dNumerics{}.validate(0.138)); }

TEST_CASE("Bad 1D numerics are rejected with the field's name", "[fdm1d]") {
  const auto rejects = [](auto mutate, const std::string& field) {
    Fdm1dNumerics n;
    mutate(n);
    CAPTURE(field);
    REQUIRE_THROWS_AS(n.validate(0.138), hm::InputError);
    REQUIRE_THROWS_WITH(n.validate(0.138), Catch::StartsWith(field + " = "));
    // run_fdm1d validates before doing anything.
    REQUIRE_THROWS_WITH(run_fdm1d(DimensionlessParameters{}, n), Catch::StartsWith(field + " = "));
  };
  rejects([](Fdm1dNumerics& n) { n.n_r = 7; }, "n_r");
  rejects([](Fdm1dNumerics& n) { n.n_r = 2; }, "n_r");
  rejects([](Fdm1dNumerics& n) { n.dt_initial = 0.0; }, "dt_initial");
  rejects([](Fdm1dNumerics& n) { n.dt_initial = -1e-3; }, "dt_initial");
  rejects([](Fdm1dNumerics& n) { n.dt_growth = 0.9; }, "dt_growth");
  rejects([](Fdm1dNumerics& n) { n.dt_max = 0.5 * n.dt_initial; }, "dt_max");
  rejects([](Fdm1dNumerics& n) { n.t_end = 0.0; }, "t_end");
  rejects([](Fdm1dNumerics& n) { n.output_times = {0.1, 2.0}; }, "output_times[1]");
  rejects([](Fdm1dNumerics& n) { n.output_times = {0.0}; }, "output_times[0]");
  rejects([](Fdm1dNumerics& n) { n.output_times = {0.2, 0.1}; }, "output_times[1]");
  rejects([](Fdm1dNumerics& n) { n.probe_radii = {0.5, 0.1}; }, "probe_radii[1]");
  rejects([](Fdm1dNumerics& n) { n.probe_radii = {1.2}; }, "probe_radii[0]");
}

TEST_CASE("The 1D model rejects a point injection (R_i = 0)", "[fdm1d]") {
  DimensionlessParameters prm;
  prm.R_i = 0.0;
  REQUIRE_THROWS_WITH(run_fdm1d(prm, Fdm1dNumerics{}), Catch::StartsWith("R_i = 0"));
}

TEST_CASE("Output times are hit exactly and t_end is always stored", "[fdm1d]") {
  Fdm1dNumerics n;
  n.n_r = 20;
  n.t_end = 0.07;
  n.output_times = {0.01, 0.05};
  const Fdm1dResult res = run_fdm1d(hm::analytic::table1_borehole(0.5), n);
  REQUIRE(res.snapshots.size() == 3);
  CHECK(res.snapshots[0].t == 0.01);
  CHECK(res.snapshots[1].t == 0.05);
  CHECK(res.snapshots[2].t == 0.07);
  CHECK(res.borehole.back().t == 0.07);
  CHECK(res.borehole.size() == static_cast<std::size_t>(res.summary.n_steps) + 1);
  CHECK(res.probe_p.size() == res.borehole.size());
  CHECK(res.r.front() == 0.138);
  CHECK(res.r.back() == 1.0);
}

TEST_CASE("The progress callback sees every step and ends at t_end", "[fdm1d]") {
  Fdm1dNumerics n;
  n.n_r = 20;
  n.t_end = 0.05;
  n.output_times = {0.01};
  long calls = 0;
  double last = 0.0;
  const Fdm1dResult res = run_fdm1d(hm::analytic::table1_borehole(0.5), n, [&](double t, double t_end) {
    ++calls;
    CHECK(t > last);
    CHECK(t_end == 0.05);
    last = t;
  });
  CHECK(calls == res.summary.n_steps);
  CHECK(last == 0.05);
}

TEST_CASE("The step observer sees t = 0 and every step, each snapshot as its step lands", "[fdm1d]") {
  Fdm1dNumerics n;
  n.n_r = 20;
  n.t_end = 0.05;
  n.output_times = {0.01};
  std::vector<std::size_t> samples, snapshots;
  const auto prm = hm::analytic::table1_borehole(0.5);
  const Fdm1dResult res = run_fdm1d(prm, n, {}, [&](const Fdm1dResult& so_far) {
    samples.push_back(so_far.borehole.size());
    snapshots.push_back(so_far.snapshots.size());
    // A snapshot is seen with the step that reached its time.
    if (!so_far.snapshots.empty()) CHECK(so_far.snapshots.back().t <= so_far.borehole.back().t);
    if (so_far.borehole.back().t == 0.01) CHECK(so_far.snapshots.size() == 1);
  });
  REQUIRE(samples.size() == static_cast<std::size_t>(res.summary.n_steps) + 1);
  for (std::size_t k = 0; k < samples.size(); ++k) CHECK(samples[k] == k + 1);
  CHECK(snapshots.front() == 0);
  CHECK(snapshots.back() == 2);
  // Observing changes nothing: the same run without an observer, bit for bit.
  const Fdm1dResult plain = run_fdm1d(prm, n);
  CHECK(plain.summary.n_steps == res.summary.n_steps);
  CHECK(plain.snapshots.back().p == res.snapshots.back().p);
}

TEST_CASE("A stop request ends the run after the step it came in, keeping the steps done", "[fdm1d]") {
  Fdm1dNumerics n;
  n.n_r = 20;
  n.t_end = 0.05;
  n.output_times = {0.01};
  const auto prm = hm::analytic::table1_borehole(0.5);
  int asked = 0;
  const Fdm1dResult res = run_fdm1d(prm, n, {}, {}, [&] { return ++asked == 5; });
  CHECK(res.summary.status == hm::fdm1d::Fdm1dSummary::Status::interrupted);
  CHECK_FALSE(res.summary.is_success());
  CHECK(asked == 5);
  CHECK(res.summary.n_steps == 5);
  REQUIRE(res.borehole.size() == 6);  // t = 0 and the five steps
  CHECK(res.probe_p.size() == 6);
  CHECK(res.snapshots.empty());  // 0.01 is not reached in five steps from dt = 1e-5
  CHECK_THAT(res.summary.message, Catch::StartsWith("stopped on request at t = "));
  // The steps done are those of the whole run.
  const Fdm1dResult whole = run_fdm1d(prm, n);
  CHECK(res.borehole.back().t == whole.borehole[5].t);
  CHECK(res.borehole.back().p_h == whole.borehole[5].p_h);
  const Fdm1dResult first = run_fdm1d(prm, n, {}, {}, [] { return true; });
  CHECK(first.summary.status == hm::fdm1d::Fdm1dSummary::Status::interrupted);
  CHECK(first.summary.n_steps == 1);
  // A request that comes with the step reaching t_end does not make a complete run incomplete.
  n.t_end = n.dt_initial;
  n.output_times = {};
  const Fdm1dResult last = run_fdm1d(prm, n, {}, {}, [] { return true; });
  CHECK(last.summary.is_success());
  CHECK(last.summary.n_steps == 1);
  CHECK(last.snapshots.size() == 1);
}

TEST_CASE("The steady state matches Appendix B at second order in dr", "[fdm1d]") {
  // Discrete steady state: p is the finite-volume solution of B1 whatever b and vol_strain are; u
  // and the stresses follow from p through the mechanics rows. The grid is uniform, so the error
  // constant is set by dr/R_i at the wall (one-sided du/dr: ~2 (dr/R_i)^2 relative for u ~ 1/r);
  // n_r = 100..400 is where the observed order is within the band (1.82..1.95 for sigma_r).
  for (const double b : {0.0, 0.5, 1.0}) {
    CAPTURE(b);
    const auto prm = hm::analytic::table1_borehole(b);
    const auto e1 = steady_errors(prm, 100), e2 = steady_errors(prm, 200), e4 = steady_errors(prm, 400);
    require_second_order(e1.p, e2.p, e4.p);
    require_second_order(e1.u, e2.u, e4.u);
    require_second_order(e1.sigma_r, e2.sigma_r, e4.sigma_r);
    require_second_order(e1.sigma_theta, e2.sigma_theta, e4.sigma_theta);
    require_second_order(e1.sigma_z, e2.sigma_z, e4.sigma_z);
    // The target for p at n_r = 400 (observed 5.0e-6 = 1.1 dr^2: the face fluxes
    // Q dr/(2 pi r) approximate (Q/2pi) ln(r_+/r_-) to dr^3/(12 r^3)).
    CHECK(e4.p <= 1e-4);
    // u and the stresses at n_r = 400: observed <= 8.1e-4 (u) and 1.8e-3 (sigma_r); bound 2x that.
    CHECK(e4.u <= 2e-3);
    CHECK(std::max({e4.sigma_r, e4.sigma_theta, e4.sigma_z}) <= 4e-3);
  }
}

TEST_CASE("The steady-state order in dr tends to 2 on fine grids", "[fdm1d][slow]") {
  const auto prm = hm::analytic::table1_borehole(0.5);
  const auto e4 = steady_errors(prm, 400), e8 = steady_errors(prm, 800), e16 = steady_errors(prm, 1600);
  for (const auto& [coarse, mid, fine] :
       {std::array{e4.u, e8.u, e16.u}, std::array{e4.sigma_r, e8.sigma_r, e16.sigma_r},
        std::array{e4.sigma_theta, e8.sigma_theta, e16.sigma_theta}}) {
    const double order = std::log2(mid / fine);
    CAPTURE(coarse, mid, fine, order);
    // Asymptotic range (dr/R_i <= 0.004): the band tightens to 0.1.
    CHECK(std::abs(order - 2.0) <= 0.1);
  }
}

TEST_CASE("Pressure and displacement divided by Q do not depend on Q", "[fdm1d]") {
  // Section 3.2: the problem is linear with zero initial data, so p/Q, u/Q and the stresses/Q are the
  // same for every Q; in floating point they agree to round-off accumulated over the steps.
  Fdm1dNumerics n;
  n.n_r = 100;
  n.t_end = 0.3;
  n.output_times = {0.01, 0.1, 0.3};
  auto prm = hm::analytic::table1_borehole(0.5);
  const Fdm1dResult ref = run_fdm1d(prm, n);
  for (const double Q : {1e-5, 3.0}) {
    prm.Q = Q;
    const Fdm1dResult res = run_fdm1d(prm, n);
    REQUIRE(res.snapshots.size() == ref.snapshots.size());
    for (std::size_t s = 0; s < ref.snapshots.size(); ++s) {
      const auto& a = ref.snapshots[s];
      const auto& c = res.snapshots[s];
      const double p_scale = max_abs(a.p) / 0.01, u_scale = max_abs(a.u_r) / 0.01,
                   s_scale = max_abs(a.sigma_theta) / 0.01;
      for (std::size_t i = 0; i < a.p.size(); ++i) {
        CAPTURE(Q, s, i);
        // 1e-12 relative to the field's max norm: round-off of ~300 LU solves (each ~1e-15).
        CHECK(std::abs(c.p[i] / Q - a.p[i] / 0.01) <= 1e-12 * p_scale);
        CHECK(std::abs(c.u_r[i] / Q - a.u_r[i] / 0.01) <= 1e-12 * u_scale);
        CHECK(std::abs(c.sigma_theta[i] / Q - a.sigma_theta[i] / 0.01) <= 1e-12 * s_scale);
      }
    }
  }
}

TEST_CASE("The fluid volume balances at every step to round-off", "[fdm1d]") {
  // injected Q dt = change of stored (E/M p + f b eps_v over the rings) + outflow through r = 1.
  // The scheme is conservative, so the only error is the sparse LU's round-off: 1e-10 is a bound
  // with margin (observed <= 1e-12).
  for (const auto vs : {VolStrain::plane_strain, VolStrain::appendix_a}) {
    for (const double b : {0.0, 0.5, 1.0}) {
      CAPTURE(b, hm::core::name_of(vs));
      Fdm1dNumerics n;  // defaults: geometric steps 1e-5 .. 1e-3, landing on the output times
      n.n_r = 100;
      const Fdm1dResult res = run_fdm1d(hm::analytic::table1_borehole(b, 0.01, vs), n);
      REQUIRE(res.summary.is_success());
      CHECK(res.summary.max_balance_error <= 1e-10);
      const auto& last = res.borehole.back();
      // The per-step balance summed: cumulative injected = stored + outflow.
      CHECK(std::abs(last.injected - last.stored - last.outflow) <= 1e-10 * last.injected);
    }
  }
}

TEST_CASE("Both volumetric-strain variants run and differ only through the coupling", "[fdm1d]") {
  Fdm1dNumerics n;
  n.n_r = 100;
  n.t_end = 0.1;
  n.output_times = {0.1};
  SECTION("b > 0: the factor 1/3 of Eq. A5 changes the transient") {
    const Fdm1dResult ps = run_fdm1d(hm::analytic::table1_borehole(0.5, 0.01, VolStrain::plane_strain), n);
    const Fdm1dResult aa = run_fdm1d(hm::analytic::table1_borehole(0.5, 0.01, VolStrain::appendix_a), n);
    REQUIRE(ps.summary.is_success());
    REQUIRE(aa.summary.is_success());
    // A smaller coupled storage (E/M + f b^2 ...) lets pressure diffuse faster: appendix-a (f = 1/3)
    // is ahead of plane strain at the borehole (observed 6% at t = 0.1).
    CHECK(aa.borehole.back().p_h > 1.02 * ps.borehole.back().p_h);
  }
  SECTION("b = 0: the variants coincide") {
    const Fdm1dResult ps = run_fdm1d(hm::analytic::table1_borehole(0.0, 0.01, VolStrain::plane_strain), n);
    const Fdm1dResult aa = run_fdm1d(hm::analytic::table1_borehole(0.0, 0.01, VolStrain::appendix_a), n);
    for (std::size_t i = 0; i < ps.r.size(); ++i) {
      CHECK(aa.snapshots.back().p[i] == hm::test::roundoff(ps.snapshots.back().p[i]));
      CHECK(aa.snapshots.back().u_r[i] == hm::test::roundoff(ps.snapshots.back().u_r[i]));
    }
  }
}

TEST_CASE("With b = 0 the pressure ignores the solid and the solid is Lame's cylinder", "[fdm1d]") {
  Fdm1dNumerics n;
  n.n_r = 200;
  n.t_end = 2e-3;  // still transient for b = 0 (E/M = 3e-3: p_h reaches 99% at t ~ 2.2e-3)
  n.output_times = {5e-4, 2e-3};
  auto prm = hm::analytic::table1_borehole(0.0);
  const Fdm1dResult a = run_fdm1d(prm, n);
  prm.material.nu = 0.1;  // another solid, same fluid
  const Fdm1dResult c = run_fdm1d(prm, n);
  for (std::size_t s = 0; s < a.snapshots.size(); ++s) {
    const auto& sa = a.snapshots[s];
    for (std::size_t i = 0; i < a.r.size(); ++i) {
      CAPTURE(s, i);
      CHECK(c.snapshots[s].p[i] == hm::test::roundoff(sa.p[i]));
    }
    // u at every time is the drained Lame solution for inner pressure p_h(t) (the effective stress
    // at the wall is -(1 - b) p_h = -p_h, no body force). Tolerance: discretisation error of u at
    // n_r = 200, observed 3.1e-3 relative, as in the steady-state convergence test (b = 0).
    const hm::analytic::LameCylinder lame(sa.p[0], 0.0, 0.138, 1.0, 0.25);
    double err = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < a.r.size(); ++i) {
      err = std::max(err, std::abs(sa.u_r[i] - lame.state(a.r[i]).u_r));
      scale = std::max(scale, std::abs(lame.state(a.r[i]).u_r));
    }
    CAPTURE(s, err / scale);
    CHECK(err <= 4e-3 * scale);
  }
}

TEST_CASE("A transient negative pressure appears for b > 0 and not for b = 0", "[fdm1d]") {
  // Fig. 10D: the solid expands ahead of the pressure front (a reversed Mandel-Cryer effect).
  Fdm1dNumerics n;
  n.n_r = 100;
  n.t_end = 0.2;
  n.output_times = {0.2};
  const double p_h_steady = -0.01 / (2.0 * 3.141592653589793) * std::log(0.138);
  for (const auto vs : {VolStrain::plane_strain, VolStrain::appendix_a}) {
    CAPTURE(hm::core::name_of(vs));
    for (const double b : {0.5, 1.0}) {
      CAPTURE(b);
      const Fdm1dResult res = run_fdm1d(hm::analytic::table1_borehole(b, 0.01, vs), n);
      // Observed about -0.6% of the steady p_h (plane strain, b = 0.5); a tenth of that is a clear
      // signal far above round-off.
      CHECK(res.min_pressure.p < -5e-4 * p_h_steady);
      CHECK(res.min_pressure.r > 0.138);
      CHECK(res.min_pressure.t > 0.0);
    }
    // b = 0 is plain diffusion from a positive source: the M-matrix scheme keeps p >= 0 up to round-off.
    const Fdm1dResult res0 = run_fdm1d(hm::analytic::table1_borehole(0.0, 0.01, vs), n);
    CHECK(res0.min_pressure.p >= -1e-14 * p_h_steady);
  }
}
