#include "hm/lattice2d/flow/flow_network.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <utility>

#include <Eigen/LU>

#include <Eigen/SparseCore>

#include "hm/core/input_error.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/core/validation.hpp"
#include "hm/lattice2d/linalg/spd_solver.hpp"

namespace hm::lattice2d {

namespace {

using hm::core::format_value;

// The volume injected over [t, t + dt] at the rate Q min(1, s / ramp): exactly, so that the run's
// volume balance closes to round-off during the ramp too.
double injected_volume(double Q, double ramp, double t, double dt) {
  if (!(ramp > 0.0)) return Q * dt;
  const double a = std::min(t, ramp), b = std::min(t + dt, ramp);
  return Q * ((b * b - a * a) / (2.0 * ramp) + std::max(0.0, t + dt - std::max(t, ramp)));
}

// |a - b - c - d| over the sum of the magnitudes; 0 if everything vanishes.
double relative_imbalance(double injected, double storage, double deformation, double outflow) {
  const double scale = std::abs(injected) + std::abs(storage) + std::abs(deformation) + std::abs(outflow);
  return scale > 0.0 ? std::abs(injected - storage - deformation - outflow) / scale : 0.0;
}

// The triangle that holds the source point x0: the one in which its smallest barycentric coordinate
// is largest, so a point on an edge or vertex picks one triangle deterministically.
int source_triangle_of(const Lattice& lattice, const Eigen::Vector2d& x0) {
  double best = -std::numeric_limits<double>::infinity();
  int found = -1;
  for (int s = 0; s < lattice.n_triangles(); ++s) {
    const auto& tri = lattice.triangles[static_cast<std::size_t>(s)];
    const Eigen::Vector2d a = lattice.points.col(tri[0]), b = lattice.points.col(tri[1]),
                          c = lattice.points.col(tri[2]);
    auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
    const double twice_area = cross(b - a, c - a);
    const double lambda = std::min({cross(b - x0, c - x0), cross(c - x0, a - x0), cross(a - x0, b - x0)}) / twice_area;
    if (lambda > best) {
      best = lambda;
      found = s;
    }
  }
  // Relative round-off of the barycentric coordinates; anything more negative is outside.
  if (best < -1e-12)
    throw InputError("source_x, source_y = " + format_value(x0.x()) + ", " + format_value(x0.y()) +
                     ", allowed: a point inside the lattice");
  return found;
}

}  // namespace

void FlowParameters::validate() const {
  using namespace hm::core;
  require_non_negative(Q, "Q");
  require_positive(E_over_M, "E_over_M");
  require_closed(b, "b", 0.0, 1.0);
  require_finite(E_over_Kw, "E_over_Kw");
  require_positive(E_over_Kw, "E_over_Kw");
  require_positive(iota, "iota");
  if (fracture_flow.law != FractureFlow::permeability && fracture_flow.law != FractureFlow::transmissivity &&
      fracture_flow.law != FractureFlow::cubic)
    throw InputError("fracture_flow = " + std::to_string(static_cast<int>(fracture_flow.law)) +
                     ", allowed: permeability, transmissivity, cubic");
  require_finite(fracture_flow.transmissivity, "crack_transmissivity");
  require_non_negative(fracture_flow.transmissivity, "crack_transmissivity");
  require_finite(fracture_flow.residual_aperture, "residual_aperture");
  require_non_negative(fracture_flow.residual_aperture, "residual_aperture");
  require_finite(injection_ramp_time, "injection_ramp_time");
  require_non_negative(injection_ramp_time, "injection_ramp_time");
  if (fracture_flow.law == FractureFlow::cubic) {
    require_finite(fracture_flow.permeability, "rock_permeability");
    require_positive(fracture_flow.permeability, "rock_permeability");
  }
  require_positive(time_step, "time_step");
  if (!(refinement_tolerance > 0.0 && refinement_tolerance < 1e-6))
    throw InputError("refinement_tolerance = " + format_value(refinement_tolerance) + ", allowed: 0 < value < 1e-6");
  if (max_refinements < 1) throw InputError("max_refinements = " + std::to_string(max_refinements) + ", allowed: >= 1");
  if (refresh_after_refinements < 0)
    throw InputError("refresh_after_refinements = " + std::to_string(refresh_after_refinements) + ", allowed: >= 0");
  if (borehole_storage != BoreholeStorage::biot_modulus && borehole_storage != BoreholeStorage::none &&
      borehole_storage != BoreholeStorage::fluid)
    throw InputError("borehole_storage = " + std::to_string(static_cast<int>(borehole_storage)) +
                     ", allowed: biot-modulus, none, fluid");
  if (crack_coupling != CrackCoupling::biot && crack_coupling != CrackCoupling::full)
    throw InputError("crack_coupling = " + std::to_string(static_cast<int>(crack_coupling)) + ", allowed: biot, full");
  if (borehole_deformation != BoreholeDeformation::biot && borehole_deformation != BoreholeDeformation::none &&
      borehole_deformation != BoreholeDeformation::full)
    throw InputError("borehole_deformation = " + std::to_string(static_cast<int>(borehole_deformation)) +
                     ", allowed: biot, none, full");
  require_finite(source_x, "source_x");
  require_finite(source_y, "source_y");
}

BoreholeDeformation default_borehole_deformation(BoreholeStorage storage) {
  switch (storage) {
    case BoreholeStorage::none: return BoreholeDeformation::none;
    case BoreholeStorage::fluid: return BoreholeDeformation::full;
    case BoreholeStorage::biot_modulus: break;
  }
  return BoreholeDeformation::biot;
}

CrackAperture default_crack_aperture(FractureFlow law) {
  return law == FractureFlow::cubic ? CrackAperture::crack_normal : CrackAperture::axial;
}

FlowParameters flow_parameters_of(const hm::analytic::DimensionlessParameters& parameters, double dt,
                                  const FlowOptions& options) {
  FlowParameters flow;
  static_cast<FlowOptions&>(flow) = options;
  flow.Q = parameters.Q;
  flow.E_over_M = parameters.material.E_over_M;
  flow.E_over_Kw = parameters.E_over_Kw;
  flow.b = parameters.material.b;
  flow.iota = parameters.iota;
  flow.time_step = dt;
  return flow;
}

// The flow's matrix on its fixed pattern (storage on the diagonal, one symmetric pair per connection)
// and the linalg solver that factorises it: CHOLMOD's simplicial LDL' with nested dissection, the
// ordering and symbolic analysis once, a numeric refactorisation with the new values whenever the
// matrix changes (every coupling pass with a deforming lattice). Measured with bench_flow_solve on the
// Fig. 12 annulus: at N = 1e5 (2e5 unknowns) 0.20 s a factorisation and solve against 0.29 s for
// Eigen's SimplicialLDLT (AMD ordering, 20% more nonzeros in L), as fast at N = 1e4; CHOLMOD's
// supernodal LL' with the same ordering factorises as fast at N = 1e5 but solves 1.7x slower and
// factorises 2x slower at N = 1e4. Triangular solves on all threads (SubtreeSolve, bitwise the same x
// on any number of them). The solver does not check residuals: a solve with an older factor
// (reuse_factorisation) is refined by conjugate gradients against the current matrix here.
// The matrix keeps both triangles so that matrix-vector products need no symmetry handling.
SpdSolverOptions flow_solver_options() {
  SpdSolverOptions o;
  o.ordering = CholmodOrdering::nested_dissection;
  o.supernodal_factorization = false;
  o.reuse_forward_solve = false;  // every right-hand side is new
  o.check_residual = false;
  // Pivots span the conductances' range (iota up to 1e12), and a pass whose triangles inverted (negative
  // storage) is refused by the coupling's small-strain check, which names the cause: CHOLMOD's verdict only.
  o.check_pivots = false;
  return o;
}

struct FlowNetwork::Solver {
  using Matrix = Eigen::SparseMatrix<double>;
  Matrix matrix;
  std::vector<int> diagonal_slot;                   // value index of (k, k)
  std::vector<std::array<int, 4>> connection_slot;  // (s,s), (t,t), (s,t), (t,s); -1 where absent
  CholmodSolver factor{flow_solver_options()};
  Eigen::VectorXd factor_values;  // the matrix `factor` holds, for a restored network to refactorise

  // A numeric factorisation of `matrix` with `values`; an empty string on success.
  std::string factorise(const Eigen::VectorXd& values) {
    std::copy(values.data(), values.data() + values.size(), matrix.valuePtr());
    factor.update_values(matrix);
    if (factor.info() != Eigen::Success) return "flow matrix factorisation failed (not positive definite?)";
    return {};
  }
};

FlowNetwork::FlowNetwork(const Lattice& lattice, const DualGraph& dual, const FlowParameters& parameters)
    : parameters_(parameters) {
  parameters_.validate();
  n_triangles_ = lattice.n_triangles();
  const int n_beams = lattice.n_beams();
  assert(dual.triangle_area.size() == n_triangles_ && dual.conductance.size() == n_beams &&
         "dual graph of another lattice");
  crack_weight_ = Eigen::VectorXd::Zero(n_beams);

  // Wall beams, with their particles in the counter-clockwise order of their triangle (the hole on
  // the right), which makes the shoelace of the reversed edges the hole's area.
  for (int s = 0; s < n_triangles_; ++s)
    for (int k = 0; k < 3; ++k) {
      const int e = lattice.triangle_beams[static_cast<std::size_t>(s)][static_cast<std::size_t>(k)];
      if (lattice.is_boundary_beam(e) && lattice.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::inner) {
        const auto& tri = lattice.triangles[static_cast<std::size_t>(s)];
        wall_beams_.push_back({tri[static_cast<std::size_t>((k + 1) % 3)], tri[static_cast<std::size_t>((k + 2) % 3)]});
      }
    }
  has_borehole_ = !wall_beams_.empty();
  const int h = has_borehole_ ? n_triangles_ : -1;

  connections_.resize(static_cast<std::size_t>(n_beams));
  for (int e = 0; e < n_beams; ++e) {
    const auto [s, t] = lattice.beam_triangles[static_cast<std::size_t>(e)];
    Connection& c = connections_[static_cast<std::size_t>(e)];
    c.s = s;
    c.t = t >= 0 ? t : (lattice.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::inner ? h : -1);
  }

  if (!has_borehole_)
    source_triangle_ = source_triangle_of(lattice, Eigen::Vector2d(parameters_.source_x, parameters_.source_y));

  // Sparsity pattern: diagonal plus one symmetric pair per triangle-triangle or triangle-borehole
  // connection. Fixed for the life of the network.
  const int n = n_unknowns();
  solver_ = std::make_unique<Solver>();
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(static_cast<std::size_t>(n + 2 * n_beams));
  for (int k = 0; k < n; ++k) pattern.emplace_back(k, k, 1.0);
  for (const Connection& c : connections_)
    if (c.t >= 0) {
      pattern.emplace_back(c.s, c.t, 1.0);
      pattern.emplace_back(c.t, c.s, 1.0);
    }
  Solver::Matrix& a = solver_->matrix;
  a.resize(n, n);
  a.setFromTriplets(pattern.begin(), pattern.end());
  a.makeCompressed();
  auto slot = [&a](int row, int col) { return static_cast<int>(&a.coeffRef(row, col) - a.valuePtr()); };
  solver_->diagonal_slot.resize(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) solver_->diagonal_slot[static_cast<std::size_t>(k)] = slot(k, k);
  solver_->connection_slot.resize(connections_.size());
  for (std::size_t e = 0; e < connections_.size(); ++e) {
    const Connection& c = connections_[e];
    solver_->connection_slot[e] =
        c.t >= 0 ? std::array<int, 4>{slot(c.s, c.s), slot(c.t, c.t), slot(c.s, c.t), slot(c.t, c.s)}
                 : std::array<int, 4>{slot(c.s, c.s), -1, -1, -1};
  }
  update_geometry(dual, lattice.points);
  pressure_ = Eigen::VectorXd::Zero(n);
  trial_pressure_ = pressure_;
}

FlowNetwork::~FlowNetwork() = default;
FlowNetwork::FlowNetwork(FlowNetwork&&) noexcept = default;
FlowNetwork& FlowNetwork::operator=(FlowNetwork&&) noexcept = default;

void FlowNetwork::update_geometry(const DualGraph& dual, const Eigen::Matrix2Xd& positions) {
  assert(dual.triangle_area.size() == n_triangles_ && "dual graph of another lattice");
  assert(dual.conductance.size() == static_cast<Eigen::Index>(connections_.size()) && "dual graph of another lattice");
  assert(std::all_of(wall_beams_.begin(), wall_beams_.end(),
                     [&](const auto& w) { return std::max(w[0], w[1]) < positions.cols(); }) &&
         "one position per particle");
  triangle_area_ = dual.triangle_area;
  base_conductance_ = dual.conductance;
  inverse_flow_distance_ = dual.flow_distance.cwiseInverse();
  borehole_volume_ = 0.0;
  for (const auto& [i, j] : wall_beams_)
    borehole_volume_ += 0.5 * (positions(0, j) * positions(1, i) - positions(1, j) * positions(0, i));
  factor_stale_ = true;
}

void FlowNetwork::set_crack_weights(const Eigen::VectorXd& weights) {
  assert(weights.size() == static_cast<Eigen::Index>(connections_.size()) && "one weight per beam");
  assert((weights.array() >= 0.0).all() && (weights.array() <= 1.0).all() && "weights in [0, 1]");
  if (weights.size() == crack_weight_.size() && weights == crack_weight_) return;
  crack_weight_ = weights;
  factor_stale_ = true;
  // With iota = 1 a crack conducts as the rock (conductance(): exactly c), so the matrix is unchanged.
  if (parameters_.fracture_flow.law != FractureFlow::permeability || parameters_.iota != 1.0)
    ++crack_conductance_changes_;
}

void FlowNetwork::set_crack_openings(const Eigen::VectorXd& openings) {
  assert(openings.size() == static_cast<Eigen::Index>(connections_.size()) && "one opening per beam");
  assert(parameters_.fracture_flow.law == FractureFlow::cubic && "openings set the cubic law's apertures");
  if (openings.size() == crack_opening_.size() && openings == crack_opening_) return;
  crack_opening_ = openings;
  factor_stale_ = true;
  ++crack_conductance_changes_;
}

void FlowNetwork::set_slot_width(const std::vector<int>& beams, double width) {
  hm::core::require_finite(width, "slot width");
  hm::core::require_non_negative(width, "slot width");
  if (slot_width_.size() == 0) slot_width_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(connections_.size()));
  for (int e : beams) {
    if (e < 0 || e >= slot_width_.size())
      throw InputError("slot beam = " + std::to_string(e) + ", allowed: 0 <= beam < " +
                       std::to_string(slot_width_.size()));
    slot_width_[e] = width;
  }
  factor_stale_ = true;
  ++crack_conductance_changes_;
}

double FlowNetwork::crack_aperture(int beam) const {
  const double w = crack_weight_[beam];
  if (parameters_.fracture_flow.law != FractureFlow::cubic || w == 0.0) return 0.0;
  const double slot = slot_width_.size() == 0 ? 0.0 : slot_width_[beam];
  const double opening = crack_opening_.size() == 0 ? 0.0 : crack_opening_[beam];
  // The crack's share of the facet's opening: a softening beam's secant leaves 1 - s = w of its
  // elongation as inelastic (crack) opening, all of it once broken. A slot closes by at most its width.
  return w * (std::max(opening + slot, 0.0) + parameters_.fracture_flow.residual_aperture);
}

void FlowNetwork::set_broken(const std::vector<bool>& broken) {
  assert(broken.size() == connections_.size() && "one flag per beam");
  Eigen::VectorXd weights(static_cast<Eigen::Index>(broken.size()));
  for (std::size_t e = 0; e < broken.size(); ++e) weights[static_cast<Eigen::Index>(e)] = broken[e] ? 1.0 : 0.0;
  set_crack_weights(weights);
}

std::vector<std::vector<int>> FlowNetwork::crack_modes(const Eigen::VectorXd& weights) const {
  assert(weights.size() == static_cast<Eigen::Index>(connections_.size()) && "one weight per beam");
  // Union-find over the cracked beams' connections (the outer surface is not an unknown).
  std::vector<int> parent(static_cast<std::size_t>(n_unknowns()));
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int u) {
    while (parent[static_cast<std::size_t>(u)] != u)
      u = parent[static_cast<std::size_t>(u)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(u)])];
    return u;
  };
  std::vector<char> on_crack(parent.size(), 0);
  for (std::size_t e = 0; e < connections_.size(); ++e) {
    if (!(weights[static_cast<Eigen::Index>(e)] > 0.0)) continue;
    const int s = connections_[e].s, t = connections_[e].t;
    if (s >= 0) on_crack[static_cast<std::size_t>(s)] = 1;
    if (t >= 0) on_crack[static_cast<std::size_t>(t)] = 1;
    if (s >= 0 && t >= 0) parent[static_cast<std::size_t>(root(s))] = root(t);
  }
  std::vector<std::vector<int>> modes;
  std::vector<int> mode_of(parent.size(), -1);
  for (int u = 0; u < n_unknowns(); ++u) {
    if (!on_crack[static_cast<std::size_t>(u)]) continue;
    int& m = mode_of[static_cast<std::size_t>(root(u))];
    if (m < 0) m = static_cast<int>(modes.size()), modes.emplace_back();
    modes[static_cast<std::size_t>(m)].push_back(u);
  }
  return modes;
}

void FlowNetwork::set_pressure(const Eigen::VectorXd& pressure) {
  assert(pressure.size() == n_unknowns() && "one pressure per unknown");
  pressure_ = pressure;
  has_trial_ = false;
}

double FlowNetwork::conductance(int beam) const {
  const double c = base_conductance_[beam];
  // Rock and crack side by side on the facet; the ends exactly c and iota c.
  const double w = crack_weight_[beam];
  if (w == 0.0) return c;
  if (parameters_.fracture_flow.law == FractureFlow::transmissivity)
    return c + w * parameters_.fracture_flow.transmissivity * inverse_flow_distance_[beam];
  if (parameters_.fracture_flow.law == FractureFlow::cubic) {
    // Parallel plates (Eqs. 25-26): a^3/12 per unit pressure gradient, over the rock's k (both per R).
    const double a = crack_aperture(beam);
    return c + a * a * a / (12.0 * parameters_.fracture_flow.permeability) * inverse_flow_distance_[beam];
  }
  return w == 1.0 ? parameters_.iota * c : (1.0 + w * (parameters_.iota - 1.0)) * c;
}

double FlowNetwork::borehole_storage_coefficient() const {
  switch (parameters_.borehole_storage) {
    case BoreholeStorage::biot_modulus: return parameters_.E_over_M * borehole_volume_;
    case BoreholeStorage::fluid: return parameters_.E_over_Kw * borehole_volume_;
    case BoreholeStorage::none: break;
  }
  return 0.0;
}

double FlowNetwork::borehole_deformation_coefficient() const {
  switch (parameters_.borehole_deformation) {
    case BoreholeDeformation::biot: return parameters_.b;
    case BoreholeDeformation::full: return 1.0;
    case BoreholeDeformation::none: break;
  }
  return 0.0;
}

void FlowNetwork::assemble_values(double dt, double storage_scale, Eigen::VectorXd& values) const {
  values = Eigen::VectorXd::Zero(solver_->matrix.nonZeros());
  for (int s = 0; s < n_triangles_; ++s)
    values[solver_->diagonal_slot[static_cast<std::size_t>(s)]] =
        storage_scale * parameters_.E_over_M * triangle_area_[s];
  if (has_borehole_)
    values[solver_->diagonal_slot[static_cast<std::size_t>(n_triangles_)]] =
        storage_scale * borehole_storage_coefficient();
  for (std::size_t e = 0; e < connections_.size(); ++e) {
    const double g = dt * conductance(static_cast<int>(e));
    const auto& slot = solver_->connection_slot[e];
    values[slot[0]] += g;
    if (slot[1] >= 0) {
      values[slot[1]] += g;
      values[slot[2]] -= g;
      values[slot[3]] -= g;
    }
  }
}

std::string FlowNetwork::factorise(double dt) {
  Eigen::VectorXd values;
  assemble_values(dt, 1.0, values);
  const std::string error = solver_->factorise(values);
  solver_->factor_values = std::move(values);
  factorised_dt_ = error.empty() ? dt : -1.0;
  factor_stale_ = false;
  factorised_conductances_ = crack_conductance_changes_;
  refresh_factor_ = false;
  return error;
}

void FlowNetwork::save_state(core::StateWriter& w) const {
  assert(!has_trial_ && "a state between steps");
  w.put("flow.triangle_area", triangle_area_);
  w.put("flow.base_conductance", base_conductance_);
  w.put("flow.inverse_flow_distance", inverse_flow_distance_);
  w.put("flow.borehole_volume", borehole_volume_);
  w.put("flow.crack_weight", crack_weight_);
  w.put("flow.crack_opening", crack_opening_);
  w.put("flow.pressure", pressure_);
  w.put("flow.charged_ahead", charged_ahead_);
  w.put("flow.totals", std::vector<double>{totals_.time, totals_.injected, totals_.storage, totals_.deformation,
                                           totals_.outflow, static_cast<double>(totals_.n_steps)});
  w.put("flow.matrix_values",
        std::vector<double>(solver_->matrix.valuePtr(), solver_->matrix.valuePtr() + solver_->matrix.nonZeros()));
  w.put("flow.factor_values", solver_->factor_values);
  w.put("flow.factorised_dt", factorised_dt_);
  w.put("flow.factor_stale", factor_stale_);
  w.put("flow.refresh_factor", refresh_factor_);
}

void FlowNetwork::restore_state(core::StateReader& r) {
  const auto fail = [&](const char* tag) { throw InputError(r.source() + ": at '" + tag + "': wrong size"); };
  r.get("flow.triangle_area", triangle_area_);
  r.get("flow.base_conductance", base_conductance_);
  if (triangle_area_.size() != n_triangles_) fail("flow.triangle_area");
  if (base_conductance_.size() != static_cast<Eigen::Index>(connections_.size())) fail("flow.base_conductance");
  r.get("flow.inverse_flow_distance", inverse_flow_distance_);
  if (inverse_flow_distance_.size() != base_conductance_.size()) fail("flow.inverse_flow_distance");
  if (!(inverse_flow_distance_.array() > 0.0).all() || !inverse_flow_distance_.allFinite())
    throw InputError(r.source() + ": at 'flow.inverse_flow_distance': a value not positive and finite");
  r.get("flow.borehole_volume", borehole_volume_);
  r.get("flow.crack_weight", crack_weight_);
  if (crack_weight_.size() != static_cast<Eigen::Index>(connections_.size())) fail("flow.crack_weight");
  if (!((crack_weight_.array() >= 0.0).all() && (crack_weight_.array() <= 1.0).all()))
    throw InputError(r.source() + ": at 'flow.crack_weight': a weight outside [0, 1]");
  r.get("flow.crack_opening", crack_opening_);
  if (crack_opening_.size() != 0 && crack_opening_.size() != crack_weight_.size()) fail("flow.crack_opening");
  if (!crack_opening_.allFinite()) throw InputError(r.source() + ": at 'flow.crack_opening': a value not finite");
  r.get("flow.pressure", pressure_);
  if (pressure_.size() != n_unknowns()) fail("flow.pressure");
  r.get("flow.charged_ahead", charged_ahead_);
  if (charged_ahead_.size() != 0 && charged_ahead_.size() != n_unknowns()) fail("flow.charged_ahead");
  std::vector<double> totals;
  r.get("flow.totals", totals);
  if (totals.size() != 6) fail("flow.totals");
  totals_ = {totals[0], totals[1], totals[2], totals[3], totals[4], static_cast<int>(totals[5])};
  std::vector<double> values;
  r.get("flow.matrix_values", values);
  Eigen::VectorXd factor_values;
  r.get("flow.factor_values", factor_values);
  const auto nnz = static_cast<std::size_t>(solver_->matrix.nonZeros());
  if (values.size() != nnz) fail("flow.matrix_values");
  if (factor_values.size() != 0 && static_cast<std::size_t>(factor_values.size()) != nnz) fail("flow.factor_values");
  r.get("flow.factorised_dt", factorised_dt_);
  r.get("flow.factor_stale", factor_stale_);
  // Not saved: a step that changes the cracks solves the flow after, which factorises when it is
  // stabilised, so between steps the factor knows the cracks wherever that is read. The count moves on,
  // so that no stabiliser's Z from before the restore is taken for current.
  factorised_conductances_ = ++crack_conductance_changes_;
  r.get("flow.refresh_factor", refresh_factor_);
  // The factor is a function of the matrix it was computed from: refactorising those values gives it
  // bitwise (a reused factor may be older than the current matrix, which is restored after it).
  if (factorised_dt_ >= 0.0) {
    const std::string error = solver_->factorise(factor_values);
    if (!error.empty()) throw std::runtime_error("restoring the flow network: " + error);
  }
  solver_->factor_values = std::move(factor_values);
  std::copy(values.begin(), values.end(), solver_->matrix.valuePtr());
  has_trial_ = false;
}

std::string FlowNetwork::factorise_if_needed(double dt) {
  if (factorised_dt_ == dt && (!factor_stale_ || (parameters_.reuse_factorisation && !refresh_factor_))) {
    if (factor_stale_) {  // the current matrix for the refinement's residuals; the factor stays
      Eigen::VectorXd values;
      assemble_values(dt, 1.0, values);
      std::copy(values.data(), values.data() + values.size(), solver_->matrix.valuePtr());
    }
    return {};
  }
  return factorise(dt);
}

Eigen::VectorXd FlowNetwork::stabilised(double dt, const Eigen::VectorXd& plain, FlowStabiliser& stabiliser) {
  // (A + A Z W^T) p = rhs + A Z W^T p_ref, W^T x summing x over a mode's unknowns, with Z = A_f^-1 V
  // solved with the factor at hand (A_f = A when it is fresh, so that A Z = V). Divided by A:
  // (I + Z W^T) p = y with y = A^-1 rhs + Z W^T p_ref (A^-1 rhs = plain, from the factor or its
  // CG refinement), and by Woodbury p = y - Z (I + W^T Z)^-1 W^T y.
  const auto k = static_cast<Eigen::Index>(stabiliser.modes.size());
  assert(stabiliser.volume_response.cols() == k && stabiliser.volume_response.rows() == n_unknowns() &&
         "one volume response per mode");
  if (stabiliser.solved_dt != dt || stabiliser.solved_conductances != crack_conductance_changes_ ||
      stabiliser.solved_response.cols() != k || stabiliser.solved_response.rows() != n_unknowns() ||
      stabiliser.solved.size() != static_cast<std::size_t>(k)) {
    stabiliser.solved_response = Eigen::MatrixXd::Zero(n_unknowns(), k);
    stabiliser.solved.assign(static_cast<std::size_t>(k), 0);
    stabiliser.solved_dt = dt;
    stabiliser.solved_conductances = crack_conductance_changes_;
  }
  for (Eigen::Index c = 0; c < k; ++c) {
    if (stabiliser.solved[static_cast<std::size_t>(c)]) continue;
    stabiliser.solved_response.col(c) = solver_->factor.solve(Eigen::VectorXd(stabiliser.volume_response.col(c)));
    stabiliser.solved[static_cast<std::size_t>(c)] = 1;
  }
  const Eigen::MatrixXd& Z = stabiliser.solved_response;
  auto mode_sums = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd s = Eigen::VectorXd::Zero(k);
    for (Eigen::Index c = 0; c < k; ++c)
      for (int u : stabiliser.modes[static_cast<std::size_t>(c)]) s[c] += x[u];
    return s;
  };
  const Eigen::VectorXd y = plain + Z * mode_sums(stabiliser.reference_pressure);
  Eigen::MatrixXd capacitance = Eigen::MatrixXd::Identity(k, k);
  for (Eigen::Index c = 0; c < k; ++c) capacitance.col(c) += mode_sums(Z.col(c));
  return y - Z * capacitance.partialPivLu().solve(mode_sums(y));
}

Eigen::VectorXd FlowNetwork::deformation(const Eigen::VectorXd& volume_change) const {
  const int n = n_unknowns();
  // The b (V^{n+1} - V^n) terms; the borehole's is dropped when it is a plain flux boundary and not
  // weighted by b when the hole is taken as all fluid.
  Eigen::VectorXd deformation =
      volume_change.size() > 0 ? Eigen::VectorXd(parameters_.b * volume_change) : Eigen::VectorXd::Zero(n);
  if (parameters_.crack_coupling == CrackCoupling::full && volume_change.size() > 0)
    for (std::size_t e = 0; e < connections_.size(); ++e) {
      // A crack's triangles: the caller's volume is already the crack's (weight 1).
      if (!(crack_weight_[static_cast<Eigen::Index>(e)] > 0.0)) continue;
      for (const int u : {connections_[e].s, connections_[e].t})
        if (u >= 0 && u < n_triangles_) deformation[u] = volume_change[u];
    }
  if (has_borehole_)
    deformation[n_triangles_] =
        borehole_deformation_coefficient() * (volume_change.size() > 0 ? volume_change[n_triangles_] : 0.0);
  return deformation;
}

namespace {

// Conjugate gradients on A from x, preconditioned by `solve` (the last factor's), until the residual's
// norm is at most target or after max_iterations; counts the iterations, returns the residual's norm.
template <class Solve>
double preconditioned_cg(const Eigen::SparseMatrix<double>& A, const Solve& solve, const Eigen::VectorXd& rhs,
                         double target, int max_iterations, Eigen::VectorXd& x, int& iterations) {
  Eigen::VectorXd residual = rhs - A * x;
  Eigen::VectorXd z = solve(residual);
  Eigen::VectorXd direction = z;
  double rz = residual.dot(z);
  while (residual.norm() > target && iterations < max_iterations) {
    const Eigen::VectorXd Ad = A * direction;
    const double alpha = rz / direction.dot(Ad);
    x += alpha * direction;
    residual -= alpha * Ad;
    ++iterations;
    z = solve(residual);
    const double rz_next = residual.dot(z);
    direction = z + (rz_next / rz) * direction;
    rz = rz_next;
  }
  return residual.norm();
}

}  // namespace

FlowStepSummary FlowNetwork::solve(double dt, const Eigen::VectorXd& volume_change, FlowStabiliser* stabiliser) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("dt = " + format_value(dt) + ", allowed: > 0, finite");
  assert((volume_change.size() == 0 || volume_change.size() == n_unknowns()) && "one volume change per unknown");
  const int n = n_unknowns();
  FlowStepSummary summary;
  summary.time = totals_.time + dt;
  summary.dt = dt;
  summary.injected = injected_volume(parameters_.Q, parameters_.injection_ramp_time, totals_.time, dt);
  has_trial_ = false;
  const bool factor_current = factorised_dt_ == dt && !factor_stale_;  // reused as it is, no factorisation
  // A stabiliser's A^-1 V comes from the factor at hand, which must know the cracks as they are: with
  // an older factor a changed crack would put A (A^-1 V) far from V, by up to iota times.
  summary.message =
      stabiliser && factorised_conductances_ != crack_conductance_changes_ ? factorise(dt) : factorise_if_needed(dt);
  if (!summary.message.empty()) return summary;

  Eigen::VectorXd storage_coefficient(n);
  storage_coefficient.head(n_triangles_) = parameters_.E_over_M * triangle_area_;
  if (has_borehole_) storage_coefficient[n_triangles_] = borehole_storage_coefficient();

  const Eigen::VectorXd deformation = this->deformation(volume_change);
  Eigen::VectorXd rhs = storage_coefficient.cwiseProduct(pressure_) - deformation;
  rhs[has_borehole_ ? n_triangles_ : source_triangle_] += summary.injected;
  if (charged_ahead_.size() > 0) {
    rhs += charged_ahead_;
    summary.resupplied = charged_ahead_.sum();
  }

  summary.factorised = !factor_current && !factor_stale_;
  trial_pressure_ = solver_->factor.solve(rhs);
  if (factor_stale_) {
    // Conjugate gradients on the current matrix, preconditioned by the last factor
    // (reuse_factorisation): fewer iterations than plain iterative refinement at tolerance 1e-10
    // (~8 against ~12 on a fracturing annulus at N = 1e4, with fewer fallbacks).
    const double target = parameters_.refinement_tolerance * rhs.norm();
    const double residual = preconditioned_cg(
        solver_->matrix, [&](const Eigen::VectorXd& r) { return solver_->factor.solve(r); }, rhs, target,
        parameters_.max_refinements, trial_pressure_, summary.refinements);
    refresh_factor_ = summary.refinements > parameters_.refresh_after_refinements;
    if (!(residual <= target)) {  // too far from the factor: a fresh one
      summary.message = factorise(dt);
      if (!summary.message.empty()) return summary;
      summary.factorised = true;
      trial_pressure_ = solver_->factor.solve(rhs);
    }
  }
  trial_charged_ahead_.resize(0);
  if (stabiliser) {
    trial_pressure_ = stabilised(dt, trial_pressure_, *stabiliser);
    trial_charged_ahead_ = rhs - solver_->matrix * trial_pressure_;
    summary.charged_ahead = trial_charged_ahead_.sum();
  }
  if (solver_->factor.info() != Eigen::Success || !trial_pressure_.allFinite()) {
    summary.message = "flow solve failed";
    return summary;
  }

  summary.storage = storage_coefficient.dot(trial_pressure_ - pressure_);
  summary.deformation = deformation.sum();
  summary.outflow = dt * outflow_rate(trial_pressure_);
  summary.balance_error =
      relative_imbalance(totals_.injected + summary.injected, totals_.storage + summary.storage,
                         totals_.deformation + summary.deformation, totals_.outflow + summary.outflow);
  summary.solved = true;
  trial_summary_ = summary;
  has_trial_ = true;
  return summary;
}

void FlowNetwork::accept() {
  assert(has_trial_ && "accept() needs a successful solve()");
  pressure_ = trial_pressure_;
  charged_ahead_ = std::move(trial_charged_ahead_);
  trial_charged_ahead_.resize(0);
  totals_.time = trial_summary_.time;
  totals_.injected += trial_summary_.injected;
  totals_.storage += trial_summary_.storage;
  totals_.deformation += trial_summary_.deformation;
  totals_.outflow += trial_summary_.outflow;
  ++totals_.n_steps;
  has_trial_ = false;
}

FlowStepSummary FlowNetwork::step(const Eigen::VectorXd& volume_change) {
  return step(parameters_.time_step, volume_change);
}

FlowStepSummary FlowNetwork::step(double dt, const Eigen::VectorXd& volume_change) {
  FlowStepSummary summary = solve(dt, volume_change);
  if (summary.is_ok()) accept();
  return summary;
}

FlowSteadyState FlowNetwork::solve_steady_state() const {
  FlowSteadyState steady;
  steady.injected_rate = parameters_.Q;
  Solver steady_solver;  // the transient factor stays as it is
  steady_solver.matrix = solver_->matrix;
  Eigen::VectorXd values;
  assemble_values(1.0, 0.0, values);
  steady.message = steady_solver.factorise(values);
  if (!steady.message.empty()) return steady;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n_unknowns());
  rhs[has_borehole_ ? n_triangles_ : source_triangle_] = parameters_.Q;
  steady.pressure = steady_solver.factor.solve(rhs);
  if (steady_solver.factor.info() != Eigen::Success || !steady.pressure.allFinite()) {
    steady.message = "steady flow solve failed";
    return steady;
  }
  steady.outflow_rate = outflow_rate(steady.pressure);
  steady.balance_error = relative_imbalance(steady.injected_rate, 0.0, 0.0, steady.outflow_rate);
  steady.solved = true;
  return steady;
}

Eigen::VectorXd FlowNetwork::beam_flow_rate(const Eigen::VectorXd& pressure) const {
  assert(pressure.size() == n_unknowns() && "one pressure per unknown");
  Eigen::VectorXd rate(static_cast<Eigen::Index>(connections_.size()));
  for (std::size_t e = 0; e < connections_.size(); ++e) {
    const Connection& c = connections_[e];
    const double p_other = c.t >= 0 ? pressure[c.t] : 0.0;
    rate[static_cast<Eigen::Index>(e)] = conductance(static_cast<int>(e)) * (pressure[c.s] - p_other);
  }
  return rate;
}

Eigen::VectorXd FlowNetwork::net_inflow_rate(const Eigen::VectorXd& pressure) const {
  const Eigen::VectorXd rate = beam_flow_rate(pressure);
  Eigen::VectorXd inflow = Eigen::VectorXd::Zero(n_unknowns());
  for (std::size_t e = 0; e < connections_.size(); ++e) {
    const Connection& c = connections_[e];
    inflow[c.s] -= rate[static_cast<Eigen::Index>(e)];
    if (c.t >= 0) inflow[c.t] += rate[static_cast<Eigen::Index>(e)];
  }
  return inflow;
}

double FlowNetwork::outflow_rate(const Eigen::VectorXd& pressure) const {
  assert(pressure.size() == n_unknowns() && "one pressure per unknown");
  double rate = 0.0;
  for (std::size_t e = 0; e < connections_.size(); ++e)
    if (connections_[e].t < 0) rate += conductance(static_cast<int>(e)) * pressure[connections_[e].s];
  return rate;
}

}  // namespace hm::lattice2d
