#pragma once
/// \file
/// Rudnicki's continuous fluid line source in an unbounded poroelastic plane (paper Section 3.1,
/// ref. 2; derivation in docs/rudnicki.md).
#include "hm/analytic/poroelastic_parameters.hpp"
#include "hm/analytic/radial_state.hpp"

namespace hm::analytic {

/// Fluid injected at rate Q (volume per unit axial length) from t = 0 at r = 0 of an unbounded,
/// initially unstressed plane-strain poroelastic medium, dimensionless as Eq. 14 (E = 1, tension
/// positive, p the deviation from p0):
///   S dp/dt - lap p = Q delta(x),   S = storage_coefficient(material),
///   p(r,t)   = Q/(4 pi) E1(X),  X = S r^2/(4 t),
///   u_r(r,t) = eta Q r/(8 pi) [E1(X) + (1 - exp(-X))/X],   eta = b (1+nu)(1-2nu)/(1-nu),
///   eps_r = du/dr = eta Q/(8 pi) [E1(X) - (1 - exp(-X))/X],  eps_theta = u_r/r,
/// so eps_r + eps_theta = eta p (radial equilibrium, Eq. A3, in a plane with u -> 0 far away).
/// Stresses are the effective (sigma_m) ones; the total stress is effective - b p.
///
/// Limits (what this solution cannot do):
/// - No outer boundary. The paper's disk has p = 0 and a free or fixed surface at r = 1; the pressure
///   agrees while the plume is far from r = 1 (X(1) = S/(4t) >> 1), but u_r ~ 1/r reaches r = 1 at
///   once, so the disk's u_r differs by a term linear in r (docs/rudnicki.md, "Bounded disk").
/// - No steady state: at fixed r, p grows like (Q/4 pi) ln t without bound.
/// - The mechanics are always plane strain; `vol_strain` changes only S (Appendix A's factor 1/3).
/// - r must be finite and > 0 (p and the strains are log-singular at the source): otherwise
///   std::domain_error. t must be finite; t <= 0 is before injection and gives the zero state.
///
/// Numerics: E1 from GSL (relative error ~ 2 (1+X) DBL_EPSILON, GSL's own estimate), called only
/// for series_below <= X <= underflow_above, where it cannot signal an error (so GSL's error handler
/// is never invoked); below, the two-term series; above, p = 0 (E1 < 1.5e-307).
class RudnickiLineSource {
 public:
  /// Below this X, E1(X) = -gamma - ln X + X (truncation < X^2/4 < 2.5e-21) with ln X formed from
  /// ln r and ln(S/4t), so an X that underflows to 0 at tiny r still gives a finite p.
  static constexpr double series_below = 1e-10;
  /// Above this X, p = 0 and the strains use (1 - exp(-X))/X alone (E1(700) ~ 1.4e-307).
  static constexpr double underflow_above = 700.0;

  /// Validates `material` and requires a finite Q (hm::InputError otherwise). Q < 0 is extraction.
  RudnickiLineSource(double Q, const PoroelasticParameters& material);

  double pressure(double r, double t) const;
  double radial_displacement(double r, double t) const;
  /// p, u_r and effective stresses at (r, t).
  RadialState state(double r, double t) const;
  /// S of the diffusion equation; the diffusivity is 1/S.
  double storage() const { return storage_; }

 private:
  double Q_;
  PoroelasticParameters material_;
  double storage_;
};

}  // namespace hm::analytic
