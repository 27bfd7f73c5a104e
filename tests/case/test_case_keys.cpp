// The key tables: one entry is read, written to config.toml and listed in the reference. A throwaway
// test-only table stands in for a new case key; the real tables are checked through a run's config.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "hm/case/case_file.hpp"
#include "hm/case/case_keys.hpp"
#include "hm/case/fdm1d_case.hpp"
#include "hm/case/run_case.hpp"
#include "hm/core/input_error.hpp"
#include "run_command.hpp"

using hm::cases::CaseFile;
using hm::cases::CaseKeys;
using hm::test::TempDir;

namespace {

struct ToyCase {
  double throwaway = 0.25;
  int count = 3;
};

// The table a contributor would extend: one entry per key.
CaseKeys<ToyCase> toy_keys() {
  CaseKeys<ToyCase> k;
  k.table("experiment")
      .real(
          "throwaway", [](auto& c) -> auto& { return c.throwaway; }, "> 0", "a key that exists only in this test")
      .integer(
          "count", [](auto& c) -> auto& { return c.count; }, 1, 9, "1 ... 9", "a bounded integer");
  return k;
}

ToyCase read_toy(const TempDir& dir, const std::string& toml) {
  dir.write("toy.toml", toml);
  CaseFile file(dir.path / "toy.toml");
  hm::cases::CaseTable root = file.root();
  ToyCase c;
  toy_keys().read(root, c);
  root.reject_unknown();
  return c;
}

std::string error_of(const TempDir& dir, const std::string& toml) {
  try {
    read_toy(dir, toml);
  } catch (const hm::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("A key added as one table entry is read, written to config.toml and listed in the reference", "[case]") {
  TempDir dir("case-keys");
  // Read: the file's value, or the struct's default when absent.
  CHECK(read_toy(dir, "[experiment]\nthrowaway = 0.5\n").throwaway == 0.5);
  CHECK(read_toy(dir, "").throwaway == 0.25);
  CHECK(read_toy(dir, "[experiment]\ncount = 7\n").count == 7);
  // Rejected with file, table, key and rule: out of range, wrong type, misspelt.
  CHECK(error_of(dir, "[experiment]\ncount = 12\n") ==
        (dir.path / "toy.toml").string() + ": [experiment] count = 12, allowed: 1 ... 9");
  CHECK_THAT(error_of(dir, "[experiment]\nthrowaway = \"x\"\n"),
             Catch::Contains("[experiment] throwaway = \"x\", allowed: a finite number"));
  CHECK_THAT(error_of(dir, "[experiment]\nthrowaway_ = 1\n"),
             Catch::Contains("[experiment] unknown key 'throwaway_', allowed: count, throwaway"));
  // Written: the resolved value, and what is written reads back to the same case.
  ToyCase c;
  c.throwaway = 0.125;
  const std::string toml = toy_keys().to_toml(c);
  CHECK(toml == "[experiment]\nthrowaway = 0.125\ncount = 3\n\n");
  CHECK(read_toy(dir, toml).throwaway == 0.125);
  // Documented: type, default, rule and meaning.
  CHECK_THAT(toy_keys().reference_markdown(),
             Catch::Contains("| `throwaway` | real | `0.25` | > 0 | a key that exists only in this test |"));
}

TEST_CASE("Every key of the 2D case tables is in the resolved config.toml and reads back to the same case", "[case]") {
  TempDir dir("case-keys-run");
  dir.write("case.toml",
            "model = \"lattice2d\"\n[physics]\nQ = 0.01\nb = 0.5\nR_i = 0\n[lattice]\nn_particles = 1000\n"
            "[coupling]\nsplit = \"drained\"\n[numerics]\nt_end = 2e-4\n");
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");
  const std::string config = hm::cases::run_case_to_toml(c, "");
  for (const auto& table : hm::cases::run_case_keys().tables())
    for (const auto& key : table.keys) CHECK_THAT(config, Catch::Contains("\n" + key.name + " = "));
  // The computed defaults: Psi follows the split, dt_max is t_end.
  CHECK_THAT(config, Catch::Contains("\npsi = 0\n"));
  CHECK_THAT(config, Catch::Contains("\nt_end = 2e-04\ndt_max = 2e-04\n"));
  dir.write("config.toml", config);
  CHECK(hm::cases::run_case_to_toml(hm::cases::read_run_case(dir.path / "config.toml"), "") == config);
}

namespace {

// Every key of the reference's tables named in `tables` (its markdown: "### [table]", then a row per
// key "| `name` | type | ..."), given a value of the wrong type on top of the case `base`: `read`
// must refuse it in one line naming the table and the key. Returns how many keys were tried.
template <class Read>
int check_every_key_refused(const TempDir& dir, const std::string& base, const std::string& reference,
                            const std::vector<std::string>& tables, Read read) {
  dir.write("case.toml", base);
  int n = 0;
  std::string table;
  std::istringstream lines(reference);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("### [", 0) == 0) table = line.substr(5, line.find(']') - 5);
    if (line.rfind("| `", 0) != 0 || std::find(tables.begin(), tables.end(), table) == tables.end()) continue;
    // "| `key` | type | ...": the cells between the bars.
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell);
    REQUIRE(cells.size() >= 3);
    const std::string key = cells[1].substr(2, cells[1].size() - 4);   // " `key` "
    const std::string type = cells[2].substr(1, cells[2].size() - 2);  // " type "
    // A value of the wrong type is bad for every key, whatever its rule.
    const std::string bad = type == "string" ? "12345" : "\"not a value\"";
    const std::string set = table + "." + key + "=" + bad;
    INFO(set);
    std::string message = "no error";
    try {
      read(dir.path / "case.toml", std::vector<std::string>{set});
    } catch (const hm::InputError& e) {
      message = e.what();
    }
    CHECK_THAT(message, Catch::Contains("[" + table + "] " + key + " = " + bad + ", allowed: "));
    CHECK(message.find('\n') == std::string::npos);
    ++n;
  }
  return n;
}

}  // namespace

TEST_CASE("A bad value of every case key is refused in one message naming its table and key", "[case]") {
  TempDir dir("case-keys-bad");
  const std::string lattice =
      "model = \"lattice2d\"\n[lattice]\nn_particles = 1000\n[coupling]\nsplit = \"drained\"\n"
      "[numerics]\nt_end = 2e-4\n";
  const auto read_2d = [](const std::filesystem::path& f, const std::vector<std::string>& o) {
    hm::cases::read_run_case(f, o);
  };
  const std::string run_reference =
      hm::cases::physics_reference_markdown() + hm::cases::run_case_keys().reference_markdown();
  std::vector<std::string> run_tables;
  for (const auto& table : hm::cases::run_case_keys().tables()) run_tables.push_back(table.name);
  const int n_2d = check_every_key_refused(dir, lattice + "[physics]\nQ = 0.01\nb = 0.5\nR_i = 0\n", run_reference,
                                           run_tables, read_2d);
  CHECK(n_2d == [] {
    std::size_t n = 0;
    for (const auto& table : hm::cases::run_case_keys().tables()) n += table.keys.size();
    return static_cast<int>(n);
  }());
  CHECK(check_every_key_refused(dir, lattice + "[physics]\nQ = 0.01\nb = 0.5\nR_i = 0\n", run_reference, {"physics"},
                                read_2d) >= 10);
  CHECK(check_every_key_refused(dir, lattice + "[physics_si]\nq = 1e-6\nb = 0.5\nR_i = 0\n", run_reference,
                                {"physics_si"}, read_2d) >= 15);
  const std::string fdm1d_reference =
      hm::cases::physics_reference_markdown() + hm::cases::fdm1d_case_keys().reference_markdown();
  std::vector<std::string> fdm1d_tables = {"physics"};
  for (const auto& table : hm::cases::fdm1d_case_keys().tables()) fdm1d_tables.push_back(table.name);
  CHECK(check_every_key_refused(dir, "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.5\n[numerics]\nt_end = 0.01\n",
                                fdm1d_reference, fdm1d_tables,
                                [](const std::filesystem::path& f, const std::vector<std::string>& o) {
                                  hm::cases::read_fdm1d_case(f, o);
                                }) >= 20);
}
