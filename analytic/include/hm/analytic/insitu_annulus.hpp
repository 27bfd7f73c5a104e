#pragma once
/// \file
/// A borehole in rock under an in-situ (far-field) horizontal stress: the finite plane-strain annulus
/// R_i <= r <= 1 loaded on its outer surface, and Kirsch's infinite plate with a hole as its
/// R_i -> 0 limit. Dry, linear elastic, isotropic; dimensionless (stresses over E, lengths over R);
/// tension positive. Derivation and sign conventions: docs/insitu.md.

namespace hm::analytic {

/// The far-field horizontal stress state as geomechanics states it: principal magnitudes,
/// compression positive (the stress tensor is sigma = -S_H e_H e_H - S_h e_h e_h), and the azimuth of
/// S_H. Dimensionless (over E).
struct FarFieldStress {
  /// S_H/E, largest horizontal stress magnitude (compressive). Allowed: S_H >= 0 and S_H >= S_h.
  double S_H = 0.0;
  /// S_h/E, smallest horizontal stress magnitude (compressive). Allowed: 0 <= S_h <= S_H.
  double S_h = 0.0;
  /// theta_H, azimuth of the S_H direction from the x axis [rad]. Allowed: finite.
  double theta_H = 0.0;

  /// Throws hm::InputError "field = value, allowed: rule".
  void validate() const;
};

/// Displacements and stresses at one point (r, theta) in polar components. Dimensionless; tension
/// positive; plane strain (sigma_z = nu (sigma_r + sigma_theta), not stored).
struct PolarState {
  double u_r = 0.0;           ///< radial displacement
  double u_theta = 0.0;       ///< hoop displacement
  double sigma_r = 0.0;       ///< radial stress
  double sigma_theta = 0.0;   ///< hoop stress
  double sigma_rtheta = 0.0;  ///< shear stress
};

/// Annulus R_i <= r <= 1 in plane strain, E = 1, with the far-field stress applied as traction at
/// r = 1 and a wall pressure p_w at r = R_i:
///   r = 1:   sigma_r = -P - q cos 2psi,  sigma_rtheta = q sin 2psi,
///   r = R_i: sigma_r = -p_w,           sigma_rtheta = 0,
/// with psi = theta - theta_H, P = (S_H + S_h)/2, q = (S_H - S_h)/2. The solution is Lame's cylinder
/// (inner pressure p_w, outer P) plus the n = 2 Michell terms
///   phi = (A r^2 + B r^4 + C r^-2 + D) cos 2psi,  m = 1 - R_i^2,
///   A = q (1 + R_i^2 + 4 R_i^4)/(2 m^3),  B = -q R_i^2/m^3,
///   C = q R_i^4 (1 + R_i^2)/(2 m^3),      D = -q R_i^2 (1 + R_i^2 + R_i^4)/m^3.
/// Stresses are total; with a uniform, unchanged pore pressure p0 the effective stress of Eq. 1 is
/// sigma + b p0. Displacements are from the unloaded annulus, with the rigid-body motion chosen so
/// that the centre stays put and the S_H axis does not rotate (u_theta = 0 on psi = 0, 90 degrees).
/// Limits: 0 < R_i < 1, 0 < nu < 0.5 (stresses do not depend on nu); no fluid flow, no fracture.
class InSituAnnulus {
 public:
  /// Throws hm::InputError for an invalid `far`, non-finite p_w, R_i outside (0, 1) or nu outside (0, 0.5).
  InSituAnnulus(const FarFieldStress& far, double p_w, double R_i, double nu);

  /// State at R_i <= r <= 1 and polar angle theta [rad] from the x axis; throws hm::InputError otherwise.
  PolarState state(double r, double theta) const;

  double inner_radius() const { return R_i_; }

 private:
  FarFieldStress far_;
  double p_w_, R_i_, nu_;
};

/// Kirsch's infinite plane with a hole of radius a under the same far field and wall pressure (the
/// R_i -> 0 limit of InSituAnnulus with lengths over a instead of R):
///   sigma_r      = -P (1 - a^2/r^2) - p_w a^2/r^2 - q (1 - 4a^2/r^2 + 3a^4/r^4) cos 2psi,
///   sigma_theta  = -P (1 + a^2/r^2) + p_w a^2/r^2 + q (1 + 3a^4/r^4) cos 2psi,
///   sigma_rtheta =  q (1 + 2a^2/r^2 - 3a^4/r^4) sin 2psi.
/// At the wall sigma_theta = p_w - (S_H + S_h) + 2 (S_H - S_h) cos 2psi: S_H - 3 S_h + p_w on the S_H
/// axis and S_h - 3 S_H + p_w across it (the textbook 3 S_h - S_H - p_w and 3 S_H - S_h - p_w in
/// compression-positive terms). Displacements as for InSituAnnulus (they grow like r).
/// Limits: a > 0, 0 < nu < 0.5, r >= a.
class KirschHole {
 public:
  /// Throws hm::InputError for an invalid `far`, non-finite p_w, a <= 0 or nu outside (0, 0.5).
  KirschHole(const FarFieldStress& far, double p_w, double a, double nu);

  /// State at r >= a and polar angle theta [rad] from the x axis; throws hm::InputError otherwise.
  PolarState state(double r, double theta) const;

 private:
  FarFieldStress far_;
  double p_w_, a_, nu_;
};

}  // namespace hm::analytic
