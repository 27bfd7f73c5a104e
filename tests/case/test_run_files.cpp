// The one table of the files `hmlattice run` writes (run_files.hpp) against what a run leaves in its
// folder, what the run and its --help say, and the README's table of them.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include "hm/case/run_case.hpp"
#include "hm/case/run_files.hpp"
#include "run_command.hpp"

using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace {

// Every regular file under `dir` (relative paths), but the .hmlattice marker and the VTK snapshots'
// numbered .vtu files, which the .pvd names.
std::set<std::string> files_in(const std::filesystem::path& dir) {
  std::set<std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    const std::string rel = std::filesystem::relative(e.path(), dir).generic_string();
    if (e.is_regular_file() && rel != ".hmlattice" && e.path().extension() != ".vtu") out.insert(rel);
  }
  return out;
}

std::set<std::string> names_of(const hm::cases::RunCase& c) {
  std::set<std::string> out;
  for (const auto& f : hm::cases::files_written(c)) out.insert(std::string(f.name));
  return out;
}

}  // namespace

TEST_CASE("A run's folder holds exactly the table's files for its case, and its closing line names them", "[case]") {
  // Without fracture, with brittle beams and VTK, and with the saw-tooth law: the three kinds of rows.
  struct Variant {
    std::string name, fracture, output;
  };
  for (const Variant& v : {Variant{"plain", "", "vtk = false"}, Variant{"brittle", "", "vtk = true"},
                           Variant{"sawtooth", "law = \"sawtooth\"\nfracture_energy = 2.34e-9\n", "vtk = false"}}) {
    DYNAMIC_SECTION(v.name) {
      TempDir dir("run-files-" + v.name);
      std::string text = hm::test::edited(hm::test::short_fig12_case("1e-4", v.fracture), {{"vtk = false", v.output}});
      if (v.name == "plain") text = hm::test::edited(text, {{"enabled = true", "enabled = false"}});
      dir.write("case.toml", text);
      const auto r = run_hmlattice("run case.toml --out run", dir.path);
      INFO("stderr: " << r.err);
      REQUIRE(r.exit_code == 0);
      const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "run" / "config.toml");
      const std::set<std::string> expected = names_of(c);
      CHECK(files_in(dir.path / "run") == expected);
      CHECK(expected.count("teeth.csv") == (v.name == "sawtooth" ? 1u : 0u));
      CHECK(expected.count("breaks.csv") == (v.name == "plain" ? 0u : 1u));
      CHECK(expected.count("vtk/lattice.pvd") == (v.name == "brittle" ? 1u : 0u));
      CHECK_THAT(r.out, Catch::Contains("Results: run/{series,radial"));
      CHECK_THAT(r.out, Catch::Contains(hm::cases::results_line("run", c)));
    }
  }
}

TEST_CASE("run --help lists every file of the table, and so does the README's table of a run's files", "[case]") {
  TempDir dir("run-files-help");
  const auto help = run_hmlattice("run --help", dir.path);
  REQUIRE(help.exit_code == 0);
  const std::string readme = slurp(std::filesystem::path(HM_SOURCE_DIR) / "README.md");
  // The README's table under "### The 2D lattice": its rows start with "| `name` |".
  const auto section = readme.find("### The 2D lattice");
  REQUIRE(section != std::string::npos);
  const std::string lattice_part = readme.substr(section, readme.find("\n## ", section) - section);
  std::set<std::string> readme_files;
  for (std::size_t at = lattice_part.find("\n| `"); at != std::string::npos; at = lattice_part.find("\n| `", at + 1)) {
    const std::size_t from = at + 4, to = lattice_part.find('`', from);
    readme_files.insert(lattice_part.substr(from, to - from));
  }
  std::set<std::string> table;
  for (const auto& f : hm::cases::run_files) {
    table.insert(std::string(f.name));
    CHECK_THAT(help.out, Catch::Contains(std::string(f.name)));
  }
  CHECK(readme_files == table);
}
