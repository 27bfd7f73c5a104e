#include "hm/case/run_case.hpp"

#include <sstream>

#include "hm/core/input_error.hpp"
#include "hm/analytic/validation.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"

namespace hm::cases {

namespace lt = hm::lattice2d;

namespace {

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + analytic::format_value(v[i]);
  return s + "]";
}

// Runs `read` and reports an InputError from a library parser or validate() as
// "<file>: [table] key = value, allowed: rule" (the library's "table." or "struct." prefix dropped).
template <class F>
void located(CaseTable& table, const std::string& prefix, F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    std::string what = e.what();
    if (what.rfind(table.file(), 0) == 0) throw;  // already located
    if (!prefix.empty() && what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    table.fail(what);
  }
}

}  // namespace

lt::BeamParameters RunCase::beams() const { return lt::calibrated_beam_parameters(stiffness_scaling); }

lt::FlowParameters RunCase::flow_parameters() const {
  lt::FlowParameters flow = lt::flow_parameters_of(physics.parameters, stepping.dt_initial);
  flow.borehole_storage = borehole_storage;
  flow.borehole_deformation = borehole_deformation;
  flow.reuse_factorisation = reuse_flow_factorisation;
  flow.refresh_after_refinements = flow_refresh_after_refinements;
  return flow;
}

RunCase read_run_case(const std::filesystem::path& file) {
  CaseFile cf(file);
  CaseTable root = cf.root();
  const std::string model = root.get_string("model", "lattice2d");
  if (model != "lattice2d")
    root.fail("model = \"" + model + "\", allowed: \"lattice2d\" (this command runs the 2D lattice model)");
  root.ignore("provenance");

  RunCase c;
  c.physics = read_physics(root);
  const double R_i = c.physics.parameters.R_i;

  // [lattice]
  CaseTable lat = root.table("lattice");
  located(lat, "", [&] {
    c.lattice.domain = lt::domain_shape_from_string(lat.get_string("domain", "disk"));
    c.lattice.n_particles = lat.get_int("n_particles", c.lattice.n_particles);
    const long long seed = lat.get_int("seed", static_cast<long long>(c.lattice.seed));
    if (seed < 0) throw InputError("seed = " + std::to_string(seed) + ", allowed: >= 0");
    c.lattice.seed = static_cast<std::uint64_t>(seed);
    c.lattice.boundary_spacing_factor = lat.get_double("boundary_spacing_factor", c.lattice.boundary_spacing_factor);
    c.stiffness_scaling = lt::stiffness_scaling_from_string(lat.get_string("stiffness_scaling", lt::to_string(c.stiffness_scaling)));
    lat.reject_unknown();
    if (c.lattice.domain == lt::DomainShape::rectangle)
      throw InputError("domain = \"rectangle\", allowed: \"disk\" or \"annulus\" (the flow needs a circular outer boundary)");
  });
  const std::string physics_table = c.physics.physical ? "physics_si" : "physics";
  if (c.lattice.domain == lt::DomainShape::disk && R_i != 0.0)
    root.table(physics_table).fail("R_i = " + analytic::format_value(R_i) +
                                   ", allowed: 0 for [lattice] domain = \"disk\" (point injection at r = 0)");
  if (c.lattice.domain == lt::DomainShape::annulus && !(R_i > 0.0))
    root.table(physics_table).fail("R_i = 0, allowed: 0 < R_i < 1 for [lattice] domain = \"annulus\"");
  if (c.lattice.domain == lt::DomainShape::annulus) c.lattice.inner_radius = R_i;
  located(lat, "", [&] { c.lattice.validate(); });

  // [mechanics]
  CaseTable mech = root.table("mechanics");
  located(mech, "", [&] {
    c.boundary.outer = lt::boundary_support_from_string(mech.get_string("outer", "free"), "outer");
    c.mechanics.solver = lt::spd_solver_kind_from_string(mech.get_string("solver", "cholmod"));
    mech.reject_unknown();
  });

  // [flow]
  CaseTable flow = root.table("flow");
  located(flow, "", [&] {
    c.borehole_storage = lt::borehole_storage_from_string(flow.get_string("borehole_storage", "biot-modulus"));
    c.borehole_deformation = lt::borehole_deformation_from_string(flow.get_string("borehole_deformation", "biot"));
    c.reuse_flow_factorisation = flow.get_bool("reuse_factorisation", c.reuse_flow_factorisation);
    const long long refresh = flow.get_int("refresh_after_refinements", c.flow_refresh_after_refinements);
    if (refresh < 0 || refresh > 1000000)
      throw InputError("refresh_after_refinements = " + std::to_string(refresh) + ", allowed: 0 ... 1000000");
    c.flow_refresh_after_refinements = static_cast<int>(refresh);
    flow.reject_unknown();
  });

  // [coupling]
  CaseTable cpl = root.table("coupling");
  located(cpl, "coupling.", [&] {
    auto& o = c.coupling;
    o.split = lt::coupling_split_from_string(cpl.get_string("split", lt::to_string(o.split)));
    // The drained split has Psi = 0 by definition: its default follows the split.
    o.terms.psi = cpl.get_double("psi", lt::default_psi(o.split));
    o.terms.xi = cpl.get_double("xi", o.terms.xi);
    o.pressure_tolerance = cpl.get_double("pressure_tolerance", o.pressure_tolerance);
    o.displacement_tolerance = cpl.get_double("displacement_tolerance", o.displacement_tolerance);
    const long long max_it = cpl.get_int("max_iterations", o.max_iterations);
    if (max_it < 1 || max_it > 1000000)
      throw InputError("max_iterations = " + std::to_string(max_it) + ", allowed: 1 <= max_iterations <= 1e6");
    o.max_iterations = static_cast<int>(max_it);
    o.accept_unconverged = cpl.get_bool("accept_unconverged", o.accept_unconverged);
    o.relaxation = lt::coupling_relaxation_from_string(cpl.get_string("relaxation", lt::to_string(o.relaxation)));
    o.initial_relaxation = cpl.get_double("initial_relaxation", o.initial_relaxation);
    const long long depth = cpl.get_int("anderson_depth", o.anderson_depth);
    if (depth < 1 || depth > 50) throw InputError("anderson_depth = " + std::to_string(depth) + ", allowed: 1 ... 50");
    o.anderson_depth = static_cast<int>(depth);
    o.fracture_check = lt::fracture_check_from_string(cpl.get_string("fracture_check", lt::to_string(o.fracture_check)));
    o.predictor = lt::coupling_predictor_from_string(cpl.get_string("predictor", lt::to_string(o.predictor)));
    cpl.reject_unknown();
    o.validate();
  });

  // [fracture]: the switch, the strength heterogeneity and the crack-tip rule; the mean strengths are
  // the material's ([physics]).
  CaseTable frac = root.table("fracture");
  located(frac, "", [&] {
    c.fracture_enabled = frac.get_bool("enabled", false);
    auto& st = c.strength;
    st.tensile_strength = c.physics.parameters.tensile_strength;
    st.compressive_strength = c.physics.parameters.compressive_strength;
    st.friction = c.physics.parameters.friction;
    st.distribution = lt::strength_distribution_from_string(frac.get_string("distribution", lt::to_string(st.distribution)));
    st.width = frac.get_double("width", st.width);
    st.weibull_modulus = frac.get_double("weibull_modulus", st.weibull_modulus);
    st.correlated = frac.get_bool("correlated", st.correlated);
    const long long seed = frac.get_int("seed", static_cast<long long>(st.seed));
    if (seed < 0) throw InputError("seed = " + std::to_string(seed) + ", allowed: >= 0");
    st.seed = static_cast<std::uint64_t>(seed);
    auto& tip = c.break_loop.crack_tip;
    tip.enabled = frac.get_bool("crack_tip", tip.enabled);
    tip.material_length = frac.get_double("crack_tip_length", tip.material_length);
    frac.reject_unknown();
    st.validate();
    analytic::require_positive(tip.material_length, "crack_tip_length");
  });

  // [numerics]
  CaseTable num = root.table("numerics");
  auto& s = c.stepping;
  s.dt_initial = num.get_double("dt_initial", s.dt_initial);
  s.dt_growth = num.get_double("dt_growth", s.dt_growth);
  s.t_end = num.get_double("t_end", s.t_end);
  s.dt_max = num.get_double("dt_max", s.t_end);  // default: no cap below t_end
  const long long halvings = num.get_int("max_step_halvings", s.max_step_halvings);
  if (halvings < 0 || halvings > 50)
    num.fail("max_step_halvings = " + std::to_string(halvings) + ", allowed: 0 ... 50");
  s.max_step_halvings = static_cast<int>(halvings);
  num.reject_unknown();

  // [output]
  CaseTable out = root.table("output");
  auto& o = c.output;
  s.output_times = out.get_doubles("times", {});
  o.times = s.output_times;
  o.vtk = out.get_bool("vtk", o.vtk);
  const long long bins = out.get_int("radial_bins", o.radial_bins);
  o.radial_max = out.get_double("radial_max", o.radial_max);
  located(out, "", [&] {
    o.fracture_link = lt::fracture_link_from_string(out.get_string("fracture_link", lt::to_string(o.fracture_link)),
                                                    "fracture_link");
  });
  out.reject_unknown();
  root.reject_unknown();
  if (bins < 1 || bins > 10000)
    out.fail("radial_bins = " + std::to_string(bins) + ", allowed: 1 <= radial_bins <= 10000");
  o.radial_bins = static_cast<int>(bins);
  if (!(o.radial_max > R_i && o.radial_max <= 1.0))
    out.fail("radial_max = " + analytic::format_value(o.radial_max) + ", allowed: R_i = " + analytic::format_value(R_i) +
             " < radial_max <= 1");

  try {
    s.validate();
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.rfind("output.", 0) == 0) out.fail(what.substr(7));
    num.fail(what.rfind("numerics.", 0) == 0 ? what.substr(9) : what);
  }
  located(num, "", [&] { c.flow_parameters().validate(); });
  return c;
}

namespace {

// The beams every run uses and the continuum they were measured to represent (not inputs: comments).
std::string calibration_comment(const RunCase& c) {
  const lt::BeamParameters beams = c.beams();
  const lt::ElasticConstants continuum = lt::calibrated_continuum(c.stiffness_scaling);
  return "# beams: calibrated_beam_parameters(" + lt::to_string(c.stiffness_scaling) +
         ") k_n = " + analytic::format_value(beams.normal_stiffness) + ", a = " + analytic::format_value(beams.aspect) +
         ", nu0 = " + analytic::format_value(beams.beam_poisson) + ";\n# measured continuum (calibration, " +
         "docs/lattice.md): E = " + analytic::format_value(continuum.youngs_modulus) +
         ", nu = " + analytic::format_value(continuum.poisson_ratio) + " (plane strain)\n";
}

}  // namespace

std::string run_case_to_toml(const RunCase& c, const std::string& provenance_toml) {
  auto v = [](double x) { return analytic::format_value(x); };
  auto b = [](bool x) { return x ? "true" : "false"; };
  const auto& o = c.coupling;
  const auto& s = c.stepping;
  std::ostringstream os;
  os << "# Resolved configuration of this run: every default filled in. Rerun with\n"
     << "#   hmlattice run config.toml --out <dir>\n"
     << "model = \"lattice2d\"\n\n"
     << physics_to_toml(c.physics) << "\n"
     << "[lattice]\ndomain = \"" << lt::to_string(c.lattice.domain) << "\"\nn_particles = " << c.lattice.n_particles
     << "\nseed = " << c.lattice.seed << "\nboundary_spacing_factor = " << v(c.lattice.boundary_spacing_factor)
     << "\nstiffness_scaling = \"" << lt::to_string(c.stiffness_scaling) << "\"\n" << calibration_comment(c) << "\n"
     << "[mechanics]\nouter = \"" << lt::to_string(c.boundary.outer) << "\"\nsolver = \""
     << lt::to_string(c.mechanics.solver) << "\"\n\n"
     << "[flow]\nborehole_storage = \"" << lt::to_string(c.borehole_storage) << "\"\nborehole_deformation = \""
     << lt::to_string(c.borehole_deformation) << "\"\nreuse_factorisation = " << b(c.reuse_flow_factorisation)
     << "\nrefresh_after_refinements = " << c.flow_refresh_after_refinements << "\n\n"
     << "[coupling]\nsplit = \"" << lt::to_string(o.split) << "\"\npsi = " << v(o.terms.psi) << "\nxi = " << v(o.terms.xi)
     << "\npressure_tolerance = " << v(o.pressure_tolerance) << "\ndisplacement_tolerance = "
     << v(o.displacement_tolerance) << "\nmax_iterations = " << o.max_iterations
     << "\naccept_unconverged = " << b(o.accept_unconverged) << "\nrelaxation = \"" << lt::to_string(o.relaxation)
     << "\"\ninitial_relaxation = " << v(o.initial_relaxation) << "\nanderson_depth = " << o.anderson_depth
     << "\nfracture_check = \"" << lt::to_string(o.fracture_check) << "\"\npredictor = \""
     << lt::to_string(o.predictor) << "\"\n\n"
     << "[numerics]\ndt_initial = " << v(s.dt_initial) << "\ndt_growth = " << v(s.dt_growth) << "\ndt_max = "
     << v(s.dt_max) << "\nt_end = " << v(s.t_end) << "\nmax_step_halvings = " << s.max_step_halvings << "\n\n"
     << "[fracture]\nenabled = " << b(c.fracture_enabled) << "\ndistribution = \"" << lt::to_string(c.strength.distribution)
     << "\"\nwidth = " << v(c.strength.width) << "\nweibull_modulus = " << v(c.strength.weibull_modulus)
     << "\ncorrelated = " << b(c.strength.correlated) << "\nseed = " << c.strength.seed
     << "\ncrack_tip = " << b(c.break_loop.crack_tip.enabled)
     << "\ncrack_tip_length = " << v(c.break_loop.crack_tip.material_length) << "\n\n"
     << "[output]\ntimes = " << list(c.output.times) << "\nvtk = " << b(c.output.vtk)
     << "\nradial_bins = " << c.output.radial_bins << "\nradial_max = " << v(c.output.radial_max)
     << "\nfracture_link = \"" << lt::to_string(c.output.fracture_link) << "\"\n\n"
     << provenance_toml;
  return os.str();
}

}  // namespace hm::cases
