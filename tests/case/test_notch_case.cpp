// [fracture] notch through the program: the beams a segment cuts are broken before the first step,
// logged at t = 0 with mode none, ignored by breakdown.csv's first break, written back to config.toml,
// kept across a resume; bad segments are one line of bad input.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/run_case.hpp"
#include "hm/lattice2d/fracture/notch.hpp"
#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::edited;
using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

// The short Fig. 12 quick case to t* = 5e-5 (four steps) with `fracture` in its [fracture] table.
std::string notched_case(const std::string& fracture) { return hm::test::short_fig12_case("5e-5", fracture); }

}  // namespace

TEST_CASE("A notch's beams are broken at t = 0, logged as cut, and the run goes on from the notched rock",
          "[case][fracture]") {
  TempDir dir("notch-case");
  // A radial notch from inside the borehole (R_i = 0.138) to r = 0.25 along +x.
  dir.write("case.toml", notched_case("notch = [[0.1, 0.0, 0.25, 0.0]]\n"));
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);

  // The expected cut, from the library on the case's own lattice.
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");
  const auto model = hm::cases::make_coupled_model(c);
  const std::vector<int> cut = hm::lattice2d::beams_crossing(model->lattice(), c.notches);
  REQUIRE(cut.size() >= 4);  // 0.11 of crack across beams ~0.03 long (N = 3000)
  CHECK(model->n_cut() == static_cast<int>(cut.size()));

  const auto breaks = hm::test::csv_rows(slurp(dir.path / "run" / "breaks.csv"));
  REQUIRE(breaks.size() > cut.size());  // the notch, then beams that failed at its tip
  for (std::size_t k = 0; k < cut.size(); ++k) {
    CHECK(breaks[k][1] == std::to_string(cut[k]));
    CHECK(breaks[k][6] == "0");      // time
    CHECK(breaks[k][9] == "0");      // ratio: cut, not failed
    CHECK(breaks[k][11] == "none");  // mode
  }
  for (std::size_t k = cut.size(); k < breaks.size(); ++k) CHECK(breaks[k][11] != "none");
  // breakdown.csv's first break is the first beam that failed, after t = 0, beyond the notch's tip.
  const auto breakdown = hm::test::csv_rows(slurp(dir.path / "run" / "breakdown.csv"));
  REQUIRE(breakdown.size() == 1);
  CHECK(std::stod(breakdown[0][0]) > 0.0);
  CHECK(breakdown[0][3] == breaks[cut.size()][4]);  // x of the first failed beam

  // config.toml carries the notch and repeats the run; so does a resume.
  CHECK_THAT(slurp(dir.path / "run" / "config.toml"), Catch::Contains("notch = [[0.1, 0, 0.25, 0]]"));
  REQUIRE(run_hmlattice("run run/config.toml --out again", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "again" / "breaks.csv") == slurp(dir.path / "run" / "breaks.csv"));
  REQUIRE(run_hmlattice("run case.toml --out part --stop-after-steps 2", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("run --resume part", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "part" / "breaks.csv") == slurp(dir.path / "run" / "breaks.csv"));
}

TEST_CASE("A bad notch is one line of bad input naming [fracture] notch", "[case][fracture]") {
  TempDir dir("notch-bad");
  for (const auto& [fracture, message] : std::vector<std::pair<std::string, std::string>>{
           {"notch = [[0.5, 0.0, 0.25]]\n",
            "[fracture] notch = [[0.5,0.0,0.25]], allowed: an array of arrays of 4 finite numbers"},
           {"notch = [[0.2, 0.0, 0.2, 0.0]]\n", "[fracture] notch = [0.2, 0, 0.2, 0], allowed: two distinct ends"},
           {"notch = [[0.2, 0.0, 1.5, 0.0]]\n", "[fracture] notch = [0.2, 0, 1.5, 0], allowed: ends inside the domain"},
           {"notch = [[0.2, 0.0, nan, 0.0]]\n", "allowed: an array of arrays of 4 finite numbers"},
           // The case's flow is the paper's iota: a slot's width means nothing there.
           {"notch = [[0.1, 0.0, 0.25, 0.0]]\nnotch_aperture = 1e-4\n",
            "[fracture] notch_aperture = 1e-04, allowed: > 0 only with a notch and [flow] fracture_flow = \"cubic\""},
           {"notch = [[0.1, 0.0, 0.25, 0.0]]\nnotch_aperture = -1e-4\n",
            "[fracture] notch_aperture = -1e-04, allowed: 0 <= value <= 0.01 (over R)"}}) {
    dir.write("case.toml", notched_case(fracture));
    const auto r = run_hmlattice("run case.toml --out run", dir.path);
    INFO(fracture << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(message));
    CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  }
  dir.write("case.toml",
            edited(notched_case("notch = [[0.1, 0.0, 0.25, 0.0]]\n"), {{"enabled = true", "enabled = false"}}));
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("[fracture] notch given, allowed: only with enabled = true"));
}

TEST_CASE("A notch's own aperture carries the fluid under the cubic law", "[case][fracture]") {
  // The KGD case's notch with the cubic law: its cut facets conduct as a slot 1e-4 wide from t = 0,
  // where a notch without the key is shut (no opening yet, no residual aperture).
  const std::string kgd = slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases" / "kgd_toughness_quick.toml");
  const std::string cubic =
      edited(kgd, {{"iota = 1e12", "iota = 1"},
                   {"crack_coupling = \"full\"",
                    "crack_coupling = \"full\"\nfracture_flow = \"cubic\"\nrock_permeability = 1e-17"}});
  TempDir dir("notch-slot");
  const auto model_of = [&](const std::string& text) {
    dir.write("case.toml", text);
    return hm::cases::make_coupled_model(hm::cases::read_run_case(dir.path / "case.toml"));
  };
  const auto shut = model_of(cubic);
  const auto slot = model_of(edited(
      cubic, {{"notch = [[-0.05, 0.0, 0.05, 0.0]]", "notch = [[-0.05, 0.0, 0.05, 0.0]]\nnotch_aperture = 1e-4"}}));
  REQUIRE(slot->n_cut() > 0);
  for (int k = 0; k < slot->n_cut(); ++k) {
    const int beam = slot->break_log()[static_cast<std::size_t>(k)].beam;
    CHECK(shut->flow().crack_aperture(beam) == 0.0);
    CHECK(slot->flow().crack_aperture(beam) == 1e-4);
  }
  const hm::cases::RunCase written = hm::cases::read_run_case(dir.path / "case.toml");
  CHECK_THAT(hm::cases::run_case_to_toml(written, ""), Catch::Contains("notch_aperture = 1e-04"));
}
