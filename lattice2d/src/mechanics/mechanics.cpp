#include "hm/lattice2d/mechanics/mechanics.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>

#include "hm/core/state_archive.hpp"

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

void BoundaryConditions::validate(const Lattice& lattice) const {
  using namespace hm::core;
  const bool annulus = lattice.spec.domain == DomainShape::annulus;
  require_finite(inner_pressure, "boundary_conditions.inner_pressure");
  require_finite(outer_pressure, "boundary_conditions.outer_pressure");
  if (!annulus && inner_pressure != 0.0)
    throw hm::InputError("boundary_conditions.inner_pressure = " + format_value(inner_pressure) +
                         ", allowed: 0 unless domain = annulus");
  if (!annulus && inner == BoundarySupport::fixed)
    throw hm::InputError("boundary_conditions.inner = 'fixed', allowed: free unless domain = annulus");
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) require_finite(outer_stress(a, b), "boundary_conditions.outer_stress");
  if (outer_stress(0, 1) != outer_stress(1, 0))
    throw hm::InputError("boundary_conditions.outer_stress(0,1) = " + format_value(outer_stress(0, 1)) +
                         ", allowed: equal to outer_stress(1,0) = " + format_value(outer_stress(1, 0)));
  if (outer == BoundarySupport::fixed && !outer_stress.isZero(0.0))
    throw hm::InputError("boundary_conditions.outer_stress = (" + format_value(outer_stress(0, 0)) + ", " +
                         format_value(outer_stress(0, 1)) + ", " + format_value(outer_stress(1, 1)) +
                         "), allowed: 0 unless outer = 'free' (a held boundary takes no traction)");
  if (prescribe_boundary_strain) {
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) require_finite(boundary_strain(a, b), "boundary_conditions.boundary_strain");
    if (boundary_strain(0, 1) != boundary_strain(1, 0))
      throw hm::InputError("boundary_conditions.boundary_strain(0,1) = " + format_value(boundary_strain(0, 1)) +
                           ", allowed: equal to boundary_strain(1,0) = " + format_value(boundary_strain(1, 0)));
    if (outer == BoundarySupport::fixed || inner == BoundarySupport::fixed)
      throw hm::InputError(
          "boundary_conditions.prescribe_boundary_strain = true, allowed: only with "
          "outer = inner = 'free'");
  }
  for (std::size_t k = 0; k < prescribed.size(); ++k) {
    const std::string name = "boundary_conditions.prescribed[" + std::to_string(k) + "]";
    const auto& p = prescribed[k];
    if (p.particle < 0 || p.particle >= lattice.n_particles())
      throw hm::InputError(name + ".particle = " + std::to_string(p.particle) + ", allowed: 0 <= particle < " +
                           std::to_string(lattice.n_particles()));
    if (p.component < 0 || p.component > 2)
      throw hm::InputError(name + ".component = " + std::to_string(p.component) +
                           ", allowed: 0 (x), 1 (y), 2 (rotation)");
    require_finite(p.value, name + ".value");
  }
}

bool BoundaryConditions::is_unloaded() const {
  return inner_pressure == 0.0 && outer_pressure == 0.0 && outer_stress.isZero(0.0) &&
         !(prescribe_boundary_strain && !boundary_strain.isZero(0.0)) &&
         std::all_of(prescribed.begin(), prescribed.end(),
                     [](const PrescribedDisplacement& d) { return d.value == 0.0; });
}

void MechanicsOptions::validate() const {
  using namespace hm::core;
  require_at_least(max_contact_iterations, "mechanics_options.max_contact_iterations", 1);
  require_at_least(contact_switches_at_once, "mechanics_options.contact_switches_at_once", 0);
  require_half_open(contact_tolerance, "mechanics_options.contact_tolerance", 0.0, 1.0);
  solver_options.validate();
}

namespace {

std::array<int, 6> beam_dofs(const Lattice& lattice, int beam) {
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(beam)];
  return {dof_index(i, 0), dof_index(i, 1), dof_index(i, 2), dof_index(j, 0), dof_index(j, 1), dof_index(j, 2)};
}

// Least-squares rigid motion (translation t at the centroid c, rotation w) of the particles'
// displacements; returns (t_x, t_y, w, c_x, c_y). A single particle keeps its own rotation.
Eigen::Matrix<double, 5, 1> rigid_fit(const Lattice& lattice, const Eigen::VectorXd& u,
                                      const std::vector<int>& particles) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero(), t = Eigen::Vector2d::Zero();
  for (int p : particles) {
    c += lattice.points.col(p);
    t += Eigen::Vector2d(u[dof_index(p, 0)], u[dof_index(p, 1)]);
  }
  const double n = static_cast<double>(particles.size());
  c /= n;
  t /= n;
  double cross = 0.0, r2 = 0.0, mean_rotation = 0.0;
  for (int p : particles) {
    const Eigen::Vector2d r = lattice.points.col(p) - c;
    cross += r.x() * u[dof_index(p, 1)] - r.y() * u[dof_index(p, 0)];
    r2 += r.squaredNorm();
    mean_rotation += u[dof_index(p, 2)];
  }
  const double w = r2 > 0.0 ? cross / r2 : mean_rotation / n;
  Eigen::Matrix<double, 5, 1> fit;
  fit << t.x(), t.y(), w, c.x(), c.y();
  return fit;
}

// Displacement of particle p under the rigid motion `fit`.
Eigen::Vector3d rigid_motion(const Lattice& lattice, const Eigen::Matrix<double, 5, 1>& fit, int p) {
  const Eigen::Vector2d r = lattice.points.col(p) - Eigen::Vector2d(fit[3], fit[4]);
  return {fit[0] - fit[2] * r.y(), fit[1] + fit[2] * r.x(), fit[2]};
}

}  // namespace

Eigen::VectorXd without_rigid_motion(const Lattice& lattice, Eigen::VectorXd u) {
  std::vector<int> all(static_cast<std::size_t>(lattice.n_particles()));
  for (int p = 0; p < lattice.n_particles(); ++p) all[static_cast<std::size_t>(p)] = p;
  const auto fit = rigid_fit(lattice, u, all);
  for (int p = 0; p < lattice.n_particles(); ++p) u.segment<3>(dof_index(p, 0)) -= rigid_motion(lattice, fit, p);
  return u;
}

namespace {

// connection_forces into `forces` (resized; every entry overwritten), with beam e's parameters from
// parameters_of(e).
template <class ParametersOf>
void fill_connection_forces(const Lattice& lattice, const ParametersOf& parameters_of,
                            const std::vector<BeamState>& states, const Eigen::VectorXd& u,
                            std::vector<BeamForce>& forces) {
  assert(u.size() == 3 * lattice.n_particles() && "connection_forces: u has 3 entries per particle");
  assert(static_cast<int>(states.size()) == lattice.n_beams() && "connection_forces: one state per beam");
  forces.resize(static_cast<std::size_t>(lattice.n_beams()));
  // Beams independent: on the threads for a large lattice (N ~ 7000 and up), the same bits.
#pragma omp parallel for schedule(static) if (lattice.n_beams() >= 20000)
  for (int e = 0; e < lattice.n_beams(); ++e)
    forces[static_cast<std::size_t>(e)] =
        beam_force(lattice, e, parameters_of(e), states[static_cast<std::size_t>(e)], u);
}

}  // namespace

std::vector<BeamForce> connection_forces(const Lattice& lattice, const BeamParameters& parameters,
                                         const std::vector<BeamState>& states, const Eigen::VectorXd& u) {
  std::vector<BeamForce> forces;
  fill_connection_forces(
      lattice, [&](int e) { return beam_parameters_for(lattice, parameters, e); }, states, u, forces);
  return forces;
}

// ------------------------------------------------------------------------------------------------

BeamMechanics::BeamMechanics(Lattice lattice, const BeamParameters& parameters, const BoundaryConditions& conditions,
                             const MechanicsOptions& options, const NormalSprings& springs)
    : lattice_(std::move(lattice)), parameters_(parameters), conditions_(conditions), options_(options) {
  parameters_.validate();
  conditions_.validate(lattice_);
  options_.validate();
  const int n_p = lattice_.n_particles();
  states_.assign(static_cast<std::size_t>(lattice_.n_beams()), BeamState::intact);
  normal_stiffness_.resize(static_cast<std::size_t>(lattice_.n_beams()));
  for (int e = 0; e < lattice_.n_beams(); ++e)
    normal_stiffness_[static_cast<std::size_t>(e)] = beam_parameters_for(lattice_, parameters_, e).normal_stiffness;
  softening_.assign(static_cast<std::size_t>(lattice_.n_beams()), 1.0);
  closed_.assign(static_cast<std::size_t>(lattice_.n_beams()), false);
  detached_.assign(static_cast<std::size_t>(n_p), false);

  hold_boundary_dofs();
  remove_rigid_body_modes();
  lump_boundary_loads();
  build_adjacency();

  raw_ = held_value_;
  displacement_ = held_value_;
  solver_ = make_spd_solver(options_.solver, options_.solver_options);
  adopt_normal_springs(springs.stiffness, springs.broken);
  setup_system();
}

void BeamMechanics::hold(int dof, double value) {
  held_[static_cast<std::size_t>(dof)] = true;
  held_value_[dof] = value;
}

// Held degrees of freedom: supports, boundary strain, explicit list (later overrides earlier).
void BeamMechanics::hold_boundary_dofs() {
  const int n_p = lattice_.n_particles(), n_dof = 3 * n_p;
  held_.assign(static_cast<std::size_t>(n_dof), false);
  held_value_ = Eigen::VectorXd::Zero(n_dof);
  for (int p = 0; p < n_p; ++p) {
    const BoundaryTag tag = lattice_.boundary[static_cast<std::size_t>(p)];
    const bool fixed = (tag == BoundaryTag::outer && conditions_.outer == BoundarySupport::fixed) ||
                       (tag == BoundaryTag::inner && conditions_.inner == BoundarySupport::fixed);
    if (fixed) {
      hold(dof_index(p, 0), 0.0);
      hold(dof_index(p, 1), 0.0);
    }
    if (conditions_.prescribe_boundary_strain && tag != BoundaryTag::interior) {
      const Eigen::Vector2d u = conditions_.boundary_strain * lattice_.points.col(p);
      hold(dof_index(p, 0), u.x());
      hold(dof_index(p, 1), u.y());
    }
  }
  for (const auto& pd : conditions_.prescribed) hold(dof_index(pd.particle, pd.component), pd.value);
}

// Rigid-body modes. Pure traction: pin the particle nearest the centroid (gauge removed after
// each solve). Otherwise the held set must stop all three rigid motions of the (connected) lattice.
void BeamMechanics::remove_rigid_body_modes() {
  const int n_dof = 3 * lattice_.n_particles();
  const bool any_held = std::any_of(held_.begin(), held_.end(), [](bool h) { return h; });
  if (!any_held) {
    const Eigen::Vector2d c = lattice_.points.rowwise().mean();
    Eigen::Index best = 0;
    (lattice_.points.colwise() - c).colwise().squaredNorm().minCoeff(&best);
    pinned_particle_ = static_cast<int>(best);
    for (int k = 0; k < 3; ++k) hold(dof_index(pinned_particle_, k), 0.0);
  } else {
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    const Eigen::Vector2d c = lattice_.points.rowwise().mean();
    for (int dof = 0; dof < n_dof; ++dof) {
      if (!held_[static_cast<std::size_t>(dof)]) continue;
      const Eigen::Vector2d r = lattice_.points.col(dof / 3) - c;
      const Eigen::Vector3d row = dof % 3 == 0   ? Eigen::Vector3d(1, 0, -r.y())
                                  : dof % 3 == 1 ? Eigen::Vector3d(0, 1, r.x())
                                                 : Eigen::Vector3d(0, 0, 1);
      M += row * row.transpose();
    }
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(M).eigenvalues();
    if (!(ev[0] > 1e-12 * ev[2]))  // relative rank test; lattice lengths are O(r_min) to O(1)
      throw hm::InputError(
          "boundary_conditions: the held degrees of freedom leave a rigid-body motion free, "
          "allowed: none held (pure traction, pinned automatically) or held so that x, y "
          "translation and rotation are all stopped");
  }
}

// Loads: boundary pressures and the outer stress as tractions on the boundary polygon, lumped
// half to each end (exact for a constant traction: the segment's force and moment).
void BeamMechanics::lump_boundary_loads() {
  const int n_dof = 3 * lattice_.n_particles();
  pressure_loads_ = Eigen::VectorXd::Zero(n_dof);
  extra_loads_ = Eigen::VectorXd::Zero(n_dof);
  const bool outer_stressed = !conditions_.outer_stress.isZero(0.0);
  for (int e = 0; e < lattice_.n_beams(); ++e) {
    const BoundaryTag tag = lattice_.beam_boundary[static_cast<std::size_t>(e)];
    if (tag == BoundaryTag::interior) continue;
    const double p = tag == BoundaryTag::inner ? conditions_.inner_pressure : conditions_.outer_pressure;
    const bool stressed = tag == BoundaryTag::outer && outer_stressed;
    if (p == 0.0 && !stressed) continue;
    const auto [i, j] = lattice_.beams[static_cast<std::size_t>(e)];
    Eigen::Vector2d f = lattice_.lumped_pressure_force(e, p);
    if (stressed) f += 0.5 * lattice_.length[e] * (conditions_.outer_stress * lattice_.outward_normal(e));
    for (int q : {i, j}) {
      pressure_loads_[dof_index(q, 0)] += f.x();
      pressure_loads_[dof_index(q, 1)] += f.y();
    }
  }
}

// Particle -> beam adjacency for the detachment search.
void BeamMechanics::build_adjacency() {
  const int n_p = lattice_.n_particles();
  adjacency_start_.assign(static_cast<std::size_t>(n_p) + 1, 0);
  for (const auto& b : lattice_.beams) {
    ++adjacency_start_[static_cast<std::size_t>(b[0]) + 1];
    ++adjacency_start_[static_cast<std::size_t>(b[1]) + 1];
  }
  for (int p = 0; p < n_p; ++p) adjacency_start_[p + 1] += adjacency_start_[p];
  adjacency_beam_.assign(static_cast<std::size_t>(adjacency_start_.back()), 0);
  std::vector<int> fill(adjacency_start_.begin(), adjacency_start_.end() - 1);
  for (int e = 0; e < lattice_.n_beams(); ++e)
    for (int q : lattice_.beams[static_cast<std::size_t>(e)]) adjacency_beam_[static_cast<std::size_t>(fill[q]++)] = e;
}

void BeamMechanics::setup_system() {
  // compute() below replaces the factor: freed first, it is never held beside the new A's assembly.
  solver_->discard_factor();
  const int n_dof = 3 * lattice_.n_particles();
  free_index_.assign(static_cast<std::size_t>(n_dof), -1);
  free_dofs_.clear();
  for (int dof = 0; dof < n_dof; ++dof)
    if (!held_[static_cast<std::size_t>(dof)]) {
      free_index_[static_cast<std::size_t>(dof)] = static_cast<int>(free_dofs_.size());
      free_dofs_.push_back(dof);
    }
  held_term_ = Eigen::VectorXd::Zero(n_dof);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(36 * static_cast<std::size_t>(lattice_.n_beams()));
  for (int e = 0; e < lattice_.n_beams(); ++e) {
    const auto d = beam_dofs(lattice_, e);
    const Matrix6d k = beam_element_stiffness(lattice_.length[e], lattice_.angle[e], beam_parameters(e),
                                              states_[static_cast<std::size_t>(e)]);
    Eigen::Matrix<double, 6, 1> uh;
    for (int a = 0; a < 6; ++a) uh[a] = held_value_[d[static_cast<std::size_t>(a)]];
    const Eigen::Matrix<double, 6, 1> kh = k * uh;
    for (int a = 0; a < 6; ++a) {
      held_term_[d[static_cast<std::size_t>(a)]] += kh[a];
      const int ra = free_index_[static_cast<std::size_t>(d[static_cast<std::size_t>(a)])];
      if (ra < 0) continue;
      // Every beam's entries are stored, open ones as zeros: state changes never alter the pattern,
      // so the factor's pattern covers every later update/downdate.
      for (int b = 0; b < 6; ++b) {
        const int rb = free_index_[static_cast<std::size_t>(d[static_cast<std::size_t>(b)])];
        if (rb >= 0) triplets.emplace_back(ra, rb, k(a, b));
      }
    }
  }
  // The coupling's normal springs (Eq. 20): k n n^T on the x, y blocks [[1, -1], [-1, 1]]. They lie
  // inside the beam's pattern, so the pattern is that of the dry lattice.
  for (int e = 0; e < springs_.size(); ++e) {
    if (springs_[e] == 0.0) continue;
    const NormalSpring spring(lattice_, e);
    const double elong_h = spring.stretch(held_value_);
    for (std::size_t a = 0; a < 4; ++a) {
      held_term_[spring.dofs[a]] += springs_[e] * spring.g[a] * elong_h;
      const int ra = free_index_[static_cast<std::size_t>(spring.dofs[a])];
      if (ra < 0) continue;
      for (std::size_t b = 0; b < 4; ++b) {
        const int rb = free_index_[static_cast<std::size_t>(spring.dofs[b])];
        if (rb >= 0) triplets.emplace_back(ra, rb, springs_[e] * spring.g[a] * spring.g[b]);
      }
    }
  }
  const int n_free = static_cast<int>(free_dofs_.size());
  SpdSolver::Matrix A(n_free, n_free);
  A.setFromTriplets(triplets.begin(), triplets.end());
  solver_->compute(A);
}

Eigen::VectorXd BeamMechanics::full_vector(const Eigen::VectorXd& x_free) const {
  Eigen::VectorXd u = held_value_;
  for (std::size_t k = 0; k < free_dofs_.size(); ++k) u[free_dofs_[k]] = x_free[static_cast<Eigen::Index>(k)];
  return u;
}

Eigen::VectorXd BeamMechanics::linear_response(const Eigen::VectorXd& forces) const {
  if (forces.size() != 3 * lattice_.n_particles())
    throw hm::InputError("linear_response: " + std::to_string(forces.size()) + " forces, allowed: 3 per particle (" +
                         std::to_string(3 * lattice_.n_particles()) + ")");
  Eigen::VectorXd b(n_free_dofs());
  for (std::size_t k = 0; k < free_dofs_.size(); ++k) b[static_cast<Eigen::Index>(k)] = forces[free_dofs_[k]];
  Eigen::VectorXd x = solver_->solve(b);
  rank_one_.correct(*solver_, free_dofs_, nullptr, x);  // the response to forces alone
  Eigen::VectorXd du = Eigen::VectorXd::Zero(forces.size());
  for (std::size_t k = 0; k < free_dofs_.size(); ++k) du[free_dofs_[k]] = x[static_cast<Eigen::Index>(k)];
  return du;
}

void BeamMechanics::modify_beam(int beam, const std::vector<int>& columns, double scale, int sigma) {
  // sigma scale V_c V_c^T for the columns c of the unsoftened intact factor: the reduced matrix by a
  // rank-|columns| modification, the held-DOF term K u_h by sigma scale V_c (V_c^T u_h).
  BeamParameters intact = parameters_;
  intact.normal_stiffness = normal_stiffness_[static_cast<std::size_t>(beam)];
  Matrix63d V = beam_element_factor(lattice_.length[beam], lattice_.angle[beam], intact, BeamState::intact);
  if (scale != 1.0) V *= std::sqrt(scale);  // a brittle lattice (scale 1) keeps its bits
  const auto d = beam_dofs(lattice_, beam);
  std::vector<Eigen::Triplet<double>> w;
  for (std::size_t c = 0; c < columns.size(); ++c)
    for (int a = 0; a < 6; ++a) {
      const int r = free_index_[static_cast<std::size_t>(d[static_cast<std::size_t>(a)])];
      if (r >= 0 && V(a, columns[c]) != 0.0) w.emplace_back(r, static_cast<int>(c), V(a, columns[c]));
    }
  Eigen::Matrix<double, 6, 1> uh;
  for (int a = 0; a < 6; ++a) uh[a] = held_value_[d[static_cast<std::size_t>(a)]];
  for (int col : columns) {
    const double s = sigma * V.col(col).dot(uh);
    for (int a = 0; a < 6; ++a) held_term_[d[static_cast<std::size_t>(a)]] += s * V(a, col);
  }
  if (w.empty()) return;  // both ends held: the reduced matrix does not change
  SpdSolver::Matrix W(n_free_dofs(), static_cast<Eigen::Index>(columns.size()));
  W.setFromTriplets(w.begin(), w.end());
  solver_->modify(W, sigma);
}

void BeamMechanics::change_state(int beam, BeamState to) {
  const BeamState from = states_[static_cast<std::size_t>(beam)];
  if (from == to) return;
  // K_e(from) - K_e(to) (or the reverse) is a subset of the columns of beam_element_factor: the
  // normal spring (0) and the bending (1, 2). An intact beam carries its softening factor on all
  // three; a contact has the unsoftened normal spring (a closed crack transmits the rock's stiffness).
  // A closed softened beam already has the unsoftened normal spring.
  const double softening = softening_[static_cast<std::size_t>(beam)];
  const double normal = closed_[static_cast<std::size_t>(beam)] ? 1.0 : softening;
  if (from == BeamState::intact && to == BeamState::contact) {
    modify_beam(beam, {1, 2}, softening, -1);
    if (normal != 1.0) modify_beam(beam, {0}, 1.0 - normal, +1);
  } else if (from == BeamState::intact && to == BeamState::open) {
    if (normal == softening) {
      modify_beam(beam, {0, 1, 2}, softening, -1);
    } else {
      modify_beam(beam, {0}, normal, -1);
      modify_beam(beam, {1, 2}, softening, -1);
    }
  } else if (from == BeamState::contact && to == BeamState::open) {
    modify_beam(beam, {0}, 1.0, -1);
  } else if (from == BeamState::open && to == BeamState::contact) {
    modify_beam(beam, {0}, 1.0, +1);
  } else {
    assert(false && "change_state: a broken beam cannot heal");
  }
  if (from == BeamState::intact) {
    broken_.push_back(beam);
    if (softening != 1.0) softened_.erase(std::lower_bound(softened_.begin(), softened_.end(), beam));
    softening_[static_cast<std::size_t>(beam)] = 1.0;
    closed_[static_cast<std::size_t>(beam)] = false;
  }
  states_[static_cast<std::size_t>(beam)] = to;
}

void BeamMechanics::soften_beam(int beam, double stiffness_factor) {
  if (beam < 0 || beam >= lattice_.n_beams())
    throw hm::InputError("beam = " + std::to_string(beam) + ", allowed: 0 <= beam < " +
                         std::to_string(lattice_.n_beams()));
  if (states_[static_cast<std::size_t>(beam)] != BeamState::intact)
    throw hm::InputError("beam " + std::to_string(beam) + " is broken, allowed: an intact beam");
  const double now = softening_[static_cast<std::size_t>(beam)];
  if (!(stiffness_factor > 0.0 && stiffness_factor < now))
    throw hm::InputError("stiffness_factor = " + hm::core::format_value(stiffness_factor) +
                         ", allowed: 0 < stiffness_factor < the beam's current " + hm::core::format_value(now));
  // A closed beam keeps its unsoftened normal spring: only its bending softens.
  if (closed_[static_cast<std::size_t>(beam)])
    modify_beam(beam, {1, 2}, now - stiffness_factor, -1);
  else
    modify_beam(beam, {0, 1, 2}, now - stiffness_factor, -1);
  if (now == 1.0) softened_.insert(std::lower_bound(softened_.begin(), softened_.end(), beam), beam);
  softening_[static_cast<std::size_t>(beam)] = stiffness_factor;
}

void BeamMechanics::remove_normal_spring(int beam) {
  // The spring as setup_system assembles it: one downdate with the column sqrt(k) g, and its share of
  // the held-DOF term.
  const double k = springs_[beam];
  const NormalSpring spring(lattice_, beam);
  const double elong_h = spring.stretch(held_value_);
  std::vector<Eigen::Triplet<double>> w;
  for (std::size_t a = 0; a < 4; ++a) {
    held_term_[spring.dofs[a]] -= k * spring.g[a] * elong_h;
    const int r = free_index_[static_cast<std::size_t>(spring.dofs[a])];
    if (r >= 0 && spring.g[a] != 0.0) w.emplace_back(r, 0, std::sqrt(k) * spring.g[a]);
  }
  springs_[beam] = 0.0;
  if (w.empty()) return;
  SpdSolver::Matrix W(n_free_dofs(), 1);
  W.setFromTriplets(w.begin(), w.end());
  solver_->modify(W, -1);
}

double BeamMechanics::elongation(int beam) const { return normal_elongation(lattice_, raw_, beam); }

BeamState BeamMechanics::break_beam(int beam) {
  if (beam < 0 || beam >= lattice_.n_beams())
    throw hm::InputError("beam = " + std::to_string(beam) + ", allowed: 0 <= beam < " +
                         std::to_string(lattice_.n_beams()));
  if (states_[static_cast<std::size_t>(beam)] != BeamState::intact) return states_[static_cast<std::size_t>(beam)];
  const auto [i, j] = lattice_.beams[static_cast<std::size_t>(beam)];
  change_state(beam, contact_state(BeamState::intact, elongation(beam), 0.0));
  if (broken_spring_ == BrokenBeamSpring::drop && springs_.size() > 0 && springs_[beam] > 0.0)
    remove_normal_spring(beam);
  check_detachment(i, j);
  return states_[static_cast<std::size_t>(beam)];
}

bool BeamMechanics::connected_part(int start, int target, std::vector<char>& seen, std::vector<int>& out) const {
  // Breadth-first over intact beams (and sprung broken ones), stopping as soon as the target is reached.
  out.assign(1, start);
  seen[static_cast<std::size_t>(start)] = 1;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const int p = out[k];
    for (int a = adjacency_start_[static_cast<std::size_t>(p)]; a < adjacency_start_[static_cast<std::size_t>(p) + 1];
         ++a) {
      const int e = adjacency_beam_[static_cast<std::size_t>(a)];
      // A broken beam still connects through its normal spring (the coupling's Eq. 20): the part
      // is then held by the fluid, not loose.
      const bool spring = springs_.size() > 0 && springs_[e] > 0.0;
      if (states_[static_cast<std::size_t>(e)] != BeamState::intact && !spring) continue;
      const auto& b = lattice_.beams[static_cast<std::size_t>(e)];
      const int q = b[0] == p ? b[1] : b[0];
      if (seen[static_cast<std::size_t>(q)]) continue;
      if (q == target) return true;
      seen[static_cast<std::size_t>(q)] = 1;
      out.push_back(q);
    }
  }
  return false;
}

bool BeamMechanics::is_anchored(const std::vector<int>& part) const {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (int p : part) c += lattice_.points.col(p);
  c /= static_cast<double>(part.size());
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (int p : part)
    for (int k = 0; k < 3; ++k) {
      if (!held_[static_cast<std::size_t>(dof_index(p, k))]) continue;
      const Eigen::Vector2d r = lattice_.points.col(p) - c;
      const Eigen::Vector3d row = k == 0   ? Eigen::Vector3d(1, 0, -r.y())
                                  : k == 1 ? Eigen::Vector3d(0, 1, r.x())
                                           : Eigen::Vector3d(0, 0, 1);
      M += row * row.transpose();
    }
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(M).eigenvalues();
  return ev[0] > 1e-12 * ev[2];
}

void BeamMechanics::freeze_part(const std::vector<int>& part) {
  // At the rigid motion nearest its last displacement: it then carries no force.
  const auto fit = rigid_fit(lattice_, raw_, part);
  for (int p : part) {
    const Eigen::Vector3d u = rigid_motion(lattice_, fit, p);
    for (int k = 0; k < 3; ++k) {
      held_[static_cast<std::size_t>(dof_index(p, k))] = true;
      held_value_[dof_index(p, k)] = u[k];
      raw_[dof_index(p, k)] = u[k];
    }
    detached_[static_cast<std::size_t>(p)] = true;
    ++n_detached_;
    for (int a = adjacency_start_[static_cast<std::size_t>(p)]; a < adjacency_start_[static_cast<std::size_t>(p) + 1];
         ++a) {
      const int e = adjacency_beam_[static_cast<std::size_t>(a)];
      if (states_[static_cast<std::size_t>(e)] == BeamState::contact)
        states_[static_cast<std::size_t>(e)] = BeamState::open;
    }
  }
}

void BeamMechanics::check_detachment(int i, int j) {
  bool changed = false;
  // The gauge pin of a pure traction problem stops the body's rigid motions only while an intact beam
  // (which carries a moment) ties it to the body. Left with springs or contacts alone, the pin is a
  // point the rest of the lattice turns about at no energy (every spring and contact points at it: a
  // zero pivot), and without them the detachment search below would freeze the whole body instead of
  // the one loose particle. Move the pin into the intact body first; then the old pin is an ordinary
  // particle, handled below like any other.
  if (is_pinned() && (i == pinned_particle_ || j == pinned_particle_) && !has_intact_beam(pinned_particle_)) {
    move_pin();
    changed = true;
  }
  // With springs (which carry no moment), a particle left without intact beams keeps its translations
  // through them but has a free rotation: hold that at its current value.
  if (springs_.size() > 0) {
    for (int p : {i, j}) {
      const Eigen::Index d = dof_index(p, 2);
      if (has_intact_beam(p) || held_[static_cast<std::size_t>(d)]) continue;
      held_[static_cast<std::size_t>(d)] = true;
      held_value_[d] = raw_[d];
      changed = true;
    }
  }
  // Usually the broken beam's triangles keep its two ends connected, and the search from i stops at j;
  // else each side is a whole part, frozen if nothing holds it.
  std::vector<char> seen(static_cast<std::size_t>(lattice_.n_particles()), 0);
  std::vector<int> part_i, part_j;
  if (connected_part(i, j, seen, part_i)) {
    if (changed) setup_system();
    return;
  }
  connected_part(j, -1, seen, part_j);
  for (const auto* part : {&part_i, &part_j}) {
    if (is_anchored(*part)) continue;
    freeze_part(*part);
    changed = true;
  }
  if (changed) setup_system();
}

bool BeamMechanics::has_intact_beam(int p) const {
  for (int a = adjacency_start_[static_cast<std::size_t>(p)]; a < adjacency_start_[static_cast<std::size_t>(p) + 1];
       ++a)
    if (states_[static_cast<std::size_t>(adjacency_beam_[static_cast<std::size_t>(a)])] == BeamState::intact)
      return true;
  return false;
}

void BeamMechanics::move_pin() {
  // The new pin: of the largest set of attached particles connected by intact beams (the body), the
  // particle nearest the lattice's centroid (the constructor's rule) with all its beams intact. The
  // gauge is arbitrary (solve() removes the rigid motion of the reported displacement), so the pin
  // holds its last displacement: raw_ stays continuous.
  const int n_p = lattice_.n_particles();
  std::vector<int> label(static_cast<std::size_t>(n_p), -1), queue;
  int body = -1;
  std::size_t body_size = 0;
  for (int s = 0; s < n_p; ++s) {
    if (label[static_cast<std::size_t>(s)] >= 0 || detached_[static_cast<std::size_t>(s)]) continue;
    queue.assign(1, s);
    label[static_cast<std::size_t>(s)] = s;
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const int p = queue[k];
      for (int a = adjacency_start_[static_cast<std::size_t>(p)]; a < adjacency_start_[static_cast<std::size_t>(p) + 1];
           ++a) {
        const int e = adjacency_beam_[static_cast<std::size_t>(a)];
        if (states_[static_cast<std::size_t>(e)] != BeamState::intact) continue;
        const auto& b = lattice_.beams[static_cast<std::size_t>(e)];
        const int q = b[0] == p ? b[1] : b[0];
        if (label[static_cast<std::size_t>(q)] >= 0 || detached_[static_cast<std::size_t>(q)]) continue;
        label[static_cast<std::size_t>(q)] = s;
        queue.push_back(q);
      }
    }
    if (queue.size() > body_size) {
      body_size = queue.size();
      body = s;
    }
  }
  const Eigen::Vector2d c = lattice_.points.rowwise().mean();
  int best = -1;
  for (bool all_intact : {true, false}) {
    double best_d2 = std::numeric_limits<double>::infinity();
    for (int p = 0; p < n_p; ++p) {
      if (label[static_cast<std::size_t>(p)] != body) continue;
      if (all_intact) {
        bool intact = true;
        for (int a = adjacency_start_[static_cast<std::size_t>(p)];
             a < adjacency_start_[static_cast<std::size_t>(p) + 1]; ++a)
          intact = intact &&
                   states_[static_cast<std::size_t>(adjacency_beam_[static_cast<std::size_t>(a)])] == BeamState::intact;
        if (!intact) continue;
      }
      const double d2 = (lattice_.points.col(p) - c).squaredNorm();
      if (d2 < best_d2) {
        best_d2 = d2;
        best = p;
      }
    }
    if (best >= 0) break;
  }
  if (best < 0) return;  // no attached particle left: nothing to pin
  for (int k = 0; k < 3; ++k) {
    const Eigen::Index old_dof = dof_index(pinned_particle_, k), new_dof = dof_index(best, k);
    held_[static_cast<std::size_t>(old_dof)] = false;
    held_value_[old_dof] = 0.0;
    held_[static_cast<std::size_t>(new_dof)] = true;
    held_value_[new_dof] = raw_[new_dof];
  }
  pinned_particle_ = best;
}

void BeamMechanics::set_normal_springs(const Eigen::VectorXd& stiffness, BrokenBeamSpring broken) {
  adopt_normal_springs(stiffness, broken);
  setup_system();
}

void BeamMechanics::adopt_normal_springs(const Eigen::VectorXd& stiffness, BrokenBeamSpring broken) {
  if (stiffness.size() != 0 && stiffness.size() != lattice_.n_beams())
    throw hm::InputError("normal_springs: size = " + std::to_string(stiffness.size()) +
                         ", allowed: 0 or n_beams = " + std::to_string(lattice_.n_beams()));
  for (Eigen::Index e = 0; e < stiffness.size(); ++e)
    if (!(std::isfinite(stiffness[e]) && stiffness[e] >= 0.0))
      throw hm::InputError("normal_springs[" + std::to_string(e) + "] = " + hm::core::format_value(stiffness[e]) +
                           ", allowed: finite, >= 0");
  springs_ = stiffness;
  broken_spring_ = broken;
  if (broken == BrokenBeamSpring::drop)
    for (int e : broken_) springs_[e] = 0.0;
}

void BeamMechanics::set_rank_one_stiffness(RankOneStiffness term) {
  if (term.is_active() && term.vector().size() != 3 * lattice_.n_particles())
    throw hm::InputError("rank-one stiffness: size = " + std::to_string(term.vector().size()) +
                         ", allowed: 3 n_particles = " + std::to_string(3 * lattice_.n_particles()));
  rank_one_ = std::move(term);
}

void BeamMechanics::set_rank_one_reference(const Eigen::VectorXd& u_reference) {
  assert(u_reference.size() == 3 * lattice_.n_particles() && "set_rank_one_reference: 3 entries per particle");
  rank_one_.set_reference(u_reference);
}

void BeamMechanics::set_external_forces(const Eigen::VectorXd& forces) {
  assert(forces.size() == 3 * lattice_.n_particles() && "set_external_forces: 3 entries per particle");
  extra_loads_ = forces;
}

BeamParameters BeamMechanics::beam_parameters(int beam) const {
  BeamParameters p = parameters_;
  // Times 1 for every beam of a brittle lattice: bit for bit the unsoftened constants.
  const auto k = static_cast<std::size_t>(beam);
  if (closed_[k]) {  // a closed crack: the unsoftened normal spring, the softened bending
    p.normal_stiffness = normal_stiffness_[k];
    p.bending_factor = softening_[k];
  } else {
    p.normal_stiffness = normal_stiffness_[k] * softening_[k];
  }
  return p;
}

MechanicsSummary BeamMechanics::solve() { return solve(true); }

MechanicsSummary BeamMechanics::solve(bool equilibrium_check) {
  const auto start = std::chrono::steady_clock::now();
  MechanicsSummary summary;
  summary.n_detached_particles = n_detached_;
  for (int it = 0; it < options_.max_contact_iterations; ++it) {
    const Eigen::VectorXd f = pressure_loads_ + extra_loads_ - held_term_;
    Eigen::VectorXd b(n_free_dofs());
    for (std::size_t k = 0; k < free_dofs_.size(); ++k) b[static_cast<Eigen::Index>(k)] = f[free_dofs_[k]];
    Eigen::VectorXd x = solver_->solve(b);
    ++summary.contact_iterations;
    summary.info = solver_->info();
    summary.solver_residual = solver_->report().relative_residual;
    if (summary.info == Eigen::Success && !rank_one_.correct(*solver_, free_dofs_, &held_value_, x))
      summary.info = solver_->info();
    if (summary.info != Eigen::Success) {
      summary.message = "linear solver: " + solver_->report().message;
      // A solve that fails its residual check far outside the small-strain range is not round-off: a part
      // of the lattice hangs on a ligament of a few beams, and the factor's conditioning goes with it.
      const double u_max = full_vector(x).cwiseAbs().maxCoeff();
      if (u_max > kMaxSmallStrainDisplacement) {
        summary.near_mechanism = true;
        summary.message = "the lattice is nearly cut through: displacements up to " + format_value(u_max) +
                          " R, a part hanging on a few beams (" + summary.message + ")";
      }
      break;
    }
    raw_ = full_vector(x);
    const double tol = options_.contact_tolerance * raw_.cwiseAbs().maxCoeff();
    const std::vector<ContactSwitch> switches = contact_switches(tol, it);
    apply(switches, tol);
    const int changes = static_cast<int>(switches.size());
    summary.n_contact_changes += changes;
    if (changes == 0) {
      summary.contact_converged = true;
      break;
    }
  }
  if (summary.info == Eigen::Success && !summary.contact_converged)
    summary.message = "contact set not stable after " + std::to_string(options_.max_contact_iterations) +
                      " iterations (max_contact_iterations); displacement of the last iterate";
  for (int e : broken_)
    (states_[static_cast<std::size_t>(e)] == BeamState::contact ? summary.n_contacts : summary.n_open)++;

  remove_rigid_motion();
  if (summary.info == Eigen::Success)
    summary.equilibrium_residual =
        equilibrium_check ? equilibrium_residual() : std::numeric_limits<double>::quiet_NaN();
  summary.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

std::vector<BeamMechanics::ContactSwitch> BeamMechanics::contact_switches(double tol, int iteration) const {
  // Active set of Eqs. 8-10: overlapping broken beams push (contact), separating ones do nothing.
  // The same for softened intact beams: a shortened one is closed (its normal spring unsoftened,
  // the difference (1 - s) k_n added as a rank-1 update), a lengthened one open again.
  std::vector<ContactSwitch> switches;
  for (int e : broken_) {
    const auto [i, j] = lattice_.beams[static_cast<std::size_t>(e)];
    if (detached_[static_cast<std::size_t>(i)] || detached_[static_cast<std::size_t>(j)]) continue;
    const double stretch = elongation(e);
    if (contact_state(states_[static_cast<std::size_t>(e)], stretch, tol) != states_[static_cast<std::size_t>(e)])
      switches.push_back({e, false, std::abs(stretch)});
  }
  for (int e : softened_) {
    const auto k = static_cast<std::size_t>(e);
    const auto [i, j] = lattice_.beams[k];
    if (detached_[static_cast<std::size_t>(i)] || detached_[static_cast<std::size_t>(j)]) continue;
    const double stretch = elongation(e);
    if ((!closed_[k] && stretch < -tol) || (closed_[k] && stretch > tol))
      switches.push_back({e, true, std::abs(stretch)});
  }
  // All at once settles in a few iterations, but can cycle (MechanicsOptions::contact_switches_at_once);
  // from then on only the most violated beam switches, one per solve.
  if (iteration >= options_.contact_switches_at_once && switches.size() > 1)
    switches = {*std::max_element(
        switches.begin(), switches.end(),
        [](const ContactSwitch& first, const ContactSwitch& second) { return first.violation < second.violation; })};
  return switches;
}

void BeamMechanics::apply(const std::vector<ContactSwitch>& switches, double tol) {
  for (const ContactSwitch& w : switches) {
    const auto k = static_cast<std::size_t>(w.beam);
    if (!w.softened) {
      change_state(w.beam, contact_state(states_[k], elongation(w.beam), tol));
      continue;
    }
    const bool close = !closed_[k];
    modify_beam(w.beam, {0}, 1.0 - softening_[k], close ? +1 : -1);
    closed_[k] = close;
  }
}

void BeamMechanics::remove_rigid_motion() {
  displacement_ = raw_;
  if (!is_pinned()) return;
  std::vector<int> attached;
  for (int p = 0; p < lattice_.n_particles(); ++p)
    if (!detached_[static_cast<std::size_t>(p)]) attached.push_back(p);
  const auto fit = rigid_fit(lattice_, raw_, attached);
  for (int p = 0; p < lattice_.n_particles(); ++p)
    displacement_.segment<3>(dof_index(p, 0)) -= rigid_motion(lattice_, fit, p);
}

double BeamMechanics::equilibrium_residual() const {
  const Eigen::VectorXd f = loads(), r = reactions();
  double r_max = 0.0;
  for (int dof : free_dofs_) r_max = std::max(r_max, std::abs(r[dof]));
  const double scale = std::max(f.cwiseAbs().maxCoeff(), (r + f).cwiseAbs().maxCoeff());
  return scale > 0.0 ? r_max / scale : r_max;
}

std::vector<BeamForce> BeamMechanics::beam_forces() const {
  std::vector<BeamForce> forces;
  beam_forces(forces);
  return forces;
}

void BeamMechanics::beam_forces(std::vector<BeamForce>& forces) const {
  fill_connection_forces(
      lattice_, [this](int e) { return beam_parameters(e); }, states_, raw_, forces);
}

Eigen::VectorXd BeamMechanics::reactions() const {
  Eigen::VectorXd r = -loads();
  for (int e = 0; e < lattice_.n_beams(); ++e) {
    const BeamState s = states_[static_cast<std::size_t>(e)];
    if (s == BeamState::open) continue;
    const auto d = beam_dofs(lattice_, e);
    const Vector6d f =
        BeamOperator(lattice_, e, beam_parameters(e), s).internal_force(element_displacements(lattice_, e, raw_));
    for (int a = 0; a < 6; ++a) r[d[static_cast<std::size_t>(a)]] += f[a];
  }
  for (int e = 0; e < springs_.size(); ++e)
    if (springs_[e] != 0.0) NormalSpring(lattice_, e).add_force(springs_[e], elongation(e), r);
  if (rank_one_.is_active()) r += rank_one_.force(raw_);
  return r;
}

void BeamMechanics::save_state(core::StateWriter& w, StateScope scope) const {
  std::string states(states_.size(), '\0');
  std::transform(states_.begin(), states_.end(), states.begin(), [](BeamState b) { return static_cast<char>(b); });
  w.put("mechanics.states", states);
  w.put("mechanics.held", held_);
  w.put("mechanics.held_value", held_value_);
  w.put("mechanics.detached", detached_);
  w.put("mechanics.n_detached", n_detached_);
  w.put("mechanics.pinned_particle", pinned_particle_);
  w.put("mechanics.free_index", free_index_);
  w.put("mechanics.free_dofs", free_dofs_);
  w.put("mechanics.pressure_loads", pressure_loads_);
  w.put("mechanics.extra_loads", extra_loads_);
  w.put("mechanics.held_term", held_term_);
  w.put("mechanics.raw", raw_);
  w.put("mechanics.displacement", displacement_);
  w.put("mechanics.broken", broken_);
  w.put("mechanics.springs", springs_);
  w.put("mechanics.softening", softening_);
  w.put("mechanics.closed", closed_);
  rank_one_.save_state(w);
  w.put("mechanics.solver", solver_->name());
  solver_->save_state(w, scope);
}

namespace {

// The numbering of the free dofs is a function of the held ones (setup_system).
template <class Check>
void check_free_numbering(const std::vector<bool>& held, const std::vector<int>& free_index,
                          const std::vector<int>& free_dofs, const Check& check) {
  check(free_index.size() == held.size(), "mechanics.free_index");
  for (std::size_t dof = 0, free = 0; dof < held.size(); ++dof) {
    check(free_index[dof] == (held[dof] ? -1 : static_cast<int>(free)), "mechanics.free_index");
    if (!held[dof]) {
      check(free < free_dofs.size() && free_dofs[free] == static_cast<int>(dof), "mechanics.free_dofs");
      ++free;
    }
  }
  check(free_dofs.size() == static_cast<std::size_t>(std::count(held.begin(), held.end(), false)),
        "mechanics.free_dofs");
}

// The broken beams, each once, are exactly those not intact.
template <class Check>
void check_broken_list(const std::vector<BeamState>& states, const std::vector<int>& broken, const Check& check) {
  std::vector<bool> listed(states.size(), false);
  for (const int e : broken) {
    check(e >= 0 && static_cast<std::size_t>(e) < states.size() && !listed[static_cast<std::size_t>(e)] &&
              states[static_cast<std::size_t>(e)] != BeamState::intact,
          "mechanics.broken");
    listed[static_cast<std::size_t>(e)] = true;
  }
  check(broken.size() == static_cast<std::size_t>(std::count_if(states.begin(), states.end(),
                                                                [](BeamState b) { return b != BeamState::intact; })),
        "mechanics.broken");
}

}  // namespace

void BeamMechanics::restore_state(core::StateReader& r) {
  const auto n_dofs = static_cast<std::size_t>(3 * lattice_.n_particles());
  const auto n_beams = states_.size();
  // Every count and index is checked against this lattice before it is used: a damaged checkpoint
  // whose checksum still matches must be refused, not followed out of an array.
  const auto check = [&](bool ok, const char* tag) {
    if (!ok)
      throw InputError(r.source() + ": at '" + tag + "': not a state of this lattice (damaged or of another case)");
  };
  const auto sized = [&](const Eigen::VectorXd& v, std::size_t n) { return static_cast<std::size_t>(v.size()) == n; };
  std::string states;
  r.get("mechanics.states", states);
  check(states.size() == n_beams, "mechanics.states");
  for (const char b : states)
    check(b == static_cast<char>(BeamState::intact) || b == static_cast<char>(BeamState::contact) ||
              b == static_cast<char>(BeamState::open),
          "mechanics.states");
  std::transform(states.begin(), states.end(), states_.begin(), [](char b) { return static_cast<BeamState>(b); });
  r.get("mechanics.held", held_);
  check(held_.size() == n_dofs, "mechanics.held");
  r.get("mechanics.held_value", held_value_);
  check(sized(held_value_, n_dofs), "mechanics.held_value");
  r.get("mechanics.detached", detached_);
  check(detached_.size() == static_cast<std::size_t>(lattice_.n_particles()), "mechanics.detached");
  r.get("mechanics.n_detached", n_detached_);
  check(n_detached_ >= 0 && n_detached_ <= lattice_.n_particles(), "mechanics.n_detached");
  r.get("mechanics.pinned_particle", pinned_particle_);
  check(pinned_particle_ >= -1 && pinned_particle_ < lattice_.n_particles(), "mechanics.pinned_particle");
  r.get("mechanics.free_index", free_index_);
  r.get("mechanics.free_dofs", free_dofs_);
  check_free_numbering(held_, free_index_, free_dofs_, check);
  r.get("mechanics.pressure_loads", pressure_loads_);
  check(sized(pressure_loads_, n_dofs), "mechanics.pressure_loads");
  r.get("mechanics.extra_loads", extra_loads_);
  check(sized(extra_loads_, n_dofs), "mechanics.extra_loads");
  r.get("mechanics.held_term", held_term_);
  check(sized(held_term_, n_dofs), "mechanics.held_term");
  r.get("mechanics.raw", raw_);
  check(sized(raw_, n_dofs), "mechanics.raw");
  r.get("mechanics.displacement", displacement_);
  check(sized(displacement_, n_dofs), "mechanics.displacement");
  r.get("mechanics.broken", broken_);
  check_broken_list(states_, broken_, check);
  r.get("mechanics.springs", springs_);
  check(springs_.size() == 0 || sized(springs_, n_beams), "mechanics.springs");
  r.get("mechanics.softening", softening_);
  check(softening_.size() == n_beams, "mechanics.softening");
  r.get("mechanics.closed", closed_);
  check(closed_.size() == n_beams, "mechanics.closed");
  softened_.clear();
  for (std::size_t e = 0; e < n_beams; ++e) {
    const bool softened = states_[e] == BeamState::intact && softening_[e] != 1.0;
    check(softening_[e] > 0.0 && softening_[e] <= 1.0 && (softened || (!closed_[e] && softening_[e] == 1.0)),
          "mechanics.softening");
    if (softened) softened_.push_back(static_cast<int>(e));
  }
  rank_one_.restore_state(r);
  std::string solver;
  r.get("mechanics.solver", solver);
  check(solver == solver_->name(), "mechanics.solver");
  solver_->restore_state(r);
  check(solver_->matrix().rows() == static_cast<Eigen::Index>(free_dofs_.size()), "cholmod.matrix");
}

}  // namespace hm::lattice2d
