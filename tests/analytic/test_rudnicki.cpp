// Rudnicki's continuous line source (analytic/rudnicki.hpp): the closed form is checked against the
// equations it claims to solve, not against itself. Every physical constant the checks need (S, eta,
// Hooke's law) is written out here independently of the library.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "approx.hpp"
#include "hm/analytic/rudnicki.hpp"
#include "hm/core/input_error.hpp"

using hm::analytic::PoroelasticParameters;
using hm::analytic::RadialState;
using hm::analytic::RudnickiLineSource;
using hm::analytic::VolStrain;
using std::numbers::pi;

namespace {

struct Case {
  const char* name;
  double Q;
  PoroelasticParameters material;
};

PoroelasticParameters material(double b, double nu, double E_over_M, VolStrain v) {
  PoroelasticParameters m;
  m.b = b;
  m.nu = nu;
  m.E_over_M = E_over_M;
  m.vol_strain = v;
  return m;
}

/// The paper's Fig. 7 case (Q = 0.1, b = 0.5, Eq. 22's E/M) and two others spanning b, nu and E/M,
/// each with both volumetric-strain variants.
std::vector<Case> cases() {
  std::vector<Case> out;
  for (VolStrain v : {VolStrain::plane_strain, VolStrain::appendix_a}) {
    out.push_back({"paper Fig. 7", 0.1, material(0.5, 0.25, hm::analytic::E_over_M_table1(0.5, 0.25), v)});
    out.push_back({"stiff fluid, b = 0.8", 0.02, material(0.8, 0.1, 0.3, v)});
    out.push_back({"soft fluid, b = 0.2", 1.0, material(0.2, 0.4, 2.0, v)});
  }
  return out;
}

/// eta = b (1+nu)(1-2nu)/(1-nu) = b/(lambda + 2G) for E = 1, from Hooke's law directly.
double eta_of(const PoroelasticParameters& m) {
  const double lambda = m.nu / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu));
  const double G = 1.0 / (2.0 * (1.0 + m.nu));
  return m.b / (lambda + 2.0 * G);
}
double factor_of(VolStrain v) { return v == VolStrain::plane_strain ? 1.0 : 1.0 / 3.0; }
/// S = E/M + f b eta: eliminating eps_r + eps_theta = eta p from the fluid equation.
double storage_of(const PoroelasticParameters& m) { return m.E_over_M + factor_of(m.vol_strain) * m.b * eta_of(m); }
/// r at which X = S r^2/(4t) takes the given value.
double radius_at(double X, double t, double S) { return std::sqrt(4.0 * t * X / S); }

// Fourth-order central differences. The step is delta times the local length (or time) scale of
// the field: p ~ E1(X) varies on r/(2X) for X > 1 and on r (log) below, and on t/X in time.
// Noise: GSL's E1 carries ~2(1+X) eps relative error (X <= 30 here: <= 1.4e-14); a second difference
// amplifies it by 64/12/delta^2 = 3.3e5 (<= 5e-9 relative), a first difference by 18/12/delta = 375
// (<= 5e-12). Truncation: ~delta^4 = 2.6e-10 times a ratio of derivatives that is O(1) on this scale.
constexpr double delta = 4e-3;
template <class F>
double d1(F f, double x, double h) {
  return (f(x - 2 * h) - 8 * f(x - h) + 8 * f(x + h) - f(x + 2 * h)) / (12 * h);
}
template <class F>
double d2(F f, double x, double h) {
  return (-f(x - 2 * h) + 16 * f(x - h) - 30 * f(x) + 16 * f(x + h) - f(x + 2 * h)) / (12 * h * h);
}
double length_scale(double r, double X) { return r / std::max(1.0, 2.0 * X); }
double time_scale(double t, double X) { return t / std::max(1.0, X); }

/// Turns GSL's abort-on-error handler off for one test and restores whatever was installed before,
/// so quadrature failures come back as a status the test checks.
class GslErrorsAsStatus {
 public:
  GslErrorsAsStatus() : previous_(gsl_set_error_handler_off()) {}
  ~GslErrorsAsStatus() { gsl_set_error_handler(previous_); }
  GslErrorsAsStatus(const GslErrorsAsStatus&) = delete;
  GslErrorsAsStatus& operator=(const GslErrorsAsStatus&) = delete;

 private:
  gsl_error_handler_t* previous_;
};

struct Quadrature {
  double value;
  double abserr;
  int status;
};

/// f on [a, b] (qags) or on [a, inf) (qagiu when b is infinite). Exceptions must not cross GSL's C
/// frames: they become NaN, which GSL reports as a failed status.
template <class F>
Quadrature integrate(F f, double a, double b, double epsrel) {
  auto trampoline = [](double x, void* p) -> double {
    try {
      return (*static_cast<F*>(p))(x);
    } catch (...) {
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
  gsl_function fn{trampoline, &f};
  constexpr std::size_t n_intervals = 2000;
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(n_intervals);
  Quadrature q{};
  q.status = std::isinf(b) ? gsl_integration_qagiu(&fn, a, 0.0, epsrel, n_intervals, w, &q.value, &q.abserr)
                           : gsl_integration_qags(&fn, a, b, 0.0, epsrel, n_intervals, w, &q.value, &q.abserr);
  gsl_integration_workspace_free(w);
  return q;
}

const std::vector<double> X_points = {1e-3, 0.1, 1.0, 5.0, 30.0};
const std::vector<double> t_points = {3e-4, 1e-2, 1.0};

}  // namespace

TEST_CASE("Rudnicki storage is E/M + f b^2 (1+nu)(1-2nu)/(1-nu) for both vol_strain variants", "[analytic]") {
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      CHECK(src.storage() == hm::test::roundoff(storage_of(c.material)));
    }
  }
}

TEST_CASE("Rudnicki pressure solves S dp/dt = (1/r) d/dr (r dp/dr)", "[analytic]") {
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double S = storage_of(c.material);
      for (double t : t_points) {
        for (double X : X_points) {
          const double r = radius_at(X, t, S);
          const double hr = delta * length_scale(r, X), ht = delta * time_scale(t, X);
          const auto p_of_r = [&](double rr) { return src.pressure(rr, t); };
          const auto p_of_t = [&](double tt) { return src.pressure(r, tt); };
          const double storage_term = S * d1(p_of_t, t, ht);
          const double p_rr = d2(p_of_r, r, hr), p_r_over_r = d1(p_of_r, r, hr) / r;
          const double residual = std::abs(storage_term - (p_rr + p_r_over_r)) /
                                  (std::abs(storage_term) + std::abs(p_rr) + std::abs(p_r_over_r));
          INFO("t = " << t << ", X = " << X << ", r = " << r << ", relative residual = " << residual);
          // Finite-difference error budget above (<= ~5e-9); 1e-6 is the required bound. A wrong S
          // (e.g. the other vol_strain factor) gives >= 1e-4 even at X = 1e-3.
          CHECK(residual <= 1e-6);
        }
      }
    }
  }
}

TEST_CASE("Rudnicki displacement solves the radial equilibrium Eq. A3 with its own pressure", "[analytic]") {
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double S = storage_of(c.material), eta = eta_of(c.material);
      for (double t : t_points) {
        for (double X : X_points) {
          const double r = radius_at(X, t, S);
          // Beyond X ~ 5, u_r is the homogeneous field C/r (the E1 part is 4 X e^-X relative), whose
          // terms cancel in Eq. A3: a step on r/(2X) would only amplify its noise, 5.3 eps (2X/delta)^2,
          // so the step stops shrinking at X = 5 (noise <= 5.3 eps (10/delta)^2 = 7e-9).
          const double h = delta * length_scale(r, std::min(X, 5.0));
          const auto u = [&](double rr) { return src.radial_displacement(rr, t); };
          const auto p = [&](double rr) { return src.pressure(rr, t); };
          // u'' + u'/r - u/r^2 = eta p'  (Eq. A3 with E = 1)
          const double terms[] = {d2(u, r, h), d1(u, r, h) / r, -u(r) / (r * r), -eta * d1(p, r, h)};
          double sum = 0.0, scale = 0.0;
          for (double term : terms) sum += term, scale += std::abs(term);
          const double residual = std::abs(sum) / scale;
          INFO("t = " << t << ", X = " << X << ", relative residual = " << residual);
          // Same finite-difference budget as the pressure test; 1e-6 required.
          CHECK(residual <= 1e-6);
        }
      }
    }
  }
}

TEST_CASE("Rudnicki effective stresses follow Hooke's law with eps_r = du/dr and balance the total stress",
          "[analytic]") {
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double S = storage_of(c.material), nu = c.material.nu, b = c.material.b;
      const double lambda = nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), two_G = 1.0 / (1.0 + nu);
      for (double t : t_points) {
        for (double X : X_points) {
          const double r = radius_at(X, t, S);
          const double h = delta * length_scale(r, X);
          const RadialState s = src.state(r, t);
          CHECK(s.p == src.pressure(r, t));
          CHECK(s.u_r == src.radial_displacement(r, t));

          const double eps_r = d1([&](double rr) { return src.radial_displacement(rr, t); }, r, h);
          const double eps_theta = s.u_r / r;
          const double trace = eps_r + eps_theta;
          const double scale = std::abs(s.sigma_r) + std::abs(s.sigma_theta);
          const double hooke = std::max({std::abs(s.sigma_r - (lambda * trace + two_G * eps_r)),
                                         std::abs(s.sigma_theta - (lambda * trace + two_G * eps_theta)),
                                         std::abs(s.sigma_z - lambda * trace)}) /
                               scale;
          INFO("t = " << t << ", X = " << X << ", Hooke deviation = " << hooke);
          // One first difference: noise 5e-12, truncation ~delta^4 = 3e-10 relative; 1e-7 is a margin
          // of 300 that still catches du/dr written as +u/r or eta p + u/r (O(1) errors).
          CHECK(std::abs(s.sigma_r - (lambda * trace + two_G * eps_r)) <= 1e-7 * scale);
          CHECK(std::abs(s.sigma_theta - (lambda * trace + two_G * eps_theta)) <= 1e-7 * scale);
          CHECK(std::abs(s.sigma_z - lambda * trace) <= 1e-7 * scale);

          // Total stress sigma_m - b p (tension positive) is in equilibrium:
          // d(sigma_r)/dr + (sigma_r - sigma_theta)/r = 0.
          const auto total_r = [&](double rr) {
            const RadialState q = src.state(rr, t);
            return q.sigma_r - b * q.p;
          };
          const double terms[] = {d1(total_r, r, h), (s.sigma_r - s.sigma_theta) / r};
          const double residual = std::abs(terms[0] + terms[1]) / (std::abs(terms[0]) + std::abs(terms[1]));
          INFO("equilibrium residual = " << residual);
          // First-difference budget as above; a sign error in b p gives O(1).
          CHECK(residual <= 1e-7);
        }
      }
    }
  }
}

TEST_CASE("Rudnicki flux through a circle is Q exp(-X) and tends to Q at the source", "[analytic]") {
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double S = storage_of(c.material), t = 3e-4;
      // X = 1e-12 lies in the series branch, 1e-9 in GSL's; at both, Q exp(-X) = Q to 1e-9.
      for (double X : {1e-12, 1e-9, 1e-6, 0.5, 4.0}) {
        const double r = radius_at(X, t, S);
        const double h = delta * length_scale(r, X);
        const double flux = -2.0 * pi * r * d1([&](double rr) { return src.pressure(rr, t); }, r, h);
        INFO("X = " << X << ", flux/(Q exp(-X)) - 1 = " << flux / (c.Q * std::exp(-X)) - 1.0);
        // First-difference budget: truncation ~delta^4 = 2.6e-10 times O(1) (measured <= 3.3e-10, at
        // X = 4); 1e-8 leaves a margin of 30 and still rejects any wrong factor.
        CHECK(std::abs(flux - c.Q * std::exp(-X)) <= 1e-8 * std::abs(c.Q));
        // The required near-source limit (Q exp(-X) differs from Q by X <= 1e-9 here).
        if (X <= 1e-9) CHECK(std::abs(flux - c.Q) <= 1e-6 * std::abs(c.Q));
      }
    }
  }
}

TEST_CASE("Rudnicki fluid content E/M p + f b eps_v integrates to the injected volume Q t", "[analytic]") {
  const GslErrorsAsStatus gsl_guard;
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double S = storage_of(c.material), f = factor_of(c.material.vol_strain);
      const double nu = c.material.nu, E_over_M = c.material.E_over_M, b = c.material.b;
      for (double t : {3e-4, 0.05}) {
        const double injected = c.Q * t;
        // eps_r + eps_theta from the returned effective stresses: sigma_r + sigma_theta = eps_v/((1+nu)(1-2nu)).
        const auto content = [&](double r) {
          if (r <= 0.0) return 0.0;  // a set of measure zero; the source point itself is excluded
          const RadialState s = src.state(r, t);
          const double eps_v = (1.0 + nu) * (1.0 - 2.0 * nu) * (s.sigma_r + s.sigma_theta);
          return (E_over_M * s.p + f * b * eps_v) * 2.0 * pi * r;
        };
        const double r_plume = radius_at(1.0, t, S);
        const Quadrature inner = integrate(content, 0.0, r_plume, 1e-11);
        const Quadrature outer = integrate(content, r_plume, std::numeric_limits<double>::infinity(), 1e-11);
        REQUIRE(inner.status == GSL_SUCCESS);
        REQUIRE(outer.status == GSL_SUCCESS);
        const double total = inner.value + outer.value, abserr = inner.abserr + outer.abserr;
        INFO("t = " << t << ", total/(Q t) - 1 = " << total / injected - 1.0
                    << ", abserr/(Q t) = " << abserr / injected);
        CHECK(abserr <= 1e-9 * std::abs(injected));  // the quadrature itself is sharp enough to mean something
        // Quadrature's own error estimate, plus round-off of the summed integrand.
        CHECK(std::abs(total - injected) <= abserr + 1e-13 * std::abs(injected));

        // Divergence form, which weighs u_r itself: int_0^R eps_v 2 pi r dr = 2 pi R u_r(R), taken at
        // X(R) = 700 where the pressure beyond R is < e^-700.
        const double R = radius_at(700.0, t, S);
        const Quadrature pressure =
            integrate([&](double r) { return r <= 0.0 ? 0.0 : src.pressure(r, t) * 2.0 * pi * r; }, 0.0, R, 1e-11);
        REQUIRE(pressure.status == GSL_SUCCESS);
        const double by_divergence = E_over_M * pressure.value + f * b * 2.0 * pi * R * src.radial_displacement(R, t);
        INFO("divergence form: /(Q t) - 1 = " << by_divergence / injected - 1.0);
        CHECK(std::abs(by_divergence - injected) <= E_over_M * pressure.abserr + 1e-13 * std::abs(injected));
      }
    }
  }
}

TEST_CASE("Rudnicki pressure equals the time integral of the instantaneous line source", "[analytic]") {
  const GslErrorsAsStatus gsl_guard;
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double S = storage_of(c.material);
      for (double t : t_points) {
        for (double X : {1e-6, 1e-2, 0.5, 3.0, 20.0, 100.0}) {
          const double r = radius_at(X, t, S);
          // p = Q/(4 pi) int_0^t exp(-S r^2/(4 tau))/tau dtau: superposed instantaneous sources (Green's
          // function of S dp/dt - lap p in 2D), no E1 involved.
          const Quadrature q = integrate(
              [&](double tau) { return tau <= 0.0 ? 0.0 : std::exp(-S * r * r / (4.0 * tau)) / tau; }, 0.0, t, 1e-12);
          REQUIRE(q.status == GSL_SUCCESS);
          const double reference = c.Q / (4.0 * pi) * q.value;
          const double p = src.pressure(r, t);
          INFO("t = " << t << ", X = " << X << ", p/reference - 1 = " << p / reference - 1.0
                      << ", quadrature relative error estimate = " << q.abserr / q.value);
          // Quadrature's error estimate plus GSL's stated E1 precision 2 (1+X) eps (relative).
          const double tol = c.Q / (4.0 * pi) * q.abserr + 2.0 * (1.0 + X) * 2.3e-16 * std::abs(p);
          CHECK(std::abs(p - reference) <= tol);
          CHECK(q.abserr <= 1e-10 * std::abs(q.value));  // the reference is tight enough to catch a wrong S
        }
      }
    }
  }
}

TEST_CASE("Rudnicki fields vanish far away, match the small-X asymptotes, and are continuous across branches",
          "[analytic]") {
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double S = storage_of(c.material), eta = eta_of(c.material), t = 3e-4;
      const double line_dilatation = eta * c.Q * t / (2.0 * pi * S);  // r u_r outside the plume

      // Far field: 0 <= p < Q/(4 pi) exp(-X)/X (the bound E1(X) < exp(-X)/X; both sides underflow to 0
      // from X ~ 700), and u_r = eta Q t/(2 pi S r), the elastic field of a line dilatation
      // (round-off: a handful of operations; E1 and exp(-X) are below 1e-290 relative here).
      for (double r : {1.0, 10.0, 1e3, 1e6}) {
        const double X = S * r * r / (4.0 * t);
        CHECK(src.pressure(r, t) >= 0.0);
        CHECK(src.pressure(r, t) <= c.Q / (4.0 * pi) * std::exp(-X) / X);
        CHECK(src.radial_displacement(r, t) == hm::test::roundoff(line_dilatation / r));
      }
      CHECK(src.pressure(10.0, t) == 0.0);
      CHECK(std::abs(src.radial_displacement(1e9, t)) < 1e-14);  // eta Q t/(2 pi S r) ~ 2e-15 here

      // Near the source: p = Q/(4 pi)(-gamma - ln X), u_r = eta Q r/(8 pi)(1 - gamma - ln X), both up
      // to O(X) relative; u_r -> 0 like r ln r.
      for (double X : {1e-14, 1e-10, 1e-8}) {
        const double r = radius_at(X, t, S);
        const double log_term = -std::numbers::egamma - std::log(X);
        INFO("X = " << X);
        // Dropped terms are O(X) relative, <= 1e-8 here; GSL/round-off are ~1e-15.
        CHECK(src.pressure(r, t) == Approx(c.Q / (4.0 * pi) * log_term).epsilon(2e-8));
        CHECK(src.radial_displacement(r, t) == Approx(eta * c.Q * r / (8.0 * pi) * (1.0 + log_term)).epsilon(2e-8));
      }
      CHECK(std::abs(src.radial_displacement(1e-150, t)) < 1e-145);
      CHECK(std::isfinite(src.pressure(1e-200, t)));  // X underflows to 0; ln X is formed from ln r

      // Branch boundaries: X = series_below (series | GSL) and X = underflow_above (GSL | zero).
      {
        const double X0 = RudnickiLineSource::series_below;
        const double r_lo = radius_at(X0 * (1 - 1e-6), t, S), r_hi = radius_at(X0 * (1 + 1e-6), t, S);
        // E1(X_lo) - E1(X_hi) = ln(X_hi/X_lo) - (X_hi - X_lo) + ...; the jump of a wrong series constant
        // would show at the 1e-13 level. Tolerance: GSL's 3 eps |ln X| absolute on E1, i.e. ~2e-14 on
        // p*4pi/Q, and round-off in the difference.
        const double expected = c.Q / (4.0 * pi) * (2.0 * std::log(r_hi / r_lo));
        CHECK(std::abs(src.pressure(r_lo, t) - src.pressure(r_hi, t) - expected) <= 1e-13 * std::abs(c.Q));
        // u_r/r = eta Q/(8 pi) (E1 + g) moves with E1 alone (g changes by ~1e-16): same tolerance.
        const double expected_u = eta * c.Q / (8.0 * pi) * (2.0 * std::log(r_hi / r_lo));
        const double du = src.radial_displacement(r_lo, t) / r_lo - src.radial_displacement(r_hi, t) / r_hi;
        CHECK(std::abs(du - expected_u) <= 1e-13 * std::abs(eta * c.Q));
      }
      {
        const double X0 = RudnickiLineSource::underflow_above;
        const double r_lo = radius_at(X0 * (1 - 1e-9), t, S), r_hi = radius_at(X0 * (1 + 1e-9), t, S);
        const double p_lo = src.pressure(r_lo, t), p_hi = src.pressure(r_hi, t);
        CHECK(p_hi == 0.0);
        CHECK(p_lo >= 0.0);
        CHECK(std::abs(p_lo) <= 1.5e-307 * std::abs(c.Q));  // E1(700) = 1.4e-307: the jump is below DBL_MIN
        // u_r r and eps are dominated by (1 - e^-X)/X, which has no branch: equal to round-off.
        CHECK(src.radial_displacement(r_lo, t) * r_lo == hm::test::roundoff(line_dilatation));
        CHECK(src.radial_displacement(r_hi, t) * r_hi == hm::test::roundoff(line_dilatation));
        const RadialState lo = src.state(r_lo, t), hi = src.state(r_hi, t);
        CHECK(lo.sigma_r * r_lo * r_lo == Approx(hi.sigma_r * r_hi * r_hi).epsilon(1e-12));
      }
    }
  }
}

TEST_CASE("Rudnicki solution in Rudnicki's notation: c = 2 G kappa (1-nu)(nu_u-nu)/(b^2 (1-2nu)^2 (1-nu_u))",
          "[analytic]") {
  // Rice & Cleary's diffusivity, in which Rudnicki (1986) writes the line source, with kappa = 1,
  // G = 1/(2(1+nu)), and nu_u from lambda_u = lambda + b^2 M. Only the plane-strain variant is Biot's
  // theory; Appendix A's factor 1/3 gives another S.
  for (const Case& c : cases()) {
    SECTION(std::string(c.name) + ", " + hm::core::name_of(c.material.vol_strain)) {
      const RudnickiLineSource src(c.Q, c.material);
      const double nu = c.material.nu, b = c.material.b, M = 1.0 / c.material.E_over_M;
      const double G = 1.0 / (2.0 * (1.0 + nu)), lambda = 2.0 * G * nu / (1.0 - 2.0 * nu);
      const double lambda_u = lambda + b * b * M, nu_u = lambda_u / (2.0 * (lambda_u + G));
      const double c_rc =
          2.0 * G * (1.0 - nu) * (nu_u - nu) / (b * b * (1.0 - 2.0 * nu) * (1.0 - 2.0 * nu) * (1.0 - nu_u));
      if (c.material.vol_strain == VolStrain::plane_strain) {
        CHECK(1.0 / src.storage() == hm::test::roundoff(c_rc));
        // u_r = (nu_u - nu)/(b (1-2nu)(1-nu_u)) Q r/(8 pi c) [E1(X) + (1 - e^-X)/X]: X = r^2/(4 c t).
        const double t = 3e-4, r = 0.02, X = r * r / (4.0 * c_rc * t);
        const double bracket = src.pressure(r, t) * 4.0 * pi / c.Q - std::expm1(-X) / X;
        const double u = (nu_u - nu) / (b * (1.0 - 2.0 * nu) * (1.0 - nu_u)) * c.Q * r / (8.0 * pi * c_rc) * bracket;
        CHECK(src.radial_displacement(r, t) == hm::test::roundoff(u));
      } else {
        // Appendix A's variant diffuses faster than Biot's (by 0.6 %, 17 % and 82 % for these cases).
        CHECK(1.0 / src.storage() > 1.005 * c_rc);
      }
    }
  }
}

TEST_CASE("Rudnicki solution: sign, linearity in Q, zero before injection, rejected arguments", "[analytic]") {
  const PoroelasticParameters m =
      material(0.5, 0.25, hm::analytic::E_over_M_table1(0.5, 0.25), VolStrain::plane_strain);
  const RudnickiLineSource inject(0.1, m), extract(-0.2, m);
  const RadialState s = inject.state(0.02, 3e-4), e = extract.state(0.02, 3e-4);
  CHECK(s.p > 0.0);
  CHECK(s.u_r > 0.0);          // injection pushes the solid outward
  CHECK(s.sigma_theta > 0.0);  // tension positive: hoop effective stress is tensile
  CHECK(e.p == hm::test::roundoff(-2.0 * s.p));
  CHECK(e.u_r == hm::test::roundoff(-2.0 * s.u_r));
  CHECK(e.sigma_r == hm::test::roundoff(-2.0 * s.sigma_r));

  const RadialState before = inject.state(0.02, 0.0), earlier = inject.state(0.02, -1.0);
  CHECK(before.p == 0.0);
  CHECK(before.u_r == 0.0);
  CHECK(earlier.sigma_theta == 0.0);

  CHECK_THROWS_AS(inject.state(0.0, 1.0), std::domain_error);
  CHECK_THROWS_AS(inject.pressure(-0.1, 1.0), std::domain_error);
  CHECK_THROWS_AS(inject.radial_displacement(std::numeric_limits<double>::quiet_NaN(), 1.0), std::domain_error);
  CHECK_THROWS_AS(inject.state(0.1, std::numeric_limits<double>::infinity()), std::domain_error);
  CHECK_THROWS_AS(RudnickiLineSource(std::numeric_limits<double>::quiet_NaN(), m), hm::InputError);
  PoroelasticParameters bad = m;
  bad.E_over_M = 0.0;
  CHECK_THROWS_AS(RudnickiLineSource(0.1, bad), hm::InputError);
}
