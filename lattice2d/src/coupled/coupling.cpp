#include "hm/lattice2d/coupled/coupling.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

namespace hm::lattice2d {

void CouplingTerms::validate() const {
  using namespace hm::core;
  // Plausibility bounds (coupling.hpp): beyond them the Eq. 20 springs or the Eq. 17 forces swamp the
  // beams by so many orders that the mechanical factor loses its digits (xi or psi = 1e12 fails the
  // first solve of the Fig. 12 quick case), and no physical setting needs them.
  if (!(xi > 0.0 && xi <= kMaxPressureForceScale))
    throw hm::FieldError("xi", "", format_value(xi), "0 < {} <= " + format_value(kMaxPressureForceScale));
  if (!(psi >= 0.0 && psi <= kMaxSplitFeedback))
    throw hm::FieldError("psi", "", format_value(psi), "0 <= {} <= " + format_value(kMaxSplitFeedback));
}

Eigen::VectorXd pressure_forces(const Lattice& lattice, const DualGraph& dual, const Eigen::VectorXd& pressure,
                                double b, const CouplingTerms& terms, const Eigen::VectorXd& crack_weight) {
  const int n_t = lattice.n_triangles();
  assert((pressure.size() == n_t || pressure.size() == n_t + 1) && "pressure_forces: one value per triangle (+ p_h)");
  assert(dual.dual_length.size() == lattice.n_beams() && "pressure_forces: dual graph of another lattice");
  const double p_h = pressure.size() > n_t ? pressure[n_t] : 0.0;
  assert((crack_weight.size() == 0 || crack_weight.size() == lattice.n_beams()) &&
         "pressure_forces: one weight per beam");
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  for (int e = 0; e < lattice.n_beams(); ++e) {
    const auto [s, t] = lattice.beam_triangles[static_cast<std::size_t>(e)];
    const BoundaryTag tag = lattice.beam_boundary[static_cast<std::size_t>(e)];
    const double p_t = t >= 0 ? pressure[t] : (tag == BoundaryTag::inner ? p_h : 0.0);
    const double p_st = 0.5 * (pressure[s] + p_t);
    const double scale = terms.xi * (crack_weight.size() == 0 ? b : face_pressure_share(b, crack_weight[e]));
    const Eigen::Vector2d F_i = -scale * dual.dual_length[e] * p_st * lattice.direction.col(e);
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    f[dof_index(i, 0)] += F_i.x();
    f[dof_index(i, 1)] += F_i.y();
    f[dof_index(j, 0)] -= F_i.x();
    f[dof_index(j, 1)] -= F_i.y();
    if (tag == BoundaryTag::inner && terms.borehole_wall_traction && p_h != 0.0) {
      const Eigen::Vector2d w = lattice.lumped_pressure_force(e, p_h);
      for (int q : {i, j}) {
        f[dof_index(q, 0)] += w.x();
        f[dof_index(q, 1)] += w.y();
      }
    }
  }
  return f;
}

Eigen::VectorXd borehole_volume_gradient(const Lattice& lattice) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (lattice.beam_boundary[static_cast<std::size_t>(e)] != BoundaryTag::inner) continue;
    const Eigen::Vector2d w = lattice.lumped_pressure_force(e, 1.0);  // per unit p_h
    for (const int q : lattice.beams[static_cast<std::size_t>(e)]) {
      g[dof_index(q, 0)] += w.x();
      g[dof_index(q, 1)] += w.y();
    }
  }
  return g;
}

RankOneStiffness borehole_spring(const Lattice& lattice, double storage_coefficient, double deformation_coefficient) {
  if (!(storage_coefficient > 0.0 && deformation_coefficient > 0.0))
    throw hm::InputError("coupling.borehole_spring = \"undrained\" with a borehole storage of " +
                         hm::core::format_value(storage_coefficient) + " and a weight of its volume change of " +
                         hm::core::format_value(deformation_coefficient) +
                         ", allowed: both > 0 (flow.borehole_storage and flow.borehole_deformation not \"none\")");
  return RankOneStiffness(borehole_volume_gradient(lattice), deformation_coefficient / storage_coefficient);
}

Eigen::VectorXd crack_opening_volumes(const Lattice& lattice, const DualGraph& dual,
                                      const Eigen::VectorXd& crack_weight, const Eigen::VectorXd& u) {
  assert(crack_weight.size() == lattice.n_beams() && "crack_opening_volumes: one weight per beam");
  assert(u.size() == 3 * lattice.n_particles() && "crack_opening_volumes: 3 dofs per particle");
  Eigen::VectorXd v = Eigen::VectorXd::Zero(lattice.n_triangles());
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (!(crack_weight[e] > 0.0)) continue;
    const double half = 0.5 * crack_weight[e] * dual.dual_length[e] * normal_elongation(lattice, u, e);
    for (const int t : lattice.beam_triangles[static_cast<std::size_t>(e)])
      if (t >= 0) v[t] += half;  // a wall beam's other half is the borehole's, whose volume is its own
  }
  return v;
}

Eigen::Vector2d local_crack_normal(const Lattice& lattice, const DualGraph& reference,
                                   const Eigen::VectorXd& crack_weight, int beam) {
  const Eigen::Vector2d n = lattice.direction.col(beam);
  const auto [s, t] = lattice.beam_triangles[static_cast<std::size_t>(beam)];
  if (t < 0) return n;
  // The far end of the cracked facet `f` that meets this one at triangle `end`, or `end` itself when
  // f is not cracked (or is a boundary beam, whose segment ends on the boundary, not at a triangle).
  const auto far_end_through = [&](int f, int end) -> Eigen::Vector2d {
    const auto [a, b] = lattice.beam_triangles[static_cast<std::size_t>(f)];
    if (f == beam || !(crack_weight[f] > 0.0) || b < 0) return reference.dual_point.col(end);
    return reference.dual_point.col(a == end ? b : a);
  };
  // The chord's vector from the s side to the t side: (far ends beyond t) - (far ends beyond s), each
  // side's ends summed as vectors from its triangle so that a branch adds its arms.
  Eigen::Vector2d chord = reference.dual_point.col(t) - reference.dual_point.col(s);
  for (const int f : lattice.triangle_beams[static_cast<std::size_t>(t)])
    chord += far_end_through(f, t) - reference.dual_point.col(t);
  for (const int f : lattice.triangle_beams[static_cast<std::size_t>(s)])
    chord += reference.dual_point.col(s) - far_end_through(f, s);
  const double length = chord.norm();
  if (!(length > 1e-9 * lattice.length[beam])) return n;
  const Eigen::Vector2d normal(-chord.y() / length, chord.x() / length);
  return normal.dot(n) >= 0.0 ? normal : Eigen::Vector2d(-normal);
}

Eigen::VectorXd crack_facet_openings(const Lattice& lattice, const DualGraph& reference,
                                     const Eigen::VectorXd& crack_weight, const Eigen::VectorXd& u,
                                     CrackAperture aperture) {
  assert(crack_weight.size() == lattice.n_beams() && "crack_facet_openings: one weight per beam");
  assert(u.size() == 3 * lattice.n_particles() && "crack_facet_openings: 3 dofs per particle");
  assert((aperture != CrackAperture::crack_normal || reference.dual_point.cols() == lattice.n_triangles()) &&
         "crack_facet_openings: the reference dual graph of another lattice");
  Eigen::VectorXd opening = Eigen::VectorXd::Zero(lattice.n_beams());
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (!(crack_weight[e] > 0.0)) continue;
    const double axial = normal_elongation(lattice, u, e);
    switch (aperture) {
      case CrackAperture::axial: opening[e] = axial; break;
      case CrackAperture::jump:
        // A closed facet's gap is its axial opening whatever it slides: the contact shuts it.
        opening[e] = axial > 0.0 ? std::hypot(axial, facet_slide(lattice, u, e)) : axial;
        break;
      case CrackAperture::crack_normal: {
        // The jump is axial n + slide s, s = n turned by +90 degrees (facet_slide).
        const Eigen::Vector2d n = lattice.direction.col(e);
        const Eigen::Vector2d normal = local_crack_normal(lattice, reference, crack_weight, e);
        const double along_normal =
            axial * n.dot(normal) + facet_slide(lattice, u, e) * (n.x() * normal.y() - n.y() * normal.x());
        opening[e] = std::max(axial, along_normal);
        break;
      }
    }
  }
  return opening;
}

Eigen::VectorXd undrained_spring_stiffness(const Lattice& lattice, const DualGraph& dual, double b, double E_over_M,
                                           const CouplingTerms& terms) {
  const double c = terms.psi * terms.xi * b * b / E_over_M;
  Eigen::VectorXd k(lattice.n_beams());
  // A negative d_st (round-off on a nearly co-circular pair) would make the spring negative and the
  // matrix possibly indefinite; such a segment carries no pressure area anyway.
  for (int e = 0; e < lattice.n_beams(); ++e) k[e] = c * std::max(dual.dual_length[e], 0.0) / lattice.length[e];
  return k;
}

Eigen::VectorXd spring_preload(const Lattice& lattice, const Eigen::VectorXd& stiffness,
                               const Eigen::VectorXd& u_reference) {
  assert(stiffness.size() == lattice.n_beams() && "spring_preload: one stiffness per beam");
  assert(u_reference.size() == 3 * lattice.n_particles() && "spring_preload: 3 dofs per particle");
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  for (int e = 0; e < lattice.n_beams(); ++e)
    if (stiffness[e] != 0.0)
      NormalSpring(lattice, e).add_force(stiffness[e], normal_elongation(lattice, u_reference, e), f);
  return f;
}

}  // namespace hm::lattice2d
