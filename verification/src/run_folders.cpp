// The planned runs of the benchmarks outside the harness's process: written as case files for a
// workflow engine (`hmlattice verify --write-cases`), and their run folders checked before they are
// read back (`hmlattice verify --runs`). See harness.hpp.
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "hm/case/provenance.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/sweep_collect.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/result_folder.hpp"
#include "hm/verification/harness.hpp"

namespace hm::verification {

namespace fs = std::filesystem;

namespace {

/// "table.key" -> value of every `key = value` line of a resolved case's TOML, in order.
std::vector<std::pair<std::string, std::string>> toml_entries(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> entries;
  std::istringstream in(text);
  std::string table;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.front() == '#') continue;
    if (line.front() == '[') {
      table = line.substr(1, line.find(']') == std::string::npos ? std::string::npos : line.find(']') - 1);
      continue;
    }
    const auto eq = line.find(" = ");
    if (eq == std::string::npos) continue;
    entries.emplace_back(table.empty() ? line.substr(0, eq) : table + "." + line.substr(0, eq), line.substr(eq + 3));
  }
  return entries;
}

/// The first key whose value differs between two resolved cases, as "key = <theirs>, the benchmark's
/// case has <ours>" ("" if none).
std::string first_difference(const std::string& ours, const std::string& theirs) {
  const auto a = toml_entries(ours), b = toml_entries(theirs);
  const std::map<std::string, std::string> in_b(b.begin(), b.end()), in_a(a.begin(), a.end());
  for (const auto& [key, value] : a) {
    const auto it = in_b.find(key);
    if (it == in_b.end()) return key + " is not there, the benchmark's case has " + value;
    if (it->second != value) return key + " = " + it->second + ", the benchmark's case has " + value;
  }
  for (const auto& [key, value] : b)
    if (!in_a.count(key)) return key + " = " + value + ", which the benchmark's case does not have";
  return "";
}

/// Every planned run of `selected`, each label once (a label planned twice is a bug of the benchmarks).
std::vector<std::pair<const Benchmark*, PlannedRun>> planned_runs(const std::vector<const Benchmark*>& selected) {
  std::vector<std::pair<const Benchmark*, PlannedRun>> runs;
  std::set<std::string> labels;
  for (const Benchmark* b : selected) {
    if (!b->planned_runs) continue;
    for (PlannedRun& r : b->planned_runs()) {
      if (!labels.insert(r.label).second)
        throw std::logic_error("planned run '" + r.label + "' of " + b->id + " planned twice");
      runs.emplace_back(b, std::move(r));
    }
  }
  return runs;
}

}  // namespace

RunFolderCheck check_run_folders(const std::vector<const Benchmark*>& selected, const fs::path& runs_dir) {
  std::error_code ec;
  if (!fs::is_directory(runs_dir, ec))
    throw InputError("--runs = '" + core::echo(runs_dir.string()) +
                     "' is not a folder, allowed: a folder of run folders <label>/ (hmlattice verify --write-cases, "
                     "then hmlattice run <label>.toml --out <folder>/<label>, or the workflow's verify target)");
  RunFolderCheck check;
  for (const auto& [benchmark, run] : planned_runs(selected)) {
    ++check.planned;
    const fs::path folder = runs_dir / run.label;
    const std::string status = cases::run_folder_status(folder);
    if (status == "missing") continue;
    if (status != "complete")
      throw InputError("--runs: " + folder.string() + " is not a complete run (stopped before t_end, still being " +
                       "written, or not written by hmlattice run): finish it (hmlattice run --resume) or remove it");
    const std::string theirs = cases::run_case_to_toml(cases::read_run_case(folder / "config.toml"), "");
    if (const std::string why = first_difference(cases::run_case_to_toml(run.c, ""), theirs); !why.empty())
      throw InputError("--runs: " + folder.string() + " is a run of another case than " + benchmark->id + "'s: " + why +
                       " (stale: remove the folder to have it redone)");
    ++check.found;
  }
  return check;
}

int write_planned_cases(const std::vector<const Benchmark*>& selected, const fs::path& dir, bool overwrite,
                        const std::string& command_line) {
  const auto runs = planned_runs(selected);
  core::ResultFolder out(dir, "--write-cases", overwrite, command_line);
  const std::string provenance = cases::to_toml(cases::make_provenance(command_line));
  for (const auto& [benchmark, run] : runs)
    core::write_file_atomically(out.path() / (run.label + ".toml"),
                                [&](std::ostream& f) { f << cases::run_case_to_toml(run.c, provenance); });
  core::write_file_atomically(out.path() / "index.csv", [&](std::ostream& f) {
    f << "name,benchmark\n";
    for (const auto& [benchmark, run] : runs) f << run.label << "," << benchmark->id << "\n";
  });
  out.commit();
  return static_cast<int>(runs.size());
}

}  // namespace hm::verification
