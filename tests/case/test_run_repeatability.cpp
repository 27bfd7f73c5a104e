// config.toml repeats a run: it records what of the environment changes the numbers (the BLAS and
// its threads, OpenMP), reads back whatever the paths in it hold, and an SI case keeps its SI inputs
// through any number of reruns.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <toml.hpp>

#include "hm/case/fdm1d_case.hpp"
#include "hm/case/run_case.hpp"
#include "run_command.hpp"

using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

// N = 600 disk, two steps, no VTK: a run of about a second.
const std::string tiny_case =
    "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 600\n"
    "[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n[output]\nradial_bins = 5\nvtk = false\n";

// The text of one table of a config.toml, from its header to the next table's (comments included).
std::string table_text(const std::string& config, const std::string& name) {
  const std::size_t at = config.find("\n[" + name + "]\n");
  if (at == std::string::npos) return "";
  const std::size_t end = config.find("\n[", at + 1);
  return config.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

}  // namespace

TEST_CASE("config.toml records the BLAS and OpenMP in effect, OpenBLAS on one thread whatever the environment says",
          "[case][cli]") {
  TempDir dir("provenance-blas");
  dir.write("case.toml", tiny_case);
  // A user's OPENBLAS_NUM_THREADS = 2 is overridden: two threads change the supernodal factor's bits.
  const auto r =
      run_hmlattice("run case.toml --out run", dir.path, "export OPENBLAS_NUM_THREADS=2 OMP_NUM_THREADS=1; ");
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const toml::value config = toml::parse((dir.path / "run" / "config.toml").string());
  const toml::value& p = toml::find(config, "provenance");
  for (const char* key : {"blas", "blas_core", "blas_threads", "omp_num_threads", "omp_max_threads", "omp_wait_policy",
                          "compiler", "libc"})
    CHECK(p.contains(key));
  // OpenMP's threads sleep between regions unless the user chose otherwise (app/main.cpp).
  CHECK(toml::find<std::string>(p, "omp_wait_policy") == "passive");
  // This machine's libblas.so.3 is OpenBLAS (scripts/install-deps.sh): its identity is known.
  CHECK_THAT(toml::find<std::string>(p, "blas"), Catch::StartsWith("OpenBLAS"));
  CHECK(toml::find<std::string>(p, "blas_core") != "unknown");
  CHECK(toml::find<long long>(p, "blas_threads") == 1);
  CHECK(toml::find<std::string>(p, "omp_num_threads") == "1");
  CHECK(toml::find<long long>(p, "omp_max_threads") == 1);
  // The rerun's config.toml reads the provenance it carries as provenance (ignored as input); a user's
  // own wait policy is kept.
  REQUIRE(run_hmlattice("run run/config.toml --out run2", dir.path, "export OMP_WAIT_POLICY=active; ").exit_code == 0);
  CHECK(toml::find<std::string>(toml::find(toml::parse((dir.path / "run2" / "config.toml").string()), "provenance"),
                                "omp_wait_policy") == "active");
  CHECK(slurp(dir.path / "run" / "series.csv") == slurp(dir.path / "run2" / "series.csv"));
}

TEST_CASE(
    "A case path and result folder holding a newline, quotes, a backslash and a non-UTF-8 byte give a "
    "config.toml that reads back",
    "[case][cli]") {
  TempDir dir("provenance-path");
  // Passed to the shell inside single quotes, where every byte but ' is literal.
  const std::string name = std::string("odd\nname \"q\" back\\slash ") + "\xff" + "end";
  dir.write(name + ".toml", tiny_case);
  const auto r = run_hmlattice("run '" + name + ".toml' --out '" + name + "'", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const std::filesystem::path folder = dir.path / name;
  REQUIRE(std::filesystem::exists(folder / "config.toml"));
  const hm::cases::RunCase c = hm::cases::read_run_case(folder / "config.toml");
  CHECK(c.lattice.n_particles == 600);
  const toml::value config = toml::parse((folder / "config.toml").string());
  const std::string command_line = toml::find<std::string>(config, "provenance", "command_line");
  // Newline, quotes and backslash come back as they were; the byte that is no UTF-8 as U+FFFD.
  CHECK_THAT(command_line, Catch::Contains("odd\nname \"q\" back\\slash \xEF\xBF\xBD"
                                           "end.toml"));
  // The result marker holds the same command line and reads back too.
  CHECK_NOTHROW(toml::parse((folder / ".hmlattice").string()));
  // The folder reruns from its config.toml.
  REQUIRE(run_hmlattice("run '" + name + "/config.toml' --out again", dir.path).exit_code == 0);
  CHECK(slurp(folder / "series.csv") == slurp(dir.path / "again" / "series.csv"));
}

TEST_CASE("An SI case rerun from its config.toml keeps its SI inputs and scales, and gives the same numbers",
          "[case][cli]") {
  TempDir dir("provenance-si");
  // Table 1 with k = 1e-14 m^2 and q = 1e-2 m^2/s: Q = mu q/(k E) = 0.1 (test_run_case.cpp).
  dir.write("si.toml",
            "model = \"lattice2d\"\n[physics_si]\nE = 1e10\nnu = 0.25\nk = 1e-14\nmu = 1e-3\nq = 1e-2\nR = 2\n"
            "R_i = 0\nb = 0.5\n[lattice]\nn_particles = 600\n[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n"
            "[output]\nradial_bins = 5\nvtk = false\n");
  REQUIRE(run_hmlattice("run si.toml --out a", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("run a/config.toml --out b", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("run b/config.toml --out c", dir.path).exit_code == 0);
  const std::string first = slurp(dir.path / "a" / "config.toml"), second = slurp(dir.path / "b" / "config.toml"),
                    third = slurp(dir.path / "c" / "config.toml");
  const std::string si = table_text(first, "physics_si");
  REQUIRE_FALSE(si.empty());
  CHECK_THAT(si, Catch::Contains("\nR = 2\n") && Catch::Contains("\nq = 0.01\n"));
  // The scales back to SI: t_s = mu R^2/(k E) = 1e-3 * 4 / (1e-14 * 1e10) = 40 s.
  CHECK_THAT(si, Catch::Contains("time x 40 s"));
  CHECK(table_text(second, "physics_si") == si);
  CHECK(table_text(third, "physics_si") == si);
  CHECK(toml::find(toml::parse((dir.path / "b" / "config.toml").string()), "physics_si") ==
        toml::find(toml::parse((dir.path / "a" / "config.toml").string()), "physics_si"));
  // The same dimensionless run: the SI inputs convert to the same doubles every time.
  CHECK(slurp(dir.path / "a" / "series.csv") == slurp(dir.path / "b" / "series.csv"));
  CHECK(slurp(dir.path / "a" / "radial.csv") == slurp(dir.path / "c" / "radial.csv"));

  // The 1D model's config.toml the same way (cases/fdm1d_sandstone_si.toml, shortened).
  std::string sandstone = slurp(std::string(HM_SOURCE_DIR) + "/cases/fdm1d_sandstone_si.toml");
  sandstone = sandstone.substr(0, sandstone.find("[numerics]")) +
              "[numerics]\nn_r = 40\nt_end = 0.01\n[output]\ntimes = [0.01]\nprobes = [0.5]\n";
  dir.write("sandstone.toml", sandstone);
  REQUIRE(run_hmlattice("fdm1d sandstone.toml --out d", dir.path).exit_code == 0);
  REQUIRE(run_hmlattice("fdm1d d/config.toml --out e", dir.path).exit_code == 0);
  const std::string d = slurp(dir.path / "d" / "config.toml"), e = slurp(dir.path / "e" / "config.toml");
  REQUIRE_FALSE(table_text(d, "physics_si").empty());
  CHECK_THAT(table_text(d, "physics_si"), Catch::Contains("time x 10 s"));
  CHECK(table_text(e, "physics_si") == table_text(d, "physics_si"));
  CHECK(slurp(dir.path / "d" / "profiles.csv") == slurp(dir.path / "e" / "profiles.csv"));
}
