#include "hm/case/fdm1d_case.hpp"

#include <cstring>
#include <sstream>

#include "hm/core/input_error.hpp"
#include "hm/analytic/validation.hpp"

namespace hm::cases {

namespace {

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + analytic::format_value(v[i]);
  return s + "]";
}

}  // namespace

Fdm1dCase read_fdm1d_case(const std::filesystem::path& file) {
  CaseFile cf(file);
  CaseTable root = cf.root();
  const std::string model = root.get_string("model", "fdm1d");
  if (model != "fdm1d") root.fail("model = \"" + model + "\", allowed: \"fdm1d\" (this command runs the 1D model)");
  root.ignore("provenance");

  Fdm1dCase c;
  c.physics = read_physics(root);
  if (!(c.physics.parameters.R_i > 0.0))
    root.fail("R_i = 0, allowed: 0 < R_i < 1 (the 1D model needs a borehole)");

  CaseTable num = root.table("numerics");
  auto& n = c.numerics;
  n.n_r = static_cast<int>(num.get_int("n_r", n.n_r));
  n.dt_initial = num.get_double("dt_initial", n.dt_initial);
  n.dt_growth = num.get_double("dt_growth", n.dt_growth);
  n.dt_max = num.get_double("dt_max", n.dt_max);
  n.t_end = num.get_double("t_end", n.t_end);
  num.reject_unknown();

  CaseTable out = root.table("output");
  n.output_times = out.get_doubles("times", n.output_times);
  n.probe_radii = out.get_doubles("probes", n.probe_radii);
  out.reject_unknown();
  root.reject_unknown();

  try {
    n.validate(c.physics.parameters.R_i);
  } catch (const InputError& e) {
    // Fdm1dNumerics names its fields; say it with the case file's table and key names.
    std::string what = e.what();
    const bool is_output = what.rfind("output_times", 0) == 0 || what.rfind("probe_radii", 0) == 0;
    for (auto [field, key] : {std::pair{"output_times", "times"}, std::pair{"probe_radii", "probes"}})
      for (std::size_t at; (at = what.find(field)) != std::string::npos;) what.replace(at, std::strlen(field), key);
    (is_output ? out : num).fail(what);
  }
  return c;
}

std::string fdm1d_case_to_toml(const Fdm1dCase& c, const std::string& provenance_toml) {
  const auto& n = c.numerics;
  std::ostringstream os;
  auto v = [](double x) { return analytic::format_value(x); };
  os << "# Resolved configuration of this run: every default filled in. Rerun with\n"
     << "#   hmlattice fdm1d config.toml --out <dir>\n"
     << "model = \"fdm1d\"\n\n"
     << physics_to_toml(c.physics) << "\n"
     << "[numerics]\nn_r = " << n.n_r << "\ndt_initial = " << v(n.dt_initial) << "\ndt_growth = " << v(n.dt_growth)
     << "\ndt_max = " << v(n.dt_max) << "\nt_end = " << v(n.t_end) << "\n\n"
     << "[output]\ntimes = " << list(n.output_times) << "\nprobes = " << list(n.probe_radii) << "\n\n"
     << provenance_toml;
  return os.str();
}

}  // namespace hm::cases
