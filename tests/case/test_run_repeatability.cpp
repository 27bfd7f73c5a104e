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
  const auto r = run_hmlattice("run case.toml --out run", dir.path, "export OPENBLAS_NUM_THREADS=2 OMP_NUM_THREADS=1; ");
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  const toml::value config = toml::parse((dir.path / "run" / "config.toml").string());
  const toml::value& p = toml::find(config, "provenance");
  for (const char* key : {"blas", "blas_core", "blas_threads", "omp_num_threads", "omp_max_threads", "compiler", "libc"})
    CHECK(p.contains(key));
  // This machine's libblas.so.3 is OpenBLAS (scripts/install-deps.sh): its identity is known.
  CHECK_THAT(toml::find<std::string>(p, "blas"), Catch::StartsWith("OpenBLAS"));
  CHECK(toml::find<std::string>(p, "blas_core") != "unknown");
  CHECK(toml::find<long long>(p, "blas_threads") == 1);
  CHECK(toml::find<std::string>(p, "omp_num_threads") == "1");
  CHECK(toml::find<long long>(p, "omp_max_threads") == 1);
  // The rerun's config.toml reads the provenance it carries as provenance (ignored as input).
  REQUIRE(run_hmlattice("run run/config.toml --out run2", dir.path).exit_code == 0);
  CHECK(slurp(dir.path / "run" / "series.csv") == slurp(dir.path / "run2" / "series.csv"));
}

TEST_CASE("A case path and result folder holding a newline, quotes, a backslash and a non-UTF-8 byte give a "
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
  CHECK_THAT(command_line, Catch::Contains("odd\nname \"q\" back\\slash \xEF\xBF\xBD" "end.toml"));
  // The result marker holds the same command line and reads back too.
  CHECK_NOTHROW(toml::parse((folder / ".hmlattice").string()));
  // The folder reruns from its config.toml.
  REQUIRE(run_hmlattice("run '" + name + "/config.toml' --out again", dir.path).exit_code == 0);
  CHECK(slurp(folder / "series.csv") == slurp(dir.path / "again" / "series.csv"));
}
