// --out as a user meets it, through the program: nothing of the user's is removed, a finished result
// is never thrown away, and a result that could not be written completely is never reported as one.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "folder_snapshot.hpp"
#include "run_command.hpp"
#include "small_disk.hpp"

namespace fs = std::filesystem;
using hm::test::count_lines;
using hm::test::folder_snapshot;
using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

const std::string fdm1d_case = "'" HM_SOURCE_DIR "/cases/fig10_fdm1d_b0.5.toml'";
// A 2D run of a few seconds: N = 600 disk, two steps.
const std::string small_run_case =
    "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 600\n"
    "[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n";
const std::string allowed = "allowed: a new or empty folder, or an earlier hmlattice result with --overwrite";

void require_refusal(const hm::test::CommandResult& r, const std::string& must_mention) {
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.err.find(must_mention) != std::string::npos);
  CHECK(r.out.empty());  // refused before any computing: not even the parameter line
}

}  // namespace

TEST_CASE("An --out naming a folder of the user's files is refused and every file stays, byte for byte",
          "[verification][cli]") {
  TempDir dir("out-foreign");
  dir.write("thesis.tex", "\\chapter{Results} -- four years");
  fs::create_directories(dir.path / "victim");
  std::ofstream(dir.path / "victim" / "thesis.tex") << "\\chapter{Results} -- four years";
  fs::copy_file(HM_SOURCE_DIR "/cases/fig10_fdm1d_b0.5.toml", dir.path / "case.toml");
  dir.write("run.toml", small_run_case);
  const auto before = folder_snapshot(dir.path);
  for (const std::string& command :
       {"fdm1d " + fdm1d_case, std::string("run run.toml"), std::string("verify --filter steady_borehole")}) {
    require_refusal(run_hmlattice(command + " --out victim", dir.path),
                    "--out = 'victim' is a folder with files that hmlattice did not write; " + allowed);
    require_refusal(run_hmlattice(command + " --out victim --overwrite", dir.path), "did not write");
  }
  // The folder holding the case file itself.
  require_refusal(run_hmlattice("fdm1d case.toml --out .", dir.path), "is the working directory or a folder above it");
  CHECK(folder_snapshot(dir.path) == before);
}

TEST_CASE("An --out of . or .., a file, a symbolic link or a device is refused before anything is computed",
          "[verification][cli]") {
  TempDir dir("out-places");
  fs::create_directories(dir.path / "work" / "sub");
  dir.write("work/notes.txt", "keep");
  dir.write("file.csv", "1,2\n");
  fs::create_directories(dir.path / "results");
  dir.write("results/a.csv", "keep");
  fs::create_directory_symlink(dir.path / "results", dir.path / "link");
  dir.write("run.toml", small_run_case);
  const auto before = folder_snapshot(dir.path);
  const fs::path sub = dir.path / "work" / "sub";
  for (const std::string out : {".", "..", "../..", "./"})
    require_refusal(run_hmlattice("fdm1d " + fdm1d_case + " --out " + out + " --overwrite", sub),
                    "is the working directory or a folder above it");
  require_refusal(run_hmlattice("fdm1d " + fdm1d_case + " --out file.csv", dir.path), "--out = 'file.csv' is a file");
  require_refusal(run_hmlattice("fdm1d " + fdm1d_case + " --out link --overwrite", dir.path),
                  "--out = 'link' is a symbolic link");
  require_refusal(run_hmlattice("run run.toml --out /dev/null", dir.path),
                  "--out = '/dev/null' is a device, pipe or socket");
  CHECK(folder_snapshot(dir.path) == before);
  CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("An earlier result is refused without --overwrite and replaced with it", "[verification][cli]") {
  TempDir dir("out-overwrite");
  REQUIRE(run_hmlattice("fdm1d " + fdm1d_case + " --out res", dir.path).exit_code == 0);
  CHECK_THAT(slurp(dir.path / "res" / ".hmlattice"), Catch::StartsWith("# hmlattice result folder"));
  const auto before = folder_snapshot(dir.path);
  require_refusal(run_hmlattice("fdm1d " + fdm1d_case + " --out res", dir.path),
                  "--out = 'res' holds an earlier hmlattice result; add --overwrite to replace it");
  CHECK(folder_snapshot(dir.path) == before);
  const auto r = run_hmlattice("fdm1d " + fdm1d_case + " --out res --overwrite", dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK(slurp(dir.path / "res" / ".hmlattice").find("--out res --overwrite") != std::string::npos);
  CHECK(slurp(dir.path / "res" / "profiles.csv") == before.at("res/profiles.csv"));  // same case, same numbers
  CHECK(folder_snapshot(dir.path).size() == before.size());                          // nothing set aside is left over
}

TEST_CASE("An earlier result holding a file the user put there is refused by --overwrite, and nothing is removed",
          "[verification][cli]") {
  TempDir dir("out-overwrite-user-file");
  REQUIRE(run_hmlattice("fdm1d " + fdm1d_case + " --out res", dir.path).exit_code == 0);
  dir.write("res/my_notes.txt", "what I saw in this run");
  const auto before = folder_snapshot(dir.path);
  require_refusal(run_hmlattice("fdm1d " + fdm1d_case + " --out res --overwrite", dir.path),
                  "--out = 'res' holds files hmlattice did not write ('my_notes.txt'), which --overwrite would "
                  "remove; allowed: move them out first, or choose another folder");
  CHECK(folder_snapshot(dir.path) == before);
}

TEST_CASE("An --out with a trailing slash or a 250-character name keeps the finished run", "[verification][cli]") {
  TempDir dir("out-names");
  auto r = run_hmlattice("fdm1d " + fdm1d_case + " --out res/", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("Results: res/{borehole,profiles,probes,steady_state}.csv, config.toml"));
  CHECK(fs::file_size(dir.path / "res" / "profiles.csv") > 0);
  const std::string long_name(250, 'r');
  r = run_hmlattice("fdm1d " + fdm1d_case + " --out " + long_name, dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::file_size(dir.path / long_name / "profiles.csv") > 0);
  dir.write("case.toml", small_run_case);
  r = run_hmlattice("run case.toml --out run2d/", dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::file_size(dir.path / "run2d" / "series.csv") > 0);
  r = run_hmlattice("verify --filter steady_borehole --out report/", dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK(fs::file_size(dir.path / "report" / "report.md") > 0);
  CHECK(fs::exists(dir.path / "report" / ".hmlattice"));
  require_refusal(run_hmlattice("verify --filter steady_borehole --out report", dir.path),
                  "holds an earlier hmlattice result");
}

TEST_CASE("On a full disk every command fails with the file named, and leaves no folder that looks complete",
          "[verification][cli]") {
  TempDir dir("out-full");
  dir.write("case.toml", small_run_case);
  hm::test::SmallDisk disk(dir.path / "disk", 48);
  INFO((disk.is_tmpfs() ? "a 48 KiB tmpfs" : "a 48 KiB file-size limit"));
  for (const std::string& command : {"fdm1d " + fdm1d_case, std::string("run case.toml")}) {
    const auto r = run_hmlattice(command + " --out disk/res", dir.path, disk.shell_prefix());
    INFO(command << "\nstdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == 1);
    CHECK(count_lines(r.err) == 1);
    CHECK_THAT(r.err, Catch::Contains("cannot write '") &&
                          Catch::Contains(disk.is_tmpfs() ? "No space left on device" : "File too large"));
    CHECK(r.out.find("Results:") == std::string::npos);
    CHECK(fs::is_empty(disk.folder()));  // no result folder, no staging folder left behind
  }
}

TEST_CASE("A run that fails while replacing an earlier result leaves that result intact", "[verification][cli]") {
  TempDir dir("out-failed-replace");
  hm::test::SmallDisk disk(dir.path / "disk", 64);
  // A result that fits: the 1D model's coarse grid with few outputs.
  dir.write("small.toml",
            "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n[numerics]\nn_r = 40\nt_end = 0.01\n[output]\ntimes = "
            "[0.01]\n");
  const auto first = run_hmlattice("fdm1d small.toml --out disk/res", dir.path, disk.shell_prefix());
  INFO("stderr: " << first.err);
  REQUIRE(first.exit_code == 0);
  const auto before = folder_snapshot(disk.folder());
  const auto r = run_hmlattice("fdm1d " + fdm1d_case + " --out disk/res --overwrite", dir.path, disk.shell_prefix());
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 1);
  CHECK(folder_snapshot(disk.folder()) == before);
}
