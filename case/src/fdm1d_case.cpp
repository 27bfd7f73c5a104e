#include "hm/case/fdm1d_case.hpp"

#include <cstring>
#include <limits>
#include <utility>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::cases {

namespace {

CaseKeys<Fdm1dCase> make_fdm1d_case_keys() {
  CaseKeys<Fdm1dCase> k;
  k.table("numerics")
      .integer("n_r", [](auto& c) -> auto& { return c.numerics.n_r; }, std::numeric_limits<int>::min(),
               std::numeric_limits<int>::max(), "8 <= n_r <= 1000000", "grid intervals on [R_i, 1]")
      .real("dt_initial", [](auto& c) -> auto& { return c.numerics.dt_initial; }, "> 0", "first time step")
      .real("dt_growth", [](auto& c) -> auto& { return c.numerics.dt_growth; }, ">= 1",
            "dt_(k+1) = min(dt_growth dt_k, dt_max)")
      .real("dt_max", [](auto& c) -> auto& { return c.numerics.dt_max; }, ">= dt_initial", "largest time step")
      .real("t_end", [](auto& c) -> auto& { return c.numerics.t_end; }, "> 0", "end time t*")
      .required();
  k.table("output")
      .reals("times", [](auto& c) -> auto& { return c.numerics.output_times; }, "increasing, in (0, t_end]",
             "times of the stored profiles; t_end is always stored")
      .reals("probes", [](auto& c) -> auto& { return c.numerics.probe_radii; }, "each in [R_i, 1]",
             "radii at which p is recorded at every step (Fig. 10C/D)");
  return k;
}

}  // namespace

const CaseKeys<Fdm1dCase>& fdm1d_case_keys() {
  static const CaseKeys<Fdm1dCase> keys = make_fdm1d_case_keys();
  return keys;
}

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
  fdm1d_case_keys().read(root, c);
  root.reject_unknown();

  try {
    c.numerics.validate(c.physics.parameters.R_i);
  } catch (const InputError& e) {
    // Fdm1dNumerics names its fields; say it with the case file's table and key names.
    std::string what = e.what();
    const bool is_output = what.rfind("output_times", 0) == 0 || what.rfind("probe_radii", 0) == 0;
    for (auto [field, key] : {std::pair{"output_times", "times"}, std::pair{"probe_radii", "probes"}})
      for (std::size_t at; (at = what.find(field)) != std::string::npos;) what.replace(at, std::strlen(field), key);
    root.table(is_output ? "output" : "numerics").fail(what);
  }
  // What an empty or truncated file lacks, once every given value has been checked.
  if (!root.has("model")) root.fail("model is missing, allowed: \"fdm1d\" (required)");
  require_physics_present(root);
  fdm1d_case_keys().require_present(root);
  return c;
}

std::string fdm1d_case_to_toml(const Fdm1dCase& c, const std::string& provenance_toml) {
  return "# Resolved configuration of this run: every default filled in. Rerun with\n"
         "#   hmlattice fdm1d config.toml --out <dir>\n"
         "model = \"fdm1d\"\n\n" +
         physics_to_toml(c.physics) + "\n" + fdm1d_case_keys().to_toml(c) + provenance_toml;
}

}  // namespace hm::cases
