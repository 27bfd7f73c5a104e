#include "hm/case/fdm1d_case.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::cases {

namespace {

// The key tables are laid out one key per entry (clang-format would break each entry before its name).
// clang-format off
CaseKeys<Fdm1dCase> make_fdm1d_case_keys() {
  CaseKeys<Fdm1dCase> k;
  // S_H and S_h as in a 2D case, so that one sweep can name both models; they must be equal here.
  k.table("mechanics")
      .real("S_H", [](auto& c) -> auto& { return c.rest.S; }, ">= 0, finite; equal to S_h",
            "in-situ stress S/E, compression positive (isotropic: S_H = S_h; docs/insitu.md)")
      .key({"S_h", "real", "S_H", "equal to S_H (the 1D model is radially symmetric)",
            "in-situ smallest horizontal stress: must be S_H",
            [](CaseTable& t, Fdm1dCase& c) {
              const double S_h = t.get_double("S_h", c.rest.S);
              if (S_h != c.rest.S)
                t.fail("S_h = " + core::format_value(S_h) + ", allowed: equal to S_H = " + core::format_value(c.rest.S) +
                       " (the 1D model is radially symmetric: isotropic in-situ stress only)");
            },
            [](const Fdm1dCase& c) { return toml_real(c.rest.S); }})
      .real("p0", [](auto& c) -> auto& { return c.rest.p0; }, ">= 0, finite",
            "rest pore pressure p0/E: p is the deviation from it (docs/insitu.md)")
      .check([](CaseTable& t, CaseTable&, Fdm1dCase& c) {
        if (!(std::isfinite(c.rest.S) && c.rest.S >= 0.0))  // RestState's S is the case's S_H
          t.fail("S_H = " + core::format_value(c.rest.S) + ", allowed: >= 0, finite (compression positive)");
        c.rest.validate();
      });
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

// clang-format on
}  // namespace

const CaseKeys<Fdm1dCase>& fdm1d_case_keys() {
  static const CaseKeys<Fdm1dCase> keys = make_fdm1d_case_keys();
  return keys;
}

Fdm1dCase read_fdm1d_case(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return read_fdm1d_case(CaseFile(file, overrides));
}

Fdm1dCase read_fdm1d_case(const CaseFile& file) {
  CaseTable root = file.root();
  const std::string model = root.get_string("model", "fdm1d");
  if (model != "fdm1d") root.fail("model = \"" + model + "\", allowed: \"fdm1d\" (this command runs the 1D model)");
  root.ignore("provenance");

  Fdm1dCase c;
  c.physics = read_physics(root);
  if (!(c.physics.parameters.R_i > 0.0)) root.fail("R_i = 0, allowed: 0 < R_i < 1 (the 1D model needs a borehole)");
  fdm1d_case_keys().read(root, c);
  root.reject_unknown();
  // The default output times are Fig. 10's, up to t* = 1: a shorter run keeps those it reaches (its
  // t_end is always stored); times the file gives are checked as given.
  if (!root.table("output").has("times"))
    std::erase_if(c.numerics.output_times, [&](double t) { return t > c.numerics.t_end; });

  try {
    c.numerics.validate(c.physics.parameters.R_i);
  } catch (const FieldError& e) {
    // Fdm1dNumerics names its fields; the case file has two of them in [output] under other keys.
    const auto output_key = e.field() == "output_times" ? "times" : e.field() == "probe_radii" ? "probes" : "";
    if (*output_key) root.table("output").fail(e.message_as(output_key));
    root.table("numerics").fail(e.what());
  } catch (const InputError& e) {
    root.table("numerics").fail(e.what());
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
