// [fracture] law = "sawtooth" through the program: teeth.csv books every tooth's energy (G_f d per
// beam taken through its teeth), config.toml carries the law and its cross-table defaults, a rerun and
// a resume repeat the logs, and bad values are one line of bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/run_case.hpp"
#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::edited;
using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

// The short Fig. 12 quick case to t* = 2e-4 with `fracture` in its [fracture] table. K_Ic = 0.5 MPa m^1/2
// on Table 1's rock: G_f / (E R) = 2.34e-9 (docs/fracture_law.md).
std::string sawtooth_case(const std::string& fracture = "law = \"sawtooth\"\nfracture_energy = 2.34e-9\n") {
  return hm::test::short_fig12_case("2e-4", fracture);
}

}  // namespace

TEST_CASE("A saw-tooth run books each broken beam's G_f d in teeth.csv and repeats on a rerun and a resume",
          "[case][fracture]") {
  TempDir dir("sawtooth-case");
  dir.write("case.toml", sawtooth_case());
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("saw-tooth law: G_f/(E R) = 2.34e-09, 10 teeth of ratio 2;"));

  const auto teeth = hm::test::csv_rows(slurp(dir.path / "run" / "teeth.csv"));
  const auto breaks = hm::test::csv_rows(slurp(dir.path / "run" / "breaks.csv"));
  REQUIRE(!breaks.empty());
  REQUIRE(teeth.size() > breaks.size());
  // Every tensile break is its beam's last tooth (stiffness factor 0), after its earlier teeth in order.
  std::map<int, int> next_tooth;
  std::map<int, double> energy;
  for (const auto& t : teeth) {
    const int beam = std::stoi(t[1]);
    CHECK(std::stoi(t[3]) == next_tooth[beam]++);
    CHECK(std::stod(t[6]) >= 1.0);  // ratio
    energy[beam] += std::stod(t[7]);
  }
  // G_f d per broken beam, d its section (the law's, for the case's own lattice).
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");
  const auto model = hm::cases::make_coupled_model(c);
  REQUIRE(model->sawtooth_law() != nullptr);
  const auto* law = model->sawtooth_law();
  int tensile = 0;
  for (const auto& b : breaks) {
    if (b[11] != "tensile") continue;
    ++tensile;
    const int beam = std::stoi(b[1]);
    INFO("beam " << beam);
    CHECK(energy[beam] == Approx(2.34e-9 * law->section(beam)).epsilon(1e-8));  // 10 significant digits written
  }
  CHECK(tensile > 0);

  // config.toml: the law, and its defaults in [coupling] and [numerics].
  const std::string config = slurp(dir.path / "run" / "config.toml");
  CHECK_THAT(config, Catch::Contains("law = \"sawtooth\""));
  CHECK_THAT(config, Catch::Contains("fracture_energy = 2.34e-09"));
  CHECK_THAT(config, Catch::Contains("fracture_check = \"at_convergence\""));
  CHECK_THAT(config, Catch::Contains("overshoot_tolerance = 0.02"));
  CHECK_THAT(config, Catch::Contains("sawtooth_strength_factor = 1.36"));
  REQUIRE(run_hmlattice("run run/config.toml --out again", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "again" / "teeth.csv") == slurp(dir.path / "run" / "teeth.csv"));
  CHECK(slurp(dir.path / "again" / "breaks.csv") == slurp(dir.path / "run" / "breaks.csv"));
  REQUIRE(run_hmlattice("run case.toml --out part --stop-after-steps 6", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("run --resume part", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "part" / "teeth.csv") == slurp(dir.path / "run" / "teeth.csv"));
  CHECK(slurp(dir.path / "part" / "breaks.csv") == slurp(dir.path / "run" / "breaks.csv"));
}

TEST_CASE("A bad saw-tooth setting is one line of bad input naming [fracture] and the key", "[case][fracture]") {
  TempDir dir("sawtooth-bad");
  for (const auto& [fracture, message] : std::vector<std::pair<std::string, std::string>>{
           {"law = \"sawtooth\"\n",
            "[fracture] fracture_energy = 0, allowed: 0 < fracture_energy <= 1 with law = \"sawtooth\""},
           {"law = \"sawtooth\"\nfracture_energy = -1e-9\n", "[fracture] fracture_energy = -1e-09, allowed: 0 <"},
           // A G_f in J/m^2 typed into the dimensionless table.
           {"law = \"sawtooth\"\nfracture_energy = 100\n",
            "[fracture] fracture_energy = 100, allowed: 0 < fracture_energy <= 1"},
           {"fracture_energy = 1e-9\n", "[fracture] fracture_energy = 1e-09, allowed: 0 with law = \"brittle\""},
           {"law = \"cohesive\"\n", "[fracture] law = 'cohesive', allowed: brittle, sawtooth"},
           {"law = \"sawtooth\"\nfracture_energy = 1e-9\nsawtooth_reduction = 1.0\n",
            "[fracture] sawtooth_reduction = 1, allowed: > 1, finite"},
           {"law = \"sawtooth\"\nfracture_energy = 1e-9\nsawtooth_teeth = 0\n",
            "[fracture] sawtooth_teeth = 0, allowed: 1 ... 100"},
           {"law = \"sawtooth\"\nfracture_energy = 1e-9\nsawtooth_strength_factor = 0\n",
            "[fracture] sawtooth_strength_factor = 0, allowed: > 0, finite"}}) {
    dir.write("case.toml", sawtooth_case(fracture));
    const auto r = run_hmlattice("run case.toml --out run", dir.path);
    INFO(fracture << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains(message));
    CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  }
  dir.write("case.toml", edited(sawtooth_case(), {{"enabled = true", "enabled = false"}}));
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("[fracture] law = \"sawtooth\", allowed: only with enabled = true"));
}

TEST_CASE("Softened beams join fractures in a saw-tooth run's statistics, as a resume and `fractures` recompute them",
          "[case][fracture]") {
  TempDir dir("sawtooth-softened");
  // To t* = 3e-4 with a snapshot at 2e-4, where one ligament on its teeth joins two fractures.
  const std::string two_snapshots =
      edited(hm::test::short_fig12_case("3e-4", "law = \"sawtooth\"\nfracture_energy = 2.34e-9\n"),
             {{"times = [3e-4]", "times = [2e-4, 3e-4]"}});
  dir.write("case.toml", two_snapshots);
  REQUIRE(run_hmlattice("run case.toml --out run", dir.path).exit_code == 0);
  const std::string summary = slurp(dir.path / "run" / "fracture_summary.csv");
  const std::string fractures = slurp(dir.path / "run" / "fractures.csv");

  // Stopped after the first snapshot, the resumed run rebuilds it from the logs it kept.
  const auto series = hm::test::csv_rows(slurp(dir.path / "run" / "series.csv"));
  const auto steps_by_first_snapshot =
      std::count_if(series.begin() + 1, series.end(), [](const auto& row) { return std::stod(row[0]) <= 2e-4; });
  const auto stop = steps_by_first_snapshot + 3;
  REQUIRE(stop < static_cast<long>(series.size()) - 1);
  REQUIRE(run_hmlattice("run case.toml --out part --stop-after-steps " + std::to_string(stop), dir.path).exit_code ==
          0);
  REQUIRE(run_hmlattice("run --resume part", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "part" / "fracture_summary.csv") == summary);
  CHECK(slurp(dir.path / "part" / "fractures.csv") == fractures);

  // `fractures` recomputes the run's statistics from its breaks.csv and teeth.csv.
  REQUIRE(run_hmlattice("fractures run", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "run" / "fracture_summary.csv") == summary);
  CHECK(slurp(dir.path / "run" / "fractures.csv") == fractures);

  // Ignoring the softened beams splits fractures (this case has one more at t* = 2e-4), and gives what
  // a run with the key writes.
  const auto fractures_at_2e4 = [](const std::string& csv) { return std::stoi(hm::test::csv_rows(csv)[1][2]); };
  REQUIRE(run_hmlattice("fractures run --softened-beams ignore", dir.path).exit_code == 0);
  const std::string ignored = slurp(dir.path / "run" / "fracture_summary.csv");
  CHECK(fractures_at_2e4(ignored) == fractures_at_2e4(summary) + 1);
  CHECK_THAT(slurp(dir.path / "run" / "config.toml"), Catch::Contains("softened_beams = \"ignore\""));
  dir.write("ignore.toml", edited(two_snapshots, {{"[output]\n", "[output]\nsoftened_beams = \"ignore\"\n"}}));
  REQUIRE(run_hmlattice("run ignore.toml --out ignore", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "ignore" / "fracture_summary.csv") == ignored);

  dir.write("bad.toml", edited(sawtooth_case(), {{"[output]\n", "[output]\nsoftened_beams = \"bridge\"\n"}}));
  const auto bad = run_hmlattice("run bad.toml --out bad", dir.path);
  CHECK(bad.exit_code == 2);
  CHECK(count_lines(bad.err) == 1);
  CHECK_THAT(bad.err, Catch::Contains("[output] softened_beams = 'bridge', allowed: link, ignore"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "bad"));
}
