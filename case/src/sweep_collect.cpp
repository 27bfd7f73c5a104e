#include "hm/case/sweep_collect.hpp"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <string>
#include <toml.hpp>
#include <vector>

#include "hm/case/fdm1d_case.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/run_files.hpp"
#include "hm/case/sweep.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/result_folder.hpp"
#include "sweep_csv.hpp"

namespace hm::cases {

namespace fs = std::filesystem;

namespace {

using Row = std::vector<std::string>;

// The header and rows of a CSV file; empty if it cannot be read.
std::vector<Row> read_csv(const fs::path& path) {
  std::vector<Row> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) rows.push_back(sweep_csv::split(line));
  return rows;
}

// `key = value` of a marker file's own lines ("" if absent), quotes dropped.
std::string marker_value(const fs::path& marker, const std::string& key) {
  std::ifstream in(marker);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + " = ", 0) == 0) {
      std::string v = line.substr(key.size() + 3);
      if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
      return v;
    }
  return "";
}

// Seconds since the epoch of "2026-12-02T14:08:00Z" (core::utc_now), or -1.
long long utc_seconds(const std::string& stamp) {
  std::tm t{};
  if (std::sscanf(stamp.c_str(), "%4d-%2d-%2dT%2d:%2d:%2dZ", &t.tm_year, &t.tm_mon, &t.tm_mday, &t.tm_hour, &t.tm_min,
                  &t.tm_sec) != 6)
    return -1;
  t.tm_year -= 1900;
  t.tm_mon -= 1;
  return static_cast<long long>(timegm(&t));
}

// From the provenance's time (written before the run starts) to the marker's (written on completion).
std::string wall_seconds(const fs::path& run) {
  std::string started;
  try {
    const toml::value config = toml::parse((run / "config.toml").string());
    started = toml::find<std::string>(config, "provenance", "utc_time");
  } catch (const std::exception&) {
    return "";
  }
  const long long from = utc_seconds(started),
                  to = utc_seconds(marker_value(run / core::result_marker_name, "utc_time"));
  return from >= 0 && to >= from ? std::to_string(to - from) : "";
}

// A run's result columns: name -> value, from the files a complete run wrote.
std::map<std::string, std::string> run_results(const fs::path& run, std::vector<std::string>& columns) {
  std::map<std::string, std::string> values;
  const auto take = [&](const Row& header, const Row& row, const std::string& prefix) {
    for (std::size_t i = 0; i < header.size() && i < row.size(); ++i) {
      const std::string column = prefix + header[i];
      if (!values.count(column) && std::find(columns.begin(), columns.end(), column) == columns.end())
        columns.push_back(column);
      values[column] = row[i];
    }
  };
  values["wall_seconds"] = wall_seconds(run);
  if (const auto b = read_csv(run_file_path(run, RunFileId::breakdown)); b.size() >= 2) take(b.front(), b[1], "");
  if (const auto s = read_csv(run_file_path(run, RunFileId::fracture_summary)); s.size() >= 2)
    take(s.front(), s.back(), "final_");
  return values;
}

}  // namespace

std::string run_folder_status(const fs::path& run) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(run, ec))) return "missing";
  if (!core::is_result_folder(run)) return "incomplete";
  const fs::path marker = run / core::result_marker_name;
  if (marker_value(marker, "complete") == "false" || marker_value(marker, "state") == "running") return "incomplete";
  return "complete";
}

namespace {

// True if the finished run in `run` is of the case `combination` (an expanded sweep's file): both read
// and resolved by the model's reader, provenance aside. A config.toml that does not read is not.
bool runs_combination(const fs::path& combination, const fs::path& run, const std::string& command) {
  try {
    if (command == "fdm1d")
      return fdm1d_case_to_toml(read_fdm1d_case(combination), "") ==
             fdm1d_case_to_toml(read_fdm1d_case(run / "config.toml"), "");
    return run_case_to_toml(read_run_case(combination), "") == run_case_to_toml(read_run_case(run / "config.toml"), "");
  } catch (const InputError&) {
    return false;
  }
}

}  // namespace

SweepCollectCounts collect_sweep(const fs::path& sweep_folder, const fs::path& runs_folder, std::ostream& csv) {
  const std::vector<Row> index = read_csv(sweep_folder / sweep_index_name);
  if (index.empty() || index.front().size() < 2 || index.front()[0] != "name" || index.front()[1] != "command")
    throw InputError(core::echo(sweep_folder.string()) + ": no readable " + sweep_index_name +
                     ", allowed: a folder written by hmlattice sweep expand");
  const Row& header = index.front();
  std::vector<std::string> columns = {"wall_seconds"};  // then every result column in order of appearance
  std::vector<std::string> status;
  std::vector<std::map<std::string, std::string>> results;
  SweepCollectCounts counts;
  for (std::size_t i = 1; i < index.size(); ++i) {
    const fs::path run = runs_folder / index[i][0];
    status.push_back(run_folder_status(run));
    if (status.back() == "complete" &&
        !runs_combination(sweep_folder / (index[i][0] + ".toml"), run, index[i].size() > 1 ? index[i][1] : "run"))
      status.back() = "other case";
    results.push_back(status.back() == "complete" ? run_results(run, columns) : std::map<std::string, std::string>{});
    ++(status.back() == "complete"     ? counts.complete
       : status.back() == "missing"    ? counts.missing
       : status.back() == "other case" ? counts.other_case
                                       : counts.incomplete);
  }

  csv << "name";
  for (std::size_t k = 2; k < header.size(); ++k) csv << ',' << sweep_csv::field(header[k]);
  csv << ",status";
  for (const std::string& c : columns) csv << ',' << sweep_csv::field(c);
  csv << '\n';
  for (std::size_t i = 1; i < index.size(); ++i) {
    csv << sweep_csv::field(index[i][0]);
    for (std::size_t k = 2; k < header.size(); ++k)
      csv << ',' << sweep_csv::field(k < index[i].size() ? index[i][k] : "");
    csv << ',' << status[i - 1];
    for (const std::string& c : columns) {
      const auto it = results[i - 1].find(c);
      csv << ',' << (it == results[i - 1].end() ? "" : sweep_csv::field(it->second));
    }
    csv << '\n';
  }
  return counts;
}

}  // namespace hm::cases
