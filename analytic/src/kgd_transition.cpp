#include "hm/analytic/kgd_transition.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_gamma.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::analytic {

namespace {

constexpr double pi = std::numbers::pi;

// The solution at the tip's viscous share v = 1 - K_hat^3 in (0, 1] (v, not K_hat, so that the
// K-vertex end, v -> 0, keeps its digits). Dontsov's tip asymptote without leak-off: the distance over
// which the tip's toughness solution gives way to the viscous one, s_hat = v / (3 C1(Delta)), with
// Delta = v / 3 the tip exponent's excess over 1/2 times 2.
struct TipShare {
  double k_hat, delta, lambda, s_hat, B;
};

TipShare tip_share(double v) {
  TipShare s;
  s.k_hat = std::cbrt(1.0 - v);
  const double Delta = v / 3.0;
  s.delta = 0.5 * (1.0 + Delta);
  s.lambda = 0.588 * v + 0.5 * (1.0 - v);
  // C1 = 4 (1 - 2 Delta) tan(pi Delta) / (Delta (1 - Delta)); tan(pi Delta) / Delta -> pi as Delta -> 0.
  const double tan_ratio = Delta < 1e-6 ? pi * (1.0 + pi * pi * Delta * Delta / 3.0) : std::tan(pi * Delta) / Delta;
  const double C1 = 4.0 * (1.0 - 2.0 * Delta) * tan_ratio / (1.0 - Delta);
  s.s_hat = v / (3.0 * C1);
  // B = 2^(1 + delta) int_{1/2}^{1} s^lambda (1 - s)^delta ds: the volume of the opening's shape
  // (1 - rho)^delta (1 + rho)^lambda over [0, 1] is 2^lambda B.
  s.B = std::pow(2.0, 1.0 + s.delta) * gsl_sf_beta(s.delta + 1.0, s.lambda + 1.0) *
        gsl_sf_beta_inc(s.delta + 1.0, s.lambda + 1.0, 0.5);
  return s;
}

// K_m^4 of a tip share: the global volume balance K_hat^4 = 3 K_m^4 B s_hat (alpha = 2/3, l ~ t^(2/3)).
double toughness_number_to_4th(double v) {
  const TipShare s = tip_share(v);
  return std::pow(s.k_hat, 4) / (3.0 * s.B * s.s_hat);
}

}  // namespace

KgdTransitionScales kgd_transition_scales(double K_m) {
  hm::core::require_finite(K_m, "K_m");
  if (!(K_m >= 0.0 && K_m <= 1e6))
    throw hm::InputError("K_m = " + hm::core::format_value(K_m) + ", allowed: 0 <= K_m <= 1e6");
  double v = 1.0;  // the M-vertex
  if (K_m > 0.0) {
    // K_m^4 falls monotonically from ~5e29 at v = 1e-30 to 0 at v = 1; solve in log v.
    const double target = std::log(K_m) * 4.0;
    struct Goal {
      double target;
    } goal{target};
    gsl_function f;
    f.function = [](double log_v, void* p) {
      return std::log(toughness_number_to_4th(std::exp(log_v))) - static_cast<Goal*>(p)->target;
    };
    f.params = &goal;
    double lo = std::log(1e-30), hi = -1e-15;
    if (f.function(hi, &goal) >= 0.0) {
      v = std::exp(hi);  // K_m below ~1e-4: the M-vertex to round-off
    } else {
      const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
          gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
      gsl_root_fsolver_set(solver.get(), &f, lo, hi);
      for (int iter = 0; iter < 200; ++iter) {
        gsl_root_fsolver_iterate(solver.get());
        lo = gsl_root_fsolver_x_lower(solver.get());
        hi = gsl_root_fsolver_x_upper(solver.get());
        if (gsl_root_test_interval(lo, hi, 1e-14, 0.0) == GSL_SUCCESS) break;
      }
      v = std::exp(gsl_root_fsolver_root(solver.get()));
    }
  }
  const TipShare s = tip_share(v);
  KgdTransitionScales out;
  out.k_hat = s.k_hat;
  out.delta = s.delta;
  out.lambda = s.lambda;
  // l and w(0) from the tip region's length (Ch^4 s_hat^2 / K_hat^10 in Dontsov's leak-off scaling,
  // where the leak-off coefficient cancels) with K_m eliminated by the volume balance.
  out.gamma =
      std::pow(2.0, 4.0 / 3.0) * 2.25 * std::pow(3.0, -11.0 / 6.0) / std::sqrt(s.B) * std::pow(s.s_hat, 1.0 / 6.0);
  out.omega = 1.5 * std::pow(2.0, 2.0 / 3.0) * std::pow(3.0, -7.0 / 6.0) / std::sqrt(s.B) *
              std::pow(s.s_hat, -1.0 / 6.0) * std::pow(2.0, -s.lambda);
  return out;
}

double kgd_toughness_number(double E_prime, double mu_prime, double Q, double K_Ic) {
  const double K_prime = 4.0 * std::sqrt(2.0 / pi) * K_Ic;
  return K_prime * std::pow(E_prime * E_prime * E_prime * mu_prime * Q, -0.25);
}

double kgd_length_scale(double E_prime, double mu_prime, double Q, double t) {
  return std::pow(E_prime * Q * Q * Q * t * t * t * t / mu_prime, 1.0 / 6.0);
}

double KgdTransition::toughness_number() const { return kgd_toughness_number(E_prime, mu_prime, Q, K_Ic); }

double KgdTransition::half_length(double t) const {
  return kgd_transition_scales(toughness_number()).gamma * kgd_length_scale(E_prime, mu_prime, Q, t);
}

double KgdTransition::opening(double x, double t) const {
  const KgdTransitionScales s = kgd_transition_scales(toughness_number());
  const double l = s.gamma * kgd_length_scale(E_prime, mu_prime, Q, t);
  const double rho = std::abs(x) / l;
  if (rho >= 1.0) return 0.0;
  const double w0 = s.omega * std::pow(mu_prime * Q * Q * Q * t * t / E_prime, 1.0 / 6.0);
  return w0 * std::pow(1.0 - rho, s.delta) * std::pow(1.0 + rho, s.lambda);
}

}  // namespace hm::analytic
