// A run stopped and resumed from its checkpoint, once or several times, gives bitwise the files of
// the run that was never stopped; a checkpoint of another case or a damaged one is refused.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

// The Fig. 12 quick case (N = 3000, fracture on) up to its first snapshot time: 27 steps, which break
// 34 beams at step 1 and 443 by step 24, so the stops below fall in a pause of the fracturing, in its
// middle and near its end, with contacts switching and the factor downdated in between.
std::string fig12_to_first_snapshot() {
  return hm::test::edited(
      slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml"),
      {{"t_end = 0.0272", "t_end = 0.0045"}, {"times = [0.0045, 0.009, 0.0272]", "times = [0.002, 0.0045]"}});
}

// Every file a user compares: the step series, the break log, the radial profiles, the fracture tables,
// the breakdown and the VTK snapshots.
const std::vector<std::string> result_files = {
    "series.csv",    "breaks.csv",      "radial.csv",           "fractures.csv",        "fracture_summary.csv",
    "breakdown.csv", "vtk/lattice.pvd", "vtk/lattice_0000.vtu", "vtk/lattice_0001.vtu", "vtk/lattice_0002.vtu"};

// case.toml in `dir` run whole (into whole/, already there), then stopped after `first` and `second` steps
// and resumed to its end in part/: every result file bitwise the same.
void check_resumed_twice_as_whole(const TempDir& dir, int first, int second) {
  REQUIRE(run_hmlattice("run case.toml --out part --stop-after-steps " + std::to_string(first), dir.path).exit_code ==
          0);
  REQUIRE(run_hmlattice("run --resume part --stop-after-steps " + std::to_string(second), dir.path).exit_code == 0);
  const auto r = run_hmlattice("run --resume part", dir.path);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const auto& file : result_files) {
    INFO(file);
    CHECK(slurp(dir.path / "part" / file) == slurp(dir.path / "whole" / file));
  }
}

}  // namespace

TEST_CASE("Stopped at several steps and resumed, a run gives bitwise the files of an uninterrupted one",
          "[case][cli]") {
  TempDir dir("run-resume");
  dir.write("case.toml", fig12_to_first_snapshot());
  const auto whole = run_hmlattice("run case.toml --out whole", dir.path);
  REQUIRE(whole.exit_code == 0);
  REQUIRE(count_lines(slurp(dir.path / "whole/series.csv")) == 29);  // header, t = 0, 27 steps

  // Stop after step 3 (34 beams broken), resume to step 12 (103), to 21 (426), then to the end (443).
  auto r = run_hmlattice("run case.toml --out part --stop-after-steps 3", dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("stopped after step 3") && Catch::Contains("--resume part"));
  CHECK_THAT(slurp(dir.path / "part/status.toml"), Catch::Contains("checkpoint_step = 3\n"));
  CHECK(count_lines(slurp(dir.path / "part/series.csv")) == 5);
  for (const int stop : {12, 21}) {
    r = run_hmlattice("run --resume part --stop-after-steps " + std::to_string(stop), dir.path);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains("resumed at step"));
    CHECK(count_lines(slurp(dir.path / "part/series.csv")) == stop + 2);
    CHECK_THAT(slurp(dir.path / "part/.hmlattice"), Catch::Contains("complete = false"));
  }
  r = run_hmlattice("run --resume part", dir.path);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const auto& file : result_files) {
    INFO(file);
    CHECK(slurp(dir.path / "part" / file) == slurp(dir.path / "whole" / file));
  }
  // Complete now: the marker says so, the checkpoint and the status are gone, a further resume is refused.
  CHECK_THAT(slurp(dir.path / "part/.hmlattice"), !Catch::Contains("complete = false"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "part/checkpoint.bin"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "part/status.toml"));
  r = run_hmlattice("run --resume part", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("--resume") && Catch::Contains("holds a complete run"));
}

TEST_CASE("A checkpoint is refused, the folder untouched, when its case was edited or the file damaged",
          "[case][cli]") {
  TempDir dir("run-resume-refused");
  dir.write("case.toml", fig12_to_first_snapshot());
  REQUIRE(run_hmlattice("run case.toml --out part --stop-after-steps 2", dir.path).exit_code == 0);
  const auto folder = dir.path / "part";
  const std::string series = slurp(folder / "series.csv"), marker = slurp(folder / ".hmlattice");

  // An edited config.toml is another case: bitwise continuation is impossible.
  const std::string config = slurp(folder / "config.toml");
  std::string edited = config;
  edited.replace(edited.find("Q = 0.01"), 8, "Q = 0.02");
  std::ofstream(folder / "config.toml") << edited;
  auto r = run_hmlattice("run --resume part", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("checkpoint.bin") && Catch::Contains("another case"));
  std::ofstream(folder / "config.toml") << config;

  // A truncated checkpoint fails its checksum.
  const std::string checkpoint = slurp(folder / "checkpoint.bin");
  std::ofstream(folder / "checkpoint.bin", std::ios::binary) << checkpoint.substr(0, checkpoint.size() / 2);
  r = run_hmlattice("run --resume part", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("checksum"));
  // A checkpoint.bin that is not a regular file: a pipe (no writer: reading would block forever), a
  // link to an endless device, a folder. Each is refused at once, naming the file.
  for (const std::string& make :
       {std::string("mkfifo part/checkpoint.bin"), std::string("ln -s /dev/zero part/checkpoint.bin"),
        std::string("mkdir part/checkpoint.bin")}) {
    INFO(make);
    REQUIRE(std::system(("cd '" + dir.path.string() + "' && rm -rf part/checkpoint.bin && " + make).c_str()) == 0);
    r = run_hmlattice("run --resume part", dir.path);  // a pipe without a writer would block the read
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains("checkpoint.bin") && Catch::Contains("not a regular file"));
  }
  std::filesystem::remove_all(folder / "checkpoint.bin");
  std::ofstream(folder / "checkpoint.bin", std::ios::binary) << checkpoint;
  // A snapshot the user removed: the run would complete without it. Refused, naming it.
  const std::string snapshot = slurp(folder / "vtk" / "lattice_0000.vtu");
  std::filesystem::remove(folder / "vtk" / "lattice_0000.vtu");
  r = run_hmlattice("run --resume part", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("vtk/lattice_0000.vtu' is missing"));
  // One cut short (a full disk, an editor): refused too, naming it and both sizes.
  std::ofstream(folder / "vtk" / "lattice_0000.vtu", std::ios::binary) << snapshot.substr(0, snapshot.size() / 2);
  r = run_hmlattice("run --resume part", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains("vtk/lattice_0000.vtu' has " + std::to_string(snapshot.size() / 2) +
                                    " bytes, not the " + std::to_string(snapshot.size())));
  std::ofstream(folder / "vtk" / "lattice_0000.vtu", std::ios::binary) << snapshot;
  // Nothing was changed by the refused attempts.
  CHECK(slurp(folder / "series.csv") == series);
  CHECK(slurp(folder / ".hmlattice") == marker);

  // A folder that is not a stopped run, and --resume with a case file, are refused too.
  r = run_hmlattice("run --resume case.toml", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  r = run_hmlattice("run case.toml --resume part", dir.path);
  CHECK(r.exit_code == 2);
}

TEST_CASE("With the borehole's undrained spring a stopped and resumed run is bitwise the uninterrupted one",
          "[case][cli]") {
  // The spring keeps K^-1 g of the current factor; the checkpoint carries it. A water-filled borehole
  // (its volume sets its pressure), Q = 0.04 so that the wall breaks before t* = 0.0045: none broken by
  // step 18, 35 by step 21, 179 at the end (step 27). Stops at 22 and 25, amid the breaks.
  TempDir dir("run-resume-borehole-spring");
  dir.write("case.toml",
            hm::test::edited(fig12_to_first_snapshot(),
                             {{"\nQ = 0.01", "\nQ = 0.04"},
                              {"borehole_storage = \"none\"", "borehole_storage = \"fluid\""},
                              {"borehole_deformation = \"none\"", "borehole_deformation = \"full\""},
                              {"split = \"undrained\"", "split = \"undrained\"\nborehole_spring = \"undrained\""}}));
  REQUIRE(run_hmlattice("run case.toml --out whole", dir.path).exit_code == 0);
  const std::string breaks = slurp(dir.path / "whole/breaks.csv");
  CHECK(count_lines(breaks) > 100);
  check_resumed_twice_as_whole(dir, 22, 25);
}

TEST_CASE("With the cubic law a stopped and resumed run is bitwise the uninterrupted one", "[case][cli]") {
  // The cracks' apertures set their conductances pass by pass and are part of the checkpoint; the
  // cubic cracks break 136 beams over steps 1-28 (against 442 with iota = 1), so both stops fall
  // between breaks with open, conducting cracks.
  TempDir dir("run-resume-cubic-law");
  dir.write("case.toml",
            hm::test::edited(fig12_to_first_snapshot(),
                             {{"borehole_storage = \"none\"",
                               "borehole_storage = \"none\"\nfracture_flow = \"cubic\"\nrock_permeability = "
                               "1e-14\nresidual_aperture = 1e-6"}}));
  REQUIRE(run_hmlattice("run case.toml --out whole", dir.path).exit_code == 0);
  const std::string breaks = slurp(dir.path / "whole/breaks.csv");
  CHECK(count_lines(breaks) > 50);
  CHECK(slurp(dir.path / "whole/vtk/lattice_0001.vtu").find("Name=\"crack_aperture\"") != std::string::npos);
  check_resumed_twice_as_whole(dir, 14, 20);
}
