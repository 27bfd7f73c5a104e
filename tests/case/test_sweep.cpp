// Sweep cases: the expansion of [sweep] into one resolved case per combination (names, the complete
// cartesian product, each file read back with the swept values), its refusals (one line, nothing
// written, through the program as a user types it), and collecting the runs' status.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <sstream>

#include "folder_snapshot.hpp"
#include "hm/case/fdm1d_case.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/sweep.hpp"
#include "hm/case/sweep_collect.hpp"
#include "hm/core/input_error.hpp"
#include "run_command.hpp"

using hm::test::TempDir;
namespace fs = std::filesystem;

namespace {

// A valid small lattice case (not run here: only read).
const std::string lattice_case =
    "model = \"lattice2d\"\n"
    "[physics]\nQ = 0.01\nb = 0.5\nR_i = 0.138\n"
    "[lattice]\ndomain = \"annulus\"\nn_particles = 1000\n"
    "[numerics]\nt_end = 1e-3\n"
    "[fracture]\nenabled = true\n";

std::string expand_error(const TempDir& dir, const std::string& sweep) {
  dir.write("s.toml", lattice_case + sweep);
  fs::create_directories(dir.path / "out");
  try {
    hm::cases::expand_sweep(dir.path / "s.toml", dir.path / "out");
  } catch (const hm::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("A sweep expands into every combination with stable, readable names", "[case][sweep]") {
  TempDir dir("sweep-names");
  dir.write("s.toml", lattice_case + "[sweep]\n\"physics.Q\" = [1e-3, 1e-2]\n\"lattice.seed\" = [1, 2, 3]\n");
  fs::create_directories(dir.path / "out");
  const auto sweep = hm::cases::expand_sweep(dir.path / "s.toml", dir.path / "out");

  CHECK(sweep.command == "run");
  REQUIRE(sweep.axes.size() == 2);
  CHECK(sweep.axes[0].key == "physics.Q");  // the file's order, not toml11's hash order
  CHECK(sweep.axes[1].key == "lattice.seed");
  std::vector<std::string> names;
  for (const auto& c : sweep.combinations) names.push_back(c.name);
  CHECK(names == std::vector<std::string>{"Q=0.001_seed=1", "Q=0.001_seed=2", "Q=0.001_seed=3", "Q=0.01_seed=1",
                                          "Q=0.01_seed=2", "Q=0.01_seed=3"});
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(dir.path / "out")) files.insert(e.path().filename().string());
  std::set<std::string> expected = {"index.csv"};
  for (const auto& n : names) expected.insert(n + ".toml");
  CHECK(files == expected);  // no scratch file left behind
  CHECK(hm::test::slurp(dir.path / "out" / "index.csv") ==
        "name,command,physics.Q,lattice.seed\n"
        "Q=0.001_seed=1,run,0.001,1\nQ=0.001_seed=2,run,0.001,2\nQ=0.001_seed=3,run,0.001,3\n"
        "Q=0.01_seed=1,run,0.01,1\nQ=0.01_seed=2,run,0.01,2\nQ=0.01_seed=3,run,0.01,3\n");

  SECTION("the same file expands to the same bytes") {
    fs::create_directories(dir.path / "again");
    hm::cases::expand_sweep(dir.path / "s.toml", dir.path / "again");
    CHECK(hm::test::folder_snapshot(dir.path / "again") == hm::test::folder_snapshot(dir.path / "out"));
  }
  SECTION("each file is a valid case holding its swept values, the rest as given") {
    for (double Q : {1e-3, 1e-2})
      for (int seed : {1, 2, 3}) {
        const std::string name = std::string(Q == 1e-3 ? "Q=0.001" : "Q=0.01") + "_seed=" + std::to_string(seed);
        const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "out" / (name + ".toml"));
        CHECK(c.physics.parameters.Q == Q);
        CHECK(c.lattice.seed == static_cast<std::uint64_t>(seed));
        CHECK(c.physics.parameters.material.b == 0.5);
        CHECK(c.lattice.n_particles == 1000);
        CHECK(c.fracture_enabled);
      }
  }
}

TEST_CASE("Swept keys with one short name are named in full, and dotted keys work as quoted ones", "[case][sweep]") {
  TempDir dir("sweep-full-names");
  dir.write("s.toml", lattice_case + "[sweep]\nlattice.seed = [1]\nfracture.seed = [2, 3]\n");
  fs::create_directories(dir.path / "out");
  const auto sweep = hm::cases::expand_sweep(dir.path / "s.toml", dir.path / "out");
  REQUIRE(sweep.combinations.size() == 2);
  CHECK(sweep.combinations[0].name == "lattice.seed=1_fracture.seed=2");
  CHECK(hm::cases::read_run_case(dir.path / "out" / "lattice.seed=1_fracture.seed=3.toml").strength.seed == 3u);
}

TEST_CASE("A swept string becomes a safe file name, and an fdm1d sweep is run by `hmlattice fdm1d`", "[case][sweep]") {
  TempDir dir("sweep-fdm1d");
  dir.write("s.toml",
            "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n[numerics]\nn_r = 50\nt_end = 1\n"
            "[sweep]\n\"physics.vol_strain\" = [\"plane-strain\", \"appendix-a\"]\n\"physics.b\" = [0.2]\n");
  fs::create_directories(dir.path / "out");
  const auto sweep = hm::cases::expand_sweep(dir.path / "s.toml", dir.path / "out");
  CHECK(sweep.command == "fdm1d");
  REQUIRE(sweep.combinations.size() == 2);
  CHECK(sweep.combinations[1].name == "vol_strain=appendix-a_b=0.2");
  const auto c = hm::cases::read_fdm1d_case(dir.path / "out" / "vol_strain=appendix-a_b=0.2.toml");
  CHECK(c.physics.parameters.material.b == 0.2);
  CHECK(c.physics.parameters.material.vol_strain == hm::analytic::VolStrain::appendix_a);
}

TEST_CASE("A bad sweep is one line naming the key, the value and the rule", "[case][sweep]") {
  TempDir dir("sweep-refusals");
  SECTION("no [sweep]") { CHECK_THAT(expand_error(dir, ""), Catch::Contains("[sweep] is missing, allowed: a table")); }
  SECTION("an empty list") {
    CHECK_THAT(expand_error(dir, "[sweep]\n\"physics.Q\" = []\n"),
               Catch::EndsWith("s.toml: [sweep] physics.Q = [], allowed: a non-empty list of numbers, strings or "
                               "booleans, all of one kind"));
  }
  SECTION("mixed kinds") {
    CHECK_THAT(expand_error(dir, "[sweep]\n\"physics.Q\" = [0.1, \"x\"]\n"),
               Catch::Contains("[sweep] physics.Q = [0.1, \"x\"], allowed: a non-empty list"));
  }
  SECTION("a table in the list") {
    CHECK_THAT(expand_error(dir, "[sweep]\n\"physics.Q\" = [{a = 1}]\n"),
               Catch::Contains("[sweep] physics.Q = [{a = 1}], allowed: a non-empty list"));
  }
  SECTION("not a list") {
    CHECK_THAT(expand_error(dir, "[sweep]\n\"physics.Q\" = 0.1\n"),
               Catch::Contains("[sweep] physics.Q = 0.1, allowed: a non-empty list"));
  }
  SECTION("a key that is not table.key") {
    CHECK_THAT(expand_error(dir, "[sweep]\nQ = [0.1]\n"),
               Catch::Contains("[sweep] Q = [0.1], allowed: a key \"table.key\" of the case"));
  }
  SECTION("a key the model does not have") {
    CHECK_THAT(expand_error(dir, "[sweep]\n\"physics.Qx\" = [0.1]\n"),
               Catch::Contains("[sweep] combination Qx=0.1 (physics.Qx = 0.1): [physics] unknown key 'Qx', allowed: "));
  }
  SECTION("a value outside its rule, in the second combination") {
    CHECK_THAT(expand_error(dir, "[sweep]\n\"physics.b\" = [0.5, 1.5]\n"),
               Catch::EndsWith(
                   "s.toml: [sweep] combination b=1.5 (physics.b = 1.5): [physics] b = 1.5, allowed: 0 <= b <= 1"));
  }
  SECTION("a value of the wrong type") {
    CHECK_THAT(
        expand_error(dir, "[sweep]\n\"lattice.seed\" = [\"one\"]\n"),
        Catch::Contains(
            "[sweep] combination seed=one (lattice.seed = \"one\"): [lattice] seed = \"one\", allowed: an integer"));
  }
  SECTION("two values with one name") {
    CHECK_THAT(expand_error(dir, "[sweep]\n\"physics.Q\" = [0.1, 0.1]\n"),
               Catch::Contains("allowed: values that differ from physics.Q = 0.1 in a letter"));
  }
}

TEST_CASE("sweep expand refuses a bad sweep with exit 2 and writes nothing", "[case][sweep]") {
  TempDir dir("sweep-cli");
  dir.write("s.toml", lattice_case + "[sweep]\n\"physics.Q\" = [0.01, -1]\n");
  const auto before = hm::test::folder_snapshot(dir.path);
  const auto r = hm::test::run_hmlattice("sweep expand s.toml --out sub/cases", dir.path);
  CHECK(r.exit_code == 2);
  CHECK(r.err ==
        "hmlattice: s.toml: [sweep] combination Q=-1 (physics.Q = -1): [physics] Q = -1, allowed: 0 <= Q <= 1e+06\n");
  CHECK(hm::test::folder_snapshot(dir.path) == before);  // not even the parent folder "sub"

  SECTION("a good one appears whole, and is not replaced without --overwrite") {
    dir.write("s.toml", lattice_case + "[sweep]\n\"physics.Q\" = [0.01, 0.1]\n");
    const auto ok = hm::test::run_hmlattice("sweep expand s.toml --out cases", dir.path);
    CHECK(ok.exit_code == 0);
    CHECK(fs::exists(dir.path / "cases" / ".hmlattice"));
    CHECK(fs::exists(dir.path / "cases" / "Q=0.1.toml"));
    CHECK(hm::test::run_hmlattice("sweep expand s.toml --out cases", dir.path).exit_code == 2);
    CHECK(hm::test::run_hmlattice("sweep expand s.toml --out cases --overwrite", dir.path).exit_code == 0);
  }
}

TEST_CASE("collect gives one row per combination with its run's status", "[case][sweep]") {
  TempDir dir("sweep-collect");
  dir.write("s.toml", lattice_case + "[sweep]\n\"physics.Q\" = [0.01, 0.1, 1]\n");
  fs::create_directories(dir.path / "cases");
  hm::cases::expand_sweep(dir.path / "s.toml", dir.path / "cases");
  // Run folders as hmlattice leaves them (markers as core::ResultFolder writes them): one complete
  // with its tables, one stopped, none for Q = 1.
  const fs::path done = dir.path / "runs" / "Q=0.01", stopped = dir.path / "runs" / "Q=0.1";
  fs::create_directories(done);
  fs::create_directories(stopped);
  std::ofstream(done / ".hmlattice") << "# hmlattice result folder: x\nutc_time = \"2026-12-03T10:00:07Z\"\n";
  // Its config.toml: the combination's case, as `hmlattice run` resolves it, with the provenance.
  std::ofstream(done / "config.toml") << hm::test::slurp(dir.path / "cases" / "Q=0.01.toml")
                                      << "[provenance]\nutc_time = \"2026-12-03T10:00:00Z\"\n";
  std::ofstream(done / "breakdown.csv") << "t_first_break,p_h_first_break\n0.001,0.0002\n";
  std::ofstream(done / "fracture_summary.csv") << "t,n_arms\n0,0\n0.002,4\n";
  std::ofstream(stopped / ".hmlattice") << "# hmlattice result folder: x\ncomplete = false\n";

  std::ostringstream csv;
  const auto n = hm::cases::collect_sweep(dir.path / "cases", dir.path / "runs", csv);
  CHECK(n.complete == 1);
  CHECK(n.incomplete == 1);
  CHECK(n.missing == 1);
  CHECK(csv.str() ==
        "name,physics.Q,status,wall_seconds,t_first_break,p_h_first_break,final_t,final_n_arms\n"
        "Q=0.01,0.01,complete,7,0.001,0.0002,0.002,4\n"
        "Q=0.1,0.1,incomplete,,,,,\n"
        "Q=1,1,missing,,,,,\n");
  CHECK_THROWS_WITH(hm::cases::collect_sweep(dir.path / "runs", dir.path / "runs", csv),
                    Catch::Contains("no readable index.csv, allowed: a folder written by hmlattice sweep expand"));

  // A finished run of another case in a combination's folder (made before the sweep was changed) is
  // never listed under the combination's values: it was "complete" with Q = 1's results.
  const fs::path other = dir.path / "runs" / "Q=1";
  fs::create_directories(other);
  for (const char* f : {".hmlattice", "breakdown.csv", "fracture_summary.csv", "config.toml"})
    fs::copy_file(done / f, other / f);
  std::ostringstream again;
  const auto m = hm::cases::collect_sweep(dir.path / "cases", dir.path / "runs", again);
  CHECK(m.complete == 1);
  CHECK(m.other_case == 1);
  CHECK_THAT(again.str(), Catch::EndsWith("Q=1,1,other case,,,,,\n"));
}

TEST_CASE("A sweep's size is bounded, the case's own values of swept keys are checked, and SIGTERM leaves nothing",
          "[case][sweep]") {
  TempDir dir("sweep-bounds");
  // 101 x 100 = 10100 combinations: more than the default bound, refused before any is written.
  std::string q = "[", seeds = "[";
  for (int k = 0; k <= 100; ++k) q += (k ? ", " : "") + std::to_string(1e-3 * (k + 1));
  for (int k = 1; k <= 100; ++k) seeds += (k > 1 ? ", " : "") + std::to_string(k);
  const std::string big = "[sweep]\n\"physics.Q\" = " + q + "]\n\"lattice.seed\" = " + seeds + "]\n";
  CHECK(expand_error(dir, big) == (dir.path / "s.toml").string() +
                                      ": [sweep] 101 x 100 = 10100 combinations, allowed: at most 10000 "
                                      "(--max-combinations N to allow more)");
  CHECK(fs::is_empty(dir.path / "out"));
  const auto refused = hm::test::run_hmlattice("sweep expand s.toml --out big", dir.path);
  CHECK(refused.exit_code == 2);
  CHECK(hm::test::count_lines(refused.err) == 1);
  CHECK_FALSE(fs::exists(dir.path / "big"));

  // The case's own b, which the sweep replaces, is still part of the file: `run` would refuse it.
  dir.write("own.toml",
            hm::test::edited(lattice_case, {{"b = 0.5", "b = 1.0000001"}}) + "[sweep]\n\"physics.b\" = [0.2, 0.8]\n");
  const auto own = hm::test::run_hmlattice("sweep expand own.toml --out own", dir.path);
  CHECK(own.exit_code == 2);
  CHECK_THAT(own.err, Catch::Contains("[physics] b = 1.0000001, allowed: 0 <= b <= 1 (the case's own value of "
                                      "physics.b, which [sweep] replaces)"));
  CHECK_FALSE(fs::exists(dir.path / "own"));

  // Allowed explicitly, a sweep far longer than a second (1e4 combinations take ~2 s here)
  // starts; SIGTERM ends it with one line, exit 143, and no folder (its staging folder removed).
  std::string many_seeds = "[";
  for (int k = 1; k <= 1000; ++k) many_seeds += (k > 1 ? ", " : "") + std::to_string(k);
  dir.write("s.toml", lattice_case + "[sweep]\n\"physics.Q\" = " + q + "]\n\"lattice.seed\" = " + many_seeds + "]\n");
  const std::string cmd = "cd '" + dir.path.string() + "' && ('" + HMLATTICE_EXE +
                          "' sweep expand s.toml --out big --max-combinations 200000 2> err.txt & pid=$!; sleep 1; "
                          "kill -TERM $pid; wait $pid; echo $? > rc.txt)";
  REQUIRE(std::system(cmd.c_str()) == 0);
  CHECK(hm::test::slurp(dir.path / "rc.txt") == "143\n");
  const std::string err = hm::test::slurp(dir.path / "err.txt");
  CHECK(hm::test::count_lines(err) == 1);
  CHECK_THAT(err, Catch::Contains("interrupted by SIGTERM after") &&
                      Catch::Contains("of 101000 combinations; nothing written"));
  for (const auto& e : fs::directory_iterator(dir.path))
    CHECK(e.path().filename().string().rfind(".hmlattice-staging-", 0) != 0);
  CHECK_FALSE(fs::exists(dir.path / "big"));
}
