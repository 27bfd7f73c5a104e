// A run stopped by SIGINT or SIGTERM keeps every step it finished: the folder appears as --out,
// marked incomplete, with status.toml, series.csv and breaks.csv (borehole.csv and probes.csv for
// fdm1d) up to the last step; the exit status is the shell's for the signal (130, 143); one line on
// stderr says so.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

// The Fig. 12 quick case (fracture on) with a constant step, so that it runs for minutes and the
// signal arrives in the middle.
std::string long_case() {
  std::string text = slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml");
  text.replace(text.find("dt_growth = 1.2"), 15, "dt_growth = 1.0");
  return text;
}

// A 1D case of 1e5 constant steps on a fine grid (minutes): the signal arrives in the middle.
const char* long_fdm1d_case =
    "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n"
    "[numerics]\nn_r = 20000\ndt_initial = 1e-5\ndt_growth = 1.0\ndt_max = 1e-5\nt_end = 1.0\n[output]\ntimes = "
    "[1.0]\n";

// Starts `command` (run or fdm1d) in the background, sends `signal` once the staged `rows_file` has
// `rows` rows (by default t = 0 and five steps, flushed as they finish), waits; returns the exit status.
int run_and_signal(const TempDir& dir, const std::string& signal, const std::string& command = "run",
                   const std::string& case_text = long_case(), const std::string& rows_file = "series.csv",
                   int rows = 6) {
  dir.write("case.toml", case_text);
  std::string script = "'";  // appended step by step: GCC 12 warns falsely (-Wrestrict) on "'" + string
  script += HMLATTICE_EXE;
  script += "' " + command +
            " case.toml --out run > out.txt 2> err.txt & pid=$!\n"
            "for i in $(seq 1200); do\n"
            "  n=$(cat .hmlattice-staging-*/" +
            rows_file +
            " 2>/dev/null | wc -l)\n"
            "  [ \"$n\" -ge " +
            std::to_string(rows + 1) +
            " ] && break\n"
            "  sleep 0.05\n"
            "done\n"
            "kill -" +
            signal + " $pid\nwait $pid\necho $? > rc.txt\n";
  dir.write("interrupt.sh", script);
  REQUIRE(std::system(("cd '" + dir.path.string() + "' && bash interrupt.sh").c_str()) == 0);
  return std::stoi(slurp(dir.path / "rc.txt"));
}

}  // namespace

TEST_CASE("An interrupted run keeps its finished steps in --out, marked incomplete", "[case][cli]") {
  for (const auto& [signal, code] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    TempDir dir(std::string("run-interrupt-") + signal);
    CHECK(run_and_signal(dir, signal) == code);
    const std::string err = slurp(dir.path / "err.txt");
    INFO(err);
    CHECK(count_lines(err) == 1);
    CHECK_THAT(err,
               Catch::Contains(std::string("interrupted by SIG") + signal) && Catch::Contains("marked incomplete"));
    const auto run = dir.path / "run";
    REQUIRE(std::filesystem::is_directory(run));
    // No staging folder is left beside it.
    for (const auto& entry : std::filesystem::directory_iterator(dir.path))
      CHECK(entry.path().filename().string().rfind(".hmlattice-staging-", 0) != 0);
    const std::string status = slurp(run / "status.toml");
    CHECK_THAT(status, Catch::Contains("complete = false"));
    CHECK_THAT(slurp(run / ".hmlattice"), Catch::Contains("complete = false"));
    // series.csv: the header, t = 0 and every finished step; status.toml names the last one.
    const int rows = count_lines(slurp(run / "series.csv"));
    CHECK(rows >= 7);
    CHECK_THAT(status, Catch::Contains("last_step = " + std::to_string(rows - 2) + "\n"));
    CHECK(slurp(run / "breaks.csv").rfind("sequence,beam,particle_i,particle_j,x,y,time,", 0) == 0);
    // The folder is a complete description of what was done: its config reruns the whole case.
    CHECK(std::filesystem::exists(run / "config.toml"));
    // It continues from the checkpoint of its last step (here for two more steps).
    CHECK_THAT(status, Catch::Contains("checkpoint_step = " + std::to_string(rows - 2) + "\n") &&
                           Catch::Contains("resume = \"hmlattice run --resume run\""));
    const auto resumed =
        hm::test::run_hmlattice("run --resume run --stop-after-steps " + std::to_string(rows), dir.path);
    INFO(resumed.err);
    CHECK(resumed.exit_code == 0);
    CHECK(count_lines(slurp(run / "series.csv")) == rows + 2);
    CHECK_THAT(slurp(run / "status.toml"), Catch::Contains("last_step = " + std::to_string(rows) + "\n"));
  }
}

TEST_CASE("An interrupted fdm1d run keeps its finished steps in --out, marked incomplete", "[case][cli]") {
  for (const auto& [signal, code] : {std::pair{"INT", 130}, std::pair{"TERM", 143}}) {
    TempDir dir(std::string("fdm1d-interrupt-") + signal);
    CHECK(run_and_signal(dir, signal, "fdm1d", long_fdm1d_case, "borehole.csv") == code);
    const std::string err = slurp(dir.path / "err.txt");
    INFO(err);
    CHECK(count_lines(err) == 1);
    CHECK_THAT(err, Catch::StartsWith(std::string("hmlattice fdm1d: interrupted by SIG") + signal) &&
                        Catch::Contains("marked incomplete (status.toml)"));
    const auto run = dir.path / "run";
    REQUIRE(std::filesystem::is_directory(run));
    for (const auto& entry : std::filesystem::directory_iterator(dir.path))
      CHECK(entry.path().filename().string().rfind(".hmlattice-staging-", 0) != 0);
    const std::string status = slurp(run / "status.toml");
    CHECK_THAT(status, Catch::Contains("complete = false\n") &&
                           Catch::Contains(std::string("stopped = \"interrupted by SIG") + signal + "\"\n") &&
                           Catch::Contains("t_end = 1\n") &&
                           Catch::Contains("rerun = \"hmlattice fdm1d run/config.toml --out <new folder>\"\n"));
    CHECK_THAT(slurp(run / ".hmlattice"), Catch::Contains("complete = false"));
    // borehole.csv and probes.csv: the header, t = 0 and every finished step, as status.toml says.
    const std::string borehole = slurp(run / "borehole.csv");
    const int rows = count_lines(borehole);
    CHECK(rows >= 7);
    CHECK_THAT(status, Catch::Contains("last_step = " + std::to_string(rows - 2) + "\n"));
    CHECK(count_lines(slurp(run / "probes.csv")) == rows);
    // t_last is the time of the last row: rows - 2 steps of 1e-5.
    const std::string last_row = borehole.substr(borehole.rfind('\n', borehole.size() - 2) + 1);
    CHECK(std::stod(last_row) == Approx((rows - 2) * 1e-5).epsilon(1e-9));
    const auto t_last = status.find("t_last = ");
    REQUIRE(t_last != std::string::npos);
    CHECK(std::stod(status.substr(t_last + 9)) == Approx(std::stod(last_row)).epsilon(1e-9));
    // No output time was reached: profiles.csv is its header; the steady state is there in full.
    CHECK(count_lines(slurp(run / "profiles.csv")) == 1);
    CHECK(count_lines(slurp(run / "steady_state.csv")) == 20002);
    CHECK(std::filesystem::exists(run / "config.toml"));
  }
}

TEST_CASE("A killed run's staging folder is reported by the next run beside it, kept, and resumable", "[case][cli]") {
  TempDir dir("run-killed");
  CHECK(run_and_signal(dir, "KILL", "run --checkpoint-every 0") == 128 + 9);
  std::filesystem::path staging;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path))
    if (entry.path().filename().string().rfind(".hmlattice-staging-", 0) == 0) staging = entry.path();
  REQUIRE_FALSE(staging.empty());
  dir.write("small.toml",
            "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n[numerics]\nn_r = 40\nt_end = 0.01\n[output]\ntimes = "
            "[0.01]\n");
  const auto r = hm::test::run_hmlattice("fdm1d small.toml --out other", dir.path);
  CHECK(r.exit_code == 0);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains(staging.filename().string()) && Catch::Contains("case.toml --out run") &&
                        Catch::Contains("kept") && Catch::Contains("--resume"));
  CHECK(std::filesystem::exists(staging / "series.csv"));
  // With a checkpoint every step, it continues from the last one the kill left complete (the steps
  // flushed after it are cut and computed again); stopped again, it stays where it is, incomplete.
  const int flushed = count_lines(slurp(staging / "series.csv")) - 2;
  const auto resumed = hm::test::run_hmlattice(
      "run --resume '" + staging.string() + "' --stop-after-steps " + std::to_string(flushed + 2), dir.path);
  INFO(resumed.err);
  CHECK(resumed.exit_code == 0);
  CHECK(count_lines(slurp(staging / "series.csv")) == flushed + 4);
  CHECK_THAT(slurp(staging / "status.toml"),
             Catch::Contains("last_step = " + std::to_string(flushed + 2) + "\n") &&
                 Catch::Contains("resume = \"hmlattice run --resume " + staging.string()));
}

TEST_CASE("A Ctrl-C inside a long step undoes that step at once, and the resumed run is bitwise the uninterrupted one",
          "[case][cli]") {
  // One step of the Fig. 12 quick case at N = 4000 straight to t* = 0.0045: ~45 coupling passes that
  // break ~1500 beams, several seconds. The signal comes as soon as the t = 0 row is written.
  const std::string one_long_step =
      hm::test::edited(long_case(), {{"n_particles = 3000", "n_particles = 4000"},
                                     {"dt_initial = 1e-5", "dt_initial = 0.0045"},
                                     {"dt_max = 5e-4", "dt_max = 0.0045"},
                                     {"t_end = 0.0272", "t_end = 0.0045"},
                                     {"times = [0.0045, 0.009, 0.0272]", "times = [0.0045]"},
                                     {"vtk = true", "vtk = false"}});
  TempDir dir("run-interrupt-in-step");
  CHECK(run_and_signal(dir, "INT", "run", one_long_step, "series.csv", 1) == 130);
  const std::string err = slurp(dir.path / "err.txt");
  INFO(err);
  CHECK(count_lines(err) == 1);
  // Had it waited for the step, the step would be in series.csv; it was undone: only t = 0 is there.
  CHECK_THAT(err, Catch::Contains("interrupted by SIGINT") && Catch::Contains("the 0 steps done"));
  CHECK(count_lines(slurp(dir.path / "run/series.csv")) == 2);
  CHECK(count_lines(slurp(dir.path / "run/breaks.csv")) == 1);
  const auto resumed = hm::test::run_hmlattice("run --resume run", dir.path);
  INFO(resumed.err);
  REQUIRE(resumed.exit_code == 0);
  dir.write("case.toml", one_long_step);
  REQUIRE(hm::test::run_hmlattice("run case.toml --out whole", dir.path).exit_code == 0);
  for (const std::string file : {"series.csv", "breaks.csv", "radial.csv", "fracture_summary.csv", "breakdown.csv"}) {
    INFO(file);
    CHECK(slurp(dir.path / "run" / file) == slurp(dir.path / "whole" / file));
  }
}

TEST_CASE("A second Ctrl-C ends the run at once and says where its files are", "[case][cli]") {
  TempDir dir("run-interrupt-twice");
  // Two signals 30 ms apart (a pending signal absorbs an identical one) inside one step: N = 1e4,
  // whose steps take ~0.2 s here.
  std::string text = long_case();
  text.replace(text.find("n_particles = 3000"), 18, "n_particles = 10000");
  CHECK(run_and_signal(dir, "INT $pid; sleep 0.03; kill -INT", "run", text) == 130);
  const std::string err = slurp(dir.path / "err.txt");
  INFO(err);
  CHECK(count_lines(err) == 1);
  CHECK_THAT(err, Catch::Contains("hmlattice: interrupted again: ended at once") &&
                      Catch::Contains(".hmlattice-staging-*") && Catch::Contains("hmlattice run --resume"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  int staged = 0;  // what was written is kept where the message says
  for (const auto& entry : std::filesystem::directory_iterator(dir.path))
    staged += entry.path().filename().string().rfind(".hmlattice-staging-", 0) == 0;
  CHECK(staged == 1);
}
