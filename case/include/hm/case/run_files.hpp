#pragma once
/// \file
/// The files `hmlattice run` writes into its result folder, in one table: the recorder opens, resumes
/// and closes them from it, the run's closing line and its --help list them, and a test holds the
/// README's table to it. A new output file is a row here and its writer in the recorder.
#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hm::cases {

struct RunCase;

enum class RunFileId {
  series,
  radial,
  breaks,
  teeth,
  breakdown,
  fractures,
  fracture_summary,
  fracture_pressure,
  vtk,
  config
};

/// Which runs write a file.
enum class RunFileWhen { always, fracture, sawtooth, vtk };

/// How: a streamed file gets its rows as the run goes (flushed every step, so an interrupted run keeps
/// what it did; a resume cuts it back to its length at the checkpoint and appends); the snapshots are a
/// .vtu file per output time and the .pvd naming them; the others are written whole when the run ends
/// (config.toml before it starts).
enum class RunFileWriting { streamed, snapshots, whole };

struct RunFile {
  RunFileId id;
  std::string_view name;  ///< path inside the result folder
  RunFileWhen when;
  RunFileWriting writing;
  std::string_view contents;  ///< one line, for --help
};

/// In the order the closing line and --help list them; the streamed ones' order is also the order of
/// their lengths in a checkpoint.
inline constexpr std::array<RunFile, 10> run_files{{
    {RunFileId::series, "series.csv", RunFileWhen::always, RunFileWriting::streamed,
     "every step: t, dt, p_h, the volume balance, n_broken, coupling iterations, residuals"},
    {RunFileId::radial, "radial.csv", RunFileWhen::always, RunFileWriting::streamed,
     "at the output times: radially averaged u_r and p"},
    {RunFileId::breaks, "breaks.csv", RunFileWhen::fracture, RunFileWriting::streamed,
     "the break log: beam, position, time, stresses, failure ratio, mode"},
    {RunFileId::teeth, "teeth.csv", RunFileWhen::sawtooth, RunFileWriting::whole,
     "every tooth that gave way: time, tooth, stiffness factor, stress, energy"},
    {RunFileId::breakdown, "breakdown.csv", RunFileWhen::fracture, RunFileWriting::whole,
     "the first break and the peak p_h (Section 3.5)"},
    {RunFileId::fractures, "fractures.csv", RunFileWhen::fracture, RunFileWriting::whole,
     "at the output times, one row per fracture: kind, length, extent, angle, modes"},
    {RunFileId::fracture_summary, "fracture_summary.csv", RunFileWhen::fracture, RunFileWriting::whole,
     "at the output times: counts of fractures, radial ones, arms, secondary ones"},
    {RunFileId::fracture_pressure, "fracture_pressure.csv", RunFileWhen::fracture, RunFileWriting::streamed,
     "at the output times: the fluid pressure in the fractures and the backflows"},
    {RunFileId::vtk, "vtk/lattice.pvd", RunFileWhen::vtk, RunFileWriting::snapshots,
     "ParaView series at the output times (vtk/lattice_NNNN.vtu)"},
    {RunFileId::config, "config.toml", RunFileWhen::always, RunFileWriting::whole,
     "the resolved case with provenance; rerunnable"},
}};

/// The table's row of `id`.
const RunFile& run_file(RunFileId id);
/// `dir / run_file(id).name`.
std::filesystem::path run_file_path(const std::filesystem::path& dir, RunFileId id);
/// Whether a run of `c` writes the file.
bool writes(const RunCase& c, const RunFile& f);
/// The files a run of `c` writes, in the table's order.
std::vector<RunFile> files_written(const RunCase& c);
/// "DIR/{series,radial,...}.csv, vtk/lattice.pvd, config.toml": the run's closing line.
std::string results_line(const std::filesystem::path& dir, const RunCase& c);
/// Every file with what it holds and which runs write it, for --help.
std::string run_files_help();

}  // namespace hm::cases
