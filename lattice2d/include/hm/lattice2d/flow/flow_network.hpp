#pragma once
/// \file
/// The dual-graph flow network of Section 2.2 (Eqs. 15-16, Fig. 4): one pressure per Delaunay
/// triangle at its Voronoi connection point, Darcy flow along the Voronoi segments, implicit Euler in
/// time, p = 0 at the outer surface, the borehole as one node (annulus) or a point source in the
/// triangle holding the source point (disk, rectangle). Dimensionless (Eq. 14); choices the paper
/// leaves open are in docs/flow.md.
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "hm/analytic/physical_parameters.hpp"
#include "hm/core/enum_names.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/linalg/spd_solver.hpp"

namespace hm::lattice2d {

/// Whether the borehole node stores fluid through pressure (the storage term of Eq. 16).
enum class BoreholeStorage {
  biot_modulus,  ///< (E/M) V_h (p_h^{n+1} - p_h^n), Eq. 16 as printed (dimensionless form); default
  none,          ///< no storage term: the borehole only passes Q on (Appendix A / fdm1d's choice)
  fluid,         ///< (E/K_w) V_h (p_h^{n+1} - p_h^n): a hole filled with water, compressed as water
};
constexpr auto enum_names(BoreholeStorage) {
  return core::enum_table<BoreholeStorage>({{BoreholeStorage::biot_modulus, "biot-modulus"},
                                            {BoreholeStorage::none, "none"},
                                            {BoreholeStorage::fluid, "fluid"}});
}

/// Whether the borehole node takes the deformation term of Eq. 16, -b (V_h^{n+1} - V_h^n).
enum class BoreholeDeformation {
  biot,  ///< Eq. 16 as printed: the borehole's area change weighted by b, like a triangle's; default
  none,  ///< no term: the borehole is a flux boundary that passes Q on (Appendix A / fdm1d's choice)
  full,  ///< -(V_h^{n+1} - V_h^n): the hole holds only fluid, so all of its area change is fluid volume
};
constexpr auto enum_names(BoreholeDeformation) {
  return core::enum_table<BoreholeDeformation>(
      {{BoreholeDeformation::biot, "biot"}, {BoreholeDeformation::none, "none"}, {BoreholeDeformation::full, "full"}});
}

/// The Biot coefficient that couples a crack to its fluid: the weight of the volume change of the
/// triangles along a broken beam (Eq. 15) and of the pressure force on the broken beam's Voronoi
/// segment (Eq. 17, CoupledModel).
enum class CrackCoupling {
  biot,  ///< b, as for the intact rock: Eqs. 15 and 17 as printed; default
  full,  ///< 1: an open crack is a fluid-filled void, its faces carry the full p and its opening is fluid
};
constexpr auto enum_names(CrackCoupling) {
  return core::enum_table<CrackCoupling>({{CrackCoupling::biot, "biot"}, {CrackCoupling::full, "full"}});
}

/// How a crack (a broken beam's Voronoi segment) conducts.
enum class FractureFlow {
  /// iota times the rock's A/d (Eq. 24): the crack's transmissivity is iota k times the beam length,
  /// so it falls with the beam length as N grows. The paper's choice; default.
  permeability,
  /// The rock's A/d plus T/d: a crack of its own transmissivity T (k_f w over k R, dimensionless) in
  /// the facet beside the rock, the same whatever the beam length.
  transmissivity,
  /// The rock's A/d plus the parallel plates' a^3/(12 k R) / d (Eqs. 25-26, the cubic law): the crack's
  /// transmissivity from its aperture a = w (opening + residual), w its crack weight.
  cubic,
};
constexpr auto enum_names(FractureFlow) {
  return core::enum_table<FractureFlow>({{FractureFlow::permeability, "permeability"},
                                         {FractureFlow::transmissivity, "transmissivity"},
                                         {FractureFlow::cubic, "cubic"}});
}

/// Which opening of a crack's facet is the cubic law's aperture. Both give the same fluid volume (the
/// charged volume is the axial opening times the facet, work-conjugate with the face force); they
/// differ where a facet is inclined to the crack it belongs to (docs/flow.md, "The cubic law on a lattice
/// crack").
enum class CrackAperture {
  /// The axial opening (u_j - u_i).n, the gap normal to the facet. A facet inclined at theta to a crack
  /// opened by w gets w cos(theta): the zig-zag path of a straight cut conducts 4-7% of w^3/12.
  axial,
  /// The length of the facet's displacement jump at the beam's midpoint (the axial opening and the slide
  /// beside it) where the facet is open, the axial opening where it is closed: w on every facet of a
  /// crack opened by w, so a straight cut conducts w^3/12 over its Voronoi path's tortuosity (0.78).
  /// Discontinuous where a sliding facet opens (0 to its whole slide).
  jump,
  /// The facet's displacement jump along the crack's local normal (the normal of the chord through the
  /// facet and the cracked facets that share its ends), or the axial opening where that is larger: ~w on
  /// a crack opened by w, ~0 on a crack sliding along itself, and continuous in the displacements.
  crack_normal,
};
constexpr auto enum_names(CrackAperture) {
  return core::enum_table<CrackAperture>(
      {{CrackAperture::axial, "axial"}, {CrackAperture::jump, "jump"}, {CrackAperture::crack_normal, "crack_normal"}});
}

/// A crack's conduction: the law, and its transmissivity where the law has one.
struct FractureFlowSpec {
  FractureFlow law = FractureFlow::permeability;
  /// T = k_f w / (k R): the crack's permeability times its aperture over the rock's permeability times
  /// R, the flux along a unit pressure gradient per unit thickness, over the rock's per unit R.
  /// Used with law = transmissivity. Allowed: finite, >= 0.
  double transmissivity = 0.0;
  /// k / R^2, the rock's permeability over the domain radius squared: the cubic law's scale (an
  /// aperture a conducts a^3/12 where the rock conducts k, so over the rock's per unit R it is
  /// a^3 / (12 k R) = (a/R)^3 / (12 k / R^2)). Used with law = cubic. Allowed: finite, > 0.
  double permeability = 0.0;
  /// w_r / R, the residual aperture of a crack: a crack closed by its contact still conducts as a
  /// plate this wide, so a pinched point does not block it. Used with law = cubic. Allowed: finite, >= 0.
  double residual_aperture = 0.0;
  /// The opening that is the cubic law's aperture. Used with law = cubic; a case's default is
  /// default_crack_aperture(law).
  CrackAperture aperture = CrackAperture::axial;
};

/// How the flow network models the borehole and the cracks and how it solves: the [flow] table's
/// choices, the physics aside. Every default is set here; FlowParameters::validate() checks each rule.
struct FlowOptions {
  /// How broken beams' segments conduct: iota (the paper) or a transmissivity of the crack's own.
  FractureFlowSpec fracture_flow;
  /// Borehole storage (Eq. 16). Default: the paper's Eq. 16; see docs/flow.md.
  BoreholeStorage borehole_storage = BoreholeStorage::biot_modulus;
  /// Borehole deformation term (Eq. 16). Default: the paper's Eq. 16 (default_borehole_deformation of
  /// the default storage). With borehole_storage = none and this = none the borehole node is the 1D
  /// model's flux boundary; see docs/flow.md.
  BoreholeDeformation borehole_deformation = BoreholeDeformation::biot;
  /// Coupling of broken beams' triangles and segments: b or 1 (CrackCoupling). Default: b (Eq. 15).
  CrackCoupling crack_coupling = CrackCoupling::biot;
  /// After a geometry or iota change with the same dt (every pass of the coupling loop), solve by
  /// conjugate gradients on the current matrix preconditioned by the last factorisation instead of
  /// refactorising (a refactorisation follows when max_refinements iterations do not reach the
  /// tolerance). Default false, a factorisation per solve; the shipped cases reuse, which pays with
  /// refresh_after_refinements (below): an old factor alone needs ~8 iterations per solve once cracks
  /// open and change their triangles' areas.
  bool reuse_factorisation = false;
  /// Stop iterating at ||rhs - A p|| <= refinement_tolerance ||rhs||. Our choice 1e-10 (the volume
  /// balance then closes to ~1e-11). Allowed: 0 < refinement_tolerance < 1e-6.
  double refinement_tolerance = 1e-10;
  /// Iterations before falling back to a refactorisation. Our choice 20. Allowed: >= 1.
  int max_refinements = 20;
  /// With reuse_factorisation: a solve that needed more iterations than this refactorises at the next
  /// solve, so the factor follows the geometry instead of aging until max_refinements. Our choice 4:
  /// the Fig. 12 run at N = 1e4 spends 12.4 s in the flow refactorising every pass, 10.2 s reusing with
  /// no refresh (the old factor ages: ~8 iterations), 7.8 / 6.5 / 7.8 s with 2 / 4 / 8 (same breaks in
  /// the same order; volume balance <= 5e-12). Allowed: >= 0.
  int refresh_after_refinements = 4;
  /// The injection rate rises linearly from 0 at t = 0 to Q at this time, then stays at Q; 0: Q from
  /// the start (the paper's). A slow start keeps a fracture that starts at zero length from the
  /// pressures of its first instants (the viscosity-dominated crack's inlet pressure grows as its length
  /// shrinks; docs/flow.md). Allowed: >= 0, finite.
  double injection_ramp_time = 0.0;
  /// Point-source position (x, y) for a domain without borehole (Section 3.1: r = 0). Our choice to
  /// make it a field; the source goes into the triangle containing it. Allowed: finite, inside the
  /// lattice (checked by FlowNetwork).
  double source_x = 0.0;
  double source_y = 0.0;
};

/// Parameters of the flow network: the physics of Eqs. 14-16 and the options. Every default is set
/// here; validate() checks each rule.
struct FlowParameters : FlowOptions {
  /// Q, dimensionless injection rate (Eq. 14, Q = mu q/(k E)), into the borehole node (annulus) or
  /// the source triangle (disk, rectangle). Allowed: finite, >= 0.
  double Q = 0.01;
  /// E/M, storage coefficient of Eqs. 14-16 (the paper prints V/M; Eq. 14 and docs/errata.md E11
  /// give E/M in dimensionless form). Default: Eq. 22 with Table 1 at b = 0.5. Allowed: > 0, finite.
  double E_over_M = hm::analytic::E_over_M_table1(0.5, 0.25);
  /// b, Biot coefficient multiplying the volume change V^{n+1} - V^n in Eqs. 15-16.
  /// Allowed: 0 <= b <= 1.
  double b = 0.5;
  /// E/K_w, the borehole water's storage coefficient with borehole_storage = fluid (dimensionless:
  /// fluid volume stored per unit pressure over E, per unit hole volume). Default Table 1's
  /// E = 1e10 Pa over K_w = 2.2e9 Pa. Allowed: > 0, finite.
  double E_over_Kw = hm::analytic::table1_E_over_Kw;
  /// iota = k_f/k, conductance factor of Voronoi segments crossing broken beams (Section 2.2), with
  /// fracture_flow.law = permeability. Allowed: > 0, finite.
  double iota = 1.0;
  /// Delta t, the default time step of step() (Eq. 15). Allowed: > 0, finite.
  double time_step = 1e-5;

  /// Throws hm::InputError "field = value, allowed: rule" for the first violated rule.
  void validate() const;
};

/// The borehole deformation term that goes with a borehole storage: Eq. 16's b dV_h with its storage,
/// the full dV_h with the water-filled hole's (fluid), none without. With no storage p_h is set by b dV_h alone and the
/// coupling loop through the borehole node does not converge (docs/coupling.md, section 3), so a case reader takes this
/// as the default.
BoreholeDeformation default_borehole_deformation(BoreholeStorage storage);

/// The aperture that goes with a crack flow law: the jump along the crack's local normal for the cubic
/// law (with the axial opening a straight lattice crack conducts a few per cent of the parallel plates,
/// and the jump is discontinuous where a facet opens: docs/flow.md), the axial opening, unused, for the
/// others. A case reader takes this as the default.
CrackAperture default_crack_aperture(FractureFlow law);

/// The options of the flow network's CholmodSolver (flow_network.cpp says why each).
SpdSolverOptions flow_solver_options();

/// The flow parameters of a shared dimensionless parameter set (Q, iota, E/M, E/K_w, b) with time step
/// dt and the given options.
FlowParameters flow_parameters_of(const hm::analytic::DimensionlessParameters& parameters, double dt,
                                  const FlowOptions& options = {});

/// Volumes moved in one step, all >= 0 unless said otherwise (dimensionless areas, Eq. 12's
/// "volume per unit length"). injected = storage + deformation + outflow up to round-off.
/// A coupling iteration's estimate of how the deformation term answers the pressure: modes c (each a
/// set of unknowns under one uniform pressure, e.g. a crack) whose unit pressure changes the
/// deformation by column c of volume_response. solve() then solves (A + V W^T) p = rhs + V W^T p_ref,
/// W^T summing over each mode's unknowns: at p = p_ref the added terms cancel, so the coupled fixed
/// point is unchanged, while a pass already sees the crack's compliance (as the fixed-stress split
/// sees the rock's). Without it a fluid-filled crack, whose compliance is thousands of times its
/// fluid's storage, makes the split diverge.
///
/// solve() computes Z = A_f^-1 V with the factor at hand, column by column where a column is not
/// solved yet, and keeps it; every solve of the same dt takes A Z as the response, A being its own
/// matrix: V itself while the factor is that of the matrix, a nearby response once the deformed
/// geometry has moved the matrix (or the factor is an older one, reuse_factorisation), at one solve
/// per pass instead of one per mode. The fixed point is the same either way. A change of the cracks'
/// conductances (iota != 1) refactorises and solves every column again: an older Z would put A Z far
/// from V, by up to iota times a facet's conductance.
struct FlowStabiliser {
  Eigen::MatrixXd volume_response;      ///< V: n_unknowns x n_modes
  std::vector<std::vector<int>> modes;  ///< the unknowns of each mode
  Eigen::VectorXd reference_pressure;   ///< p_ref: the pressure the mechanics was solved with
  Eigen::MatrixXd solved_response;      ///< Z: n_unknowns x n_modes where solved
  std::vector<char> solved;             ///< per mode: its column of Z is A_f^-1 V for solved_dt
  double solved_dt = -1.0;              ///< the dt of those solves (another dt solves again)
  long solved_conductances = -1;        ///< FlowNetwork::crack_conductance_changes() at those solves
};

struct FlowStepSummary {
  double time = 0.0;         ///< t^{n+1}
  double dt = 0.0;           ///< Delta t of this step
  double injected = 0.0;     ///< Q dt
  double storage = 0.0;      ///< sum (E/M) V^{n+1} (p^{n+1} - p^n), borehole included if it stores (signed)
  double deformation = 0.0;  ///< b sum (V^{n+1} - V^n), triangles and (unless its term is off) borehole (signed)
  double outflow = 0.0;      ///< sum over outer segments dt (A/d_su) (p_s^{n+1} - 0) (signed)
  /// Fluid the crack stabiliser charged to cracks ahead of their opening, V W^T (p - p_ref) = rhs - A p
  /// summed over unknowns (signed; 0 without a stabiliser): in neither storage nor deformation, it is
  /// missing from this step's balance, and the next step supplies it again, unknown by unknown, when the
  /// mechanics opens the crack for it. So the stabiliser shifts fluid by one step and loses none.
  double charged_ahead = 0.0;
  double resupplied = 0.0;  ///< the previous step's charged_ahead, added to this step's supply
  /// The run's volume balance after this step (FlowTotals with this step added):
  /// |injected - storage - deformation - outflow| / (|injected| + |storage| + |deformation| + |outflow|),
  /// 0 when all four vanish. Round-off, plus the last step's charged_ahead.
  double balance_error = 0.0;
  bool solved = false;      ///< the factorisation and solve succeeded
  bool factorised = false;  ///< this solve factorised the matrix (else it reused the last factor)
  int refinements = 0;      ///< preconditioned CG iterations with a reused factor
  std::string message;      ///< empty when solved, else what went wrong (numerical trouble, not thrown)
  bool is_ok() const { return solved; }
};

/// Running totals since the initial state (sums of the accepted steps' FlowStepSummary fields).
struct FlowTotals {
  double time = 0.0;
  double injected = 0.0;  ///< = Q t
  double storage = 0.0;
  double deformation = 0.0;
  double outflow = 0.0;
  int n_steps = 0;
};

/// Steady state (no storage, no deformation): K p = source with the same conductances.
struct FlowSteadyState {
  Eigen::VectorXd pressure;    ///< one value per unknown (triangles, then the borehole node)
  double injected_rate = 0.0;  ///< Q
  double outflow_rate = 0.0;   ///< sum over outer segments (A/d_su) p_s
  double balance_error = 0.0;  ///< |Q - outflow| / Q (0 if Q = 0)
  bool solved = false;
  std::string message;
};

/// The linear system of Eqs. 15-16 on a fixed lattice topology.
///
/// Unknowns: p_s for every triangle s (index s), then p_h of the borehole (index n_triangles) when the
/// lattice has beams tagged inner. Row s of the implicit Euler step reads
///   (E/M) V_s (p_s - p_s^n) + dt sum_t iota_st (A_st/d_st) (p_s - p_t) + dt sum_u iota_su (A_su/d_su) p_s
///     = -b dV_s + source_s dt,
/// with A = beam length, d = DualGraph::flow_distance (the Voronoi segment, floored), the t-sum over
/// interior beams and the borehole wall (p_t = p_h there), the u-sum over outer beams (p = 0), and
/// iota_e = iota on broken beams, 1 on intact ones (1 + w (iota - 1) for a crack weight w in between);
/// with FractureFlow::transmissivity the segment conducts (A_st + w T)/d_st instead, with
/// FractureFlow::cubic (A_st + a^3 / (12 k/R^2))/d_st for the crack's aperture a. Every interior
/// flux appears in two rows with opposite signs, so the scheme conserves volume exactly up to
/// round-off.
///
/// Usage (Fig. 5): construct; optionally set_pressure(); per step and coupling iteration call
/// update_geometry() / set_broken() if the mechanics moved or broke something, solve(dt, dV), then
/// accept() once the coupling has converged. step() = solve() + accept().
///
/// Linear algebra: the sparsity pattern depends only on the topology (a broken beam changes a value,
/// not the pattern), so the symbolic analysis is done once; the numeric factorisation is redone only
/// when dt, the geometry or the broken set changed since the last one.
///
/// Limits: the pattern is that of the initial triangulation (no re-meshing); p = 0 on the whole
/// outer boundary (no other boundary conditions yet); at most one source (borehole or one point);
/// fracture aperture is ignored (constant iota as the paper, or a constant transmissivity); the borehole node has no
/// volume of its own unless borehole_storage says so.
class FlowNetwork {
 public:
  /// Validates `parameters` (hm::InputError) and builds the network on `lattice` with the geometry
  /// `dual` (build_dual_graph of the same lattice). Throws hm::InputError "source_x, source_y = ..."
  /// if a point source lies in no triangle. All beams intact, p = 0 at t = 0.
  FlowNetwork(const Lattice& lattice, const DualGraph& dual, const FlowParameters& parameters);
  ~FlowNetwork();
  FlowNetwork(FlowNetwork&&) noexcept;
  FlowNetwork& operator=(FlowNetwork&&) noexcept;
  FlowNetwork(const FlowNetwork&) = delete;
  FlowNetwork& operator=(const FlowNetwork&) = delete;

  const FlowParameters& parameters() const { return parameters_; }
  int n_triangles() const { return n_triangles_; }
  /// n_triangles, plus 1 with a borehole.
  int n_unknowns() const { return n_triangles_ + (has_borehole() ? 1 : 0); }
  bool has_borehole() const { return has_borehole_; }
  /// Index of the borehole node (n_triangles), or -1.
  int borehole_index() const { return has_borehole_ ? n_triangles_ : -1; }
  /// Triangle receiving the point source, or -1 with a borehole.
  int source_triangle() const { return source_triangle_; }
  /// V_h, area of the polygon the wall particles enclose at the current geometry (0 without borehole).
  double borehole_volume() const { return borehole_volume_; }
  /// s_h of Eq. 16 per borehole_storage at the current V_h: (E/M) V_h, (E/K_w) V_h or 0.
  double borehole_storage_coefficient() const;
  /// The weight of dV_h in the borehole's balance per borehole_deformation: b, 1 or 0.
  double borehole_deformation_coefficient() const;

  /// Replaces the geometry (V_s^{n+1}, A/d) by that of a deformed configuration: `dual` must be
  /// build_dual_graph(lattice, positions). V_h is recomputed from `positions`.
  void update_geometry(const DualGraph& dual, const Eigen::Matrix2Xd& positions);
  /// How much of each beam's Voronoi facet is crack (size n_beams, each in [0, 1]): 1 broken, 0 intact
  /// rock, the damage 1 - s of a softening beam (CoupledModel). The facet conducts as rock and crack
  /// side by side, (1 + w (iota - 1)) A/d or (A + w T)/d; a facet with w > 0 joins its triangles to a
  /// crack.
  void set_crack_weights(const Eigen::VectorXd& weights);
  /// The same with weight 1 on the flagged beams and 0 elsewhere.
  void set_broken(const std::vector<bool>& broken);
  /// With FractureFlow::cubic: each beam's opening (u_j - u_i).n (size n_beams; a closed one, < 0,
  /// counts as 0), from which a crack's aperture a = w (max(opening, 0) + residual) is taken.
  void set_crack_openings(const Eigen::VectorXd& openings);
  /// With FractureFlow::cubic: the flagged beams' facets are a cut slot `width` wide (over R) before
  /// any opening, e.g. a saw-cut notch, which carries the fluid to its tips while the cracks grown
  /// from it conduct by their own opening alone. Allowed: 0 <= width, finite; beams in range.
  void set_slot_width(const std::vector<int>& beams, double width);
  /// a / R of a beam's crack: w (max(opening + slot, 0) + w_r / R) with the cubic law (slot the beam's
  /// set_slot_width, else 0), 0 for intact rock or another law.
  double crack_aperture(int beam) const;
  const Eigen::VectorXd& crack_weights() const { return crack_weight_; }
  /// The cracks as sets of unknowns: the triangles (and the borehole) joined by the connections of
  /// beams with a crack weight above 0, one set per connected crack, in order of their first unknown.
  std::vector<std::vector<int>> crack_modes() const { return crack_modes(crack_weight_); }
  /// How many times the cracks' conductances have changed in this object's life (set_crack_weights with
  /// iota != 1 or a transmissivity, restore_state): a stabiliser's Z of another count is stale.
  long crack_conductance_changes() const { return crack_conductance_changes_; }
  /// The same for other weights (size n_beams).
  std::vector<std::vector<int>> crack_modes(const Eigen::VectorXd& weights) const;

  /// Sets p^n (size n_unknowns), e.g. an initial condition. Does not change time or totals.
  void set_pressure(const Eigen::VectorXd& pressure);
  /// p^n, the last accepted pressures (size n_unknowns).
  const Eigen::VectorXd& pressure() const { return pressure_; }
  /// p_h^n (0 without borehole).
  double borehole_pressure() const { return has_borehole_ ? pressure_[n_triangles_] : 0.0; }
  double time() const { return totals_.time; }
  const FlowTotals& totals() const { return totals_; }

  /// Solves one implicit Euler step of length dt > 0 from p^n (hm::InputError if dt is not > 0).
  /// volume_change: V^{n+1} - V^n per unknown (triangles, then the borehole), from the mechanics;
  /// empty means zero. Does not change p^n: the result is trial_pressure() until accept().
  FlowStepSummary solve(double dt, const Eigen::VectorXd& volume_change = {}, FlowStabiliser* stabiliser = nullptr);
  /// The deformation term of the balance for a volume change per unknown: b times it, 1 times it on
  /// a crack's triangles with CrackCoupling::full, the borehole's by its coefficient.
  Eigen::VectorXd deformation(const Eigen::VectorXd& volume_change) const;
  /// The pressure of the last solve().
  const Eigen::VectorXd& trial_pressure() const { return trial_pressure_; }
  /// Makes the last successful solve() the new state (p^n, time, totals). Precondition: a solve()
  /// that succeeded and was not yet accepted.
  void accept();
  /// solve(parameters().time_step or dt, volume_change), accepted if it succeeded.
  FlowStepSummary step(const Eigen::VectorXd& volume_change = {});
  FlowStepSummary step(double dt, const Eigen::VectorXd& volume_change = {});

  /// Steady state of the current conductances: storage and deformation dropped, the source Q per
  /// unit time. Does not change the state.
  FlowSteadyState solve_steady_state() const;

  /// Flow rate per beam (volume per unit time, no dt) for `pressure` (size n_unknowns): from
  /// beam_triangles[0] into beam_triangles[1], into the borehole for a wall beam, out of the domain
  /// for an outer beam. Includes iota.
  Eigen::VectorXd beam_flow_rate(const Eigen::VectorXd& pressure) const;
  /// Net inflow rate from the neighbours (and the surface at p = 0) into each unknown, the sum of
  /// the signed beam_flow_rate terms; exactly 0 for a node whose neighbours share its pressure.
  Eigen::VectorXd net_inflow_rate(const Eigen::VectorXd& pressure) const;
  /// Sum over outer segments of (A/d_su) iota p_s: the outflow rate through the outer surface.
  double outflow_rate(const Eigen::VectorXd& pressure) const;

  /// The state between steps (pressure, totals, geometry, broken flags, the factor's matrix), for
  /// checkpoints: a network built on the same lattice that restores it continues bitwise.
  void save_state(core::StateWriter& w) const;
  /// Throws hm::InputError for a state of another network or written by other code.
  void restore_state(core::StateReader& r);

 private:
  // The stabilised pressure from the plain one A^-1 rhs (FlowStabiliser).
  Eigen::VectorXd stabilised(double dt, const Eigen::VectorXd& plain, FlowStabiliser& stabiliser);
  struct Solver;  // the one place that names the sparse factorisation (flow_network.cpp)

  // One flow connection per beam: between triangles s and t, triangle s and the borehole (t = h),
  // or triangle s and the outer surface (t = -1).
  struct Connection {
    int s = -1;
    int t = -1;
  };

  double conductance(int beam) const;  // (1 + w (iota - 1)) A/d, (A + w T)/d or (A + a^3/(12 k))/d
  void assemble_values(double dt, double storage_scale, Eigen::VectorXd& values) const;
  std::string factorise_if_needed(double dt);  // empty on success
  std::string factorise(double dt);            // assemble and factorise for dt; empty on success

  FlowParameters parameters_;
  int n_triangles_ = 0;
  bool has_borehole_ = false;
  int source_triangle_ = -1;
  std::vector<Connection> connections_;
  std::vector<std::array<int, 2>> wall_beams_;  // particle pairs of the borehole wall
  Eigen::VectorXd triangle_area_;               // V_s^{n+1}
  Eigen::VectorXd base_conductance_;            // A/d_flow per beam
  Eigen::VectorXd inverse_flow_distance_;       // 1/d_flow per beam: a crack's T/d is T times it
  double borehole_volume_ = 0.0;
  Eigen::VectorXd crack_weight_;   // per beam, 0 rock ... 1 broken
  Eigen::VectorXd crack_opening_;  // per beam with the cubic law (else empty)
  Eigen::VectorXd slot_width_;     // per beam, a cut slot's own aperture (empty: none)

  Eigen::VectorXd pressure_;
  Eigen::VectorXd trial_pressure_;
  // Per unknown, the fluid the last accepted stabilised solve charged ahead of the cracks' opening
  // (rhs - A p), which the next step supplies again; empty when that solve had no stabiliser.
  Eigen::VectorXd charged_ahead_;
  Eigen::VectorXd trial_charged_ahead_;
  FlowStepSummary trial_summary_;
  bool has_trial_ = false;
  FlowTotals totals_;

  std::unique_ptr<Solver> solver_;
  double factorised_dt_ = -1.0;         // dt of the current numeric factorisation; < 0: none
  bool factor_stale_ = false;           // geometry or iota changed since: refine with the old factor
  bool refresh_factor_ = false;         // the last refinement was slow: refactorise at the next solve
  long crack_conductance_changes_ = 0;  // never restored: a count that only grows never repeats
  long factorised_conductances_ = 0;    // that count at the last factorisation (else the cracks changed)
};

}  // namespace hm::lattice2d
