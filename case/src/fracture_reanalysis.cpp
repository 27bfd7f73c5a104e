#include "hm/case/fracture_reanalysis.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "hm/case/provenance.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/run_files.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/result_folder.hpp"
#include "hm/core/toml_text.hpp"
#include "hm/core/validation.hpp"
#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/io/break_log.hpp"
#include "hm/lattice2d/io/fracture_tables.hpp"
#include "hm/lattice2d/io/vtk_writer.hpp"

namespace hm::cases {

namespace lt = hm::lattice2d;

namespace {

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The t column of a fracture_summary.csv.
std::vector<double> snapshot_times(const std::filesystem::path& file) {
  std::istringstream in(text_of(file));
  std::string line;
  std::getline(in, line);
  if (line.rfind("t,n_broken,", 0) != 0)
    throw InputError(file.string() +
                     ":1: not a fracture summary, allowed: the fracture_summary.csv `hmlattice run` wrote");
  std::vector<double> times;
  for (int line_no = 2; std::getline(in, line); ++line_no) {
    if (line.empty()) continue;
    try {
      times.push_back(std::stod(line.substr(0, line.find(','))));
    } catch (const std::logic_error&) {
      throw InputError(file.string() + ":" + std::to_string(line_no) + ": no time in '" + core::echo(line) +
                       "', allowed: the fracture_summary.csv `hmlattice run` wrote");
    }
  }
  return times;
}

// The run's [provenance] table and the notes of earlier reanalyses above it.
std::string provenance_part(const std::string& config) {
  const std::string note = "# fracture statistics recomputed";
  std::size_t at = config.find("\n" + note);
  if (at == std::string::npos) at = config.find("\n[provenance]");
  return at == std::string::npos ? std::string() : config.substr(at + 1);
}

}  // namespace

FractureReanalysis recompute_fracture_statistics(const std::filesystem::path& run_dir, const StatisticsChange& change,
                                                 const std::string& command_line) {
  const std::filesystem::path config_file = run_file_path(run_dir, RunFileId::config),
                              breaks_file = run_file_path(run_dir, RunFileId::breaks),
                              fractures_file = run_file_path(run_dir, RunFileId::fractures),
                              summary_file = run_file_path(run_dir, RunFileId::fracture_summary);
  for (const std::filesystem::path& file : {config_file, breaks_file, summary_file})
    if (!std::filesystem::is_regular_file(file))
      throw InputError("run folder = " + run_dir.string() + " has no " + file.filename().string() +
                       ", allowed: the output folder of `hmlattice run` with [fracture] enabled");
  // A stopped run is continued with --resume, which checks its config.toml against the checkpoint:
  // rewriting it here would make the run impossible to continue.
  if (!core::is_complete_result(run_dir))
    throw InputError("run folder = " + run_dir.string() +
                     " holds a run that has not finished (see its status.toml), allowed: a finished run; continue it "
                     "with hmlattice run --resume " +
                     run_dir.string() + " first");
  RunCase c = read_run_case(config_file);
  if (!c.fracture_enabled)
    throw InputError("run folder = " + run_dir.string() + ": [fracture] enabled = false in its config.toml");
  const std::vector<lt::BreakEvent> log = lt::read_break_log(breaks_file);
  const std::vector<double> times = snapshot_times(summary_file);
  // The saw-tooth law's softened beams; a brittle run has no teeth.csv and none.
  const std::filesystem::path teeth_file = run_file_path(run_dir, RunFileId::teeth);
  const std::vector<lt::ToothEvent> teeth =
      c.fracture_law == lt::FractureLaw::sawtooth ? lt::read_tooth_log(teeth_file) : std::vector<lt::ToothEvent>{};

  const lt::Lattice lattice = lt::generate_lattice(c.lattice);
  lt::FractureStatisticsOptions& options = c.output.statistics;
  if (change.link) options.link = *change.link;
  if (change.arm_gap) options.arm_gap = *change.arm_gap;
  if (change.softened) options.softened = *change.softened;
  if (!lt::is_allowed_arm_gap(options.arm_gap))
    throw InputError("--arm-gap = " + core::format_value(options.arm_gap) + ", allowed: " + lt::kArmGapRule);
  // The log names each beam's particles: a lattice that differs from the run's (another version of
  // the generator, an edited config) is caught here instead of giving wrong statistics.
  for (const lt::BreakEvent& ev : log) {
    const bool known = ev.beam >= 0 && ev.beam < lattice.n_beams();
    const std::array<int, 2> ends =
        known ? lattice.beams[static_cast<std::size_t>(ev.beam)] : std::array<int, 2>{-1, -1};
    if (ends[0] != ev.particle_i || ends[1] != ev.particle_j)
      throw std::runtime_error(
          breaks_file.string() + ": beam " + std::to_string(ev.beam) + " joins particles " +
          std::to_string(ev.particle_i) + "-" + std::to_string(ev.particle_j) +
          " in the log but not in the lattice of config.toml; was the run made by another version?");
  }
  std::vector<lt::FractureSnapshot> snapshots;
  for (double t : times) {
    // Times are written with 10 digits in all three files; the margin absorbs the last digit.
    const double until = t + 1e-9 * std::abs(t);
    std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
    for (const lt::BreakEvent& ev : log)
      if (ev.load <= until) broken[static_cast<std::size_t>(ev.beam)] = true;
    snapshots.push_back({t, lt::compute_fracture_statistics(lattice, broken, log, options,
                                                            lt::softened_flags(teeth, lattice.n_beams(), until))});
  }

  const std::string provenance = provenance_part(text_of(config_file));
  const std::string config =
      run_case_to_toml(c, "# fracture statistics recomputed with fracture_link = \"" + hm::core::name_of(options.link) +
                              "\", arm_gap = " + toml_real(options.arm_gap) + ", softened_beams = \"" +
                              hm::core::name_of(options.softened) + "\" by: " + core::toml_string(command_line) + " (" +
                              make_provenance(command_line).utc_time + ")\n" + provenance);
  lt::write_fracture_table(fractures_file, snapshots);
  lt::write_fracture_summary(summary_file, snapshots);
  core::write_file_atomically(config_file, [&](std::ostream& out) { out << config; });
  return {static_cast<int>(snapshots.size()), static_cast<int>(log.size())};
}

}  // namespace hm::cases
