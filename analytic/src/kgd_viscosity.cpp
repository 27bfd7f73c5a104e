#include "hm/analytic/kgd_viscosity.hpp"

#include "hm/analytic/kgd_transition.hpp"

#include <gsl/gsl_sf_gamma.h>
#include <gsl/gsl_sf_hyperg.h>

#include <cmath>
#include <numbers>

namespace hm::analytic {

namespace {

// B(a, b) through Gamma functions: Pi's second term needs B(-3/2, 8/3), outside gsl_sf_beta's a, b > 0.
double beta_function(double a, double b) { return gsl_sf_gamma(a) * gsl_sf_gamma(b) / gsl_sf_gamma(a + b); }

double scale_eps(const KgdViscosityVertex& v, double t) { return std::cbrt(v.mu_prime / (v.E_prime * t)); }
double scale_L(const KgdViscosityVertex& v, double t) { return kgd_length_scale(v.E_prime, v.mu_prime, v.Q, t); }

}  // namespace

double kgd_viscosity_opening_shape(double rho) {
  const double r2 = rho * rho;
  if (r2 >= 1.0) return 0.0;
  // Adachi & Detournay's two-term expansion plus the log term that carries the tip's w ~ s^(2/3).
  constexpr double A0 = std::numbers::sqrt3, A1 = -0.156, B1 = 0.0663;
  const double s = std::sqrt(1.0 - r2);
  const double log_term = r2 == 0.0 ? 0.0 : 2.0 * r2 * std::log((1.0 - s) / (1.0 + s));
  return A0 * std::pow(1.0 - r2, 2.0 / 3.0) + A1 * std::pow(1.0 - r2, 5.0 / 3.0) + B1 * (4.0 * s + log_term);
}

double kgd_viscosity_pressure_shape(double rho) {
  const double r2 = rho * rho;
  constexpr double A1 = 1.61750, A2 = 0.39650, B = 0.06858;
  const double pi = std::numbers::pi;
  const double star1 = beta_function(0.5, 2.0 / 3.0) / (3.0 * pi) * gsl_sf_hyperg_2F1(-1.0 / 6.0, 1.0, 0.5, r2);
  const double star2 = 3.0 / (20.0 * pi) * beta_function(-1.5, 8.0 / 3.0) *
                       (2.0 / 3.0 * r2 * gsl_sf_hyperg_2F1(-1.0 / 6.0, 2.0, 1.5, r2) -
                        0.5 * gsl_sf_hyperg_2F1(-7.0 / 6.0, 1.0, 0.5, r2));
  return A1 * star1 + A2 * star2 + B * (2.0 - pi * std::abs(rho));
}

double KgdViscosityVertex::half_length(double t) const { return gamma * scale_L(*this, t); }

double KgdViscosityVertex::opening(double x, double t) const {
  return scale_eps(*this, t) * scale_L(*this, t) * gamma * kgd_viscosity_opening_shape(x / half_length(t));
}

double KgdViscosityVertex::net_pressure(double x, double t) const {
  return scale_eps(*this, t) * E_prime * kgd_viscosity_pressure_shape(x / half_length(t));
}

double KgdViscosityVertex::toughness_number(double K_Ic) const {
  return kgd_toughness_number(E_prime, mu_prime, Q, K_Ic);
}

}  // namespace hm::analytic
