#pragma once
/// \file
/// Calibration of the beam constants (Section 2.1, text after Eq. 4: "k_n, a and nu0 are adjusted to
/// reproduce the wanted continuum scale elastic behavior ... Young modulus equal to one"): the relaxed
/// plane-strain E and nu of a lattice measured by numerical homogeneous-strain tests, the search for
/// (k_n, a) at fixed nu0 that gives the target, and the toolkit's stored default. Dimensionless
/// (stresses over E, lengths over R). Method, choices and measured numbers: docs/lattice.md, "Calibration".
///
/// The lattice is a 2D body; its in-plane stiffness C is read as plane strain (C11 = lambda + 2 mu,
/// C12 = lambda, C66 = mu), so nu = C12/(C11 + C12) and E = (C11 - C12)(C11 + 2 C12)/(C11 + C12).
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

namespace hm::lattice2d {

/// Numerics of one measurement (measure_elastic_properties).
struct ElasticTestOptions {
  /// Radius of the central averaging region over the largest circle inside the domain (half the
  /// shorter rectangle side; the disk radius). Particles within it, away from the boundary layer that
  /// the prescribed boundary strain stiffens, give the measured stress. Our choice 0.6: the layer is a
  /// few spacings thick, and 0.6 keeps ~1/3 of the particles (docs/lattice.md, "Calibration").
  /// Allowed: 0 < region_fraction <= 0.95.
  double region_fraction = 0.6;

  /// Throws hm::InputError "elastic_test.field = value, allowed: rule".
  void validate() const;
};

/// The effective (relaxed) elastic constants of one lattice. Voigt order (xx, yy, xy), engineering
/// shear: sigma = C (eps_xx, eps_yy, 2 eps_xy).
struct ElasticProperties {
  /// C from the area-weighted mean stress of the interior particles in the central region, column k
  /// = unit boundary strain state k (xx, yy, shear), every boundary particle held at u = eps x
  /// (rotations free), the interior relaxed by a solve. The calibration's measurement.
  Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();
  /// The same C from the boundary reactions, sym(sum_b x_b (x) R_b) / area (the whole body's mean
  /// stress by the virial theorem); includes the stiffened boundary layer, so an upper estimate.
  Eigen::Matrix3d boundary_stiffness = Eigen::Matrix3d::Zero();
  /// Particle-to-particle standard deviation (unweighted) of the region's stresses, entry-wise:
  /// a random lattice with uniform beam constants is not elastically uniform.
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  double c11 = 0.0;             ///< (C(0,0) + C(1,1)) / 2
  double c12 = 0.0;             ///< (C(0,1) + C(1,0)) / 2
  double c66 = 0.0;             ///< C(2,2), the shear modulus mu
  double youngs_modulus = 0.0;  ///< plane strain, from c11, c12: (C11 - C12)(C11 + 2 C12)/(C11 + C12)
  double poisson_ratio = 0.0;   ///< plane strain, C12/(C11 + C12)
  /// Isotropy check: (c66 - (c11 - c12)/2) / ((c11 - c12)/2); 0 for an isotropic lattice.
  double shear_isotropy_error = 0.0;
  /// max_ab |C_ab - C_iso,ab| / c11, C_iso the isotropic tensor of (c11, c12).
  double anisotropy = 0.0;
  double boundary_youngs_modulus = 0.0;  ///< E from boundary_stiffness
  double boundary_poisson_ratio = 0.0;   ///< nu from boundary_stiffness
  int n_particles_used = 0;              ///< interior particles in the region
  double seconds = 0.0;                  ///< wall time (three assemblies, factorisations and solves)
  /// All three solves succeeded (BeamMechanics::solve().is_converged()); if false the numbers above are
  /// not to be trusted (e.g. a nearly singular stiffness from an extreme a) and `message` says why.
  bool is_converged = true;
  std::string message;  ///< empty when converged
};

/// Measures the relaxed elastic constants of `lattice` (a rectangle or a disk; centred at the origin)
/// with beam constants `parameters`: three solves with prescribe_boundary_strain (unit eps_xx, eps_yy,
/// eps_xy), all beams intact. Validates everything (throws hm::InputError; also for an annulus, whose
/// hole leaves no central region). Linear in k_n at fixed (a, nu0): E scales with k_n, nu does not change.
/// Limits: a finite-size estimate; the region mean carries a sampling error of ~scatter/sqrt(n_used)
/// and the boundary layer's influence decays with distance (docs/lattice.md, "Calibration").
ElasticProperties measure_elastic_properties(const Lattice& lattice, const BeamParameters& parameters,
                                             const ElasticTestOptions& options = {});

/// The test rectangle of the calibration: a square of side `side` centred at the origin with the point
/// density of the unit disk of `disk_particles` particles, i.e. n = disk_particles side^2 / pi.
LatticeSpec calibration_rectangle(long long disk_particles, double side, std::uint64_t seed);

/// Input of calibrate_beams.
struct CalibrationSpec {
  /// Particle count of the unit disk whose point density is calibrated (Section 2.1: 1e3 to 2.5e5;
  /// default 1e4). E is independent of the density for per-beam constants (measured, see
  /// docs/lattice.md). Allowed: 500 <= n_particles, and the rectangle holding 500 to 5e6 particles.
  long long n_particles = 10000;
  /// Side of the square test rectangle, over R. Our choice 2 (the disk's diameter): at N = 1e4 it
  /// holds ~1.3e4 particles. Allowed: > 0.
  double rectangle_side = 2.0;
  /// Lattice seeds; the measurement is the mean over them. Allowed: non-empty.
  std::vector<std::uint64_t> seeds = {1, 2, 3};
  /// Wanted plane-strain Young's modulus (Section 2.1: "equal to one"). Allowed: > 0.
  double target_youngs_modulus = 1.0;
  /// Wanted plane-strain Poisson ratio (Table 1: 0.25). Allowed: -1 < target < 0.5.
  double target_poisson_ratio = 0.25;
  /// nu0, held fixed while the aspect a is searched (two knobs, one target nu; they enter nu only
  /// through k_omega/k_n and gamma). Our choice 0.25, the rock's own value; see docs/lattice.md.
  /// Allowed: -1 < beam_poisson < 0.5.
  double beam_poisson = 0.25;
  /// Search bracket of the aspect a = d/L (log-bisection on nu(a), which falls with a). Our choice
  /// [0.05, 2]: below 0.05 the beams are nearly central springs (k_omega/k_n < 1.3e-3) and the
  /// rotations nearly unrestrained. Allowed: 0 < aspect_min < aspect_max.
  double aspect_min = 0.05;
  double aspect_max = 2.0;
  /// Per-beam stiffness variation of the calibrated beams (BeamParameters::stiffness_scaling and
  /// facet_floor). Default voronoi_facet (the toolkit's default lattice): its central-force limit of nu
  /// is ~0.32, so nu = 0.25 lies inside the bracket; with the paper's uniform beams nu tops out at
  /// ~0.224 (docs/lattice.md, "Calibration" and "Stiffness scaling and boundary spacing").
  StiffnessScaling stiffness_scaling = StiffnessScaling::voronoi_facet;
  double facet_floor = 0.0;
  /// Stop when the seed-mean nu is within this of the target. Allowed: > 0.
  double poisson_tolerance = 2e-4;
  /// Cap on the bisection steps. Allowed: >= 1.
  int max_iterations = 30;
  /// Numerics of each measurement.
  ElasticTestOptions test;

  /// Throws hm::InputError "calibration.field = value, allowed: rule".
  void validate() const;
};

/// Result of calibrate_beams: the constants, and what they give (Ceres' Summary in small).
struct Calibration {
  BeamParameters beams;                     ///< k_n, a (searched), nu0 (fixed)
  std::vector<ElasticProperties> per_seed;  ///< measured with `beams`, one per spec.seeds
  double youngs_modulus_mean = 0.0;         ///< over seeds
  double youngs_modulus_sd = 0.0;           ///< sample standard deviation over seeds (0 for one seed)
  double poisson_ratio_mean = 0.0;
  double poisson_ratio_sd = 0.0;
  /// The seed-mean nu is within poisson_tolerance of the target. If false, `beams` gives the closest
  /// reachable nu (an end of the bracket) and `message` says by how much the target is missed.
  bool target_poisson_reached = false;
  /// Seed-mean nu at aspect_min and at aspect_max: the reachable range at this nu0.
  double poisson_ratio_at_aspect_min = 0.0;
  double poisson_ratio_at_aspect_max = 0.0;
  int n_measurements = 0;  ///< measure_elastic_properties calls
  double seconds = 0.0;
  std::string message;  ///< human-readable summary
};

/// Searches a (at nu0 = spec.beam_poisson) for the target nu on the spec's rectangles, then sets
/// k_n = target_E / E(k_n = 1) (exact: E is linear in k_n) and re-measures. Validates the spec.
/// Cost: (3 + iterations) measurements per seed, ~1.2-2 s each at N = 1e4; the default spec takes 9
/// measurements, ~15 s (nu = 0.25 lies outside the bracket, so no iterations run).
Calibration calibrate_beams(const CalibrationSpec& spec);

/// The toolkit's beam constants for a stiffness scaling: the result of calibrate_beams with that
/// scaling (otherwise CalibrationSpec{}) stored as constants (the measurement, date and commit are in
/// the comment at the definition and in docs/lattice.md; `test_lattice2d "[slow]"` re-measures them).
/// Default voronoi_facet (E = 1, nu = 0.25, the paper's Table 1); uniform is the paper's lattice, whose
/// nu cannot exceed ~0.224. Use these for any lattice of about the calibrated density (and
/// LatticeSpec's default boundary spacing); E does not depend on the density, nu only weakly.
BeamParameters calibrated_beam_parameters(StiffnessScaling scaling = StiffnessScaling::voronoi_facet);

/// Plane-strain isotropic constants of a continuum.
struct ElasticConstants {
  double youngs_modulus = 1.0;  ///< E (over the toolkit's E scale)
  double poisson_ratio = 0.25;  ///< nu, plane strain
};

/// The continuum the lattice with calibrated_beam_parameters(scaling) represents, as measured by the
/// calibration (mean over seeds 1-3 at N = 1e4): voronoi_facet E = 1.000, nu = 0.250; uniform
/// E = 1.000, nu = 0.2236 (the target 0.25 is not reachable with uniform beams; docs/lattice.md,
/// "Calibration"). Compare the lattice with a continuum solution (Lame, Sneddon, first-break
/// predictions) at these constants.
ElasticConstants calibrated_continuum(StiffnessScaling scaling = StiffnessScaling::voronoi_facet);

}  // namespace hm::lattice2d
