// The command line as a user meets it: bad input gives one line naming the parameter, the value
// and what is allowed, exit code 2, and writes nothing.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <vector>

#include "hm/verification/benchmark.hpp"
#include "hm/verification/harness.hpp"
#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::TempDir;

namespace {

void require_clean_rejection(const hm::test::CommandResult& r, const std::string& must_mention) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find(must_mention) != std::string::npos);
  CHECK(r.out.empty());
}

}  // namespace

TEST_CASE("An unknown subcommand is rejected with the list of allowed ones", "[verification][cli]") {
  TempDir dir("cli-unknown");
  const auto r = run_hmlattice("frobnicate", dir.path);
  require_clean_rejection(r, "unknown subcommand 'frobnicate', allowed: ");
  for (const char* command : {"verify", "fdm1d", "analytic"}) CHECK_THAT(r.err, Catch::Contains(command));
  CHECK(dir.is_empty());
}

TEST_CASE("Out-of-range analytic parameters name the parameter, the value and the range", "[verification][cli]") {
  TempDir dir("cli-analytic");
  SECTION("Biot coefficient above 1") {
    require_clean_rejection(run_hmlattice("analytic rudnicki --b 1.5 --r 0.01", dir.path),
                            "b = 1.5, allowed: 0 <= b <= 1");
  }
  SECTION("Poisson ratio at 0.5") {
    require_clean_rejection(run_hmlattice("analytic borehole-steady --nu 0.5 --r 0.5", dir.path),
                            "nu = 0.5, allowed: 0 < nu < 0.5");
  }
  SECTION("borehole radius not below the outer radius") {
    require_clean_rejection(run_hmlattice("analytic borehole-steady --Ri 1 --r 0.5", dir.path),
                            "Ri = 1, allowed: 0 < Ri < 1");
  }
  SECTION("radius outside the annulus") {
    require_clean_rejection(run_hmlattice("analytic borehole-steady --r 0.1", dir.path),
                            "r = 0.1, allowed: 0.138 <= r <= 1");
  }
  SECTION("non-positive time") {
    require_clean_rejection(run_hmlattice("analytic rudnicki --t 0 --r 0.1", dir.path), "t = 0, allowed: t > 0");
  }
  SECTION("unknown volumetric-strain variant") {
    require_clean_rejection(run_hmlattice("analytic rudnicki --vol_strain 3d --r 0.1", dir.path),
                            "--vol_strain = '3d', allowed: plane-strain, appendix-a");
  }
  SECTION("a value that is not a number") {
    require_clean_rejection(run_hmlattice("analytic rudnicki --Q fast --r 0.1", dir.path), "--Q = fast");
  }
  CHECK(dir.is_empty());
}

TEST_CASE("A bad verification tier writes no report", "[verification][cli]") {
  TempDir dir("cli-verify");
  require_clean_rejection(run_hmlattice("verify --tier full --out report", dir.path),
                          "--tier = 'full', allowed: quick, paper");
  CHECK(dir.is_empty());
}

TEST_CASE("verify --list prints each benchmark of the tier with what it checks, and runs and writes nothing",
          "[verification][cli]") {
  TempDir dir("cli-verify-list");
  for (const auto& [tier, filter] :
       std::vector<std::pair<hm::verification::Tier, std::string>>{{hm::verification::Tier::quick, ""},
                                                                   {hm::verification::Tier::paper, ""},
                                                                   {hm::verification::Tier::paper, "fig1"}}) {
    const std::string tier_name = hm::core::name_of(tier);
    const auto r =
        run_hmlattice("verify --list --tier " + tier_name + (filter.empty() ? "" : " --filter " + filter), dir.path);
    INFO("stderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    const auto selected = hm::verification::select_benchmarks(hm::verification::all_benchmarks(), tier, filter);
    REQUIRE(selected.size() > 1);
    // Two lines per benchmark (id and title; its description) and the count.
    CHECK(count_lines(r.out) == 2 * static_cast<int>(selected.size()) + 1);
    for (const hm::verification::Benchmark* b : selected) {
      CHECK_THAT(r.out, Catch::Contains(b->id + " (" + hm::core::name_of(b->tier) + " tier"));
      CHECK_THAT(r.out, Catch::Contains("    " + b->description));
    }
    CHECK_THAT(r.out, Catch::Contains(std::to_string(selected.size()) + " benchmarks in the " + tier_name + " tier"));
  }
  CHECK_THAT(run_hmlattice("verify --list --tier paper --filter fig12", dir.path).out,
             Catch::Contains("the paper's Fig. 12"));
  CHECK(dir.is_empty());
  require_clean_rejection(run_hmlattice("verify --list --out report", dir.path), "--out excludes --list");
  CHECK(dir.is_empty());
}

TEST_CASE("hmlattice analytic prints a CSV header and one row per radius", "[verification][cli]") {
  TempDir dir("cli-csv");
  const auto r = run_hmlattice("analytic lame --pi 1e-3 --Ri 0.5 --Ro 1 --nu 0.25 --r 0.5,1", dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  // Hand check (plane strain, E = 1): A = p_i R_i^2/(R_o^2 - R_i^2) = 1e-3 * 0.25/0.75 = 3.3333e-4,
  // B = A R_o^2 = 3.3333e-4; at r = 1: sigma_r = A - B = 0, sigma_theta = 2A = 6.6667e-4, sigma_z = 2 nu A.
  // u_r(1) = (1+nu)((1-2nu) A + B) = 1.25 * 1.5 * 3.3333e-4 = 6.25e-4; at r = 0.5: sigma_r = A - 4B = -1e-3,
  // sigma_theta = A + 4B, u_r = 1.25 (0.5 A 0.5 + 2B) = 9.375e-4.
  CHECK(r.out ==
        "r,u_r,sigma_r,sigma_theta,sigma_z\n"
        "0.5,0.0009375,-0.001,0.001666666667,0.0001666666667\n"
        "1,0.000625,0,0.0006666666667,0.0001666666667\n");
}

TEST_CASE("hmlattice analytic kgd prints the KGD scales per toughness number", "[verification][cli]") {
  TempDir dir("cli-kgd");
  const auto r = run_hmlattice("analytic kgd --Km 0,100", dir.path);
  REQUIRE(r.exit_code == 0);
  const auto rows = hm::test::csv_rows(r.out);
  REQUIRE(rows.size() == 2);
  CHECK(r.out.rfind("K_m,gamma,omega,k_hat,delta,lambda\n", 0) == 0);
  // The M-vertex (Adachi & Detournay's gamma = 0.6152, within the approximation's 0.15%) and the K-vertex,
  // gamma = 0.9324 K_m^(-2/3) (Griffith's crack holding Q t).
  CHECK(std::stod(rows[0][1]) == Approx(0.6152).epsilon(0.0015));
  CHECK(std::stod(rows[1][1]) == Approx(0.9324 * std::pow(100.0, -2.0 / 3.0)).epsilon(1e-3));
  require_clean_rejection(run_hmlattice("analytic kgd --Km -1", dir.path), "K_m = -1, allowed: 0 <= K_m <= 1e6");
  CHECK(dir.is_empty());
}

TEST_CASE("Bad 1D cases are rejected before anything is written", "[verification][cli]") {
  TempDir dir("cli-fdm1d");
  auto rejected = [&](const std::string& toml, const std::string& must_mention) {
    dir.write("case.toml", toml);
    const auto r = run_hmlattice("fdm1d case.toml --out run", dir.path);
    require_clean_rejection(r, must_mention);
    CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  };
  rejected("model = \"fdm1d\"\n[physics]\nb = 1.2\n", "case.toml: [physics] b = 1.2, allowed: 0 <= b <= 1");
  rejected("[physics]\nnu = 0.6\n", "case.toml: [physics] nu = 0.6, allowed: 0 < nu < 0.5");
  rejected("[physics]\nR_i = 1.0\n", "case.toml: [physics] R_i = 1, allowed: 0 <= R_i < 1");
  rejected("[physics]\nR_i = 0\n", "R_i = 0, allowed: 0 < R_i < 1 (the 1D model needs a borehole)");
  rejected("[mechanics]\nS_H = 2e-4\nS_h = 1e-4\n",
           "case.toml: [mechanics] S_h = 1e-04, allowed: equal to S_H = 2e-04 (the 1D model is radially symmetric");
  rejected("[mechanics]\nS_H = -2e-4\nS_h = -2e-4\n", "case.toml: [mechanics] S_H = -2e-04, allowed: >= 0");
  rejected("[mechanics]\np0 = -1e-5\n", "case.toml: [mechanics] p0 = -1e-05, allowed: >= 0");
  rejected("[physics_si]\nk = -1e-14\n", "case.toml: [physics_si] k = -1e-14, allowed: k > 0");
  rejected("[numerics]\nn_r = 4\n", "case.toml: [numerics] n_r = 4, allowed: 8 <= n_r <= 1000000");
  rejected("[numerics]\nn_r = 40\nsolver = \"cg\"\n", "case.toml: [numerics] unknown key 'solver', allowed: ");
  rejected("[output]\ntimes = [2.0]\n", "case.toml: [output] times[0] = 2, allowed: 0 < times[0] <= t_end (1)");
  rejected("[output]\nprobes = [0.1]\n", "case.toml: [output] probes[0] = 0.1, allowed: 0.138 <= probes[0] <= 1");
  rejected("model = \"lattice2d\"\n", "model = \"lattice2d\", allowed: \"fdm1d\"");
  rejected("[physics\nb = 0.5\n", "case.toml:1: malformed TOML: ");
  require_clean_rejection(run_hmlattice("fdm1d missing.toml", dir.path), "missing.toml: no such case file");
}

TEST_CASE("hmlattice fdm1d writes its CSV files and a resolved config that reruns identically", "[verification][cli]") {
  TempDir dir("cli-fdm1d-run");
  dir.write("case.toml",
            "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n[numerics]\nn_r = 40\nt_end = 0.05\n"
            "[output]\ntimes = [0.01, 0.05]\n");
  const auto first = run_hmlattice("fdm1d case.toml --out run1", dir.path);
  REQUIRE(first.exit_code == 0);
  for (const char* f : {"borehole.csv", "profiles.csv", "probes.csv", "steady_state.csv", "config.toml"})
    CHECK(std::filesystem::exists(dir.path / "run1" / f));
  const auto second = run_hmlattice("fdm1d run1/config.toml --out run2", dir.path);
  REQUIRE(second.exit_code == 0);
  CHECK(hm::test::slurp(dir.path / "run1" / "profiles.csv") == hm::test::slurp(dir.path / "run2" / "profiles.csv"));
  CHECK_THAT(hm::test::slurp(dir.path / "run1" / "config.toml"), Catch::Contains("E_over_M = 0.75229695454"));
}

TEST_CASE("A 1D case of only t_end = 0.5 keeps the default output times it reaches", "[verification][cli]") {
  // The defaults are Fig. 10's times up to t* = 1; a run to 0.5 was refused over the time 1.
  TempDir dir("cli-fdm1d-short");
  dir.write("case.toml", "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n[numerics]\nn_r = 40\nt_end = 0.5\n");
  const auto r = run_hmlattice("fdm1d case.toml --out run", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(hm::test::slurp(dir.path / "run" / "config.toml"), Catch::Contains("times = [0.025, 0.05, 0.1, 0.25]"));
  // Times the file gives are still checked as given.
  dir.write("late.toml",
            "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n[numerics]\nt_end = 0.5\n[output]\ntimes = [1]\n");
  CHECK(run_hmlattice("fdm1d late.toml --out late", dir.path).exit_code == 2);
}

TEST_CASE("A case given in SI units gives the same dimensionless results as its dimensionless twin",
          "[verification][cli]") {
  // PorePy's scaled-vs-unscaled check, end to end through the command a user runs.
  TempDir dir("cli-si");
  const std::string cases = std::string(HM_SOURCE_DIR) + "/cases/";
  REQUIRE(run_hmlattice("fdm1d '" + cases + "fdm1d_sandstone_si.toml' --out si", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("fdm1d '" + cases + "fig10_fdm1d_b0.5.toml' --out dimensionless", dir.path).exit_code == 0);
  // Compare numerically, not as text: mu q/(k E) need not round to exactly the double 0.01.
  const auto si = hm::test::slurp(dir.path / "si" / "profiles.csv");
  const auto dl = hm::test::slurp(dir.path / "dimensionless" / "profiles.csv");
  REQUIRE(si.size() > 1000);
  // Per column: the largest difference relative to the column's largest magnitude (values near
  // zero, e.g. p ahead of the plume, differ by round-off that a pointwise ratio would blow up).
  auto columns = [](const std::string& csv) {
    std::istringstream in(csv);
    std::string line, x;
    std::getline(in, line);
    std::vector<std::vector<double>> cols;
    while (std::getline(in, line)) {
      std::istringstream cells(line);
      for (std::size_t k = 0; std::getline(cells, x, ','); ++k) {
        if (cols.size() <= k) cols.emplace_back();
        cols[k].push_back(std::stod(x));
      }
    }
    return cols;
  };
  const auto ca = columns(si), cb = columns(dl);
  REQUIRE(si.substr(0, si.find('\n')) == dl.substr(0, dl.find('\n')));  // same header
  REQUIRE(ca.size() == cb.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < ca.size(); ++k) {
    REQUIRE(ca[k].size() == cb[k].size());
    double scale = 1e-300, diff = 0.0;
    for (std::size_t i = 0; i < ca[k].size(); ++i) {
      scale = std::max(scale, std::abs(cb[k][i]));
      diff = std::max(diff, std::abs(ca[k][i] - cb[k][i]));
    }
    worst = std::max(worst, diff / scale);
  }
  // Measured 1.7e-10 (u_r): the CSV holds 10 digits, and Q = mu q/(k E) is 0.01 minus one ulp.
  CHECK(worst < 1e-9);
  CHECK_THAT(hm::test::slurp(dir.path / "si" / "config.toml"), Catch::Contains("time x 10 s"));
}
