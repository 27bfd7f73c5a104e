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
    const BeamState state = state_of(states, e);
    if (state == BeamState::open) continue;
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    Eigen::Matrix<double, 6, 1> ue;
    ue << displacement.segment<3>(dof_index(i, 0)), displacement.segment<3>(dof_index(j, 0));
    if (state == BeamState::contact) {
      // Eq. 8: k_n (L - L_eq) H(L_eq - L) n with the linearised stretch (u_j - u_i).n.
      const Eigen::Vector2d n = lattice.direction.col(e);
      const double stretch = (ue.segment<2>(3) - ue.segment<2>(0)).dot(n);
      if (stretch < 0.0)
        out.force.col(e) = beam_parameters_for(lattice, parameters, e).normal_stiffness * stretch * n;
      continue;
    }
    // Internal force = -K_e u_e: the same matrix as the assembly, so forces and K u = f agree exactly.
    const Eigen::Matrix<double, 6, 1> f =
        -beam_element_stiffness(lattice.length[e], lattice.angle[e], beam_parameters_for(lattice, parameters, e), state) * ue;
    out.force.col(e) = f.segment<2>(0);
    out.moment.col(e) << f[2], f[5];
  }
  return out;
}

ParticleStress compute_particle_stress(const Lattice& lattice, const DualGraph& dual, const BeamForces& forces) {
  const int n = lattice.n_particles();
  assert(dual.particle_area.size() == n && "dual graph of another lattice");
  assert(forces.force.cols() == lattice.n_beams() && "forces of another lattice");
  // Raw sums S_i = sum_j F_ij (x) L_ij, row-major (xx, xy, yx, yy). Both ends of a beam add the same
  // outer product: F_ji (x) L_ji = (-F_ij) (x) (-L_ij).
  Eigen::Matrix4Xd raw = Eigen::Matrix4Xd::Zero(4, n);
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const Eigen::Vector2d F = forces.force.col(e);
    const Eigen::Vector2d L = lattice.length[e] * lattice.direction.col(e);
    const Eigen::Vector4d outer(F.x() * L.x(), F.x() * L.y(), F.y() * L.x(), F.y() * L.y());
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    raw.col(i) += outer;
    raw.col(j) += outer;
  }
  ParticleStress out{Eigen::Matrix3Xd(3, n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    const double scale = 0.5 / dual.particle_area[i];
    const Eigen::Vector4d s = scale * raw.col(i);
    out.stress.col(i) << s[0], s[3], 0.5 * (s[1] + s[2]);
    out.skew[i] = 0.5 * (s[1] - s[2]);
  }
  return out;
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
      if (tip[static_cast<std::size_t>(e)])
        out.crack_tip_factor[e] = options.factor(lattice.length[e]);
  }
  for (int e = 0; e < n_beams; ++e) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    out.stress.col(e) =
        out.crack_tip_factor[e] * 0.5 * (particle_stress.stress.col(i) + particle_stress.stress.col(j));
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
    if (k < 2) eps(k, k) = 1.0;
    else eps(0, 1) = eps(1, 0) = 0.5;
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
