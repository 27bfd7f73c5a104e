#include "hm/case/run_files.hpp"

#include <sstream>
#include <stdexcept>

#include "hm/case/run_case.hpp"

namespace hm::cases {

const RunFile& run_file(RunFileId id) {
  for (const RunFile& f : run_files)
    if (f.id == id) return f;
  throw std::logic_error("run_file: an id without a row in run_files");
}

std::filesystem::path run_file_path(const std::filesystem::path& dir, RunFileId id) {
  return dir / std::string(run_file(id).name);
}

bool writes(const RunCase& c, const RunFile& f) {
  switch (f.when) {
    case RunFileWhen::always: return true;
    case RunFileWhen::fracture: return c.fracture_enabled;
    case RunFileWhen::sawtooth: return c.fracture_enabled && c.fracture_law == lattice2d::FractureLaw::sawtooth;
    case RunFileWhen::vtk: return c.output.vtk;
  }
  return false;
}

std::vector<RunFile> files_written(const RunCase& c) {
  std::vector<RunFile> out;
  for (const RunFile& f : run_files)
    if (writes(c, f)) out.push_back(f);
  return out;
}

std::string results_line(const std::filesystem::path& dir, const RunCase& c) {
  std::string csv, rest;
  for (const RunFile& f : files_written(c)) {
    const std::string name(f.name);
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".csv") == 0) {
      if (!csv.empty()) csv += ',';
      csv.append(name, 0, name.size() - 4);
    } else {
      rest += ", " + name;
    }
  }
  return dir.string() + "/{" + csv + "}.csv" + rest;
}

std::string run_files_help() {
  std::ostringstream out;
  out << "Files in the result folder:\n";
  for (const RunFile& f : run_files) {
    out << "  " << f.name << std::string(f.name.size() < 24 ? 24 - f.name.size() : 1, ' ') << f.contents;
    switch (f.when) {
      case RunFileWhen::always: break;
      case RunFileWhen::fracture: out << "; with [fracture] enabled"; break;
      case RunFileWhen::sawtooth: out << "; with [fracture] law = \"sawtooth\""; break;
      case RunFileWhen::vtk: out << "; with [output] vtk = true"; break;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace hm::cases
