#pragma once
/// \file
/// Beam forces, particle stresses and beam stresses (Section 2.1: Eqs. 3, 8-10, the particle stress
/// after Eq. 10, the crack-tip factor of Fig. 2), and the affine estimate of the lattice's effective
/// stiffness. Dimensionless (stresses over E, lengths over R). Tension positive.
///
/// Sign convention, stated once: F_ij is the force that the connection exerts on particle i, and
/// L_ij = x_j - x_i. A pair pulled apart along n_ij gives F_ij = +|F| n_ij and so a positive (tensile)
/// sigma_nn at both particles (tested).
///
/// Limits: geometrically linear (forces from the linearised Eqs. 5-7 and 9-10, L_ij of the undeformed
/// lattice); in-plane stresses only (the plane-strain sigma_zz is not formed; principal stresses are the
/// in-plane ones, as in Fig. 3); no fluid-pressure forces (Eqs. 17-20): pass the mechanical beam forces.
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "hm/analytic/failure_criteria.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

namespace hm::lattice2d {

/// Forces and moments of every connection for a displacement vector.
struct BeamForces {
  /// Column e = F_ij on the beam's first particle i (beams[e][0]); the force on j is its negative.
  Eigen::Matrix2Xd force;
  /// Column e = (M on i, M on j), the end moments (Eq. 4); zero for contact and open connections.
  Eigen::Matrix2Xd moment;
};

/// Forces from displacements u (size 3 n, dof = 3 i + component) and states (empty = all intact), each
/// beam's beam_force (beam_stiffness.hpp: minus BeamOperator's internal force K_e u_e, the matrix its
/// state assembles), bit for bit connection_forces' F_ij and moments:
///  - intact: the linearised Eqs. 3-7, so equilibrium of the assembled K u = f means zero net force
///    and moment per free particle;
///  - contact: the normal spring of Eqs. 9-10. Eq. 8's Heaviside is the state's (contact_state), not
///    the force's: pass states that belong to u, as BeamMechanics' active set leaves them (a contact
///    then separates by at most its contact_tolerance); a contact given a separating u pulls;
///  - open: zero.
/// Validates `parameters` (throws hm::InputError).
BeamForces compute_beam_forces(const Lattice& lattice, const BeamParameters& parameters,
                               const Eigen::VectorXd& displacement, const std::vector<BeamState>& states = {});

/// Per-particle stress tensors.
struct ParticleStress {
  /// Column i = (sigma_xx, sigma_yy, sigma_xy) of the symmetrised tensor
  /// sigma_i = sym(1/2 V_i^-1 sum_j F_ij (x) L_ij).
  Eigen::Matrix3Xd stress;
  /// Skew part dropped by the symmetrisation, 1/2 (S_xy - S_yx) of the raw sum S, per particle.
  /// The beams' end moments make S non-symmetric (a particle's moment balance involves the moments,
  /// not only L x F); the Cauchy stress the failure criteria of Eq. 11 expect is symmetric. Kept as a
  /// diagnostic: small against |sigma| where the lattice behaves like a classical continuum.
  Eigen::VectorXd skew;
};

/// sigma_i = 1/2 V_i^-1 sum_j F_ij (x) L_ij (Section 2.1, after Eq. 10; Allen & Tildesley's virial),
/// symmetrised, with V_i = dual.particle_area and the sum over all intact and contact connections of i.
/// Boundary particles get the same formula; their stress is one-sided (missing neighbours) and not a
/// continuum stress.
ParticleStress compute_particle_stress(const Lattice& lattice, const DualGraph& dual, const BeamForces& forces);
/// The same from connection_forces' layout (F_ij = force_on_i) into `out`, whose storage is reused:
/// the form of the break loop, which evaluates it after every broken beam.
void compute_particle_stress(const Lattice& lattice, const DualGraph& dual, const std::vector<BeamForce>& forces,
                             ParticleStress& out);

/// Beam `beam`'s stress (sigma_xx, sigma_yy, sigma_xy) for the failure check (Section 2.1): "the mean
/// value of the stress in the particles that it connects", times its crack-tip factor (1 elsewhere).
inline Eigen::Vector3d beam_stress(const Lattice& lattice, const ParticleStress& particle_stress, int beam,
                                   double crack_tip_factor) {
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(beam)];
  return crack_tip_factor * 0.5 * (particle_stress.stress.col(i) + particle_stress.stress.col(j));
}

/// Crack-tip factor of Fig. 2: the stress of an intact beam in a triangle of 2 intact + 1 broken
/// beams is multiplied by (L_ij / (2 L_m))^(1/2).
struct CrackTipOptions {
  /// Apply the factor at all (false gives the plain two-particle mean everywhere; for comparisons).
  bool enabled = true;
  /// L_m, "a material parameter describing the typical radius of curvature of a crack tip" (Section 2.1),
  /// over R. Not given in the paper; our choice (docs/lattice.md, "Crack-tip factor"): half the mean beam
  /// length of the paper's production lattice (N = 1e5 disk, mean L = 6.25e-3), so an average crack-tip beam
  /// at the paper's resolution keeps factor ~1 and other resolutions are corrected towards it.
  /// A fixed length, deliberately not derived from the current lattice: L_m = c * mean(L) would make the
  /// factor resolution-independent and so undo its purpose. Allowed: > 0.
  double material_length = 3.13e-3;

  void validate() const;
  /// (L / (2 L_m))^(1/2) for a crack-tip beam of length L (whether it applies is `enabled`'s business).
  double factor(double length) const { return std::sqrt(length / (2.0 * material_length)); }
};

/// true for every intact beam that lies in at least one triangle of exactly 2 intact and 1 broken
/// (contact or open) beams. `states` empty = all intact = no crack tips.
std::vector<bool> find_crack_tip_beams(const Lattice& lattice, const std::vector<BeamState>& states);

/// Per-beam stress used by the failure check.
struct BeamStress {
  /// Column e = (sigma_xx, sigma_yy, sigma_xy): mean of the two particles, times crack_tip_factor[e].
  Eigen::Matrix3Xd stress;
  Eigen::VectorXd sigma_1;           ///< major in-plane principal stress (most tensile)
  Eigen::VectorXd sigma_3;           ///< minor in-plane principal stress (most compressive)
  Eigen::VectorXd crack_tip_factor;  ///< (L/2L_m)^(1/2) at a crack tip, else 1
};

using hm::analytic::principal_pair;
using hm::analytic::PrincipalPair;

/// Beam stresses from particle stresses (Section 2.1: "the mean value of the stress in the particles
/// that it connects", times the crack-tip factor). Computed for every beam, broken ones included
/// (they are simply not candidates for breaking; see failure.hpp). Validates `options`.
BeamStress compute_beam_stress(const Lattice& lattice, const ParticleStress& particle_stress,
                               const std::vector<BeamState>& states = {}, const CrackTipOptions& options = {});

// ---------------------------------------------------------------------------------------------------
// Affine (kinematic) estimate of the effective stiffness

/// Particles whose stresses are averaged: non-boundary particles with |x - center| <= radius.
struct AveragingRegion {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< over R; finite
  double radius = 0.5;                               ///< over R; > 0

  void validate() const;
};

/// Effective plane-strain stiffness of the lattice under an imposed homogeneous strain, every
/// particle displaced affinely (u = eps x, omega = 0: the rigid rotation of a symmetric eps), with no
/// relaxation. This is the upper (Voigt-type) bound of the lattice's stiffness, exact for the mean
/// over the whole lattice by the virial identity, not the relaxed response a solve would give: the
/// calibration of k_n, a, nu0 must use relaxed solves. Voigt order (xx, yy, xy) with engineering shear:
/// sigma = C (eps_xx, eps_yy, 2 eps_xy).
struct AffineStiffness {
  /// C, column k = area-weighted mean stress of the region's particles under unit strain state k.
  Eigen::Matrix3d stiffness;
  /// Particle-to-particle standard deviation (unweighted) of the same stresses, entry-wise: the
  /// scatter of a random lattice with uniform beam constants. Relative scatter = scatter(k,k)/C(k,k).
  Eigen::Matrix3d scatter;
  /// Plane-strain E and nu of the isotropic part, from C11 = (C(0,0) + C(1,1))/2 and
  /// C12 = (C(0,1) + C(1,0))/2: nu = C12/(C11 + C12), E = C11 (1 + nu)(1 - 2 nu)/(1 - nu).
  double youngs_modulus = 0.0;
  double poisson_ratio = 0.0;
  /// max_ab |C_ab - C_iso,ab| / C11 with C_iso the isotropic tensor of (E, nu), whose shear entry is
  /// (C11 - C12)/2: 0 for an isotropic lattice.
  double anisotropy = 0.0;
  int n_particles_used = 0;  ///< particles in the region
};

/// The affine estimate on `lattice` with beam constants `parameters`, averaged over `region`.
/// Throws hm::InputError for invalid parameters or region, or a region holding no interior particle.
AffineStiffness affine_effective_stiffness(const Lattice& lattice, const BeamParameters& parameters,
                                           const AveragingRegion& region = {});

/// Mean particle stress over a set of particles, weighted by their Voronoi areas (the region's
/// average stress), and the particle-to-particle standard deviation (unweighted), both in Voigt
/// order (xx, yy, xy). `particles` must not be empty.
struct RegionStress {
  Eigen::Vector3d area_mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d scatter = Eigen::Vector3d::Zero();
};
RegionStress region_stress(const ParticleStress& stress, const DualGraph& dual, const std::vector<int>& particles);

/// Plane-strain (E, nu) from the isotropic stiffness entries C11 = E(1-nu)/((1+nu)(1-2nu)) and
/// C12 = E nu/((1+nu)(1-2nu)): nu = C12/(C11 + C12), E = C11 (1+nu)(1-2nu)/(1-nu).
/// Precondition: C11 > |C12|.
struct PlaneStrainModuli {
  double youngs_modulus;
  double poisson_ratio;
};
PlaneStrainModuli plane_strain_moduli(double c11, double c12);

}  // namespace hm::lattice2d
