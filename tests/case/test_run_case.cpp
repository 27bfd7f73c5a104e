// `hmlattice run` and its case format (hm/case/run_case.hpp), through the executable as a user
// meets it: a bad case gives one line naming [table] key, value and rule, exit code 2, nothing written.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::TempDir;

namespace {

// A valid small case: N = 600 disk, two steps. Tests prepend or append one bad table.
const std::string small_case =
    "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 600\n"
    "[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n";

}  // namespace

TEST_CASE("Bad 2D cases are rejected with one line naming table, key, value and rule, and nothing is written",
          "[verification][cli]") {
  TempDir dir("cli-run-bad");
  auto rejected = [&](const std::string& toml, const std::string& must_mention) {
    dir.write("case.toml", toml);
    const auto r = run_hmlattice("run case.toml --out run", dir.path);
    INFO("case:\n" << toml << "stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(must_mention));
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  };
  const std::string physics = "[physics]\nQ = 0.1\nR_i = 0\n";
  rejected("model = \"fdm1d\"\n" + physics, "model = \"fdm1d\", allowed: \"lattice2d\"");
  rejected("[physics]\nb = 1.2\nR_i = 0\n", "case.toml: [physics] b = 1.2, allowed: 0 <= b <= 1");
  rejected("[physics]\nQ = 0.1\n", "case.toml: [physics] R_i = 0.138, allowed: 0 for [lattice] domain = \"disk\"");
  rejected("[physics]\nR_i = 0\n[lattice]\ndomain = \"annulus\"\n",
           "case.toml: [physics] R_i = 0, allowed: 0 < R_i < 1 for [lattice] domain = \"annulus\"");
  rejected(physics + "[lattice]\ndomain = \"square\"\n",
           "case.toml: [lattice] domain = 'square', allowed: disk, annulus");
  rejected(physics + "[lattice]\ndomain = \"rectangle\"\n",
           "case.toml: [lattice] domain = 'rectangle', allowed: disk, annulus");
  rejected(physics + "[lattice]\nn_particles = 10\n", "case.toml: [lattice] n_particles = 10, allowed: ");
  rejected(physics + "[lattice]\nseed = -3\n", "case.toml: [lattice] seed = -3, allowed: >= 0");
  rejected(physics + "[lattice]\nN = 1000\n", "case.toml: [lattice] unknown key 'N', allowed: ");
  rejected(physics + "[lattice]\nstiffness_scaling = \"facet\"\n",
           "case.toml: [lattice] stiffness_scaling = 'facet', allowed: voronoi_facet, uniform");
  rejected(physics + "[lattice]\nboundary_spacing_factor = 2\n",
           "case.toml: [lattice] boundary_spacing_factor = 2, allowed: ");
  rejected(physics + "[flow]\nrefresh_after_refinements = -2\n",
           "case.toml: [flow] refresh_after_refinements = -2, allowed: 0 ... 1000000");
  rejected(physics + "[coupling]\nfracture_check = \"sometimes\"\n",
           "case.toml: [coupling] fracture_check = 'sometimes', allowed: every_pass, at_convergence");
  rejected(physics + "[coupling]\npredictor = \"quadratic\"\n",
           "case.toml: [coupling] predictor = 'quadratic', allowed: previous, linear");
  rejected(physics + "[output]\nfracture_link = \"beam\"\n",
           "case.toml: [output] fracture_link = 'beam', allowed: particle, triangle");
  rejected(physics + "[output]\narm_gap = 0\n", "case.toml: [output] arm_gap = 0, allowed: 0 < arm_gap <= 1");
  rejected(physics + "[mechanics]\nouter = \"clamped\"\n",
           "case.toml: [mechanics] outer = 'clamped', allowed: free, fixed");
  rejected(physics + "[mechanics]\nsolver = \"lu\"\n", "case.toml: [mechanics] solver = 'lu', allowed: cholmod, pcg");
  rejected(physics + "[mechanics]\nS_H = 1e-4\nS_h = 2e-4\n",
           "case.toml: [mechanics] S_h = 2e-04, allowed: 0 <= S_h <= S_H (1e-04)");
  rejected(physics + "[mechanics]\nS_H = -1e-4\n", "case.toml: [mechanics] S_H = -1e-04, allowed: ");
  rejected(physics + "[mechanics]\np0 = -1e-5\n", "case.toml: [mechanics] p0 = -1e-05, allowed: >= 0");
  rejected(physics + "[mechanics]\nouter = \"fixed\"\nS_H = 1e-4\n",
           "case.toml: [mechanics] outer = \"fixed\", allowed: \"free\" with an in-situ stress or p0");
  rejected(physics + "[flow]\nborehole_storage = \"tank\"\n", "case.toml: [flow] borehole_storage = 'tank', allowed: ");
  rejected(physics + "[coupling]\nsplit = \"monolithic\"\n",
           "case.toml: [coupling] split = 'monolithic', allowed: undrained, drained");
  rejected(physics + "[coupling]\npsi = -1\n", "case.toml: [coupling] psi = -1, allowed: ");
  rejected(physics + "[coupling]\nsplit = \"drained\"\npsi = 1.3\n",
           "case.toml: [coupling] psi = 1.3, allowed: 0 for split = drained");
  rejected(physics + "[coupling]\nxi = 0\n", "case.toml: [coupling] xi = 0, allowed: ");
  rejected(physics + "[coupling]\npressure_tolerance = 2\n", "case.toml: [coupling] pressure_tolerance = 2, allowed: ");
  rejected(physics + "[coupling]\nbalance_tolerance = 0\n",
           "case.toml: [coupling] balance_tolerance = 0, allowed: 1e-10 <= ");
  rejected(physics + "[coupling]\nmax_iterations = 0\n", "case.toml: [coupling] max_iterations = 0, allowed: ");
  rejected(physics + "[flow]\nborehole_deformation = \"half\"\n",
           "case.toml: [flow] borehole_deformation = 'half', allowed: biot, none, full");
  rejected(physics + "[flow]\ncrack_coupling = \"half\"\n",
           "case.toml: [flow] crack_coupling = 'half', allowed: biot, full");
  rejected(physics + "[flow]\nfracture_flow = \"plates\"\n",
           "case.toml: [flow] fracture_flow = 'plates', allowed: permeability, transmissivity, cubic");
  rejected(physics + "[flow]\nfracture_flow = \"cubic\"\n",
           "case.toml: [flow] rock_permeability is missing, allowed: 1e-25 <= value <= 1e-2 (k/R^2), required with "
           "fracture_flow = \"cubic\" and [physics]");
  rejected(physics + "[flow]\nfracture_flow = \"cubic\"\nrock_permeability = 1e-30\n",
           "case.toml: [flow] rock_permeability = 1e-30, allowed: 1e-25 <= value <= 1e-2 (k/R^2)");
  rejected(physics + "[flow]\nrock_permeability = 1e-14\n",
           "case.toml: [flow] rock_permeability = 1e-14, allowed: only with fracture_flow = \"cubic\"");
  rejected(physics + "[flow]\nfracture_flow = \"cubic\"\nrock_permeability = 1e-14\nresidual_aperture = 0.1\n",
           "case.toml: [flow] residual_aperture = 0.1, allowed: 0 <= value <= 0.01 (over R)");
  rejected(physics + "[flow]\nfracture_flow = \"cubic\"\nrock_permeability = 1e-14\nresidual_aperture = nan\n",
           "case.toml: [flow] residual_aperture = nan, allowed: a finite number");
  rejected(physics + "[flow]\nresidual_aperture = 1e-4\n",
           "case.toml: [flow] residual_aperture = 1e-04, allowed: only with fracture_flow = \"cubic\"");
  rejected(physics + "[flow]\ncrack_aperture = \"jump\"\n",
           "case.toml: [flow] crack_aperture = \"jump\", allowed: only with fracture_flow = \"cubic\" (the other laws "
           "have no aperture)");
  rejected(physics + "[flow]\nfracture_flow = \"cubic\"\nrock_permeability = 1e-14\ncrack_aperture = \"normal\"\n",
           "case.toml: [flow] crack_aperture = 'normal', allowed: axial, jump");
  rejected(
      "[physics_si]\nq = 1e-4\nb = 0.5\nk = 1e-15\nR = 10\nR_i = 0\n[flow]\nfracture_flow = "
      "\"cubic\"\nrock_permeability = 1e-14\n",
      "case.toml: [flow] rock_permeability = 1e-14, allowed: k/R^2 of [physics_si] (1e-17)");
  rejected("[physics]\nQ = 0.1\nR_i = 0\niota = 1000\n[flow]\nfracture_flow = \"cubic\"\nrock_permeability = 1e-14\n",
           "case.toml: [physics] iota = 1000, allowed: 1 with [flow] fracture_flow = \"cubic\" (the crack's "
           "conductance is its aperture's)");
  rejected(physics + "[flow]\nfracture_flow = \"transmissivity\"\ncrack_transmissivity = -1\n",
           "case.toml: [flow] crack_transmissivity = -1, allowed: 0 <= value <= 1e12");
  rejected(physics + "[flow]\ncrack_transmissivity = 5\n",
           "case.toml: [flow] crack_transmissivity = 5, allowed: only with fracture_flow = \"transmissivity\"");
  rejected(
      "[physics]\nQ = 0.1\nR_i = 0\niota = 1000\n[flow]\nfracture_flow = \"transmissivity\"\ncrack_transmissivity = "
      "5\n",
      "case.toml: [physics] iota = 1000, allowed: 1 with [flow] fracture_flow = \"transmissivity\"");
  rejected(physics + "[coupling]\nbroken_beam_spring = \"soft\"\n",
           "case.toml: [coupling] broken_beam_spring = 'soft', allowed: keep, drop");
  rejected(physics + "[coupling]\nborehole_spring = \"soft\"\n",
           "case.toml: [coupling] borehole_spring = 'soft', allowed: none, undrained");
  rejected(physics + "[coupling]\nborehole_spring = \"undrained\"\n",
           "case.toml: [coupling] borehole_spring = \"undrained\", allowed: only with [lattice] domain = \"annulus\"");
  rejected(
      "[physics]\nQ = 0.1\n[lattice]\ndomain = \"annulus\"\n[flow]\nborehole_storage = \"none\"\n"
      "[coupling]\nborehole_spring = \"undrained\"\n",
      "case.toml: [coupling] borehole_spring = \"undrained\", allowed: only with [flow] borehole_storage and "
      "borehole_deformation not \"none\"");
  rejected(physics + "[flow]\nreuse_factorisation = 1\n", "case.toml: [flow] reuse_factorisation = ");
  rejected(physics + "[coupling]\nrelaxation = \"secant\"\n", "case.toml: [coupling] relaxation = 'secant', allowed: ");
  rejected(physics + "[coupling]\nanderson_depth = 0\n", "case.toml: [coupling] anderson_depth = 0, allowed: 1 ... 50");
  rejected(physics + "[numerics]\nmax_step_halvings = -1\n",
           "case.toml: [numerics] max_step_halvings = -1, allowed: 0 ... 50");
  rejected(physics + "[fracture]\nseed = -2\n", "case.toml: [fracture] seed = -2, allowed: >= 0");
  rejected(physics + "[fracture]\nwidth = 1.5\n", "case.toml: [fracture] width = 1.5, allowed: ");
  rejected(physics + "[fracture]\ndistribution = \"normal\"\n",
           "case.toml: [fracture] distribution = 'normal', allowed: ");
  rejected(physics + "[fracture]\ncrack_tip_length = 0\n", "case.toml: [fracture] crack_tip_length = 0, allowed: ");
  rejected(physics + "[fracture]\nstop_at_first_break = true\n",
           "case.toml: [fracture] stop_at_first_break = true, allowed: true only with enabled = true");
  rejected(physics + "[fracture]\nenabled = true\nstop_at_first_break = \"yes\"\n",
           "case.toml: [fracture] stop_at_first_break = ");
  rejected(physics + "[fracture]\nenabled = true\nstop_at_first_break = 1\n",
           "case.toml: [fracture] stop_at_first_break = ");
  rejected("[physics]\nQ = 0.1\nR_i = 0\ntensile_strength = -1\n",
           "case.toml: [physics] tensile_strength = -1, allowed: ");
  rejected(physics + "[numerics]\ndt_initial = -1\n", "case.toml: [numerics] dt_initial = -1, allowed: ");
  rejected(physics + "[numerics]\ndt_growth = 0.9\n", "case.toml: [numerics] dt_growth = 0.9, allowed: >= 1");
  rejected(physics + "[numerics]\nt_end = 1e-4\ndt_initial = 1e-3\n",
           "case.toml: [numerics] dt_initial = 0.001, allowed: <= t_end = 1e-04");
  rejected(physics + "[output]\ntimes = [1.0]\n", "case.toml: [output] times[0] = 1, allowed: 0 < t <= t_end = 1e-04");
  rejected(physics + "[output]\nradial_bins = 0\n", "case.toml: [output] radial_bins = 0, allowed: 1 <= radial_bins");
  rejected(physics + "[output]\nradial_max = 2\n",
           "case.toml: [output] radial_max = 2, allowed: R_i = 0 < radial_max <= 1");
  rejected(physics + "[output]\nvtk = \"yes\"\n", "case.toml: [output] vtk = ");
  rejected(physics + "[numerics\n", "case.toml:4: malformed TOML: ");
}

TEST_CASE("hmlattice run writes series, radial profiles, VTK and a resolved config that reruns identically",
          "[verification][cli]") {
  TempDir dir("cli-run");
  dir.write("case.toml", small_case + "[output]\ntimes = [5e-6]\nradial_bins = 5\n");
  const auto first = run_hmlattice("run case.toml --out run1", dir.path);
  INFO("stderr: " << first.err);
  REQUIRE(first.exit_code == 0);
  for (const char* f :
       {"series.csv", "radial.csv", "config.toml", "vtk/lattice.pvd", "vtk/lattice_0000.vtu", "vtk/lattice_0002.vtu"})
    CHECK(std::filesystem::exists(dir.path / "run1" / f));
  // Header plus t = 0 plus two steps; three outputs (0, 5e-6, 1e-5) of five shells plus a header.
  CHECK(count_lines(hm::test::slurp(dir.path / "run1" / "series.csv")) == 4);
  CHECK(count_lines(hm::test::slurp(dir.path / "run1" / "radial.csv")) == 16);
  // The summary states the peak memory: at least the lattice and its factor, a few MB at N = 600,
  // and far below 1 GB.
  const auto at = first.out.find("peak memory ");
  REQUIRE(at != std::string::npos);
  const double mb = std::stod(first.out.substr(at + 12));
  CHECK(mb > 1.0);
  CHECK(mb < 1000.0);
  const auto second = run_hmlattice("run run1/config.toml --out run2", dir.path);
  REQUIRE(second.exit_code == 0);
  CHECK(hm::test::slurp(dir.path / "run1" / "radial.csv") == hm::test::slurp(dir.path / "run2" / "radial.csv"));
  const std::string config = hm::test::slurp(dir.path / "run1" / "config.toml");
  CHECK_THAT(config, Catch::Contains("split = \"undrained\""));
  CHECK_THAT(config, Catch::Contains("[provenance]"));
  // The lattice's defaults are written out (facet-scaled beams, boundary row at 1.3 r_min) ...
  CHECK_THAT(config, Catch::Contains("stiffness_scaling = \"voronoi_facet\""));
  CHECK_THAT(config, Catch::Contains("boundary_spacing_factor = 1.3"));
  // ... and the paper's uniform lattice is a different, repeatable model.
  const std::string uniform_case =
      "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 600\n"
      "stiffness_scaling = \"uniform\"\nboundary_spacing_factor = 1.0\n"
      "[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n[output]\ntimes = [5e-6]\nradial_bins = 5\n";
  dir.write("uniform.toml", uniform_case);
  REQUIRE(run_hmlattice("run uniform.toml --out run3", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("run run3/config.toml --out run4", dir.path).exit_code == 0);
  CHECK(hm::test::slurp(dir.path / "run3" / "radial.csv") == hm::test::slurp(dir.path / "run4" / "radial.csv"));
  CHECK(hm::test::slurp(dir.path / "run3" / "radial.csv") != hm::test::slurp(dir.path / "run1" / "radial.csv"));
  CHECK_THAT(hm::test::slurp(dir.path / "run3" / "config.toml"), Catch::Contains("stiffness_scaling = \"uniform\""));
}

TEST_CASE("A coupled run that does not converge exits 1 with the reason and keeps its steps, marked incomplete",
          "[verification][cli]") {
  TempDir dir("cli-run-fail");
  dir.write("case.toml", small_case + "max_step_halvings = 0\n[coupling]\nmax_iterations = 1\n");
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("numerical failure: coupling at t = 5e-06: not converged after 1 passes"));
  // With retries, the step is halved max_step_halvings times before the run gives up.
  dir.write("case2.toml", small_case + "max_step_halvings = 2\n[coupling]\nmax_iterations = 1\n");
  const auto retried = run_hmlattice("run case2.toml --out run2", dir.path);
  CHECK(retried.exit_code == 1);
  CHECK_THAT(retried.err, Catch::Contains("coupling at t = 1.25e-06: not converged after 1 passes"));
  // The steps before the failure (here none: it is the first) are kept with the reason.
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(hm::test::slurp(dir.path / "run" / "status.toml"), Catch::Contains("complete = false") &&
                                                                    Catch::Contains("not converged after 1 passes") &&
                                                                    Catch::Contains("last_step = 0\n"));
  CHECK(count_lines(hm::test::slurp(dir.path / "run" / "series.csv")) == 2);  // header and t = 0
}

TEST_CASE("Command-line numbers follow the case files' rules: finite, and an integer written as one",
          "[verification][cli]") {
  TempDir dir("cli-run-values");
  const std::string case_file = std::string(HM_SOURCE_DIR) + "/cases/fig12_b0.2_quick.toml";
  for (const auto& [option, message] : std::vector<std::pair<std::string, std::string>>{
           {"--checkpoint-every nan", "--checkpoint-every: nan, allowed: 0 <= value <= 1e+09, finite"},
           {"--checkpoint-every inf", "--checkpoint-every: inf, allowed: 0 <= value <= 1e+09, finite"},
           {"--stop-after-steps 1e3", "--stop-after-steps: 1e3, allowed: an integer, 1 ... 100000000"},
           {"--stop-after-steps 0", "--stop-after-steps: 0, allowed: an integer, 1 ... 100000000"}}) {
    const auto r = run_hmlattice("run '" + case_file + "' --out run " + option, dir.path);
    INFO(option << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(message));
    CHECK(dir.is_empty());
  }
}

TEST_CASE("A fracturing borehole case of only the required keys runs to its end", "[verification][cli]") {
  // Q, b, n_particles and t_end, with the annulus and fracture on: the defaults (Anderson's relaxation,
  // steps growing by 1.2) run it. With Fig. 5's plain loop and constant steps (the former defaults) the
  // first step did not converge, its oscillating pressures broke the lattice apart and the mechanics
  // became singular after 68 passes.
  TempDir dir("cli-run-required-keys");
  dir.write("case.toml",
            "model = \"lattice2d\"\n[physics]\nQ = 0.01\nb = 0.2\n[lattice]\ndomain = \"annulus\"\n"
            "n_particles = 1000\n[numerics]\nt_end = 0.0272\n[fracture]\nenabled = true\n");
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const std::string config = hm::test::slurp(dir.path / "run" / "config.toml");
  CHECK_THAT(config, Catch::Contains("relaxation = \"anderson\"") && Catch::Contains("dt_growth = 1.2"));
  // It fractures: the borehole breaks down within t_end at Q = 0.01 (Fig. 12's setting).
  CHECK(count_lines(hm::test::slurp(dir.path / "run" / "breaks.csv")) > 10);

  // The former defaults, stated: a numerical failure that says what to try.
  dir.write("plain.toml",
            hm::test::slurp(dir.path / "case.toml") + "[coupling]\nrelaxation = \"none\"\nmax_iterations = 10\n");
  const auto plain = run_hmlattice("run plain.toml --out plain", dir.path);
  CHECK(plain.exit_code == 1);
  CHECK(count_lines(plain.err) == 1);
  CHECK_THAT(plain.err,
             Catch::Contains("numerical failure") &&
                 Catch::Contains("to try: [coupling] relaxation = \"anderson\", a smaller [numerics] dt_initial"));
}

TEST_CASE(
    "A spring feedback, force scale, tolerance, fracture permeability or in-situ stress beyond its plausibility bound "
    "is refused before the run",
    "[verification][cli]") {
  // Psi = 2^63 - 1 once crashed the run (a failed factorisation's snapshot; the crash itself is tested
  // on the solver, test_spd_solver.cpp); psi or xi = 1e12 failed the first solve, and a tolerance of
  // 5e-324 ran 100 passes of the first step before failing. Now each is one line of bad input.
  TempDir dir("cli-run-bounds");
  const std::string base =
      hm::test::edited(hm::test::slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml"),
                       {{"vtk = true", "vtk = false"}});
  for (const auto& [edit, message] : std::vector<std::pair<std::pair<std::string, std::string>, std::string>>{
           {{"psi = 1.3", "psi = 9223372036854775807"},
            "[coupling] psi = 9223372036854775808, allowed: 0 <= psi <= 1e+06"},
           {{"psi = 1.3", "psi = 1.3\nxi = 1e12"}, "[coupling] xi = 1e+12, allowed: 0 < xi <= 1000"},
           {{"pressure_tolerance = 1e-4", "pressure_tolerance = 5e-324"},
            "[coupling] pressure_tolerance = 5e-324, allowed: 1e-10 <= pressure_tolerance < 1"},
           // S_H or p0 = 1e300 overflowed the rest state's loads into NaN at the first solve.
           {{"outer = \"free\"", "outer = \"free\"\nS_H = 1e300\nS_h = 1e-3"},
            "[mechanics] S_H = 1e+300, allowed: <= 1 (over E; the lattice is small-strain)"},
           {{"outer = \"free\"", "outer = \"free\"\np0 = 2.0"}, "[mechanics] p0 = 2, allowed: <= 1 (over E"},
           // iota = 1e18 ran for minutes at N = 1000, 1e300 failed the first step; 1e-3 shattered the
           // lattice (8177 beams) and failed at t = 0.026.
           {{"iota = 1.0", "iota = 1e18"}, "iota = 1e+18, allowed: 1 <= iota <= 1e+12"},
           {{"iota = 1.0", "iota = 1e-3"}, "iota = 0.001, allowed: 1 <= iota <= 1e+12"}}) {
    dir.write("case.toml", hm::test::edited(base, {edit}));
    const auto r = run_hmlattice("run case.toml --out run", dir.path);
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(message));
    CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  }
  // At the bounds the case runs (its first step).
  dir.write("case.toml", hm::test::edited(base, {{"psi = 1.3", "psi = 1e6"},
                                                 {"iota = 1.0", "iota = 1e12"},
                                                 {"t_end = 0.0272", "t_end = 1e-5"},
                                                 {"times = [0.0045, 0.009, 0.0272]", "times = [1e-5]"}}));
  CHECK(run_hmlattice("run case.toml --out at_bound", dir.path).exit_code == 0);
}

TEST_CASE("A 2D case in SI units gives the same dimensionless results as its dimensionless twin",
          "[verification][cli]") {
  // PorePy's scaled-vs-unscaled check through `hmlattice run`: Table 1 with k = 1e-14 m^2 and
  // q = 1e-2 m^2/s is Q = mu q/(k E) = 0.1; E/M comes from Eq. 22 in both (b = 0.5, nu = 0.25).
  TempDir dir("cli-run-si");
  const std::string rest =
      "[lattice]\nn_particles = 600\n[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n"
      "[output]\nradial_bins = 5\nvtk = false\n";
  dir.write("dimensionless.toml", "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nnu = 0.25\nR_i = 0\n" + rest);
  dir.write("si.toml",
            "model = \"lattice2d\"\n[physics_si]\nE = 1e10\nnu = 0.25\nk = 1e-14\nmu = 1e-3\nq = 1e-2\nR = 1\nR_i = "
            "0\nb = 0.5\n" +
                rest);
  REQUIRE(run_hmlattice("run dimensionless.toml --out a", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("run si.toml --out b", dir.path).exit_code == 0);
  auto numbers = [](const std::string& csv) {
    std::istringstream in(csv);
    std::string line, x;
    std::getline(in, line);
    std::vector<double> v;
    while (std::getline(in, line)) {
      std::istringstream cells(line);
      while (std::getline(cells, x, ',')) v.push_back(std::stod(x));
    }
    return v;
  };
  for (const char* file : {"series.csv", "radial.csv"}) {
    const auto a = numbers(hm::test::slurp(dir.path / "a" / file)), b = numbers(hm::test::slurp(dir.path / "b" / file));
    REQUIRE(a.size() == b.size());
    REQUIRE(a.size() > 10);
    double diff = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (std::isnan(a[k])) {
        CHECK(std::isnan(b[k]));
        continue;
      }
      diff = std::max(diff, std::abs(a[k] - b[k]) / std::max(std::abs(a[k]), 1e-300));
    }
    // Round-off of the SI conversion (mu q/(k E) need not be the double 0.1), carried through a linear
    // model and printed with 10 digits; differences in the smallest entries are relative to themselves.
    INFO(file);
    CHECK(diff < 1e-8);
  }
}

TEST_CASE(
    "A fracturing borehole run writes the break log, breakdown and fracture statistics that agree with the series",
    "[verification][cli]") {
  // Fig. 12's setting (b = 0.2, Eq. 16's borehole) at 3x the rate on a coarse annulus: breaks within ~1e-3.
  TempDir dir("cli-run-fracture");
  dir.write("case.toml",
            "model = \"lattice2d\"\n[physics]\nQ = 0.03\nb = 0.2\nR_i = 0.138\n[lattice]\ndomain = \"annulus\"\n"
            "n_particles = 2000\n[coupling]\nrelaxation = \"aitken\"\n[numerics]\ndt_initial = 1e-4\nt_end = 1.2e-3\n"
            "[fracture]\nenabled = true\n[output]\ntimes = [6e-4]\nvtk = false\n");
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const std::string series = hm::test::slurp(dir.path / "run" / "series.csv");
  const std::string breaks = hm::test::slurp(dir.path / "run" / "breaks.csv");
  const std::string breakdown = hm::test::slurp(dir.path / "run" / "breakdown.csv");
  const std::string fractures = hm::test::slurp(dir.path / "run" / "fractures.csv");
  const std::string summary = hm::test::slurp(dir.path / "run" / "fracture_summary.csv");
  CHECK_THAT(breaks, Catch::StartsWith("sequence,beam,particle_i,particle_j,x,y,time,"));
  CHECK_THAT(breakdown, Catch::StartsWith("t_first_break,p_h_before,p_h_first_break,"));
  CHECK(count_lines(summary) == 1 + 3);  // t = 0, 6e-4, 1.2e-3
  // The last series row's n_broken (9th column) equals the break log's length, and is > 0.
  const std::string last = series.substr(series.rfind('\n', series.size() - 2) + 1);
  std::vector<std::string> cells;
  for (std::size_t a = 0, b; a <= last.size(); a = b + 1) {
    b = last.find(',', a);
    if (b == std::string::npos) b = last.size();
    cells.push_back(last.substr(a, b - a));
  }
  REQUIRE(cells.size() >= 9);
  const int n_broken = std::stoi(cells[8]);
  CHECK(n_broken > 0);
  CHECK(count_lines(breaks) == 1 + n_broken);
  // At least one radial fracture from the borehole at the end (the tensile hoop stress peaks at the wall).
  CHECK_THAT(fractures, Catch::Contains(",radial,"));
  const auto config = hm::test::slurp(dir.path / "run" / "config.toml");
  CHECK_THAT(config,
             Catch::Contains("[fracture]\nenabled = true\nstop_at_first_break = false\ndistribution = \"uniform\""));
  CHECK_THAT(config, Catch::Contains("fracture_link = \"particle\""));

  // hmlattice fractures recomputes the same statistics from config.toml and breaks.csv (the rule the
  // run used): byte-identical files; with the triangle rule at least as many fractures (a subset of links).
  auto r2 = run_hmlattice("fractures run", dir.path);
  INFO("stderr: " << r2.err);
  REQUIRE(r2.exit_code == 0);
  CHECK(hm::test::slurp(dir.path / "run" / "fractures.csv") == fractures);
  CHECK(hm::test::slurp(dir.path / "run" / "fracture_summary.csv") == summary);
  r2 = run_hmlattice("fractures run --link triangle", dir.path);
  REQUIRE(r2.exit_code == 0);
  const auto n_fractures = [](const std::string& csv) {  // last row's third column
    const std::string row = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
    return std::stoi(row.substr(row.find(',', row.find(',') + 1) + 1));
  };
  CHECK(n_fractures(hm::test::slurp(dir.path / "run" / "fracture_summary.csv")) >= n_fractures(summary));
  const auto reconfigured = hm::test::slurp(dir.path / "run" / "config.toml");
  CHECK_THAT(reconfigured, Catch::Contains("fracture_link = \"triangle\""));
  CHECK_THAT(reconfigured, Catch::Contains("# fracture statistics recomputed with fracture_link = \"triangle\", "
                                           "arm_gap = 0.03, softened_beams = \"link\" by: "));
  CHECK_THAT(reconfigured, Catch::Contains("[provenance]"));
  // Bad input: one line naming what is wrong, nothing changed.
  r2 = run_hmlattice("fractures run --link beam", dir.path);
  CHECK(r2.exit_code == 2);
  CHECK_THAT(r2.err, Catch::Contains("--link = 'beam', allowed: particle, triangle"));
  r2 = run_hmlattice("fractures nowhere", dir.path);
  CHECK(r2.exit_code == 2);
  CHECK_THAT(r2.err, Catch::Contains("run folder = nowhere has no config.toml"));
  CHECK(hm::test::slurp(dir.path / "run" / "config.toml") == reconfigured);
  // Arms counted with another fixed gap: only that count can change, and config.toml keeps the gap.
  // A gap of the whole arm circle makes every crossing one arm.
  r2 = run_hmlattice("fractures run --arm-gap 1", dir.path);
  REQUIRE(r2.exit_code == 0);
  const auto last_cell = [](const std::string& csv) {
    const std::string row = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
    return std::stoi(row.substr(row.rfind(',') + 1));
  };
  const auto regapped = hm::test::slurp(dir.path / "run" / "fracture_summary.csv");
  CHECK(last_cell(regapped) <= 1);
  CHECK(last_cell(summary) >= last_cell(regapped));
  CHECK_THAT(hm::test::slurp(dir.path / "run" / "config.toml"), Catch::Contains("arm_gap = 1\n"));
  CHECK_THAT(hm::test::slurp(dir.path / "run" / "config.toml"), Catch::Contains("fracture_link = \"triangle\""));
  r2 = run_hmlattice("fractures run --arm-gap 0", dir.path);
  CHECK(r2.exit_code == 2);
  CHECK_THAT(r2.err, Catch::Contains("--arm-gap = 0, allowed: 0 < arm_gap <= 1"));
}

TEST_CASE("A key changed with --set is as the file would have it, validated like it, and kept in config.toml",
          "[case][cli]") {
  TempDir dir("cli-run-set");
  const std::string base = hm::test::short_fig12_case("2e-5");
  dir.write("case.toml", base);
  dir.write("edited.toml",
            hm::test::edited(base, {{"\nQ = 0.01\n", "\nQ = 0.003\n"}, {"\niota = 1.0\n", "\niota = 1000\n"}}));
  // Given before the case file too: each --set takes one value.
  const auto set = run_hmlattice("run --set physics.Q=0.003 case.toml --set physics.iota=1e3 --out set", dir.path);
  INFO(set.err);
  REQUIRE(set.exit_code == 0);
  REQUIRE(run_hmlattice("run edited.toml --out edited", dir.path).exit_code == 0);
  CHECK(hm::test::slurp(dir.path / "set/series.csv") == hm::test::slurp(dir.path / "edited/series.csv"));
  CHECK(hm::test::slurp(dir.path / "set/breaks.csv") == hm::test::slurp(dir.path / "edited/breaks.csv"));
  const std::string config = hm::test::slurp(dir.path / "set/config.toml");
  CHECK_THAT(config, Catch::Contains("\nQ = 0.003\n") && Catch::Contains("\niota = 1000\n"));
  // The resolved config reruns the changed case.
  REQUIRE(run_hmlattice("run set/config.toml --out rerun", dir.path).exit_code == 0);
  CHECK(hm::test::slurp(dir.path / "rerun/series.csv") == hm::test::slurp(dir.path / "set/series.csv"));

  for (const auto& [arg, message] : std::vector<std::pair<std::string, std::string>>{
           {"--set physics.Q=2e6", "case.toml with --set: [physics] Q = 2e+06, allowed: 0 <= Q <= 1e+06"},
           {"--set physics.bogus=1", "case.toml with --set: [physics] unknown key 'bogus'"},
           {"--set physicsQ=1", "--set physicsQ=1: not of the form table.key=value"},
           {"--set 'output.times=[1e-5'", "--set output.times=[1e-5: the value is not TOML"},
           {"--set physics.Q=nan", "[physics] Q = nan"}}) {
    const auto r = run_hmlattice("run case.toml " + arg + " --out bad", dir.path);
    INFO(arg << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(message));
    CHECK_FALSE(std::filesystem::exists(dir.path / "bad"));
  }
  // A resumed run continues its own case.
  const auto resumed = run_hmlattice("run --resume set --set physics.Q=1", dir.path);
  CHECK(resumed.exit_code == 2);
  CHECK_THAT(resumed.err, Catch::Contains("--resume excludes --set"));
  // fdm1d takes it too.
  const auto fdm1d = run_hmlattice("fdm1d " + std::string(HM_SOURCE_DIR) +
                                       "/cases/fdm1d_b0.2.toml --set numerics.n_r=40 --set numerics.t_end=0.03 "
                                       "--set output.times=[0.01,0.03] --out f",
                                   dir.path);
  INFO(fdm1d.err);
  REQUIRE(fdm1d.exit_code == 0);
  CHECK_THAT(hm::test::slurp(dir.path / "f/config.toml"),
             Catch::Contains("\nn_r = 40\n") && Catch::Contains("t_end = 0.03\n"));
}
