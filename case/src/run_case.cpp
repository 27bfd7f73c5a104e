#include "hm/case/run_case.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "hm/case/case_keys.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/far_field.hpp"

namespace hm::cases {

namespace lt = hm::lattice2d;

lt::BeamParameters RunCase::beams() const { return lt::calibrated_beam_parameters(stiffness_scaling); }

hm::analytic::FarFieldStress InSituState::far_field() const {
  return {S_H, S_h, theta_H_deg * std::numbers::pi / 180.0};
}

lt::BoundaryConditions RunCase::boundary_conditions() const {
  lt::BoundaryConditions bc = boundary;
  if (!insitu.is_zero())
    lt::add_far_field_loads(insitu.far_field(), insitu.p0, physics.parameters.material.b, lattice.domain, bc);
  return bc;
}

lt::FlowParameters RunCase::flow_parameters() const {
  return lt::flow_parameters_of(physics.parameters, stepping.dt_initial, flow);
}

namespace {

// A step whose first tooth gives way more than 2% past its strength is retried with half the step
// under the saw-tooth law: well inside the strengths' own scatter (5% half-width by default), and
// the measured cost of the brittle law's retry at this tolerance is ~3x the steps (docs/fracture_law.md).
constexpr double kSawtoothOvershootTolerance = 0.02;

// The beams every run uses and the continuum they were measured to represent (not inputs: comments).
std::string calibration_comment(const RunCase& c) {
  const lt::BeamParameters beams = c.beams();
  const lt::ElasticConstants continuum = lt::calibrated_continuum(c.stiffness_scaling);
  return "# beams: calibrated_beam_parameters(" + hm::core::name_of(c.stiffness_scaling) +
         ") k_n = " + core::format_value(beams.normal_stiffness) + ", a = " + core::format_value(beams.aspect) +
         ", nu0 = " + core::format_value(beams.beam_poisson) + ";\n# measured continuum (calibration, " +
         "docs/lattice.md): E = " + core::format_value(continuum.youngs_modulus) +
         ", nu = " + core::format_value(continuum.poisson_ratio) + " (plane strain)\n";
}

// k/R^2 of a [physics_si] case (the cubic law's scale); 0 for a dimensionless one, which must give it.
double si_permeability(const RunCase& c) {
  if (!c.physics.physical) return 0.0;
  return c.physics.physical->k_si / (c.physics.physical->R_si * c.physics.physical->R_si);
}

void check_cubic_law(CaseTable& flow, const RunCase& c) {
  const lt::FractureFlowSpec& f = c.flow.fracture_flow;
  const bool cubic = f.law == lt::FractureFlow::cubic;
  const double w_r = f.residual_aperture;
  // 1% of R (1 cm at R = 1 m) is an open crack, not the roughness of closed faces.
  if (!(w_r >= 0.0 && w_r <= 0.01))
    flow.fail("residual_aperture = " + core::format_value(w_r) + ", allowed: 0 <= value <= 0.01 (over R)");
  if (!cubic && w_r != 0.0)
    flow.fail("residual_aperture = " + core::format_value(w_r) + ", allowed: only with fracture_flow = \"cubic\"");
  if (!cubic && f.aperture != lt::CrackAperture::axial)
    flow.fail("crack_aperture = \"" + core::name_of(f.aperture) +
              "\", allowed: only with fracture_flow = \"cubic\" (the other laws have no aperture)");
  const double k = f.permeability;
  if (!cubic) {
    if (k != 0.0)
      flow.fail("rock_permeability = " + core::format_value(k) + ", allowed: only with fracture_flow = \"cubic\"");
    return;
  }
  if (k == 0.0 && !c.physics.physical)
    flow.fail(
        "rock_permeability is missing, allowed: 1e-25 <= value <= 1e-2 (k/R^2), required with fracture_flow = "
        "\"cubic\" and [physics]");
  // 1e-25: a nanodarcy shale (1e-21 m^2) in a domain of 100 m; 1e-2: a pore as wide as a tenth of R.
  if (!(k >= 1e-25 && k <= 1e-2))
    flow.fail("rock_permeability = " + core::format_value(k) + ", allowed: 1e-25 <= value <= 1e-2 (k/R^2)");
  const double si = si_permeability(c);
  if (c.physics.physical && std::abs(k - si) > 1e-12 * si)
    flow.fail("rock_permeability = " + core::format_value(k) + ", allowed: k/R^2 of [physics_si] (" +
              core::format_value(si) + ")");
}

// The key tables are laid out one key per entry (clang-format would break each entry before its name).
// clang-format off
// [lattice]: the domain and the particles.
void add_lattice_keys(CaseKeys<RunCase>& k) {
  k.table("lattice")
      .choice("domain", [](auto& c) -> auto& { return c.lattice.domain; }, {lt::DomainShape::disk, lt::DomainShape::annulus},
              "disk: point injection at r = 0; annulus: the borehole R_i <= r <= 1 (R_i from [physics]); not the "
              "lattice's rectangle: the flow needs a circular outer boundary")
      .integer("n_particles", [](auto& c) -> auto& { return c.lattice.n_particles; }, std::numeric_limits<long long>::min(),
               std::numeric_limits<long long>::max(), "500 <= n_particles <= 5e6", "number of particles (about; Poisson-disk sampling)")
      .required()
      .integer("seed", [](auto& c) -> auto& { return c.lattice.seed; }, 0, std::numeric_limits<long long>::max(), ">= 0",
               "seed of the lattice's points; equal seeds give bitwise equal lattices")
      .real("boundary_spacing_factor", [](auto& c) -> auto& { return c.lattice.boundary_spacing_factor; },
            "1 <= factor <= 1.35", "boundary particles' spacing over the Poisson-disk radius")
      .choice("stiffness_scaling", [](auto& c) -> auto& { return c.stiffness_scaling; },
              {lt::StiffnessScaling::voronoi_facet, lt::StiffnessScaling::uniform},
              "the calibrated beams of that scaling (docs/lattice.md)")
      .check([](CaseTable&, CaseTable& root, RunCase& c) {
        const double R_i = c.physics.parameters.R_i;
        const std::string physics_table = c.physics.physical ? "physics_si" : "physics";
        if (c.lattice.domain == lt::DomainShape::disk && R_i != 0.0)
          root.table(physics_table).fail("R_i = " + core::format_value(R_i) +
                                         ", allowed: 0 for [lattice] domain = \"disk\" (point injection at r = 0)");
        if (c.lattice.domain == lt::DomainShape::annulus && !(R_i > 0.0))
          root.table(physics_table).fail("R_i = 0, allowed: 0 < R_i < 1 for [lattice] domain = \"annulus\"");
        if (c.lattice.domain == lt::DomainShape::annulus) c.lattice.inner_radius = R_i;
        c.lattice.validate();
      })
      .comment(calibration_comment);
}

// [mechanics]: the outer boundary, the solver and the in-situ state.
void add_mechanics_keys(CaseKeys<RunCase>& k) {
  k.table("mechanics")
      .choice("outer", [](auto& c) -> auto& { return c.boundary.outer; },
              "the outer boundary r = 1: traction-free or held")
      .choice("solver", [](auto& c) -> auto& { return c.mechanics.solver; },
              "the mechanics' linear solver: CHOLMOD's Cholesky factor or preconditioned CG")
      .real("S_H", [](auto& c) -> auto& { return c.insitu.S_H; }, "S_h <= S_H <= 1 (over E: a stress of E strains the rock by order one)",
            "in-situ largest horizontal stress S_H/E, compression positive: the far field at rest (docs/insitu.md)")
      .real("S_h", [](auto& c) -> auto& { return c.insitu.S_h; }, "0 <= S_h <= S_H", "in-situ smallest horizontal stress S_h/E")
      .real("theta_H", [](auto& c) -> auto& { return c.insitu.theta_H_deg; }, "finite",
            "azimuth of S_H from the x axis, degrees")
      .real("p0", [](auto& c) -> auto& { return c.insitu.p0; }, "0 <= p0 <= 1 (over E)",
            "rest pore pressure p0/E: the flow's p is the deviation from it (docs/insitu.md)")
      .check([](CaseTable& mechanics, CaseTable&, RunCase& c) {
        if (c.insitu.is_zero()) return;
        if (c.boundary.outer != lt::BoundarySupport::free)
          mechanics.fail("outer = \"" + core::name_of(c.boundary.outer) +
                         "\", allowed: \"free\" with an in-situ stress or p0 (a held boundary takes no traction)");
        c.boundary_conditions();  // validates S_H, S_h, theta_H and p0 with the library's rules
      });
}

// [flow]: the borehole node and how cracks hold and conduct fluid.
void add_flow_keys(CaseKeys<RunCase>& k) {
  k.table("flow")
      .choice("borehole_storage", [](auto& c) -> auto& { return c.flow.borehole_storage; },
              "the borehole node's storage: Eq. 16's E/M V_h, none, or the water-filled hole's E/K_w V_h "
              "(docs/flow.md)")
      .choice("borehole_deformation", [](auto& c) -> auto& { return c.flow.borehole_deformation; },
              "the weight of the borehole's volume change in its balance: b (Eq. 16), none, or 1 (full: the "
              "hole holds only fluid) (docs/flow.md)",
              [](const RunCase& c) { return lt::default_borehole_deformation(c.flow.borehole_storage); },
              "`\"" + core::name_of(lt::default_borehole_deformation(lt::BoreholeStorage::biot_modulus)) +
                  "\"`; `\"" + core::name_of(lt::default_borehole_deformation(lt::BoreholeStorage::none)) +
                  "\"` for borehole_storage = \"none\"; `\"" +
                  core::name_of(lt::default_borehole_deformation(lt::BoreholeStorage::fluid)) +
                  "\"` for \"fluid\"")
      .choice("crack_coupling", [](auto& c) -> auto& { return c.flow.crack_coupling; },
              "the Biot coefficient of a crack: the rock's b on broken beams' triangles and segments (Eqs. 15, 17), "
              "or 1 (full: a fluid-filled void, docs/flow.md)")
      .choice("fracture_flow", [](auto& c) -> auto& { return c.flow.fracture_flow.law; },
              "how a crack conducts: [physics] iota times the rock's A/d (Eq. 24; the crack's transmissivity then "
              "scales with the beam length), the rock's A/d plus crack_transmissivity / d (the same at every N), or "
              "the rock's A/d plus the parallel plates' a^3/(12 k) / d of the crack's aperture a (the cubic law, "
              "Eqs. 25-26; docs/flow.md)")
      .real("crack_transmissivity", [](auto& c) -> auto& { return c.flow.fracture_flow.transmissivity; },
            "0 <= value <= 1e12, finite; > 0 only with fracture_flow = \"transmissivity\"",
            "T = k_f w / (k R), a crack's permeability times its aperture over the rock's permeability times R")
      .real("rock_permeability", [](auto& c) -> auto& { return c.flow.fracture_flow.permeability; },
            "1e-25 <= value <= 1e-2, finite; only with fracture_flow = \"cubic\", where it is required with "
            "[physics] and is k/R^2 of [physics_si]",
            "k/R^2, the rock's permeability over the domain radius squared: the cubic law's scale (an aperture a "
            "conducts a^3/12 where the rock conducts k)",
            [](const RunCase& c) { return c.flow.fracture_flow.law == lt::FractureFlow::cubic ? si_permeability(c) : 0.0; },
            "`0`; k/R^2 of [physics_si] with fracture_flow = \"cubic\"")
      .real("residual_aperture", [](auto& c) -> auto& { return c.flow.fracture_flow.residual_aperture; },
            "0 <= value <= 0.01, finite; > 0 only with fracture_flow = \"cubic\"",
            "w_r/R, the aperture a crack keeps when its faces touch (the cubic law): a pinched point does not "
            "block the crack's flow")
      .choice("crack_aperture", [](auto& c) -> auto& { return c.flow.fracture_flow.aperture; },
              "the cubic law's aperture of a facet: its axial opening (the gap normal to the facet); the length "
              "of its displacement jump (axial opening and slide) where open; or the jump along the crack's "
              "local normal (through the facet and its cracked neighbours) where that is larger than the axial "
              "opening. A facet inclined to its crack needs one of the last two to conduct the crack's opening "
              "(docs/flow.md, \"The cubic law on a lattice crack\"); other than \"axial\" only with "
              "fracture_flow = \"cubic\"",
              [](const RunCase& c) { return lt::default_crack_aperture(c.flow.fracture_flow.law); },
              "`\"" + core::name_of(lt::default_crack_aperture(lt::FractureFlow::cubic)) +
                  "\"` with fracture_flow = \"cubic\"; `\"" +
                  core::name_of(lt::default_crack_aperture(lt::FractureFlow::permeability)) + "\"` otherwise")
      .check([](CaseTable& flow, CaseTable& root, RunCase& c) {
        check_cubic_law(flow, c);
        if (const double ramp = c.flow.injection_ramp_time; !(ramp >= 0.0 && std::isfinite(ramp)))
          flow.fail("injection_ramp_time = " + core::format_value(ramp) + ", allowed: >= 0, finite");
        const double T = c.flow.fracture_flow.transmissivity;
        if (!(T >= 0.0 && T <= 1e12))
          flow.fail("crack_transmissivity = " + core::format_value(T) +
                    ", allowed: 0 <= value <= 1e12 (iota's bound in units of R: a 0.3 mm aperture at k_f ~ 1e-8 m^2 "
                    "in a nanodarcy rock)");
        if (c.flow.fracture_flow.law == lt::FractureFlow::permeability && T != 0.0)
          flow.fail("crack_transmissivity = " + core::format_value(T) +
                    ", allowed: only with fracture_flow = \"transmissivity\" (iota sets the crack's conductance otherwise)");
        const double iota = c.physics.parameters.iota;
        if (c.flow.fracture_flow.law != lt::FractureFlow::permeability && iota != 1.0) {
          const std::string law = core::name_of(c.flow.fracture_flow.law);
          const std::string rule = " with [flow] fracture_flow = \"" + law + "\" (the crack's conductance is " +
                                   (c.flow.fracture_flow.law == lt::FractureFlow::cubic ? "its aperture's"
                                                                                  : "crack_transmissivity's") + ")";
          if (c.physics.physical)
            root.table("physics_si").fail("k_f = " + core::format_value(iota) + " k, allowed: k_f = k" + rule);
          root.table("physics").fail("iota = " + core::format_value(iota) + ", allowed: 1" + rule);
        }
      })
      .real("injection_ramp_time", [](auto& c) -> auto& { return c.flow.injection_ramp_time; }, ">= 0, finite",
            "the injection rate rises linearly from 0 to [physics] Q over this dimensionless time, then stays at Q; "
            "0: Q from the start (the paper's)")
      .boolean("reuse_factorisation", [](auto& c) -> auto& { return c.flow.reuse_factorisation; },
               "reuse the flow matrix's factor while the geometry changes little (iterative refinement)")
      .integer("refresh_after_refinements", [](auto& c) -> auto& { return c.flow.refresh_after_refinements; }, 0, 1000000,
               "0 ... 1000000", "refactorise the flow matrix after this many refinement sweeps (0: never)");
}

// [coupling]: the split, its iteration and the stabilisers.
void add_coupling_keys(CaseKeys<RunCase>& k) {
  k.table("coupling")
      .choice("split", [](auto& c) -> auto& { return c.coupling.split; },
              "the operator split of Section 2.3")
      .real("psi", [](auto& c) -> auto& { return c.coupling.terms.psi; },
            "0 ... 1e6 (the paper's study ends at 10; 1e12 swamps the beams); 0 for split = \"drained\"",
            "Psi, the undrained split's feedback (Eq. 20)", [](const RunCase& c) { return lt::default_psi(c.coupling.split); },
            "`" + toml_real(lt::CouplingTerms{}.psi) + "`; `0` for split = \"drained\"")
      .real("xi", [](auto& c) -> auto& { return c.coupling.terms.xi; },
            "0 < xi <= 1e3 (1 by the divergence theorem; 1e12 swamps the beams)", "xi, scaling of the pressure force (Eq. 17)")
      .choice("broken_beam_spring", [](auto& c) -> auto& { return c.coupling.terms.broken_beam_spring; },
              "the Psi spring of a beam that breaks: kept, or dropped with the beam (docs/coupling.md)")
      .choice("borehole_spring", [](auto& c) -> auto& { return c.coupling.terms.borehole_spring; },
              "the borehole fluid inside a mechanical solve (a break cascade): none (its pressure is the pass's "
              "guess), or undrained (its wall is held by the hole's undrained stiffness, relaxed at the pass "
              "iterate; needs [lattice] domain = \"annulus\" and [flow] borehole_storage and borehole_deformation "
              "not \"none\"; docs/coupling.md)")
      .real("pressure_tolerance", [](auto& c) -> auto& { return c.coupling.pressure_tolerance; },
            "1e-10 <= value < 1 (a pass's change stalls at round-off, ~1e-11)",
            "a step has converged when the pressure's change between passes, relative to its largest value, is below this...")
      .real("displacement_tolerance", [](auto& c) -> auto& { return c.coupling.displacement_tolerance; },
            "1e-10 <= value < 1",
            "...and the displacement's relative change is below this")
      .real("balance_tolerance", [](auto& c) -> auto& { return c.coupling.balance_tolerance; },
            "1e-10 <= value <= 1 (1: off)",
            "...and the run's volume balance error after the step is at most this (round-off unless fluid-filled "
            "cracks' stabiliser is on: then the fluid it charged ahead of the opening, which the next step supplies "
            "again; docs/fracture_convergence.md)")
      .integer("max_iterations", [](auto& c) -> auto& { return c.coupling.max_iterations; }, 1, 1000000,
               "1 <= max_iterations <= 1e6", "cap on the passes of one step")
      .boolean("accept_unconverged", [](auto& c) -> auto& { return c.coupling.accept_unconverged; },
               "accept a step that hit max_iterations (the paper's one pass per step with max_iterations = 1)")
      // Anderson by default: the plain loop of Fig. 5 ("none") does not converge with the paper's
      // borehole node (Eq. 16) at any step (pressure residual ~1 after 100 passes at dt = 4e-9), and
      // with fracture its oscillating pressures break the lattice apart within the first step.
      .choice("relaxation", [](auto& c) -> auto& { return c.coupling.relaxation; },
              "how the next pass's guess is formed (docs/coupling.md, section 3)",
              [](const RunCase&) { return lt::CouplingRelaxation::anderson; },
              "`\"anderson\"` (Fig. 5's plain loop is \"none\")")
      .real("initial_relaxation", [](auto& c) -> auto& { return c.coupling.initial_relaxation; }, "0 < value <= 1",
            "Aitken's first factor, Anderson's mixing")
      .integer("anderson_depth", [](auto& c) -> auto& { return c.coupling.anderson_depth; }, 1, 50, "1 ... 50",
               "residual differences Anderson combines (the paper cases of Figs. 12, 14, 16, 17 use 20: a crack draining "
               "under the cubic law holds a slow mode that 10 do not span; each costs two vectors of the "
               "(p, u) state; docs/coupling.md)")
      .choice("fracture_check", [](auto& c) -> auto& { return c.coupling.fracture_check; },
              "when beams are checked for failure: every pass (Fig. 5) or at the coupled equilibrium", {},
              "`\"" + core::name_of(lt::CouplingOptions{}.fracture_check) +
                  "\"`; `\"at_convergence\"` with [fracture] law = \"sawtooth\"")
      .integer("events_per_check", [](auto& c) -> auto& { return c.coupling.events_per_check; }, 0,
               lt::CouplingOptions::kMaxEventsPerCheck, "0 ... 1e6",
               "breaks or teeth taken at one failure check before the coupling solves again; 0 (default): all "
               "that fail under the check's loads, at fixed pressure (Fig. 5); 1 by default with [fracture] law = "
               "\"sawtooth\" (the fluid answers each tooth before the next is judged)")
      .choice("predictor", [](auto& c) -> auto& { return c.coupling.predictor; },
              "the first pass's guess: the last step's state or its linear extrapolation")
      .choice("crack_stabiliser", [](auto& c) -> auto& { return c.coupling.crack_stabiliser; },
              "with [flow] crack_coupling = \"full\": each crack's response to a uniform pressure in the flow "
              "solve (same fixed point; without it a fluid-filled crack's passes stall or diverge), each crack "
              "unknown's own response (for a crack whose pressure is far from uniform: a viscous fluid, the cubic "
              "law; a solve per crack unknown), or none (docs/coupling.md)")
      .check([](CaseTable& coupling, CaseTable&, RunCase& c) {
        c.coupling.validate();
        if (c.coupling.terms.borehole_spring != lt::BoreholeSpring::undrained) return;
        if (c.lattice.domain != lt::DomainShape::annulus)
          coupling.fail("borehole_spring = \"undrained\", allowed: only with [lattice] domain = \"annulus\" (a borehole)");
        if (c.flow.borehole_storage == lt::BoreholeStorage::none || c.flow.borehole_deformation == lt::BoreholeDeformation::none)
          coupling.fail("borehole_spring = \"undrained\", allowed: only with [flow] borehole_storage and "
                        "borehole_deformation not \"none\" (the hole's volume must set its pressure)");
      });
}

// [numerics]: the time stepping.
void add_numerics_keys(CaseKeys<RunCase>& k) {
  k.table("numerics")
      .real("dt_initial", [](auto& c) -> auto& { return c.stepping.dt_initial; }, "> 0, finite, <= t_end", "first time step")
      // 1.2: the shipped cases' growth; dt_initial = 1e-6 with a constant step would take 27,200 steps
      // to the Fig. 12 cases' t_end.
      .real("dt_growth", [](auto& c) -> auto& { return c.stepping.dt_growth; }, ">= 1, finite", "factor between consecutive steps",
            [](const RunCase&) { return 1.2; }, "`1.2`")
      .real("t_end", [](auto& c) -> auto& { return c.stepping.t_end; }, "> 0, finite", "end time t*")
      .required()
      .real("dt_max", [](auto& c) -> auto& { return c.stepping.dt_max; }, ">= dt_initial, finite", "largest time step",
            [](const RunCase& c) { return c.stepping.t_end; }, "t_end (no cap)")
      .integer("max_step_halvings", [](auto& c) -> auto& { return c.stepping.max_step_halvings; }, 0, 50, "0 ... 50",
               "retries of an unconverged step with half the step")
      .real("overshoot_tolerance", [](auto& c) -> auto& { return c.stepping.overshoot_tolerance; },
            "0 <= value < 1; > 0 only with [coupling] fracture_check = \"at_convergence\"",
            "> 0 (with fracture_check = \"at_convergence\"): a step whose first break (or tooth) has failure ratio "
            "above 1 + this is retried with half the step (the last of max_step_halvings tries is accepted); 0: off",
            {}, "`0`; `" + toml_real(kSawtoothOvershootTolerance) + "` with [fracture] law = \"sawtooth\"");
}

// [fracture]'s rules across its keys and with [physics]' strengths.
void check_fracture_keys(CaseTable& fracture, CaseTable&, RunCase& c) {
  if (c.stop_at_first_break && !c.fracture_enabled)
    fracture.fail("stop_at_first_break = true, allowed: true only with enabled = true (no beam breaks with "
                  "fracture disabled)");
  if (!c.notches.empty() && !c.fracture_enabled)
    fracture.fail("notch given, allowed: only with enabled = true (a notch is a set of broken beams)");
  if (!(std::isfinite(c.notch_aperture) && c.notch_aperture >= 0.0 && c.notch_aperture <= 0.01))
    fracture.fail("notch_aperture = " + core::format_value(c.notch_aperture) + ", allowed: 0 <= value <= 0.01 (over R)");
  if (c.notch_aperture > 0.0 && (c.notches.empty() || c.flow.fracture_flow.law != lt::FractureFlow::cubic))
    fracture.fail("notch_aperture = " + core::format_value(c.notch_aperture) +
                  ", allowed: > 0 only with a notch and [flow] fracture_flow = \"cubic\"");
  // The mean strengths and mu_i are the material's ([physics]).
  auto& st = c.strength;
  st.tensile_strength = c.physics.parameters.tensile_strength;
  st.compressive_strength = c.physics.parameters.compressive_strength;
  st.friction = c.physics.parameters.friction;
  st.validate();
  core::require_positive(c.break_loop.crack_tip.material_length, "crack_tip_length");
  const double g_f = c.sawtooth.fracture_energy;
  if (c.fracture_law == lt::FractureLaw::sawtooth) {
    if (!c.fracture_enabled)
      fracture.fail("law = \"sawtooth\", allowed: only with enabled = true");
    // G_f/(E R) <= 1: G_f/E, a length, at most the domain's radius (rocks: G_f/E ~ 1e-8 m);
    // above it is a G_f in J/m^2 typed into a dimensionless table.
    if (!(g_f > 0.0 && g_f <= 1.0))
      fracture.fail("fracture_energy = " + core::format_value(g_f) +
                    ", allowed: 0 < fracture_energy <= 1 with law = \"sawtooth\" (required there; G_f/(E R), "
                    "so a value in J/m^2 is refused)");
    const double a = c.sawtooth.teeth.reduction;
    if (!(std::isfinite(a) && a > 1.0))
      fracture.fail("sawtooth_reduction = " + core::format_value(a) + ", allowed: > 1, finite");
    const double kappa = c.sawtooth.strength_factor;
    if (!(std::isfinite(kappa) && kappa > 0.0))
      fracture.fail("sawtooth_strength_factor = " + core::format_value(kappa) + ", allowed: > 0, finite");
  } else if (g_f != 0.0) {
    fracture.fail("fracture_energy = " + core::format_value(g_f) +
                  ", allowed: 0 with law = \"brittle\" (a fracture energy belongs to law = \"sawtooth\")");
  }
}

// [fracture]: the strengths, the law and pre-cut cracks.
void add_fracture_keys(CaseKeys<RunCase>& k) {
  k.table("fracture")
      .boolean("enabled", [](auto& c) -> auto& { return c.fracture_enabled; }, "break beams (Eq. 11)")
      .boolean("stop_at_first_break", [](auto& c) -> auto& { return c.stop_at_first_break; },
               "end the run with the step that breaks the first beam (breakdown.csv's), its state written as an "
               "output time's", "true or false; true only with enabled = true")
      .choice("distribution", [](auto& c) -> auto& { return c.strength.distribution; },
              "the beams' strength heterogeneity around [physics]' means")
      .real("width", [](auto& c) -> auto& { return c.strength.width; }, "0 <= width < 1", "uniform: relative half-width")
      .real("weibull_modulus", [](auto& c) -> auto& { return c.strength.weibull_modulus; }, "1 ... 1000", "weibull: modulus m")
      .boolean("correlated", [](auto& c) -> auto& { return c.strength.correlated; },
               "one random factor per beam for both strengths (else independent)")
      .integer("seed", [](auto& c) -> auto& { return c.strength.seed; }, 0, std::numeric_limits<long long>::max(), ">= 0",
               "seed of the strengths, independent of the lattice's")
      .boolean("crack_tip", [](auto& c) -> auto& { return c.break_loop.crack_tip.enabled; },
               "the crack-tip factor (L/2L_m)^(1/2) of Fig. 2")
      .real("crack_tip_length", [](auto& c) -> auto& { return c.break_loop.crack_tip.material_length; }, "> 0",
            "L_m over R, the crack-tip factor's material length")
      .choice("law", [](auto& c) -> auto& { return c.fracture_law; },
              "how a beam fails in tension: removed at its strength with the crack-tip factor (the paper's), or "
              "softened tooth by tooth until it has dissipated the fracture energy (docs/fracture_law.md; the "
              "crack-tip keys are then not used)")
      .real("fracture_energy", [](auto& c) -> auto& { return c.sawtooth.fracture_energy; },
            "0 < fracture_energy <= 1 with law = \"sawtooth\" (required there); 0 with \"brittle\"",
            "G_f / (E R), the energy per unit crack area of the saw-tooth law", {}, "`0` (none)")
      .real("sawtooth_reduction", [](auto& c) -> auto& { return c.sawtooth.teeth.reduction; }, "> 1, finite",
            "saw-tooth law: each tooth's stiffness over the next's")
      .integer("sawtooth_teeth", [](auto& c) -> auto& { return c.sawtooth.teeth.n_teeth; }, 1, 100, "1 ... 100",
               "saw-tooth law: teeth before the beam breaks")
      .real("sawtooth_strength_factor", [](auto& c) -> auto& { return c.sawtooth.strength_factor; }, "> 0, finite",
            "saw-tooth law: a beam's f_t over its strength drawn around [physics] tensile_strength (the default "
            "makes uniaxial tension of an unnotched lattice peak at T_u; docs/fracture_law.md)",
            [](const RunCase&) { return lt::calibrated_sawtooth_strength_factor(); },
            "`" + toml_real(lt::calibrated_sawtooth_strength_factor()) + "` (calibrated)")
      .key({"notch", "list of [x0, y0, x1, y1]", "`[]`",
            "each 4 finite numbers, two distinct ends inside the domain (at most 1 from the centre); only with enabled = true",
            "pre-cut cracks: the beams each segment crosses are broken before the first step (breaks.csv, t = 0, "
            "mode none)",
            [](CaseTable& t, RunCase& c) {
              c.notches.clear();
              for (const std::vector<double>& v : t.get_double_lists("notch", 4, {})) {
                lt::NotchSegment n{{v[0], v[1]}, {v[2], v[3]}};
                const std::string shown = "notch = [" + toml_real(v[0]) + ", " + toml_real(v[1]) + ", " +
                                          toml_real(v[2]) + ", " + toml_real(v[3]) + "]";
                if (n.a == n.b) t.fail(shown + ", allowed: two distinct ends");
                if (n.a.norm() > 1.0 || n.b.norm() > 1.0) t.fail(shown + ", allowed: ends inside the domain (at most 1 from the centre)");
                c.notches.push_back(n);
              }
            },
            [](const RunCase& c) {
              std::string out = "[";
              for (std::size_t s = 0; s < c.notches.size(); ++s) {
                const lt::NotchSegment& n = c.notches[s];
                out += (s ? ", [" : "[") + toml_real(n.a.x()) + ", " + toml_real(n.a.y()) + ", " + toml_real(n.b.x()) +
                       ", " + toml_real(n.b.y()) + "]";
              }
              return out + "]";
            }})
      .real("notch_aperture", [](auto& c) -> auto& { return c.notch_aperture; },
            "0 <= value <= 0.01 (over R); > 0 only with a notch and [flow] fracture_flow = \"cubic\"",
            "the notches' own aperture, a cut slot's width: the cubic law's aperture of a notch's facet is its "
            "opening plus this, so the slot carries the fluid to its tips (docs/flow.md)")
      .check(check_fracture_keys);
}

// [output]: what a run writes and when.
void add_output_keys(CaseKeys<RunCase>& k) {
  k.table("output")
      .reals("times", [](auto& c) -> auto& { return c.stepping.output_times; }, "increasing, in (0, t_end]",
             "times t* of the radial profiles and VTK snapshots besides t = 0; t_end is always added")
      .boolean("vtk", [](auto& c) -> auto& { return c.output.vtk; }, "write VTK snapshots (.vtu + .pvd) at the output times")
      .integer("radial_bins", [](auto& c) -> auto& { return c.output.radial_bins; }, 1, 10000, "1 <= radial_bins <= 10000",
               "equal radial shells of radial.csv on [R_i, radial_max]")
      .real("radial_max", [](auto& c) -> auto& { return c.output.radial_max; }, "R_i < radial_max <= 1",
            "outer edge of the radial shells")
      .choice("fracture_link", [](auto& c) -> auto& { return c.output.statistics.link; },
              "which broken beams form one fracture in fractures.csv")
      .choice("softened_beams", [](auto& c) -> auto& { return c.output.statistics.softened; },
              "whether beams on their saw-tooth teeth (a crack's process zone) join the broken beams they touch "
              "into one fracture in fractures.csv; they are never counted as broken")
      .real("arm_gap", [](auto& c) -> auto& { return c.output.statistics.arm_gap; }, lt::kArmGapRule,
            "arms crossing the arm circle closer than this (over R, along it) count as one in fracture_summary.csv's "
            "n_arms_fixed_gap (n_arms' gap is 3 mean beam lengths; docs/fracture_statistics.md)")
      .check([](CaseTable& out, CaseTable&, RunCase& c) {
        const double R_i = c.physics.parameters.R_i;
        if (!(c.output.radial_max > R_i && c.output.radial_max <= 1.0))
          out.fail("radial_max = " + core::format_value(c.output.radial_max) + ", allowed: R_i = " +
                   core::format_value(R_i) + " < radial_max <= 1");
        if (!lt::is_allowed_arm_gap(c.output.statistics.arm_gap))
          out.fail("arm_gap = " + core::format_value(c.output.statistics.arm_gap) + ", allowed: " + lt::kArmGapRule);
      });
}

CaseKeys<RunCase> make_run_case_keys() {
  CaseKeys<RunCase> k;
  add_lattice_keys(k);
  add_mechanics_keys(k);
  add_flow_keys(k);
  add_coupling_keys(k);
  add_numerics_keys(k);
  add_fracture_keys(k);
  add_output_keys(k);
  return k;
}

// clang-format on
}  // namespace

const CaseKeys<RunCase>& run_case_keys() {
  static const CaseKeys<RunCase> keys = make_run_case_keys();
  return keys;
}

RunCase read_run_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return read_run_case(CaseFile(file, overrides));
}

RunCase read_run_case(const CaseFile& file) {
  CaseTable root = file.root();
  const std::string model = root.get_string("model", "lattice2d");
  if (model != "lattice2d")
    root.fail("model = \"" + model + "\", allowed: \"lattice2d\" (this command runs the 2D lattice model)");
  root.ignore("provenance");

  RunCase c;
  c.physics = read_physics(root);
  run_case_keys().read(root, c);
  root.reject_unknown();
  // Rules across tables: the time stepping's (times are [output]'s) and the flow's.
  try {
    c.stepping.validate();
  } catch (const FieldError& e) {
    // TimeStepping's fields are [numerics]' keys, but for its output times: [output] times.
    if (e.field() == "output_times") root.table("output").fail(e.message_as("times"));
    root.table("numerics").fail(e.what());
  }
  CaseTable numerics = root.table("numerics");
  // The saw-tooth law's defaults in other tables: a tooth judged on a converged state, and a step
  // whose first tooth overshoots retried (docs/fracture_law.md).
  if (c.fracture_law == lt::FractureLaw::sawtooth) {
    if (!root.table("coupling").has("fracture_check")) c.coupling.fracture_check = lt::FractureCheck::at_convergence;
    if (!root.table("coupling").has("events_per_check")) c.coupling.events_per_check = 1;
    if (!numerics.has("overshoot_tolerance")) c.stepping.overshoot_tolerance = kSawtoothOvershootTolerance;
  }
  // A first break checked on every pass can overshoot through the iteration itself (an unconverged
  // pass's pressure; 14% at dt -> 0 in the Fig. 12 quick case), which no shorter step removes: only
  // the converged states' check makes the retry meaningful.
  if (c.stepping.overshoot_tolerance > 0.0 && c.coupling.fracture_check != lt::FractureCheck::at_convergence)
    numerics.fail("overshoot_tolerance = " + core::format_value(c.stepping.overshoot_tolerance) +
                  ", allowed: 0 unless [coupling] fracture_check = \"at_convergence\" (a break on an unconverged "
                  "pass overshoots whatever the step)");
  located(numerics, [&] { c.flow_parameters().validate(); });
  // What an empty or truncated file lacks, once every given value has been checked.
  if (!root.has("model")) root.fail("model is missing, allowed: \"lattice2d\" (required)");
  require_physics_present(root);
  run_case_keys().require_present(root);
  return c;
}

std::string run_case_to_toml(const RunCase& c, const std::string& provenance_toml) {
  return "# Resolved configuration of this run: every default filled in. Rerun with\n"
         "#   hmlattice run config.toml --out <dir>\n"
         "model = \"lattice2d\"\n\n" +
         physics_to_toml(c.physics) + "\n" + run_case_keys().to_toml(c) + provenance_toml;
}

}  // namespace hm::cases
