#pragma once
/// \file
/// The lattice's boundary loads for a rock at rest under an in-situ (far-field) horizontal stress,
/// in the paper's deviation form: the flow's pressure is the deviation from the rest pore pressure
/// p0, and the beams carry the effective stress of Eq. 1, sigma_m = sigma + b p (tension positive).
/// At rest (uniform p0 in the rock and the hole) the effective state is the total one plus b p0 I, so
/// the beams see the far field -S + b p0 I on the outer boundary and the wall pressure (1 - b) p0.
/// Derivation and limits: docs/insitu.md. Dimensionless (over E).
#include <Eigen/Core>

#include "hm/analytic/insitu_annulus.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"

namespace hm::lattice2d {

/// The far-field total stress tensor -S_H e_H e_H - S_h e_h e_h (tension positive), e_H at theta_H.
Eigen::Matrix2d far_field_tensor(const analytic::FarFieldStress& far);

/// Adds the rest state's effective loads to `conditions`: outer_stress += far_field_tensor(far) +
/// b p0 I, and on an annulus inner_pressure += (1 - b) p0. Throws hm::InputError for an invalid
/// `far`, p0 < 0 or not finite, S_H or p0 above 1 (E: a strain of order one), or b outside [0, 1].
void add_far_field_loads(const analytic::FarFieldStress& far, double p0, double b, DomainShape domain,
                         BoundaryConditions& conditions);

/// The finite annulus' displacement (`exact`, for E = 1) at the particles for Young's modulus E, in
/// the gauge of a free lattice's solve (without_rigid_motion), 3 entries per particle: what a dry
/// lattice under the far field should show. Radii are clamped to the annulus R_i <= r <= 1.
Eigen::VectorXd annulus_displacement(const Lattice& lattice, const analytic::InSituAnnulus& exact,
                                     double youngs_modulus);

/// A displacement field against a reference, both 3 entries per particle, over the particles'
/// translations: the RMS and the largest |u - u_ref|, each over max |u_ref|.
struct DisplacementError {
  double rms = 0.0, max = 0.0;
};
DisplacementError displacement_error(const Lattice& lattice, const Eigen::VectorXd& u, const Eigen::VectorXd& u_ref);

}  // namespace hm::lattice2d
