#pragma once
/// \file
/// The plane-strain (KGD) hydraulic fracture driven by a Newtonian fluid in the viscosity-dominated limit
/// (zero toughness, no leak-off, no fluid lag): the M-vertex of Adachi & Detournay (2002), "Self-similar
/// solution of a plane-strain fracture driven by a power-law fluid", Int. J. Numer. Anal. Meth. Geomech.
/// 26:579-604, after Spence & Sharp (1985). The opening and pressure are their approximations
/// (Adachi & Detournay's Eqs. for n = 1, as also used by GEOS's validation of its KGD solver):
///   l(t) = gamma L(t),  L = (E' Q^3 t^4 / mu')^(1/6),  eps = (mu' / (E' t))^(1/3),
///   w(x, t) = eps L gamma Omega_bar(x / l),   p(x, t) = eps E' Pi(x / l),   gamma = 0.616.
/// Q is the rate into the whole crack (both wings), w the full aperture, p the net pressure.
///
/// In the lattice's units (lengths over R, pressures over E, time over mu R^2 / (k E), Q = mu q / (k E))
/// a crack of aperture a carries a^3 / (12 k/R^2) per unit pressure gradient (the cubic law,
/// docs/flow.md), so mu' = 12 k / R^2 and E' = 1 / (1 - nu^2).

namespace hm::analytic {

/// Omega_bar(rho), 0 <= |rho| <= 1: the opening's shape, w = eps L gamma Omega_bar (0 outside).
double kgd_viscosity_opening_shape(double rho);
/// Pi(rho), 0 < |rho| < 1: the net pressure's shape, p = eps E' Pi; finite at rho = 0, -> -inf at the tip.
double kgd_viscosity_pressure_shape(double rho);

struct KgdViscosityVertex {
  static constexpr double gamma = 0.616;  ///< l / L

  double E_prime;   ///< plane-strain modulus E / (1 - nu^2) (over E)
  double mu_prime;  ///< 12 mu; in the lattice's units 12 k / R^2
  double Q;         ///< injection rate into the crack (both wings)

  double half_length(double t) const;
  double opening(double x, double t) const;       ///< full aperture w at distance x from the source
  double net_pressure(double x, double t) const;  ///< p at x (x = 0: the inlet)
  /// K_m = K' (E'^3 mu' Q)^(-1/4), K' = 4 sqrt(2/pi) K_Ic: the toughness number; the M-vertex is the
  /// limit K_m -> 0 (a KGD fracture is within a few % of it for K_m below ~1).
  double toughness_number(double K_Ic) const;
};

}  // namespace hm::analytic
