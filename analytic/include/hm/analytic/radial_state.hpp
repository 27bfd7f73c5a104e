#pragma once
/// \file
/// The value type every radially symmetric solution returns at one radius.

namespace hm::analytic {

/// Pore pressure, radial displacement and effective (Terzaghi-Biot, sigma_m of Eq. 1) stresses at
/// one radius of a radially symmetric plane-strain state. Dimensionless; tension positive.
/// Total stress = effective - b p (Eq. 1 with sigma_f = -p I).
struct RadialState {
  double p = 0.0;            ///< pore pressure p*
  double u_r = 0.0;          ///< radial displacement u_r*
  double sigma_r = 0.0;      ///< effective radial stress sigma_mr*
  double sigma_theta = 0.0;  ///< effective hoop stress sigma_mtheta*
  double sigma_z = 0.0;      ///< effective axial stress sigma_mz* (plane strain: nu (sigma_r + sigma_theta))
};

/// Effective plane-strain stresses (E = 1) from the radial strains eps_r = du/dr, eps_theta = u/r.
/// Fills sigma_r, sigma_theta, sigma_z of `state`, leaves p and u_r.
void set_plane_strain_stresses(RadialState& state, double nu, double eps_r, double eps_theta);

}  // namespace hm::analytic
