#pragma once
/// \file
/// Sneddon's pressurised straight crack in an unbounded plane-strain solid (paper Appendix C, Eq. C1).

namespace hm::analytic {

/// Crack of length 2c under uniform internal pressure p in an impermeable, initially unstressed,
/// isotropic plane-strain solid (E = 1). The faces open into an ellipse (Eq. C1):
///   (x/c)^2 + (w/eps)^2 = 1,  eps = 2 (1 - nu^2) p c,
/// where 2w is the full aperture. Limits: |x| <= c (w = 0 outside); no fluid coupling.
struct SneddonCrack {
  double p;   ///< internal pressure p/E
  double c;   ///< half length
  double nu;  ///< Poisson ratio

  /// Half aperture w(x) (one face's normal displacement); 0 for |x| >= c.
  double half_aperture(double x) const;
  /// eps = w(0), the maximum half aperture.
  double max_half_aperture() const;
  /// Opened area per unit axial length, integral of 2w over the crack = pi c eps.
  double crack_volume() const;
};

}  // namespace hm::analytic
