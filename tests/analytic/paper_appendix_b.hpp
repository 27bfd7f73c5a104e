#pragma once
/// \file
/// Test-only: Ulven & Sun 2017 Appendix B, Eqs. B3 and B5-B9 transcribed exactly as printed
/// (misprints included), so tests can show numerically which printed formulas fail.
/// The toolkit's corrected forms are in hm/analytic/steady_borehole.hpp; docs/errata.md explains.
/// Symbols as in the paper: lambda = (1+nu)(1-2nu), p_h = -(Q/2pi) ln R_i; dimensionless, E = 1.
#include <cmath>
#include <numbers>

namespace hm::test::paper_b {

struct Setting {
  double Q, b, nu, R_i;
  double lambda() const { return (1.0 + nu) * (1.0 - 2.0 * nu); }
  double p_h() const { return -Q / (2.0 * std::numbers::pi) * std::log(R_i); }
  double a() const { return R_i * R_i / (1.0 - R_i * R_i); }  // R_i^2/(1-R_i^2), recurring in B6-B9
};

/// B3: p = -(Q/2pi) ln r.
inline double p_B3(const Setting& s, double r) { return -s.Q / (2.0 * std::numbers::pi) * std::log(r); }

/// B5 as printed: u = -lambda b p_h/(2(1-nu)) r ln r/ln R_i + C_1/r + C_2 r.
inline double u_B5(const Setting& s, double r, double C_1, double C_2) {
  return -s.lambda() * s.b * s.p_h() / (2.0 * (1.0 - s.nu)) * r * std::log(r) / std::log(s.R_i) + C_1 / r + C_2 * r;
}

/// B6 as printed:
/// u = (b p_h/2)(lambda r/ln R_i ((1-nu) ln r - 1) - a (1-2nu)/(1-nu)((1+nu)/r + lambda r))
///     + p_h a ((1+nu)/r + lambda r).
inline double u_B6(const Setting& s, double r) {
  const double nu = s.nu, lam = s.lambda(), ph = s.p_h(), a = s.a();
  return s.b * ph / 2.0 *
             (lam * r / std::log(s.R_i) * ((1.0 - nu) * std::log(r) - 1.0) -
              a * (1.0 - 2.0 * nu) / (1.0 - nu) * ((1.0 + nu) / r + lam * r)) +
         ph * a * ((1.0 + nu) / r + lam * r);
}

/// B7 as printed:
/// sigma_mr = (b p_h/2)(ln r/((1-nu) ln R_i) + a (1-2nu)/(1-nu)(1/r^2 - 1)) + p_h a (1 - 1/r^2).
inline double sigma_r_B7(const Setting& s, double r) {
  const double nu = s.nu, ph = s.p_h(), a = s.a();
  return s.b * ph / 2.0 *
             (std::log(r) / ((1.0 - nu) * std::log(s.R_i)) +
              a * (1.0 - 2.0 * nu) / (1.0 - nu) * (1.0 / (r * r) - 1.0)) +
         ph * a * (1.0 - 1.0 / (r * r));
}

/// B8 as printed:
/// sigma_mtheta = (b p_h/2)((ln r - 1 + 2nu)/((1-nu) ln R_i) - a (1-2nu)/(1-nu)(1/r^2 + 1))
///                + p_h a (1/r^2 + 1).
inline double sigma_theta_B8(const Setting& s, double r) {
  const double nu = s.nu, ph = s.p_h(), a = s.a();
  return s.b * ph / 2.0 *
             ((std::log(r) - 1.0 + 2.0 * nu) / ((1.0 - nu) * std::log(s.R_i)) -
              a * (1.0 - 2.0 * nu) / (1.0 - nu) * (1.0 / (r * r) + 1.0)) +
         ph * a * (1.0 / (r * r) + 1.0);
}

/// B9 as printed:
/// sigma_mz = b p_h nu ((ln r - 1 + 2nu)/((1-nu) ln R_i) - a (1-2nu)/(1-nu)) + 2 p_h nu a.
inline double sigma_z_B9(const Setting& s, double r) {
  const double nu = s.nu, ph = s.p_h(), a = s.a();
  return s.b * ph * nu *
             ((std::log(r) - 1.0 + 2.0 * nu) / ((1.0 - nu) * std::log(s.R_i)) - a * (1.0 - 2.0 * nu) / (1.0 - nu)) +
         2.0 * ph * nu * a;
}

/// The boundary condition at the wall as Appendix B's text prints it: sigma_mr(R_i) = +(1-b) p_h.
inline double wall_sigma_r_as_printed(const Setting& s) { return (1.0 - s.b) * s.p_h(); }

}  // namespace hm::test::paper_b
