// Inputs that used to change the experiment silently, loop forever, print inf or a page of echo:
// each now ends with exit code 2, one line on stderr naming what is wrong, and no result folder.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>

#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

void require_one_line_exit_2(const hm::test::CommandResult& r, const std::string& must_mention) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK_THAT(r.err, Catch::Contains(must_mention));
}

// A valid 1D case up to its [numerics] table; tests append their own.
const std::string fdm1d_head = "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.2\n";

}  // namespace

TEST_CASE("Empty, comment-only and truncated cases say what is missing instead of running the defaults",
          "[verification][cli]") {
  TempDir dir("cli-required");
  const auto rejected = [&](const std::string& toml, const std::string& must_mention) {
    dir.write("case.toml", toml);
    require_one_line_exit_2(run_hmlattice("fdm1d case.toml --out run", dir.path), must_mention);
    CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  };
  rejected("", "case.toml: model is missing, allowed: \"fdm1d\" (required)");
  rejected("   \n\t\n", "model is missing");
  rejected("# only a comment\n", "model is missing");
  rejected("model = \"fdm1d\"\n", "neither [physics] nor [physics_si] given");
  rejected("model = \"fdm1d\"\n[physics]\nQ = 0.01\n",
           "case.toml: [physics] b is missing, allowed: 0 <= b <= 1 (required)");
  // Cut before its [numerics]: the run's length is never implied.
  rejected(fdm1d_head, "case.toml: [numerics] t_end is missing");
  dir.write("run2d.toml", "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[numerics]\nt_end = 1e-5\n");
  require_one_line_exit_2(run_hmlattice("run run2d.toml --out run", dir.path),
                          "run2d.toml: [lattice] n_particles is missing");
}

TEST_CASE("Numbers that would wrap, exhaust memory or never finish are refused with the reason",
          "[verification][cli]") {
  TempDir dir("cli-limits");
  const auto rejected = [&](const std::string& numerics, const std::string& must_mention) {
    dir.write("case.toml", fdm1d_head + "[numerics]\n" + numerics);
    require_one_line_exit_2(run_hmlattice("fdm1d case.toml --out run", dir.path), must_mention);
    CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
  };
  // 4294967696 = 2^32 + 400 once became n_r = 400.
  rejected("n_r = 4294967696\nt_end = 1\n", "[numerics] n_r = 4294967696, allowed: 8 <= n_r <= 1000000");
  rejected("n_r = 100000000\nt_end = 1\n", "n_r = 100000000, allowed: 8 <= n_r <= 1000000 (about 170 GB");
  // 5e-324 * 1.05 == 5e-324: the step never grew and the run never ended.
  rejected("dt_initial = 5e-324\nt_end = 1\n", "dt_initial = 5e-324, allowed: dt_initial >= 1e-12 t_end");
  rejected("t_end = 1e308\n", "t_end = 1e+308, allowed: t_end <= 1e6");
  rejected("dt_initial = 1e-9\ndt_growth = 1\nt_end = 1\n", "allowed: a stepping of at most 1e6 steps");
  dir.write("run2d.toml",
            "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 600\n"
            "[numerics]\ndt_initial = 5e-324\nt_end = 1e-5\n");
  require_one_line_exit_2(run_hmlattice("run run2d.toml --out run", dir.path), "[numerics] dt_initial = 5e-324");
}

TEST_CASE("Results that overflow double precision are refused, not printed as inf", "[verification][cli]") {
  TempDir dir("cli-overflow");
  const auto r = run_hmlattice("analytic rudnicki --t 1e308 --r 0.1", dir.path);
  require_one_line_exit_2(r, "p = inf at r = 0.1: the inputs overflow double precision");
  CHECK(r.out.empty());
  require_one_line_exit_2(run_hmlattice("analytic lame --Ro 1e308 --r 0.5", dir.path), "u_r = -nan at r = 0.5");
  dir.write("case.toml",
            "model = \"fdm1d\"\n[physics]\nQ = 1e308\nb = 0.2\n[numerics]\nn_r = 40\nt_end = 0.1\n"
            "[output]\ntimes = [0.1]\n");
  // Q itself is bounded (pressures scale with it): 1e308 is refused before anything runs.
  const auto f = run_hmlattice("fdm1d case.toml --out run", dir.path);
  require_one_line_exit_2(f, "case.toml: [physics] Q = 1e+308, allowed: 0 <= Q <= 1e+06");
  CHECK_FALSE(std::filesystem::exists(dir.path / "run"));
}

TEST_CASE("Command-line values: empty numbers, a negative E/M, no jobs and a filter that matches nothing are refused",
          "[verification][cli]") {
  TempDir dir("cli-values");
  // CLI11 read '' as 0: Q = 0 ran.
  for (const char* option : {"--Q", "--b", "--nu", "--t"})
    require_one_line_exit_2(run_hmlattice(std::string("analytic rudnicki --r 0.1 ") + option + " ''", dir.path),
                            std::string(option) + ": '' (empty), allowed: a value");
  // A negative E/M once fell back to Eq. 22's.
  require_one_line_exit_2(run_hmlattice("analytic rudnicki --r 0.1 --E_over_M -5", dir.path),
                          "E_over_M = -5, allowed: E_over_M > 0");
  require_one_line_exit_2(run_hmlattice("verify --filter typo --out report", dir.path),
                          "--filter = 'typo' matches no benchmark id of the quick tier");
  require_one_line_exit_2(run_hmlattice("verify --jobs 0 --out report", dir.path),
                          "--jobs = 0, allowed: an integer >= 1");
  CHECK_FALSE(std::filesystem::exists(dir.path / "report"));
}

TEST_CASE("Messages stay one line: inline tables, arrays of tables and very long values are cut",
          "[verification][cli]") {
  TempDir dir("cli-one-line");
  const auto rejected = [&](const std::string& value, const std::string& must_mention) {
    dir.write("case.toml", fdm1d_head + value + "[numerics]\nt_end = 1\n");
    const auto r = run_hmlattice("fdm1d case.toml --out run", dir.path);
    require_one_line_exit_2(r, must_mention);
    CHECK(r.err.size() < 700);
  };
  rejected("nu = { a = 1, b = [1, 2, 3] }\n", "[physics] nu = ");
  rejected("[[numerics_list]]\nx = 1\n[[numerics_list]]\nx = 2\n", "unknown key 'numerics_list'");
  rejected("nu = \"" + std::string(100000, 'x') + "\"\n", "…");
}

TEST_CASE("A case file behind a link loop and a damaged run folder are bad input (exit 2)", "[verification][cli]") {
  TempDir dir("cli-links");
  std::filesystem::create_symlink("loop_b", dir.path / "loop_a");
  std::filesystem::create_symlink("loop_a", dir.path / "loop_b");
  require_one_line_exit_2(run_hmlattice("run loop_a", dir.path),
                          "loop_a: cannot read: Too many levels of symbolic links");
  // A run folder whose breaks.csv was damaged: the reader names the file and the line.
  dir.write("run2d.toml",
            "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 600\n"
            "[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n[fracture]\nenabled = true\n");
  REQUIRE(run_hmlattice("run run2d.toml --out run", dir.path).exit_code == 0);
  const std::string breaks = hm::test::slurp(dir.path / "run" / "breaks.csv");
  dir.write("run/breaks.csv", "garbage\n");
  require_one_line_exit_2(run_hmlattice("fractures run", dir.path), "breaks.csv:1: header 'garbage', expected");
  dir.write("run/breaks.csv", breaks);
  // An empty fracture_summary.csv is a damaged file too (it exited 1, as if the computation failed).
  dir.write("run/fracture_summary.csv", "");
  require_one_line_exit_2(run_hmlattice("fractures run", dir.path), "fracture_summary.csv:1: not a fracture summary");

  // A run that stopped before t_end is refused, its files untouched: rewriting its config.toml made
  // `run --resume` refuse the checkpoint as another case's.
  dir.write("long.toml",
            "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 600\n"
            "[numerics]\ndt_initial = 5e-6\nt_end = 2e-5\n[fracture]\nenabled = true\n");
  REQUIRE(run_hmlattice("run long.toml --out part --stop-after-steps 1", dir.path).exit_code == 0);
  const std::string config = hm::test::slurp(dir.path / "part" / "config.toml");
  require_one_line_exit_2(run_hmlattice("fractures part", dir.path), "holds a run that has not finished");
  CHECK(hm::test::slurp(dir.path / "part" / "config.toml") == config);
  CHECK(run_hmlattice("run --resume part", dir.path).exit_code == 0);
  CHECK(run_hmlattice("fractures part", dir.path).exit_code == 0);  // finished now
}
