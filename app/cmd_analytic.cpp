// hmlattice analytic <solution>: evaluate a closed-form solution of analytic/ and print CSV
// (a header row, then one row per radius; per (r, theta) pair for insitu; per Biot coefficient for
// breakdown, or per Biot coefficient and formula under a far field) to stdout. Dimensionless, tension positive
// (far-field magnitudes S_H, S_h and pressures are given compression positive, as geomechanics
// states them).
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "hm/analytic/biot_modulus.hpp"
#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/analytic/breakdown_limits.hpp"
#include "hm/analytic/insitu_annulus.hpp"
#include "hm/analytic/kgd_transition.hpp"
#include "hm/analytic/lame.hpp"
#include "hm/analytic/rudnicki.hpp"
#include "hm/analytic/sneddon.hpp"
#include "hm/analytic/steady_borehole.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::app {

namespace {

using namespace hm::analytic;
using namespace hm::core;  // require_* and format_value
using core::CsvWriter;

const std::vector<std::string> radial_columns = {"r", "p", "u_r", "sigma_r", "sigma_theta", "sigma_z"};

// Prints the table once every value is known to be finite: an overflowing closed form (t = 1e308,
// R_o = 1e308) is bad input, reported in one line with nothing printed, not a row of inf or nan.
void print_table(const std::vector<std::string>& columns, const std::vector<std::vector<double>>& rows) {
  std::ostringstream table;
  CsvWriter w(table, columns, core::NonFinite::reject);
  for (const auto& row : rows) w.row(row);
  std::cout << table.str();
}

// A table whose first column is a name (CsvWriter writes numbers only): the same number format, and
// the same refusal of a value that overflowed, named by its row.
void print_named_table(const std::string& name_column, const std::vector<std::string>& columns,
                       const std::vector<std::pair<std::string, std::vector<double>>>& rows) {
  std::ostringstream table;
  table << name_column;
  for (const auto& c : columns) table << "," << c;
  table << "\n";
  for (const auto& [name, values] : rows) {
    table << name;
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!std::isfinite(values[i]))
        throw InputError(columns[i] + " = " + csv_number(values[i]) + " for " + name_column + " = " + name +
                         ": the inputs overflow double precision, allowed: inputs whose " + columns[i] + " is finite");
      table << "," << csv_number(values[i]);
    }
    table << "\n";
  }
  std::cout << table.str();
}

double radians(double deg) { return deg * std::numbers::pi / 180.0; }
double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

void print_radial(const std::vector<double>& radii, const std::function<RadialState(double)>& state) {
  std::vector<std::vector<double>> rows;
  for (double r : radii) {
    const RadialState s = state(r);
    rows.push_back({r, s.p, s.u_r, s.sigma_r, s.sigma_theta, s.sigma_z});
  }
  print_table(radial_columns, rows);
}

void require_radii_within(const std::vector<double>& radii, const char* name, double lo, double hi) {
  for (double r : radii) require_closed(r, name, lo, hi);
}

CLI::Option* add_radii(CLI::App* cmd, std::vector<double>& radii, const char* name = "--r") {
  return cmd->add_option(name, radii, "comma-separated positions")->delimiter(',')->required();
}

void add_rudnicki(CLI::App* parent) {
  struct Args {
    double Q = 0.1, b = 0.5, nu = 0.25, t = 3e-4;
    std::optional<double> E_over_M;  // unset: Eq. 22
    std::string vol_strain = "plane-strain";
    std::vector<double> r;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = parent->add_subcommand("rudnicki", "Line source in an unbounded plane (Section 3.1)");
  cmd->add_option("--Q", a->Q, "injection rate")->capture_default_str();
  cmd->add_option("--b", a->b, "Biot coefficient")->capture_default_str();
  cmd->add_option("--nu", a->nu, "Poisson ratio")->capture_default_str();
  cmd->add_option("--t", a->t, "time since injection started")->capture_default_str();
  cmd->add_option("--E_over_M", a->E_over_M, "E/M [default: Eq. 22 with Table 1's porosity, K_w, E]");
  cmd->add_option("--vol_strain", a->vol_strain, "plane-strain or appendix-a")->capture_default_str();
  add_radii(cmd, a->r);
  cmd->callback([a] {
    PoroelasticParameters m;
    m.b = a->b;
    m.nu = a->nu;
    m.E_over_M = a->E_over_M.value_or(E_over_M_table1(a->b, a->nu));
    m.vol_strain = core::from_name<VolStrain>(a->vol_strain, "--vol_strain");
    m.validate();
    require_non_negative(a->Q, "Q");
    require_positive(a->t, "t");
    for (double r : a->r) require_positive(r, "r");
    const RudnickiLineSource sol(a->Q, m);
    print_radial(a->r, [&](double r) { return sol.state(r, a->t); });
  });
}

void add_borehole_steady(CLI::App* parent) {
  struct Args {
    double Q = 0.01, b = 0.5, nu = 0.25, Ri = 0.138;
    std::vector<double> r;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = parent->add_subcommand("borehole-steady", "Steady borehole injection (Appendix B, corrected)");
  cmd->add_option("--Q", a->Q, "injection rate")->capture_default_str();
  cmd->add_option("--b", a->b, "Biot coefficient")->capture_default_str();
  cmd->add_option("--nu", a->nu, "Poisson ratio")->capture_default_str();
  cmd->add_option("--Ri", a->Ri, "borehole radius R_i/R")->capture_default_str();
  add_radii(cmd, a->r);
  cmd->callback([a] {
    require_non_negative(a->Q, "Q");
    require_closed(a->b, "b", 0.0, 1.0);
    require_open(a->nu, "nu", 0.0, 0.5);
    require_open(a->Ri, "Ri", 0.0, 1.0);
    require_radii_within(a->r, "r", a->Ri, 1.0);
    const SteadyBorehole sol(a->Q, a->b, a->nu, a->Ri);
    print_radial(a->r, [&](double r) { return sol.state(r); });
  });
}

void add_sneddon(CLI::App* parent) {
  struct Args {
    double p = 1e-3, c = 0.1, nu = 0.25;
    std::vector<double> x;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = parent->add_subcommand("sneddon", "Pressurised crack aperture (Appendix C, Eq. C1)");
  cmd->add_option("--p", a->p, "crack pressure p/E")->capture_default_str();
  cmd->add_option("--c", a->c, "crack half length")->capture_default_str();
  cmd->add_option("--nu", a->nu, "Poisson ratio")->capture_default_str();
  add_radii(cmd, a->x, "--x");
  cmd->callback([a] {
    require_non_negative(a->p, "p");
    require_positive(a->c, "c");
    require_open(a->nu, "nu", 0.0, 0.5);
    for (double x : a->x) require_finite(x, "x");
    const SneddonCrack crack{a->p, a->c, a->nu};
    std::vector<std::vector<double>> rows;
    for (double x : a->x) rows.push_back({x, crack.half_aperture(x)});
    print_table({"x", "w"}, rows);
  });
}

void add_kgd(CLI::App* parent) {
  struct Args {
    std::vector<double> K_m{0.0, 1.0, 2.0, 4.0};
  };
  auto a = std::make_shared<Args>();
  auto* cmd = parent->add_subcommand(
      "kgd",
      "Plane-strain hydraulic fracture without leak-off between its viscosity and toughness vertices "
      "(Dontsov 2017): l = gamma (E' Q^3 t^4/mu')^(1/6), w(0) = omega (mu' Q^3 t^2/E')^(1/6)");
  cmd->add_option("--Km", a->K_m, "toughness numbers K' (E'^3 mu' Q)^(-1/4), comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  cmd->callback([a] {
    std::vector<std::vector<double>> rows;
    for (double K_m : a->K_m) {
      const KgdTransitionScales s = kgd_transition_scales(K_m);
      rows.push_back({K_m, s.gamma, s.omega, s.k_hat, s.delta, s.lambda});
    }
    print_table({"K_m", "gamma", "omega", "k_hat", "delta", "lambda"}, rows);
  });
}

void add_lame(CLI::App* parent) {
  struct Args {
    double pi = 1e-3, po = 0.0, Ri = 0.138, Ro = 1.0, nu = 0.25;
    std::vector<double> r;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = parent->add_subcommand("lame", "Thick-walled cylinder, plane strain (pressures positive inward)");
  cmd->add_option("--pi", a->pi, "inner pressure")->capture_default_str();
  cmd->add_option("--po", a->po, "outer pressure")->capture_default_str();
  cmd->add_option("--Ri", a->Ri, "inner radius")->capture_default_str();
  cmd->add_option("--Ro", a->Ro, "outer radius")->capture_default_str();
  cmd->add_option("--nu", a->nu, "Poisson ratio")->capture_default_str();
  add_radii(cmd, a->r);
  cmd->callback([a] {
    require_finite(a->pi, "pi");
    require_finite(a->po, "po");
    require_positive(a->Ro, "Ro");
    require_open(a->Ri, "Ri", 0.0, a->Ro);
    require_open(a->nu, "nu", 0.0, 0.5);
    require_radii_within(a->r, "r", a->Ri, a->Ro);
    const LameCylinder sol(a->pi, a->po, a->Ri, a->Ro, a->nu);
    std::vector<std::vector<double>> rows;
    for (double r : a->r) {
      const RadialState s = sol.state(r);
      rows.push_back({r, s.u_r, s.sigma_r, s.sigma_theta, s.sigma_z});
    }
    print_table({"r", "u_r", "sigma_r", "sigma_theta", "sigma_z"}, rows);
  });
}

void add_insitu(CLI::App* parent) {
  struct Args {
    double SH = 0.0, Sh = 0.0, pw = 0.0, theta_H = 0.0, Ri = 0.138, nu = 0.25;
    std::vector<double> r, theta;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = parent->add_subcommand(
      "insitu", "Borehole annulus R_i <= r <= 1 under a far-field stress (traction at r = 1) and a wall pressure");
  cmd->add_option("--SH,--S_H", a->SH, "largest far-field stress magnitude S_H/E, compression positive")->required();
  cmd->add_option("--Sh,--S_h", a->Sh, "smallest far-field stress magnitude S_h/E <= S_H, compression positive")
      ->required();
  cmd->add_option("--pw,--p_w", a->pw, "wall pressure p_w/E (sigma_r = -p_w at r = R_i)")->capture_default_str();
  cmd->add_option("--theta-H,--theta_H", a->theta_H, "azimuth of S_H from the x axis, degrees")->capture_default_str();
  cmd->add_option("--Ri,--R_i", a->Ri, "borehole radius R_i/R")->capture_default_str();
  cmd->add_option("--nu", a->nu, "Poisson ratio")->capture_default_str();
  add_radii(cmd, a->r);
  cmd->add_option("--theta", a->theta,
                  "comma-separated polar angles, degrees from the x axis: from S_H with the default --theta-H 0")
      ->delimiter(',')
      ->required();
  cmd->callback([a] {
    const InSituAnnulus sol({a->SH, a->Sh, radians(a->theta_H)}, a->pw, a->Ri, a->nu);
    std::vector<std::vector<double>> rows;
    for (double r : a->r)
      for (double theta : a->theta) {
        const PolarState s = sol.state(r, radians(theta));
        rows.push_back({r, theta, s.sigma_r, s.sigma_theta, s.sigma_rtheta});
      }
    print_table({"r", "theta", "sigma_r", "sigma_theta", "sigma_rtheta"}, rows);
  });
}

void add_breakdown(CLI::App* parent) {
  struct Args {
    std::vector<double> b;
    hm::analytic::DimensionlessParameters d;  // Table 1's nu, R_i, T_u
    double SH = 0.0, Sh = 0.0, p0 = 0.0;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = parent->add_subcommand(
      "breakdown",
      "Breakdown pressures: without --SH/--Sh the unfractured borehole's limits (1D model: q_min, slow, "
      "fast, jacketed); with them Hubbert-Willis, Haimson-Fairhurst and the jacketed annulus under the "
      "far field (docs/insitu.md)");
  cmd->add_option("--b", a->b, "comma-separated Biot coefficients; E/M by Eq. 22 with Table 1's porosity, K_w, E")
      ->delimiter(',')
      ->required();
  cmd->add_option("--nu", a->d.material.nu, "Poisson ratio")->capture_default_str();
  cmd->add_option("--Ri,--R_i", a->d.R_i, "borehole radius R_i/R")->capture_default_str();
  cmd->add_option("--Tu,--T_u", a->d.tensile_strength, "tensile strength T_u/E")->capture_default_str();
  auto* SH = cmd->add_option("--SH,--S_H", a->SH, "largest far-field stress magnitude S_H/E, compression positive");
  auto* Sh =
      cmd->add_option("--Sh,--S_h", a->Sh, "smallest far-field stress magnitude S_h/E <= S_H, compression positive");
  auto* p0 = cmd->add_option("--p0", a->p0, "in-situ pore pressure p0/E, compression positive (with --SH, --Sh)")
                 ->capture_default_str();
  SH->needs(Sh);
  Sh->needs(SH);
  p0->needs(SH);
  cmd->callback([a, SH] {
    // Named as the user typed them; every row is validated before any is printed.
    require_open(a->d.material.nu, "nu", 0.0, 0.5);
    require_open(a->d.R_i, "Ri", 0.0, 1.0);
    require_positive(a->d.tensile_strength, "Tu");
    if (SH->count() > 0) {
      // One row per b and formula: the wall pressure at which the effective hoop stress first reaches
      // T_u, and its angle from S_H.
      const FarFieldStress far{a->SH, a->Sh, 0.0};
      std::vector<std::pair<std::string, std::vector<double>>> rows;
      for (double b : a->b) {
        const BreakdownParameters m{.T_u = a->d.tensile_strength, .p0 = a->p0, .b = b, .nu = a->d.material.nu};
        for (const auto& [name, bd] : {std::pair{"hubbert_willis", hubbert_willis_breakdown(far, m)},
                                       std::pair{"haimson_fairhurst", haimson_fairhurst_breakdown(far, m)},
                                       std::pair{"annulus_jacketed", annulus_jacketed_breakdown(far, m, a->d.R_i)}})
          rows.push_back({name, {b, bd.p_w, degrees(bd.theta)}});
      }
      print_named_table("formula", {"b", "p_b", "theta_deg"}, rows);
      return;
    }
    std::vector<std::vector<double>> rows;
    for (double b : a->b) {
      require_closed(b, "b", 0.0, 1.0);
      DimensionlessParameters d = a->d;
      d.material.b = b;
      d.material.E_over_M = E_over_M_table1(b, d.material.nu);
      const BreakdownLimits l = breakdown_limits(d);
      rows.push_back({b, l.q_min, l.p_b_slow, l.p_b_fast, l.p_b_jacketed});
    }
    print_table({"b", "q_min", "p_b_slow", "p_b_fast", "p_b_jacketed"}, rows);
  });
}

}  // namespace

void add_analytic_command(CLI::App& app, int& /*exit_code*/) {
  auto* cmd = app.add_subcommand("analytic", "Print a closed-form solution as CSV");
  cmd->require_subcommand(1);
  add_rudnicki(cmd);
  add_borehole_steady(cmd);
  add_sneddon(cmd);
  add_kgd(cmd);
  add_lame(cmd);
  add_insitu(cmd);
  add_breakdown(cmd);
}

}  // namespace hm::app
