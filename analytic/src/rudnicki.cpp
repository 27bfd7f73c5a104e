#include "hm/analytic/rudnicki.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_expint.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "hm/core/validation.hpp"

namespace hm::analytic {

using namespace hm::core;  // require_* and format_value

namespace {

/// E1(X) and g(X) = (1 - exp(-X))/X at X = S r^2/(4t): p = Q/(4pi) E1, u_r/r = eta Q/(8pi) (E1 + g).
struct Kernel {
  double e1;
  double g;
};

Kernel kernel(double r, double t, double S) {
  const double X = S * r * r / (4.0 * t);
  // expm1 keeps g accurate as X -> 0 (1 - exp(-X) would cancel); X == 0 (underflow at tiny r) -> 1.
  const double g = X > 0.0 ? -std::expm1(-X) / X : 1.0;
  if (X > RudnickiLineSource::underflow_above) return {0.0, g};
  if (X < RudnickiLineSource::series_below) {
    // ln X from the factors: S r^2/(4t) itself may have underflowed to 0 or lost digits.
    const double log_X = std::log(S) + 2.0 * std::log(r) - std::log(4.0 * t);
    return {-std::numbers::egamma - log_X + X, g};
  }
  // Inside (series_below, underflow_above] GSL's E1 has no error path (gsl/specfunc/expint.c signals
  // only for X == 0, X < -701.8, or a result that underflows, i.e. X > 701.8), so the default handler,
  // which would abort, is never reached. The status is still checked in case a caller's handler
  // returns.
  gsl_sf_result e1;
  const int status = gsl_sf_expint_E1_e(X, &e1);
  if (status != GSL_SUCCESS)
    throw std::runtime_error("RudnickiLineSource: gsl_sf_expint_E1_e(" + format_value(X) +
                             ") failed: " + gsl_strerror(status));
  return {e1.val, g};
}

}  // namespace

RudnickiLineSource::RudnickiLineSource(double Q, const PoroelasticParameters& m) : Q_(Q), material_(m), storage_(0.0) {
  material_.validate();
  require_finite(Q, "Q");
  storage_ = storage_coefficient(material_);
}

RadialState RudnickiLineSource::state(double r, double t) const {
  if (!(std::isfinite(r) && r > 0.0) || !std::isfinite(t))
    throw std::domain_error("RudnickiLineSource: need finite r > 0 and finite t, got r = " + format_value(r) +
                            ", t = " + format_value(t));
  RadialState s;
  if (t <= 0.0) return s;  // before injection starts: unstressed, p = p0

  const auto [e1, g] = kernel(r, t, storage_);
  const double eta = material_.b * oedometric_compliance(material_.nu);
  const double strain_scale = eta * Q_ / (8.0 * std::numbers::pi);
  s.p = Q_ / (4.0 * std::numbers::pi) * e1;
  s.u_r = strain_scale * r * (e1 + g);
  // eps_r = eta p - u/r follows from d(r u)/dr = eta r p (Eq. A3 integrated once).
  set_plane_strain_stresses(s, material_.nu, strain_scale * (e1 - g), strain_scale * (e1 + g));
  return s;
}

double RudnickiLineSource::pressure(double r, double t) const { return state(r, t).p; }

double RudnickiLineSource::radial_displacement(double r, double t) const { return state(r, t).u_r; }

}  // namespace hm::analytic
