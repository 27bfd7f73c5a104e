// [fracture] stop_at_first_break = true: the run ends, complete, with the accepted step that breaks the
// first beam, and that step is exactly the one the same case without the key breaks first (bit for bit),
// written as an output time; stopped before it and resumed, it ends at the same step with the same files;
// with no break it runs to t_end and says so.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

// The Fig. 12 quick case on a coarser lattice (N = 1000), at half the rate and to t* = 4.5e-3: the first
// beams break at step 9 (t* = 2.08e-4; at Q = 0.01 the flux boundary's first step already breaks 49),
// 6 of them, and the run without the key goes on to 27 steps. Each run takes well under a second.
std::string small_fig12(bool stop_at_first_break) {
  std::vector<std::pair<std::string, std::string>> edits = {
      {"Q = 0.01\n", "Q = 0.005\n"},
      {"n_particles = 3000", "n_particles = 1000"},
      {"t_end = 0.0272", "t_end = 0.0045"},
      {"times = [0.0045, 0.009, 0.0272]", "times = [0.002, 0.0045]"}};
  if (stop_at_first_break) edits.push_back({"enabled = true\n", "enabled = true\nstop_at_first_break = true\n"});
  return hm::test::edited(slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml"), edits);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

}  // namespace

TEST_CASE("stop_at_first_break ends the run, complete, with the step that breaks the first beam", "[case][cli]") {
  TempDir dir("run-first-break");
  dir.write("stop.toml", small_fig12(true));
  dir.write("full.toml", small_fig12(false));
  const auto stopped = run_hmlattice("run stop.toml --out stop", dir.path);
  INFO("stdout: " << stopped.out << "\nstderr: " << stopped.err);
  REQUIRE(stopped.exit_code == 0);
  CHECK(stopped.err.empty());
  const auto full = run_hmlattice("run full.toml --out full", dir.path);
  REQUIRE(full.exit_code == 0);

  // breakdown.csv: the first break of both runs, the same to the last digit (the same steps were taken).
  const auto breakdown = lines_of(slurp(dir.path / "stop/breakdown.csv"));
  const auto breakdown_full = lines_of(slurp(dir.path / "full/breakdown.csv"));
  REQUIRE(breakdown.size() == 2);
  REQUIRE(breakdown_full.size() == 2);
  const auto b = cells_of(breakdown[1]), b_full = cells_of(breakdown_full[1]);
  REQUIRE(b.size() == 8);
  for (std::size_t k = 0; k < 5; ++k) CHECK(b[k] == b_full[k]);  // t, p_h before and at it, x, y
  const std::string t_first = b[0], p_first = b[2];
  CHECK(t_first != "nan");
  CHECK_THAT(stopped.out, Catch::Contains("Stopped at the first break: t* = "));

  // series.csv ends with that step, and is the full run's up to it; the full run goes on past it.
  const auto series = lines_of(slurp(dir.path / "stop/series.csv"));
  const auto series_full = lines_of(slurp(dir.path / "full/series.csv"));
  REQUIRE(series.size() >= 3);
  CHECK(cells_of(series.back())[0] == t_first);
  CHECK(cells_of(series[series.size() - 2])[8] == "0");  // n_broken: none before that step
  REQUIRE(series_full.size() > series.size());
  for (std::size_t k = 0; k < series.size(); ++k) CHECK(series[k] == series_full[k]);

  // breaks.csv holds that step's breaks only (column 7 is the time), the first of the full run's.
  const auto breaks = lines_of(slurp(dir.path / "stop/breaks.csv"));
  const auto breaks_full = lines_of(slurp(dir.path / "full/breaks.csv"));
  REQUIRE(breaks.size() >= 2);
  REQUIRE(breaks_full.size() > breaks.size());
  for (std::size_t k = 1; k < breaks.size(); ++k) {
    CHECK(cells_of(breaks[k])[6] == t_first);
    CHECK(breaks[k] == breaks_full[k]);
  }
  CHECK(cells_of(breaks_full[breaks.size()])[6] != t_first);
  CHECK(cells_of(breakdown[1])[7] == std::to_string(breaks.size() - 1));  // n_broken at the end

  // The stdout line gives the same numbers (breakdown.csv has 10 digits, the line the shortest form).
  const std::string line = stopped.out.substr(stopped.out.find("Stopped at the first break"));
  const double t_printed = std::stod(line.substr(line.find("t* = ") + 5));
  const double p_printed = std::stod(line.substr(line.find("p_h = ") + 6));
  CHECK(t_printed == Approx(std::stod(t_first)).epsilon(1e-9));
  CHECK(p_printed == Approx(std::stod(p_first)).epsilon(1e-9));

  // That step is written as an output time: its radial profile, VTK snapshot and fracture statistics.
  const auto radial = lines_of(slurp(dir.path / "stop/radial.csv"));
  CHECK(cells_of(radial.back())[0] == t_first);
  std::vector<std::string> radial_times;
  for (std::size_t k = 1; k < radial.size(); ++k)
    if (radial_times.empty() || radial_times.back() != cells_of(radial[k])[0])
      radial_times.push_back(cells_of(radial[k])[0]);
  const std::string pvd = slurp(dir.path / "stop/vtk/lattice.pvd");
  std::size_t n_snapshots = 0;
  for (auto at = pvd.find("<DataSet"); at != std::string::npos; at = pvd.find("<DataSet", at + 1)) ++n_snapshots;
  CHECK(n_snapshots == radial_times.size());
  const auto summary = lines_of(slurp(dir.path / "stop/fracture_summary.csv"));
  CHECK(cells_of(summary.back())[0] == t_first);

  // A complete folder: no status, no checkpoint, a marker without "complete = false"; nothing to resume.
  CHECK_FALSE(std::filesystem::exists(dir.path / "stop/status.toml"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "stop/checkpoint.bin"));
  CHECK_THAT(slurp(dir.path / "stop/.hmlattice"), !Catch::Contains("complete = false"));
  const auto resumed = run_hmlattice("run --resume stop", dir.path);
  CHECK(resumed.exit_code == 2);
  CHECK_THAT(resumed.err, Catch::Contains("holds a complete run"));

  // config.toml says so, and reruns to the same files.
  CHECK_THAT(slurp(dir.path / "stop/config.toml"),
             Catch::Contains("[fracture]\nenabled = true\nstop_at_first_break = true\n"));
  CHECK_THAT(slurp(dir.path / "full/config.toml"), Catch::Contains("stop_at_first_break = false\n"));
}

TEST_CASE("A stop_at_first_break run stopped before its first break and resumed ends at the same step", "[case][cli]") {
  TempDir dir("run-first-break-resume");
  dir.write("stop.toml", small_fig12(true));
  REQUIRE(run_hmlattice("run stop.toml --out whole", dir.path).exit_code == 0);
  const auto whole_series = lines_of(slurp(dir.path / "whole/series.csv"));
  const int first_break_step = static_cast<int>(whole_series.size()) - 2;  // header and t = 0
  REQUIRE(first_break_step >= 2);
  auto r =
      run_hmlattice("run stop.toml --out part --stop-after-steps " + std::to_string(first_break_step - 1), dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(slurp(dir.path / "part/.hmlattice"), Catch::Contains("complete = false"));
  r = run_hmlattice("run --resume part", dir.path);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("Stopped at the first break"));
  for (const char* file : {"series.csv", "breaks.csv", "radial.csv", "breakdown.csv", "fractures.csv",
                           "fracture_summary.csv", "vtk/lattice.pvd"}) {
    INFO(file);
    CHECK(slurp(dir.path / "part" / file) == slurp(dir.path / "whole" / file));
  }
  CHECK_FALSE(std::filesystem::exists(dir.path / "part/checkpoint.bin"));
  CHECK_FALSE(std::filesystem::exists(dir.path / "part/status.toml"));
  CHECK_THAT(slurp(dir.path / "part/.hmlattice"), !Catch::Contains("complete = false"));
}

TEST_CASE("A stop_at_first_break run in which nothing breaks goes to t_end and says so", "[case][cli]") {
  TempDir dir("run-first-break-none");
  std::string text = small_fig12(true);
  // t_end = 1e-4 is before the first break (t* = 2.08e-4); the output times beyond it are dropped.
  text.replace(text.find("t_end = 0.0045"), 14, "t_end = 1e-4");
  text.replace(text.find("times = [0.002, 0.0045]"), 23, "times = [1e-4]");
  dir.write("case.toml", text);
  const auto r = run_hmlattice("run case.toml --out run", dir.path);
  INFO("stdout: " << r.out << "\nstderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("No beam broke by t_end = 1e-04\n"));
  CHECK_THAT(r.out, !Catch::Contains("Stopped at the first break"));
  CHECK(cells_of(lines_of(slurp(dir.path / "run/breakdown.csv"))[1])[0] == "nan");
  CHECK(cells_of(lines_of(slurp(dir.path / "run/series.csv")).back())[0] == "0.0001");
  CHECK_THAT(slurp(dir.path / "run/.hmlattice"), !Catch::Contains("complete = false"));
}

namespace {

// The Fig. 12 quick case (N = 3000) ended at its first break, with constant steps dt, the given overshoot
// tolerance, and `law_keys` after [fracture] enabled.
std::string fig12_first_break(const std::string& dt, const std::string& tolerance, const std::string& law_keys,
                              std::pair<std::string, std::string> extra_edit) {
  return hm::test::edited(slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml"),
                          {std::move(extra_edit),
                           {"dt_initial = 1e-5", "dt_initial = " + dt},
                           {"dt_max = 5e-4", "dt_max = " + dt},
                           {"[numerics]\n", "[numerics]\novershoot_tolerance = " + tolerance + "\n"},
                           {"vtk = true", "vtk = false"},
                           {"enabled = true\n", "enabled = true\nstop_at_first_break = true\n" + law_keys}});
}

// The paper's brittle law, checked at converged states.
std::string first_break_case(const std::string& dt, const std::string& tolerance) {
  return fig12_first_break(dt, tolerance, "", {"[coupling]\n", "[coupling]\nfracture_check = \"at_convergence\"\n"});
}

// The saw-tooth law (a sandstone's G_f, the process zone wet by its damage), whose defaults check at
// converged states, one event at a time.
std::string sawtooth_first_break_case(const std::string& dt, const std::string& tolerance) {
  return fig12_first_break(dt, tolerance, "law = \"sawtooth\"\nfracture_energy = 2.34e-9\n",
                           {"[flow]\n", "[flow]\ncrack_coupling = \"full\"\n"});
}

struct FirstBreak {
  double t, p, ratio;
  std::string breaks;
};

FirstBreak first_break(const TempDir& dir, const std::string& name, const std::string& dt, const std::string& tolerance,
                       bool sawtooth = false) {
  dir.write(name + ".toml", sawtooth ? sawtooth_first_break_case(dt, tolerance) : first_break_case(dt, tolerance));
  const auto r = run_hmlattice("run " + name + ".toml --out " + name, dir.path);
  INFO(name << ": " << r.err);
  REQUIRE(r.exit_code == 0);
  const auto breakdown = lines_of(slurp(dir.path / name / "breakdown.csv"));
  const std::string breaks = slurp(dir.path / name / "breaks.csv");
  std::vector<std::string> b, e;
  std::istringstream bd(breakdown.at(1)), first(lines_of(breaks).at(1));
  for (std::string cell; std::getline(bd, cell, ',');) b.push_back(cell);
  for (std::string cell; std::getline(first, cell, ',');) e.push_back(cell);
  return {std::stod(b.at(0)), std::stod(b.at(2)), std::stod(e.at(9)), breaks};
}

}  // namespace

TEST_CASE("With an overshoot tolerance the first break happens within it of the threshold, whatever the step",
          "[case][fracture]") {
  TempDir dir("overshoot");
  // Without it the first break lands wherever the step ends: ratio 2.18 at dt = 2e-4, 1.72 at 1e-4
  // (p_h 2.18e-4 against 1.88e-4), so halving the step moves the breakdown pressure by 16%.
  const FirstBreak coarse = first_break(dir, "coarse", "2e-4", "0");
  const FirstBreak fine = first_break(dir, "fine", "1e-4", "0");
  CHECK(coarse.ratio > 1.5);
  CHECK(std::abs(coarse.p - fine.p) > 0.1 * fine.p);
  // With 2%: the step that overshoots is undone and halved until its first break is within 2% (here
  // 1.0101 after four and three halvings: t* = 1.25e-5, p_h = 1.357e-4 from both), and the breakdown
  // pressure no longer depends on the step.
  const FirstBreak coarse_retried = first_break(dir, "coarse_retried", "2e-4", "0.02");
  const FirstBreak fine_retried = first_break(dir, "fine_retried", "1e-4", "0.02");
  CHECK(coarse_retried.ratio <= 1.02);
  CHECK(fine_retried.ratio <= 1.02);
  CHECK(std::abs(coarse_retried.p - fine_retried.p) <= 0.02 * fine_retried.p);
  // The retried step is the step of that length taken in the first place: a run at the halved step
  // gives the same break log bit for bit (a failed attempt leaves no trace).
  std::ostringstream dt;
  dt.precision(17);
  dt << fine_retried.t;
  const FirstBreak halved = first_break(dir, "halved", dt.str(), "0");
  CHECK(halved.t == fine_retried.t);
  CHECK(halved.breaks == fine_retried.breaks);

  // Checked on every pass, a first break overshoots through the unconverged iterate itself (14% at
  // dt -> 0 here), which no halving removes: the tolerance is refused there.
  dir.write("every.toml",
            hm::test::edited(first_break_case("1e-4", "0.02"), {{"fracture_check = \"at_convergence\"\n", ""}}));
  const auto r = run_hmlattice("run every.toml --out every", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err,
             Catch::Contains("[numerics] overshoot_tolerance = 0.02, allowed: 0 unless [coupling] fracture_check"));
}

TEST_CASE("With the saw-tooth law's overshoot tolerance the first break does not depend on the step either",
          "[case][fracture]") {
  TempDir dir("overshoot-sawtooth");
  // Without it the first break comes at the end of the first step, through teeth taken far past their
  // thresholds (the first at ratio 3.6 at dt = 2e-4): p_h 2.10e-4 at dt = 2e-4 against 1.76e-4 at 1e-4.
  const FirstBreak coarse = first_break(dir, "coarse", "2e-4", "0", true);
  const FirstBreak fine = first_break(dir, "fine", "1e-4", "0", true);
  CHECK(std::abs(coarse.p - fine.p) > 0.1 * fine.p);
  // With the law's default 2% every step whose first tooth overshoots is halved: the first break comes
  // at t* = 3.28e-5 and 3.20e-5, p_h 1.6612e-4 and 1.6603e-4 (measured 0.05% apart): within the tolerance.
  const FirstBreak coarse_retried = first_break(dir, "coarse_retried", "2e-4", "0.02", true);
  const FirstBreak fine_retried = first_break(dir, "fine_retried", "1e-4", "0.02", true);
  CHECK(std::abs(coarse_retried.p - fine_retried.p) <= 0.02 * fine_retried.p);
  CHECK(coarse_retried.t < 1e-4);
}
