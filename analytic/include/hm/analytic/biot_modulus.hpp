#pragma once
/// \file
/// Biot modulus of the paper's Eq. 22 and the textbook relation it departs from (docs/errata.md).

namespace hm::analytic {

/// E/M by the paper's Eq. 22: E/M = E*Phi/K_w + 3 (b - Phi)(1 - Phi)(1 - 2 nu).
/// Inputs dimensionless: porosity Phi, E_over_Kw = E/K_w, b, nu. Can be <= 0 for b < Phi.
constexpr double E_over_M_eq22(double b, double nu, double porosity, double E_over_Kw) {
  return porosity * E_over_Kw + 3.0 * (b - porosity) * (1.0 - porosity) * (1.0 - 2.0 * nu);
}

/// E/M by the standard micromechanical relation (Detournay & Cheng 1993, with K_s = K/(1-b)):
/// 1/M = Phi/K_w + (b - Phi)(1 - b)/K, K = E/(3(1-2nu)). Differs from Eq. 22 in (1-b) vs (1-Phi).
constexpr double E_over_M_standard(double b, double nu, double porosity, double E_over_Kw) {
  return porosity * E_over_Kw + 3.0 * (b - porosity) * (1.0 - b) * (1.0 - 2.0 * nu);
}

/// Table 1 values used for the default E/M: Phi = 1e-3, E = 1e10 Pa, K_w = 2.2e9 Pa.
inline constexpr double table1_porosity = 1e-3;
inline constexpr double table1_E_over_Kw = 1e10 / 2.2e9;

/// E/M of Eq. 22 with Table 1's porosity, E and K_w: the default whenever a case gives only b, nu.
constexpr double E_over_M_table1(double b, double nu) {
  return E_over_M_eq22(b, nu, table1_porosity, table1_E_over_Kw);
}

}  // namespace hm::analytic
