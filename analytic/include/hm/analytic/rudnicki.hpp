#pragma once
/// \file
/// Rudnicki's continuous fluid line source in an unbounded poroelastic plane (paper Section 3.1,
/// ref. 2; derivation in docs/rudnicki.md).
#include "hm/analytic/poroelastic_parameters.hpp"
#include "hm/analytic/radial_state.hpp"

namespace hm::analytic {

/// Fluid injected at rate Q (per unit axial length) from t = 0 at r = 0 of an unbounded,
/// initially unstressed plane-strain poroelastic medium, dimensionless as Eq. 14:
///   S dp/dt - lap p = Q delta(x),   S = storage_coefficient(material),
///   p(r,t) = Q/(4 pi) E1(X),  X = S r^2/(4 t),
///   u_r(r,t) = (b (1+nu)(1-2nu)/(1-nu)) Q r/(8 pi) [E1(X) + (1 - exp(-X))/X].
/// Limits: no outer boundary (the paper's disk has one, so compare only while the plume is far from
/// r = 1); r > 0 and t > 0; the mechanics are always plane strain, `vol_strain` changes only S.
class RudnickiLineSource {
 public:
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
