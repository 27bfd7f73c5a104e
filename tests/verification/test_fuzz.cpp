// Seeded fuzzing of case files and command lines: every mutated input ends either as a valid run
// (exit 0, the result folder with its config.toml) or as bad input (exit 2, exactly one line on
// stderr, no result folder), never a crash, a signal, a hang, another exit code or a half-written
// folder. The seed is fixed, so a failure is reproducible; the failing input is printed.
#include <catch2/catch.hpp>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::TempDir;

namespace fs = std::filesystem;

namespace {

const std::string fdm1d_case =
    "model = \"fdm1d\"\n[physics]\nQ = 0.01\nb = 0.2\nnu = 0.25\nR_i = 0.138\n[numerics]\nn_r = 40\n"
    "dt_initial = 1e-4\ndt_growth = 1.2\nt_end = 0.01\n[output]\ntimes = [0.005, 0.01]\nprobes = [0.2, 0.5]\n";
const std::string lattice_case =
    "model = \"lattice2d\"\n[physics]\nQ = 0.1\nb = 0.5\nR_i = 0\n[lattice]\ndomain = \"disk\"\nn_particles = 500\n"
    "seed = 3\n[coupling]\nsplit = \"undrained\"\nmax_iterations = 50\n[numerics]\ndt_initial = 5e-6\nt_end = 1e-5\n"
    "[output]\nvtk = false\nradial_bins = 4\n";

// Values that once slipped through somewhere (wrapping, overflow, empty, wrong type), and plain ones.
const std::vector<std::string> values = {"-1",
                                         "0",
                                         "0.5",
                                         "2",
                                         "1e308",
                                         "-1e308",
                                         "nan",
                                         "inf",
                                         "-inf",
                                         "4294967696",
                                         "9223372036854775807",
                                         "9223372036854775808",
                                         "-9223372036854775809",
                                         "99999999999999999999",
                                         "1e-320",
                                         "\"\"",
                                         "\"x\"",
                                         "[1, 2]",
                                         "{ a = 1 }",
                                         "true",
                                         "\"" + std::string(3000, 'y') + "\"",
                                         "0x10",
                                         "1_000"};

std::string mutate(const std::string& text, std::mt19937& rng) {
  std::vector<std::string> lines;
  for (std::size_t at = 0, next; at < text.size(); at = next + 1) {
    next = text.find('\n', at);
    lines.push_back(text.substr(at, next - at));
  }
  const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const std::size_t k = pick(lines.size());
  switch (pick(6)) {
    case 0: lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(k)); break;             // a key or table left out
    case 1: lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(k), lines[k]); break;  // given twice
    case 2: {                                                                               // a value replaced
      const auto eq = lines[k].find(" = ");
      if (eq != std::string::npos) lines[k] = lines[k].substr(0, eq + 3) + values[pick(values.size())];
      break;
    }
    case 3: {  // the file cut at a random byte
      std::string joined;
      for (const auto& l : lines) joined += l + "\n";
      return joined.substr(0, pick(joined.size() + 1));
    }
    case 4: lines[k].insert(pick(lines[k].size() + 1), 1, "=[]{}\"#\\\n\t\x01\xff"[pick(12)]); break;  // a stray byte
    default: lines[k] = lines[k].empty() ? "x" : lines[k].substr(0, lines[k].size() / 2);              // a line cut
  }
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

// No staging or replaced folder may be left in `dir` after a command.
bool has_leftovers(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".hmlattice-", 0) == 0) return true;
  return false;
}

void check_outcome(const hm::test::CommandResult& r, const fs::path& dir, const fs::path& out,
                   const std::string& input) {
  INFO("input:\n" << input << "\nexit " << r.exit_code << ", stderr: " << r.err);
  const bool valid_run = r.exit_code == 0 && fs::exists(out / "config.toml");
  const bool bad_input = r.exit_code == 2 && count_lines(r.err) == 1 && !fs::exists(out);
  CHECK((valid_run || bad_input));
  CHECK_FALSE(has_leftovers(dir));
}

}  // namespace

TEST_CASE("Fuzzed case files end as a valid run or as one line of bad input", "[verification][cli][fuzz]") {
  TempDir dir("fuzz-cases");
  std::mt19937 rng(20261202);
  int n = 0;
  for (const auto& [command, base, count] :
       {std::tuple{"fdm1d", fdm1d_case, 300}, std::tuple{"run", lattice_case, 150}}) {
    for (int i = 0; i < count; ++i, ++n) {
      const std::string input = mutate(base, rng);
      dir.write("case.toml", input);
      const fs::path out = dir.path / ("out" + std::to_string(n));
      // A hang is a failure too: 60 s is ~100x what any of these runs takes.
      const auto r = hm::test::run_hmlattice(std::string(command) + " case.toml --out " + out.filename().string(),
                                             dir.path, "ulimit -t 60; ");
      check_outcome(r, dir.path, out, input);
      fs::remove_all(out);
    }
  }
}

TEST_CASE("Fuzzed command lines end as a valid result or as one line of bad input", "[verification][cli][fuzz]") {
  TempDir dir("fuzz-cli");
  std::mt19937 rng(7);
  const std::vector<std::string> commands = {"analytic rudnicki --r 0.1,0.2", "analytic borehole-steady --r 0.2,0.5",
                                             "analytic sneddon --x 0,0.05", "analytic lame --r 0.5,1",
                                             "analytic kgd --Km 0,2"};
  const std::vector<std::string> options = {"--Q",  "--b",  "--nu", "--t",    "--E_over_M", "--Ri",
                                            "--Ro", "--pi", "--po", "--p",    "--c",        "--vol_strain",
                                            "--r",  "--x",  "--Km", "--bogus"};
  const std::vector<std::string> cli_values = {"''", "-1",  "0",        "0.3",          "1e308",      "nan",   "inf",
                                               "x",  "1,2", "0.1,,0.2", "plane-strain", "appendix-a", "1e-320"};
  const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  for (int i = 0; i < 200; ++i) {
    std::string line = commands[pick(commands.size())];
    for (std::size_t k = 0, m = 1 + pick(3); k < m; ++k)
      line += " " + options[pick(options.size())] + " " + cli_values[pick(cli_values.size())];
    const auto r = hm::test::run_hmlattice(line, dir.path, "ulimit -t 60; ");
    INFO(line << "\nexit " << r.exit_code << ", stderr: " << r.err);
    const bool valid = r.exit_code == 0 && r.err.empty() && (r.out.rfind("r,", 0) == 0 || r.out.rfind("x,", 0) == 0);
    const bool bad_input = r.exit_code == 2 && count_lines(r.err) == 1 && r.out.empty();
    CHECK((valid || bad_input));
    CHECK(dir.is_empty());
  }
}

TEST_CASE("Fuzzed sweep tables end as the expanded cases or as one line of bad input", "[verification][cli][fuzz]") {
  TempDir dir("fuzz-sweeps");
  std::mt19937 rng(5);
  // One swept key of each kind: a real, a bounded real, an integer and a choice; the case's own
  // values of the swept keys are mutated too (line 3 of the base is b's).
  const std::string base = fdm1d_case +
                           "[sweep]\n\"physics.Q\" = [0.001, 0.01]\n\"physics.b\" = [0.2, 0.8]\n"
                           "\"numerics.n_r\" = [40, 80]\n";
  const std::string huge_list = [] {  // 1000 values: two such keys give 1e6 combinations, over the default cap
    std::string list = "[";
    for (int k = 1; k <= 1000; ++k) list += std::to_string(k) + (k < 1000 ? ", " : "]");
    return list;
  }();
  for (int i = 0; i < 120; ++i) {
    std::string input = mutate(base, rng);
    if (i % 10 == 0)  // a sweep far past the cap, which must be refused before anything is written
      input += "\"numerics.n_r\" = " + huge_list + "\n\"numerics.dt_growth\" = " + huge_list + "\n";
    dir.write("case.toml", input);
    const fs::path out = dir.path / ("sweep" + std::to_string(i));
    const auto r =
        hm::test::run_hmlattice("sweep expand case.toml --out " + out.filename().string(), dir.path, "ulimit -t 60; ");
    INFO("input:\n" << input << "\nexit " << r.exit_code << ", stderr: " << r.err);
    const bool expanded = r.exit_code == 0 && fs::exists(out / "index.csv");
    const bool bad_input = r.exit_code == 2 && count_lines(r.err) == 1 && !fs::exists(out);
    CHECK((expanded || bad_input));
    CHECK_FALSE(has_leftovers(dir.path));
    fs::remove_all(out);
  }
}

TEST_CASE("Fuzzed result folders: no hang, no crash, and a file the user put there survives every command",
          "[verification][cli][fuzz]") {
  TempDir dir("fuzz-folders");
  std::mt19937 rng(20261206);
  const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  // A stopped run (one of its two steps, with VTK): every kind of file a result folder holds.
  std::string with_vtk = lattice_case;
  with_vtk.replace(with_vtk.find("vtk = false"), 11, "vtk = true");
  dir.write("case.toml", with_vtk);
  REQUIRE(hm::test::run_hmlattice("run case.toml --out pristine --stop-after-steps 1", dir.path).exit_code == 0);
  std::vector<fs::path> toolkit_files;
  for (const auto& e : fs::recursive_directory_iterator(dir.path / "pristine"))
    if (e.is_regular_file()) toolkit_files.push_back(fs::relative(e.path(), dir.path / "pristine"));
  REQUIRE(toolkit_files.size() >= 8);
  const std::vector<std::string> user_files = {"my_notes.txt", "vtk/my_view.pvsm", "analysis/plot.py", ".my_hidden"};
  // What a file the toolkit expects may have become: a pipe without a writer (reading it would block),
  // a link to an endless device, a folder, nothing, half of itself, noise.
  const std::vector<std::string> damage = {"mkfifo", "ln -s /dev/zero", "mkdir", "empty", "half", "noise"};
  const std::vector<std::string> commands = {"run --resume part", "run case.toml --out part --overwrite",
                                             "fractures part", "run case.toml --out part"};
  for (int i = 0; i < 60; ++i) {
    fs::remove_all(dir.path / "part");
    fs::copy(dir.path / "pristine", dir.path / "part", fs::copy_options::recursive);
    std::string what;
    std::vector<std::pair<fs::path, std::string>> kept;  // the user's files and their content
    for (std::size_t k = 0, m = 1 + pick(2); k < m; ++k) {
      if (pick(2) == 0) {
        const fs::path file = dir.path / "part" / user_files[pick(user_files.size())];
        fs::create_directories(file.parent_path());
        const std::string text = "the user's " + std::to_string(i);
        std::ofstream(file) << text;
        kept.emplace_back(file, text);
        what += "user file " + fs::relative(file, dir.path).string() + "; ";
      } else {
        const fs::path name = toolkit_files[pick(toolkit_files.size())];
        const fs::path file = dir.path / "part" / name;
        const std::string make = damage[pick(damage.size())];
        const std::string original = hm::test::slurp(dir.path / "pristine" / name);
        fs::remove_all(file);
        if (make == "empty" || make == "half" || make == "noise")
          std::ofstream(file, std::ios::binary) << (make == "half"    ? original.substr(0, original.size() / 2)
                                                    : make == "noise" ? std::string("\001\377x")
                                                                      : std::string());
        else
          REQUIRE(std::system((make + " '" + file.string() + "'").c_str()) == 0);
        what += make + " " + name.string() + "; ";
      }
    }
    const std::string command = commands[pick(commands.size())];
    // A hang is a failure: killed after 60 s of wall time (a FIFO blocks without using CPU), exit 137.
    const auto r = hm::test::run_hmlattice(command, dir.path, "", "timeout -s KILL 60 ");
    INFO("damage: " << what << "\ncommand: " << command << "\nexit " << r.exit_code << ", stderr: " << r.err);
    CHECK((r.exit_code == 0 || ((r.exit_code == 1 || r.exit_code == 2) && count_lines(r.err) == 1)));
    for (const auto& [file, text] : kept) {
      CHECK(fs::is_regular_file(file));
      CHECK(hm::test::slurp(file) == text);
    }
    CHECK_FALSE(has_leftovers(dir.path));
  }
}
