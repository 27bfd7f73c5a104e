#pragma once
/// \file
/// The folder a command writes its results into (`--out`), made so that the toolkit never removes
/// anything it did not write and never leaves a folder that looks complete but is not.
///
/// The target may be
///   - absent: it is created (with any missing parent folders);
///   - an empty folder: it is filled;
///   - an earlier result of the toolkit, recognised by the marker file `.hmlattice` that every result
///     folder gets: replaced only when the user asked for it (`--overwrite`), otherwise refused; and
///     only when every file in it is one the marker lists as the toolkit's (a user's notes put in
///     there are never removed: the folder is refused, naming them).
/// Anything else is refused before any computing: a folder holding other files, a file, a device, a
/// symbolic link, the working directory or a folder above it, `/` and the home directory.
/// Results are written into a staging folder with a short fixed-length name beside the target, which
/// takes the target's place on commit() in one rename; an earlier result is first renamed aside and
/// removed only once the new one is in place, so at no moment is neither there. If the last rename
/// fails, the finished staging folder is kept and the error says where.
/// A staging folder carries the marker from the start, with the writing process's id: a staging
/// folder whose process is gone (killed, or the machine went down) is reported, never removed, by
/// the next ResultFolder made beside it — what it holds may be all that is left of a long run.
#include <filesystem>
#include <string>
#include <vector>

namespace hm::core {

/// Name of the marker file in every result folder.
inline constexpr const char* result_marker_name = ".hmlattice";

/// What a `--out` target is, once it is known to be allowed.
enum class ResultTarget {
  absent,          ///< nothing there: created
  empty_folder,    ///< an empty folder: filled
  earlier_result,  ///< a folder with the toolkit's marker: replaced (only with overwrite)
};

/// Classifies `target` (as the user typed it) for writing a result folder. Throws hm::InputError with
/// one line naming `option`, the path, why it is refused and what is allowed; `overwrite` allows an
/// earlier result. Reads only: nothing is created or removed.
ResultTarget inspect_result_target(const std::filesystem::path& target, const std::string& option, bool overwrite);

/// The entries under a result folder that its marker does not list as written by the toolkit (every
/// marker of a finished or stopped result lists its files), e.g. notes a user put in there; all of
/// them if the marker lists nothing. '/'-separated relative paths, sorted.
std::vector<std::string> files_not_written_by_toolkit(const std::filesystem::path& folder);

/// True if `folder` is a result folder whose marker says it was finished: neither stopped early
/// (`complete = false`) nor still being written (`state = "running"`, a run in progress or killed).
bool is_complete_result(const std::filesystem::path& folder);

/// True if `folder` holds the toolkit's marker file (a regular file whose first line is the marker's).
bool is_result_folder(const std::filesystem::path& folder);

/// The checkpoint a stopped run can be resumed from (step < 0: none).
struct StoppedCheckpoint {
  long step = -1;
  double t = 0.0;
};

/// Writes `path` (a result folder's status.toml) for a run that stopped before t_end: why, the last
/// step it finished, its time, the checkpoint it resumes from (`hmlattice <command> --resume
/// <folder>`) if any, and how to repeat it (`hmlattice <command> <folder>/config.toml`). The format is
/// the same for every command that runs in time steps.
void write_stopped_status(const std::filesystem::path& path, const std::string& command, const std::string& why,
                          long last_step, double t_last, double t_end, const std::filesystem::path& folder,
                          const StoppedCheckpoint& checkpoint = {});

/// A result folder being written. Construct it before computing anything: bad targets and unwritable
/// parents are reported (hm::InputError) before the work starts.
class ResultFolder {
 public:
  /// `command_line` goes into the marker, so a folder tells which command wrote it.
  ResultFolder(const std::filesystem::path& target, const std::string& option, bool overwrite,
               std::string command_line);
  /// Continues the folder of a run that stopped before its end (marker `complete = false`) or was
  /// killed (a staging folder whose marker says running, by a process of this machine that is gone):
  /// results are written in place, the marker says running until commit(). Throws hm::InputError
  /// naming `option` for any other folder. Never removes anything; if destroyed without commit(),
  /// the marker is put back as it was.
  struct Resume {};
  ResultFolder(Resume, const std::filesystem::path& folder, const std::string& option, std::string command_line);
  ~ResultFolder();  ///< removes the staging folder (and parents it created) unless committed or kept
  ResultFolder(const ResultFolder&) = delete;
  ResultFolder& operator=(const ResultFolder&) = delete;

  /// Where to write now (the staging folder).
  const std::filesystem::path& path() const { return staging_; }
  /// The final location, as the user gave it without a trailing separator (for messages).
  const std::filesystem::path& target() const { return shown_; }

  /// Writes the marker and moves the staged results into place. Throws std::runtime_error if they
  /// cannot be put there (the target changed meanwhile, a rename failed): the finished results are
  /// then kept in the staging folder, whose path the message gives. A non-empty `incomplete` (why
  /// the run stopped early) goes into the marker as `complete = false`; the results are still kept.
  void commit(const std::string& incomplete = "");

 private:
  void write_marker(const std::string& state) const;  // "running", "" (complete) or why it stopped

  std::filesystem::path shown_, target_, staging_;
  std::string option_, command_line_;
  bool overwrite_;
  bool resumed_ = false;                     // continues an earlier run's folder in place
  std::string previous_marker_;              // its marker before, restored if not committed
  bool done_ = false;                        // committed, or kept after a failed commit
  std::vector<std::filesystem::path> made_;  // parent folders this object created, deepest last
};

}  // namespace hm::core
