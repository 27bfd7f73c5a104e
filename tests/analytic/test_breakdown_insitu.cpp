// Breakdown pressures under an in-situ stress: Hubbert-Willis and Haimson-Fairhurst against the
// Kirsch wall they come from, the jacketed finite annulus against its closed form and its R_i -> 0
// limit, and bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "approx.hpp"
#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/core/input_error.hpp"

using namespace hm::analytic;
using hm::test::roundoff;

namespace {

const FarFieldStress far{3e-3, 2e-3, 0.4};

// Largest effective hoop stress sigma_theta + b p0 on a wall of radius a, over 720 angles of every
// quarter degree from the S_H axis (which is one of them).
double max_wall_hoop(const std::function<PolarState(double, double)>& state, double a, double b_p0) {
  double worst = -1e300;
  for (int i = 0; i < 720; ++i)
    worst = std::max(worst, state(a, far.theta_H + i * std::numbers::pi / 360.0).sigma_theta + b_p0);
  return worst;
}

}  // namespace

TEST_CASE("Hubbert-Willis is the Kirsch wall reaching the tensile strength", "[analytic]") {
  BreakdownParameters m;  // T_u = 2e-4, p0 = 0, b = 1
  // Hand check: 3 S_h - S_H + T_u = 6e-3 - 3e-3 + 2e-4 = 3.2e-3.
  CHECK(hubbert_willis_breakdown(far, m).p_w == roundoff(3.2e-3));
  CHECK(hubbert_willis_breakdown(far, m).theta == 0.0);  // on the S_H axis
  CHECK(haimson_fairhurst_breakdown(far, m).theta == 0.0);
  SECTION("p0 = 0: the wall hoop stress at p_b is T_u on the S_H axis and nowhere above") {
    const KirschHole k(far, hubbert_willis_breakdown(far, m).p_w, 0.05, m.nu);
    CHECK(k.state(0.05, far.theta_H).sigma_theta == roundoff(m.T_u));
    CHECK(max_wall_hoop([&](double r, double t) { return k.state(r, t); }, 0.05, 0.0) == roundoff(m.T_u));
  }
  SECTION("with a pore pressure the effective hoop stress sigma_theta + b p0 reaches T_u") {
    m.p0 = 1e-3;
    m.b = 0.6;
    CHECK(hubbert_willis_breakdown(far, m).p_w == roundoff(3.2e-3 - 0.6e-3));
    const KirschHole k(far, hubbert_willis_breakdown(far, m).p_w, 0.05, m.nu);
    CHECK(k.state(0.05, far.theta_H).sigma_theta + m.b * m.p0 == roundoff(m.T_u));
  }
}

TEST_CASE("Haimson-Fairhurst is the Kirsch wall with the penetrating fluid's hoop stress", "[analytic]") {
  BreakdownParameters m;
  m.p0 = 1e-3;
  SECTION("textbook form at b = 1: (3 S_h - S_H + T_u - 2 eta p0)/(2 - 2 eta)") {
    // nu = 0.25: eta = 0.5/1.5 = 1/3; (3.2e-3 - (2/3) 1e-3)/(4/3) = 2.5333e-3 * 0.75 = 1.9e-3.
    CHECK(poroelastic_stress_coefficient(1.0, 0.25) == roundoff(1.0 / 3.0));
    CHECK(haimson_fairhurst_breakdown(far, m).p_w == roundoff(1.9e-3));
  }
  SECTION("at p_b: Kirsch's hoop stress - 2 eta (p_b - p0) + b p_b = T_u, for any b and nu") {
    for (double b : {0.0, 0.3, 1.0})
      for (double nu : {0.1, 0.25, 0.45}) {
        CAPTURE(b, nu);
        m.b = b;
        m.nu = nu;
        const double p_b = haimson_fairhurst_breakdown(far, m).p_w, eta = poroelastic_stress_coefficient(b, nu);
        const KirschHole k(far, p_b, 0.05, nu);
        CHECK(k.state(0.05, far.theta_H).sigma_theta - 2.0 * eta * (p_b - m.p0) + b * p_b == roundoff(m.T_u));
      }
  }
  SECTION("without poroelastic coupling (b = 0) it is Hubbert-Willis") {
    m.b = 0.0;
    CHECK(haimson_fairhurst_breakdown(far, m).p_w == roundoff(hubbert_willis_breakdown(far, m).p_w));
  }
}

TEST_CASE("The jacketed finite annulus breaks down where its wall hoop stress reaches T_u", "[analytic]") {
  BreakdownParameters m;
  m.p0 = 5e-4;
  m.b = 0.8;
  const double R_i = 0.138;
  const auto bd = annulus_jacketed_breakdown(far, m, R_i);
  CHECK(bd.theta == 0.0);
  const InSituAnnulus ann(far, bd.p_w, R_i, m.nu);
  CHECK(ann.state(R_i, far.theta_H + bd.theta).sigma_theta + m.b * m.p0 == roundoff(m.T_u));
  CHECK(max_wall_hoop([&](double r, double t) { return ann.state(r, t); }, R_i, m.b * m.p0) == roundoff(m.T_u));
  SECTION("closed form: p_b = (T_u - b p0 - g q + 2P/m) m/(1 + R_i^2), g = 4 (1 + 2R_i^2)/m^2, m = 1 - R_i^2") {
    const double a2 = R_i * R_i, mm = 1.0 - a2, g = 4.0 * (1.0 + 2.0 * a2) / (mm * mm);
    const double P = 0.5 * (far.S_H + far.S_h), q = 0.5 * (far.S_H - far.S_h);
    CHECK(bd.p_w == roundoff((m.T_u - m.b * m.p0 - g * q + 2.0 * P / mm) * mm / (1.0 + a2)));
  }
  SECTION("it tends to Hubbert-Willis like R_i^2") {
    const double hw = hubbert_willis_breakdown(far, m).p_w;
    const auto d = [&](double a) { return std::abs(annulus_jacketed_breakdown(far, m, a).p_w - hw); };
    const double e1 = d(1e-3), e2 = d(2e-3), e4 = d(4e-3);
    CAPTURE(e1, e2, e4);
    // Next term O(R_i^4): a relative 1.6e-5 at R_i = 4e-3; round-off 1e-16 hw against e1 ~ 1e-6 hw.
    CHECK(std::log2(e2 / e1) == Approx(2.0).margin(1e-3));
    CHECK(std::log2(e4 / e2) == Approx(2.0).margin(1e-3));
  }
}

TEST_CASE("Breakdown input is refused with one line naming value and rule", "[analytic]") {
  const auto refused = [](const std::function<void()>& f, const std::string& message) {
    CHECK_THROWS_AS(f(), hm::InputError);
    CHECK_THROWS_WITH(f(), message);
  };
  const auto with = [](const std::function<void(BreakdownParameters&)>& change) {
    BreakdownParameters m;
    change(m);
    return m;
  };
  CHECK_NOTHROW(BreakdownParameters{}.validate());
  refused([&] { hubbert_willis_breakdown(far, with([](auto& m) { m.T_u = 0.0; })); }, "T_u = 0, allowed: T_u > 0");
  refused([&] { haimson_fairhurst_breakdown(far, with([](auto& m) { m.p0 = -1.0; })); }, "p0 = -1, allowed: p0 >= 0");
  refused([&] { haimson_fairhurst_breakdown(far, with([](auto& m) { m.b = 1.5; })); }, "b = 1.5, allowed: 0 <= b <= 1");
  refused([&] { annulus_jacketed_breakdown(far, with([](auto& m) { m.nu = 0.5; }), 0.138); },
          "nu = 0.5, allowed: 0 < nu < 0.5");
  refused([&] { annulus_jacketed_breakdown(far, BreakdownParameters{}, 1.0); }, "R_i = 1, allowed: 0 < R_i < 1");
  refused(
      [] {
        hubbert_willis_breakdown({1.0, 2.0, 0.0}, BreakdownParameters{});
      },
      "S_h = 2, allowed: 0 <= S_h <= S_H (1)");
}
