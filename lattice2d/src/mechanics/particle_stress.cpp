#include "hm/lattice2d/mechanics/particle_stress.hpp"

#include <cassert>
#include <cmath>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

namespace {

BeamState state_of(const std::vector<BeamState>& states, int beam) {
  return states.empty() ? BeamState::intact : states[static_cast<std::size_t>(beam)];
}

bool is_broken(BeamState state) { return state != BeamState::intact; }

}  // namespace

BeamForces compute_beam_forces(const Lattice& lattice, const BeamParameters& parameters,
                               const Eigen::VectorXd& displacement, const std::vector<BeamState>& states) {
  parameters.validate();
  assert(displacement.size() == 3 * lattice.n_particles() && "displacement: one (x, y, omega) per particle");
  assert((states.empty() || static_cast<int>(states.size()) == lattice.n_beams()) && "one state per beam");
  const int n_beams = lattice.n_beams();
  BeamForces out{Eigen::Matrix2Xd::Zero(2, n_beams), Eigen::Matrix2Xd::Zero(2, n_beams)};
  for (int e = 0; e < n_beams; ++e) {
    const BeamForce f =
        beam_force(lattice, e, beam_parameters_for(lattice, parameters, e), state_of(states, e), displacement);
    out.force.col(e) = f.force_on_i;
    out.moment.col(e) << f.moment_i, f.moment_j;
  }
  return out;
}

namespace {

// sigma_i = sym(1/2 V_i^-1 sum_j F_ij (x) L_ij) with F_ij = force_of(e), into out (resized). The raw sums
// S_i (xx, xy, yx, yy) are accumulated in place, in out.stress rows (xx, yy, xy) and out.skew (yx), so a
// caller that keeps `out` across calls (the break loop) allocates nothing.
template <class ForceOf>
void virial_stress(const Lattice& lattice, const DualGraph& dual, const ForceOf& force_of, ParticleStress& out) {
  const int n = lattice.n_particles();
  assert(dual.particle_area.size() == n && "dual graph of another lattice");
  out.stress.setZero(3, n);
  out.skew.setZero(n);
  // Both ends of a beam add the same outer product: F_ji (x) L_ji = (-F_ij) (x) (-L_ij).
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const Eigen::Vector2d& F = force_of(e);
    const Eigen::Vector2d L = lattice.length[e] * lattice.direction.col(e);
    const Eigen::Vector3d xx_yy_xy(F.x() * L.x(), F.y() * L.y(), F.x() * L.y());
    const double yx = F.y() * L.x();
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    out.stress.col(i) += xx_yy_xy;
    out.stress.col(j) += xx_yy_xy;
    out.skew[i] += yx;
    out.skew[j] += yx;
  }
  for (int i = 0; i < n; ++i) {
    const double scale = 0.5 / dual.particle_area[i];
    const double xy = scale * out.stress(2, i), yx = scale * out.skew[i];
    out.stress(0, i) *= scale;
    out.stress(1, i) *= scale;
    out.stress(2, i) = 0.5 * (xy + yx);
    out.skew[i] = 0.5 * (xy - yx);
  }
}

}  // namespace

ParticleStress compute_particle_stress(const Lattice& lattice, const DualGraph& dual, const BeamForces& forces) {
  assert(forces.force.cols() == lattice.n_beams() && "forces of another lattice");
  ParticleStress out;
  virial_stress(
      lattice, dual, [&](int e) { return forces.force.col(e); }, out);
  return out;
}

void compute_particle_stress(const Lattice& lattice, const DualGraph& dual, const std::vector<BeamForce>& forces,
                             ParticleStress& out) {
  assert(static_cast<int>(forces.size()) == lattice.n_beams() && "forces of another lattice");
  virial_stress(
      lattice, dual, [&](int e) -> const Eigen::Vector2d& { return forces[static_cast<std::size_t>(e)].force_on_i; },
      out);
}

void CrackTipOptions::validate() const { hm::core::require_positive(material_length, "material_length"); }

std::vector<bool> find_crack_tip_beams(const Lattice& lattice, const std::vector<BeamState>& states) {
  assert((states.empty() || static_cast<int>(states.size()) == lattice.n_beams()) && "one state per beam");
  std::vector<bool> tip(static_cast<std::size_t>(lattice.n_beams()), false);
  if (states.empty()) return tip;
  for (const auto& beams : lattice.triangle_beams) {
    int n_broken = 0;
    for (int e : beams) n_broken += is_broken(state_of(states, e)) ? 1 : 0;
    if (n_broken != 1) continue;
    for (int e : beams)
      if (!is_broken(state_of(states, e))) tip[static_cast<std::size_t>(e)] = true;
  }
  return tip;
}

BeamStress compute_beam_stress(const Lattice& lattice, const ParticleStress& particle_stress,
                               const std::vector<BeamState>& states, const CrackTipOptions& options) {
  options.validate();
  assert(particle_stress.stress.cols() == lattice.n_particles() && "stresses of another lattice");
  const int n_beams = lattice.n_beams();
  BeamStress out{Eigen::Matrix3Xd(3, n_beams), Eigen::VectorXd(n_beams), Eigen::VectorXd(n_beams),
                 Eigen::VectorXd::Ones(n_beams)};
  if (options.enabled) {
    const std::vector<bool> tip = find_crack_tip_beams(lattice, states);
    for (int e = 0; e < n_beams; ++e)
      if (tip[static_cast<std::size_t>(e)]) out.crack_tip_factor[e] = options.factor(lattice.length[e]);
  }
  for (int e = 0; e < n_beams; ++e) {
    out.stress.col(e) = beam_stress(lattice, particle_stress, e, out.crack_tip_factor[e]);
    const PrincipalPair p = principal_pair(out.stress(0, e), out.stress(1, e), out.stress(2, e));
    out.sigma_1[e] = p.sigma_1;
    out.sigma_3[e] = p.sigma_3;
  }
  return out;
}

void AveragingRegion::validate() const {
  hm::core::require_finite(center.x(), "region.center.x");
  hm::core::require_finite(center.y(), "region.center.y");
  hm::core::require_positive(radius, "region.radius");
}

PlaneStrainModuli plane_strain_moduli(double c11, double c12) {
  assert(c11 > std::abs(c12) && "plane_strain_moduli: C11 > |C12| for a positive-definite isotropic tensor");
  const double nu = c12 / (c11 + c12);
  return {c11 * (1.0 + nu) * (1.0 - 2.0 * nu) / (1.0 - nu), nu};
}

RegionStress region_stress(const ParticleStress& stress, const DualGraph& dual, const std::vector<int>& particles) {
  assert(!particles.empty() && "region_stress: no particles");
  RegionStress out;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (int i : particles) {
    out.area_mean += dual.particle_area[i] * stress.stress.col(i);
    area += dual.particle_area[i];
    mean += stress.stress.col(i);
  }
  out.area_mean /= area;
  mean /= static_cast<double>(particles.size());
  Eigen::Vector3d variance = Eigen::Vector3d::Zero();
  for (int i : particles) variance += (stress.stress.col(i) - mean).cwiseAbs2();
  out.scatter = (variance / static_cast<double>(particles.size())).cwiseSqrt();
  return out;
}

AffineStiffness affine_effective_stiffness(const Lattice& lattice, const BeamParameters& parameters,
                                           const AveragingRegion& region) {
  parameters.validate();
  region.validate();
  std::vector<int> chosen;
  for (int i = 0; i < lattice.n_particles(); ++i)
    if (lattice.boundary[static_cast<std::size_t>(i)] == BoundaryTag::interior &&
        (lattice.points.col(i) - region.center).norm() <= region.radius)
      chosen.push_back(i);
  if (chosen.empty())
    throw hm::InputError("region.radius = " + hm::core::format_value(region.radius) +
                         ", allowed: a region holding at least one interior particle");

  const DualGraph dual = build_dual_graph(lattice);
  AffineStiffness out;
  out.n_particles_used = static_cast<int>(chosen.size());
  for (int k = 0; k < 3; ++k) {
    Eigen::Matrix2d eps = Eigen::Matrix2d::Zero();  // unit Voigt strain state k (engineering shear)
    if (k < 2)
      eps(k, k) = 1.0;
    else
      eps(0, 1) = eps(1, 0) = 0.5;
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * lattice.n_particles());
    for (int i = 0; i < lattice.n_particles(); ++i) u.segment<2>(dof_index(i, 0)) = eps * lattice.points.col(i);
    const ParticleStress stress = compute_particle_stress(lattice, dual, compute_beam_forces(lattice, parameters, u));
    const RegionStress region_mean = region_stress(stress, dual, chosen);
    out.stiffness.col(k) = region_mean.area_mean;
    out.scatter.col(k) = region_mean.scatter;
  }

  const double c11 = 0.5 * (out.stiffness(0, 0) + out.stiffness(1, 1));
  const double c12 = 0.5 * (out.stiffness(0, 1) + out.stiffness(1, 0));
  const PlaneStrainModuli moduli = plane_strain_moduli(c11, c12);
  out.youngs_modulus = moduli.youngs_modulus;
  out.poisson_ratio = moduli.poisson_ratio;
  Eigen::Matrix3d iso;
  iso << c11, c12, 0, c12, c11, 0, 0, 0, 0.5 * (c11 - c12);
  out.anisotropy = (out.stiffness - iso).cwiseAbs().maxCoeff() / c11;
  return out;
}

}  // namespace hm::lattice2d
