#pragma once
/// \file
/// The plane-strain (KGD) hydraulic fracture between its toughness and viscosity limits, without leak-off
/// or fluid lag: Dontsov's approximate solution (E. V. Dontsov, "An approximate solution for a plane
/// strain hydraulic fracture that accounts for fracture toughness, fluid viscosity, and leak-off",
/// Int. J. Fract. 205 (2017) 221-237), here in its no-leak-off limit. Without leak-off the solution is
/// self-similar at every toughness: with the toughness number K_m = K' (E'^3 mu' Q)^(-1/4),
///   l(t) = gamma(K_m) (E' Q^3 t^4 / mu')^(1/6),   w(0, t) = Omega(K_m) (mu' Q^3 t^2 / E')^(1/6),
///   w(x, t) = w(0, t) (1 - rho)^delta (1 + rho)^lambda,  rho = |x| / l,
/// Q the rate into the whole crack (both wings), w the full aperture, mu' = 12 mu, K' = 4 sqrt(2/pi) K_Ic,
/// E' = E / (1 - nu^2). The opening's tip exponent delta runs from 2/3 (viscosity) to 1/2 (toughness)
/// with the tip's own toughness share K_hat in (0, 1], which the global volume balance fixes; gamma and
/// Omega reach the M-vertex (Adachi & Detournay 2002: gamma = 0.6152) as K_m -> 0 and the K-vertex
/// (a uniformly pressurised Griffith crack holding Q t: gamma = 0.9324 K_m^(-2/3)) as K_m -> infinity.
/// Between the vertices it is an approximation (its author's, not checked here against a numerical
/// solution); the crack holds Q t exactly.

namespace hm::analytic {

/// The KGD scales both vertex solutions share (Q into the whole crack, mu' = 12 mu):
/// K_m = K' (E'^3 mu' Q)^(-1/4) with K' = 4 sqrt(2/pi) K_Ic, and the viscous length (E' Q^3 t^4 / mu')^(1/6).
double kgd_toughness_number(double E_prime, double mu_prime, double Q, double K_Ic);
double kgd_length_scale(double E_prime, double mu_prime, double Q, double t);

/// The solution's dimensionless numbers at one toughness number.
struct KgdTransitionScales {
  double gamma = 0.0;   ///< l / (E' Q^3 t^4 / mu')^(1/6)
  double omega = 0.0;   ///< w(0, t) / (mu' Q^3 t^2 / E')^(1/6)
  double k_hat = 0.0;   ///< the tip's toughness share: 0 at the M-vertex, 1 at the K-vertex
  double delta = 0.0;   ///< the opening's tip exponent, (1 + (1 - k_hat^3) / 3) / 2
  double lambda = 0.0;  ///< the opening's exponent towards the inlet, 0.588 (1 - k_hat^3) + 0.5 k_hat^3
};

/// gamma, Omega, ... at toughness number K_m. Throws hm::InputError unless 0 <= K_m <= 1e6 (beyond, the
/// K-vertex: gamma = 0.9324 K_m^(-2/3) to better than 1e-6).
KgdTransitionScales kgd_transition_scales(double K_m);

struct KgdTransition {
  double E_prime;   ///< plane-strain modulus E / (1 - nu^2) (over E in the lattice's units)
  double mu_prime;  ///< 12 mu; in the lattice's units 12 k / R^2 (docs/flow.md)
  double Q;         ///< injection rate into the crack (both wings)
  double K_Ic;      ///< fracture toughness (in the lattice's units, over E sqrt(R))

  double toughness_number() const;           ///< K_m
  double half_length(double t) const;        ///< l(t)
  double opening(double x, double t) const;  ///< w(x, t), 0 beyond the tips
};

}  // namespace hm::analytic
