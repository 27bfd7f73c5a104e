#pragma once
// Runs the hmlattice executable as a user would and captures exit code, stdout and stderr.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hm::test {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// `text` with each edit's first `from` replaced by its `to`, in order; throws std::runtime_error for
/// a `from` that is not there (the case file the test edits has changed under it).
inline std::string edited(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("edited: '" + from + "' is not in the text");
    text.replace(at, from.size(), to);
  }
  return text;
}

/// Runs `HMLATTICE_EXE <args>` in `workdir` (args are passed to the shell as written), after the
/// shell commands `prefix` (e.g. a ulimit), through `launcher` (e.g. "timeout -s KILL 60 "). stdout and
/// stderr are captured outside `workdir`, so that a test can compare the folder's content before and after.
inline CommandResult run_hmlattice(const std::string& args, const std::filesystem::path& workdir,
                                   const std::string& prefix = "", const std::string& launcher = "") {
  const std::string tag = "hmlattice-capture-" + std::to_string(::getpid()) + "-" +
                          std::to_string(std::hash<std::string>{}(workdir.string()));
  const auto out = std::filesystem::temp_directory_path() / (tag + ".stdout.txt"),
             err = std::filesystem::temp_directory_path() / (tag + ".stderr.txt");
  const std::string cmd = prefix + "cd '" + workdir.string() + "' && " + launcher + "'" + HMLATTICE_EXE + "' " + args +
                          " > '" + out.string() + "' 2> '" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  CommandResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

/// A fresh empty folder under the system temp dir, removed at scope exit.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / ("hmlattice-test-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  bool is_empty() const { return std::filesystem::is_empty(path); }
  void write(const std::string& file, const std::string& text) const { std::ofstream(path / file) << text; }
};

/// The Fig. 12 quick case (b = 0.2, N = 3000) to t* = `t_end` (its only output time), without VTK,
/// with `fracture` added at the top of its [fracture] table: the short run the case tests make.
inline std::string short_fig12_case(const std::string& t_end, const std::string& fracture = "") {
  return edited(slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml"),
                {{"t_end = 0.0272", "t_end = " + t_end},
                 {"times = [0.0045, 0.009, 0.0272]", "times = [" + t_end + "]"},
                 {"vtk = true", "vtk = false"},
                 {"[fracture]\n", "[fracture]\n" + fracture}});
}

/// The data rows of a CSV text (header dropped), split at commas.
inline std::vector<std::vector<std::string>> csv_rows(const std::string& csv) {
  std::vector<std::vector<std::string>> out;
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // header
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    out.push_back(cells);
  }
  return out;
}

inline int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += (c == '\n');
  return n;
}

}  // namespace hm::test
