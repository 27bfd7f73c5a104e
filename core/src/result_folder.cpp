#include "hm/core/result_folder.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <system_error>

#include <toml.hpp>

#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/toml_text.hpp"
#include "hm/core/validation.hpp"

namespace hm::core {

namespace fs = std::filesystem;

namespace {

constexpr const char* marker_first_line = "# hmlattice result folder";
constexpr const char* allowed = "allowed: a new or empty folder, or an earlier hmlattice result with --overwrite";

std::string quoted(const fs::path& p) {
  std::string s = "'";  // appended step by step: GCC 12 warns falsely (-Wrestrict) on "'" + string
  s += p.string();
  s += "'";
  return s;
}

[[noreturn]] void refuse(const std::string& option, const fs::path& shown, const std::string& why,
                         const std::string& what_is_allowed = allowed) {
  throw InputError(option + " = " + quoted(shown) + " " + why + "; " + what_is_allowed);
}

// The path as typed without trailing separators ("res/" names the folder res).
fs::path without_trailing_separators(const fs::path& p) {
  std::string s = p.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

// The physical location of `shown`: `.` and `..` resolved as the shell does, then the existing
// part of the parent through its symbolic links (the last component itself is not followed).
fs::path physical_location(const fs::path& shown) {
  fs::path absolute = fs::absolute(shown).lexically_normal();
  if (!absolute.has_filename() && absolute != absolute.root_path()) absolute = absolute.parent_path();
  if (absolute == absolute.root_path()) return absolute;
  std::error_code ec;
  const fs::path parent = fs::weakly_canonical(absolute.parent_path(), ec);
  return (ec ? absolute.parent_path() : parent) / absolute.filename();
}

// True if `a` is `b` or a folder above it (component-wise, both absolute and normal).
bool is_same_or_above(const fs::path& a, const fs::path& b) {
  return std::mismatch(a.begin(), a.end(), b.begin(), b.end()).first == a.end();
}

fs::path canonical_or_empty(const fs::path& p) {
  std::error_code ec;
  fs::path c = fs::canonical(p, ec);
  return ec ? fs::path() : c;
}

// A new folder `<parent>/<prefix>XXXXXX` (fixed length, whatever the target's name), with the
// permissions an ordinary mkdir would give (mkdtemp makes it private).
fs::path make_unique_folder(const fs::path& parent, const std::string& prefix, std::error_code& ec) {
  std::string name = (parent / (prefix + "XXXXXX")).string();
  if (::mkdtemp(name.data()) == nullptr) {
    ec.assign(errno, std::generic_category());
    return {};
  }
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(name.c_str(), 0777 & ~mask);
  ec.clear();
  return name;
}

constexpr const char* staging_prefix = ".hmlattice-staging-";

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? std::string(name) : std::string();
}

// The value of `key = ...` in a marker file ("" if absent), for the few keys written above.
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

// One line on stderr for each staging folder in `parent` whose writing process no longer runs on
// this machine (killed with SIGKILL, out of memory, a crash): its partial results stay where they are.
void report_orphaned_staging(const fs::path& parent) {
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(staging_prefix, 0) != 0 || !it->is_directory(ec)) continue;
    const fs::path marker = it->path() / result_marker_name;
    const std::string pid = marker_value(marker, "pid");
    if (!pid.empty() && marker_value(marker, "host") == host_name()) {
      const long id = std::strtol(pid.c_str(), nullptr, 10);
      if (id > 0 && (::kill(static_cast<pid_t>(id), 0) == 0 || errno != ESRCH)) continue;  // still running
    } else if (!pid.empty()) {
      continue;  // written on another machine: cannot tell
    }
    std::cerr << "hmlattice: note: " << quoted(it->path()) << " holds the partial results of a run that was killed ("
              << (marker_value(marker, "command_line").empty() ? std::string("command unknown")
                                                               : marker_value(marker, "command_line"))
              << "); kept: "
              << (fs::exists(it->path() / "checkpoint.bin", ec)
                      ? "continue it with hmlattice run --resume " + quoted(it->path())
                      : std::string("look inside, then remove it"))
              << "\n";
  }
}

// Every file, link and other non-folder entry under `folder`, as '/'-separated relative paths in
// sorted order, the marker at the top left out (it is the list's own file).
std::vector<std::string> entries_under(const fs::path& folder) {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_directory(ec) && !it->is_symlink(ec)) continue;
    const std::string relative = it->path().lexically_relative(folder).generic_string();
    if (relative != result_marker_name) out.push_back(relative);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The marker's `files` list (what the toolkit wrote into the folder); false if the marker has none,
// as markers written before the toolkit listed its files, or cannot be read as TOML.
bool listed_files(const fs::path& marker, std::vector<std::string>& files) {
  try {
    const toml::value v = toml::parse(marker.string());
    if (!v.contains("files")) return false;
    files = toml::find<std::vector<std::string>>(v, "files");
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

std::vector<std::string> files_not_written_by_toolkit(const fs::path& folder) {
  std::vector<std::string> listed;
  const bool has_list = listed_files(folder / result_marker_name, listed);
  std::sort(listed.begin(), listed.end());
  std::vector<std::string> foreign;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string relative = it->path().lexically_relative(folder).generic_string();
    if (it->is_directory(ec) && !it->is_symlink(ec)) {
      // A result folder inside (figures added to a run folder's subfolder) answers by its own list.
      if (!is_result_folder(it->path())) continue;
      it.disable_recursion_pending();
      for (const std::string& f : files_not_written_by_toolkit(it->path())) foreign.push_back(relative + "/" + f);
      continue;
    }
    if (relative == result_marker_name) continue;
    if (!has_list || !std::binary_search(listed.begin(), listed.end(), relative)) foreign.push_back(relative);
  }
  std::sort(foreign.begin(), foreign.end());
  return foreign;
}

bool is_complete_result(const fs::path& folder) {
  if (!is_result_folder(folder)) return false;
  const fs::path marker = folder / result_marker_name;
  return marker_value(marker, "complete") != "false" && marker_value(marker, "state") != "running";
}

bool is_result_folder(const fs::path& folder) {
  const fs::path marker = folder / result_marker_name;
  std::error_code ec;
  if (fs::symlink_status(marker, ec).type() != fs::file_type::regular) return false;
  std::ifstream in(marker);
  std::string first;
  std::getline(in, first);
  return first.rfind(marker_first_line, 0) == 0;
}

ResultTarget inspect_result_target(const fs::path& target, const std::string& option, bool overwrite) {
  const fs::path shown = without_trailing_separators(target);
  if (shown.empty()) refuse(option, shown, "is empty", "allowed: the path of a folder for the results");
  const fs::path where = physical_location(shown);
  if (where == where.root_path()) refuse(option, shown, "is the root folder");
  const fs::path cwd = canonical_or_empty(fs::current_path());
  if (!cwd.empty() && is_same_or_above(where, cwd))
    refuse(option, shown, "is the working directory or a folder above it");
  if (const char* home = std::getenv("HOME"); home && *home && canonical_or_empty(home) == where)
    refuse(option, shown, "is the home directory");

  // Every name on the way must be one the file system takes: caught here, not when the finished run
  // is moved into place.
  const long reported = ::pathconf("/", _PC_NAME_MAX), name_max = reported > 0 ? reported : 255;
  for (const fs::path& part : where)
    if (static_cast<long>(part.string().size()) > name_max)
      refuse(option, shown, "has a name of " + std::to_string(part.string().size()) + " characters",
             "allowed: names of at most " + std::to_string(name_max) + " characters");

  std::error_code ec;
  const fs::file_status st = fs::symlink_status(where, ec);
  switch (st.type()) {
    case fs::file_type::not_found: {
      // The nearest existing folder above must be a folder we can create the rest in.
      fs::path up = where.parent_path();
      while (!fs::exists(fs::symlink_status(up, ec)) && up != up.root_path()) up = up.parent_path();
      if (!fs::is_directory(up, ec)) refuse(option, shown, "lies under " + quoted(up) + ", which is not a folder");
      return ResultTarget::absent;
    }
    case fs::file_type::symlink: refuse(option, shown, "is a symbolic link");
    case fs::file_type::directory: {
      const bool empty = fs::is_empty(where, ec);
      if (ec) refuse(option, shown, "cannot be read (" + ec.message() + ")");
      if (empty) return ResultTarget::empty_folder;
      if (!is_result_folder(where)) refuse(option, shown, "is a folder with files that hmlattice did not write");
      if (!overwrite)
        refuse(option, shown, "holds an earlier hmlattice result",
               "add --overwrite to replace it, or choose another folder");
      // --overwrite replaces what the toolkit wrote, never a file put in there since.
      std::vector<std::string> ignored;
      if (!listed_files(where / result_marker_name, ignored))
        refuse(option, shown, "holds an earlier hmlattice result whose marker lists no files (an older version's)",
               "allowed: a folder whose every file hmlattice wrote; remove it yourself, or choose another folder");
      if (const std::vector<std::string> foreign = files_not_written_by_toolkit(where); !foreign.empty()) {
        std::string names;
        for (std::size_t k = 0; k < foreign.size() && k < 3; ++k)
          names += (k ? ", " : "") + quoted(fs::path(foreign[k]));
        if (foreign.size() > 3) names += " and " + std::to_string(foreign.size() - 3) + " more";
        refuse(option, shown, "holds files hmlattice did not write (" + names + "), which --overwrite would remove",
               "allowed: move them out first, or choose another folder");
      }
      return ResultTarget::earlier_result;
    }
    case fs::file_type::regular: refuse(option, shown, "is a file");
    default: refuse(option, shown, "is a device, pipe or socket");
  }
}

ResultFolder::ResultFolder(const fs::path& target, const std::string& option, bool overwrite, std::string command_line)
    : shown_(without_trailing_separators(target)),
      option_(option),
      command_line_(std::move(command_line)),
      overwrite_(overwrite) {
  inspect_result_target(shown_, option_, overwrite_);
  target_ = physical_location(shown_);
  const fs::path parent = target_.parent_path();
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path up = parent; !fs::exists(fs::symlink_status(up, ec)) && up != up.root_path(); up = up.parent_path())
    missing.push_back(up);
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec) {
      const std::string reason = ec.message();
      for (auto made = made_.rbegin(); made != made_.rend(); ++made) fs::remove(*made, ec);
      refuse(option_, shown_, "cannot be created: folder " + quoted(*it) + " cannot be made (" + reason + ")",
             "allowed: a folder in a place you can write to");
    }
    made_.push_back(*it);
  }
  report_orphaned_staging(parent);
  staging_ = make_unique_folder(parent, staging_prefix, ec);
  if (ec) {
    const std::string reason = ec.message();
    for (auto made = made_.rbegin(); made != made_.rend(); ++made) fs::remove(*made, ec);
    refuse(option_, shown_, "cannot be written: its folder " + quoted(parent) + " refuses new files (" + reason + ")",
           "allowed: a folder in a place you can write to");
  }
  write_marker("running");
}

void ResultFolder::write_marker(const std::string& state) const {
  // Listed before the marker's own temporary file appears beside them.
  const std::vector<std::string> files = state == "running" ? std::vector<std::string>() : entries_under(staging_);
  write_file_atomically(staging_ / result_marker_name, [&](std::ostream& out) {
    out << marker_first_line << ": written by the command below; `--overwrite` may replace this folder.\n"
        << "command_line = " << toml_string(command_line_) << "\n"
        << "version = " << toml_string(HM_VERSION) << "\n"
        << "utc_time = " << toml_string(utc_now()) << "\n";
    if (state == "running")
      out << "state = \"running\"\nhost = " << toml_string(host_name()) << "\npid = " << ::getpid() << "\n"
          << "target = " << toml_string(target_.string()) << "\n";
    else if (!state.empty())
      out << "complete = false\nstopped = " << toml_string(state) << "\n";
    if (state != "running") {  // the folder's content is final: list it, for --overwrite's check
      out << "files = [\n";
      for (const std::string& f : files) out << "  " << toml_string(f) << ",\n";
      out << "]\n";
    }
  });
}

namespace {

// Why `folder` cannot be resumed ("" if it can): only a stopped run (complete = false) or a killed
// one (its marker says running, by a process of this machine that is gone) is continued.
std::string why_not_resumable(const fs::path& folder) {
  if (!is_result_folder(folder)) return "is not an hmlattice result folder";
  const fs::path marker = folder / result_marker_name;
  if (marker_value(marker, "complete") == "false") return "";
  if (marker_value(marker, "state") != "running") return "holds a complete run";
  if (marker_value(marker, "host") != host_name()) return "is being written on machine " + marker_value(marker, "host");
  const long id = std::strtol(marker_value(marker, "pid").c_str(), nullptr, 10);
  if (id > 0 && (::kill(static_cast<pid_t>(id), 0) == 0 || errno != ESRCH))
    return "is being written by process " + std::to_string(id);
  return "";
}

}  // namespace

ResultFolder::ResultFolder(Resume, const fs::path& folder, const std::string& option, std::string command_line)
    : shown_(without_trailing_separators(folder)),
      option_(option),
      command_line_(std::move(command_line)),
      overwrite_(false),
      resumed_(true) {
  std::error_code ec;
  if (fs::symlink_status(shown_, ec).type() != fs::file_type::directory)
    refuse(option_, shown_, "is not a folder", "allowed: the folder of a run that stopped before t_end");
  if (const std::string why = why_not_resumable(shown_); !why.empty())
    refuse(option_, shown_, why, "allowed: the folder of a run that stopped before t_end");
  staging_ = physical_location(shown_);
  target_ = staging_;
  // A killed run's staging folder goes where that run would have put it, if the name is plain.
  const std::string target = marker_value(staging_ / result_marker_name, "target");
  if (staging_.filename().string().rfind(staging_prefix, 0) == 0 && !target.empty() &&
      target.find('\\') == std::string::npos) {
    target_ = target;
    shown_ = target;
  }
  std::ifstream in(staging_ / result_marker_name, std::ios::binary);
  previous_marker_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  write_marker("running");
}

ResultFolder::~ResultFolder() {
  if (resumed_) {
    if (done_) return;
    // Not continued after all (bad checkpoint, an error): the folder is as it was.
    std::ofstream out(staging_ / result_marker_name, std::ios::binary | std::ios::trunc);
    out << previous_marker_;
    return;
  }
  if (done_) return;
  std::error_code ec;  // never throw from a destructor; what is removed here is only what this object made
  fs::remove_all(staging_, ec);
  for (auto made = made_.rbegin(); made != made_.rend(); ++made) fs::remove(*made, ec);
}

void ResultFolder::commit(const std::string& incomplete) {
  write_marker(incomplete);
  if (resumed_) {
    done_ = true;
    if (target_ == staging_ || !incomplete.empty()) return;
    std::error_code ec;
    if (fs::exists(fs::symlink_status(target_, ec)) && !(fs::is_directory(target_, ec) && fs::is_empty(target_, ec)))
      throw std::runtime_error("the finished results could not be put in " + quoted(target_) +
                               " (it exists meanwhile); they are complete in " + quoted(staging_));
    fs::rename(staging_, target_, ec);
    if (ec)
      throw std::runtime_error("the finished results could not be put in " + quoted(target_) + " (" + ec.message() +
                               "); they are complete in " + quoted(staging_));
    return;
  }
  const auto keep = [&](const std::string& why) {
    done_ = true;  // a finished result is never deleted by the toolkit
    throw std::runtime_error("the finished results could not be put in " + quoted(shown_) + " (" + why +
                             "); they are complete in " + quoted(staging_));
  };
  ResultTarget now;
  try {  // the target may have changed while the run computed
    now = inspect_result_target(shown_, option_, overwrite_);
  } catch (const InputError& e) {
    keep(e.what());
  }
  std::error_code ec;
  if (now != ResultTarget::earlier_result) {
    fs::rename(staging_, target_, ec);  // rename(2) replaces an empty folder, never a non-empty one
    if (ec) keep(ec.message());
    done_ = true;
    return;
  }
  const fs::path aside = make_unique_folder(target_.parent_path(), ".hmlattice-replaced-", ec);
  if (ec) keep("cannot set the earlier result aside: " + ec.message());
  fs::rename(target_, aside, ec);
  if (ec) {
    const std::string reason = ec.message();
    fs::remove(aside, ec);
    keep("cannot set the earlier result aside: " + reason);
  }
  fs::rename(staging_, target_, ec);
  if (ec) {
    const std::string reason = ec.message();
    fs::rename(aside, target_, ec);  // the earlier result back in its place
    keep(ec ? reason + "; the earlier result is in " + quoted(aside) : reason);
  }
  done_ = true;
  fs::remove_all(aside, ec);
  if (ec)
    std::cerr << "hmlattice: warning: the replaced result is left in " << quoted(aside) << " (" << ec.message()
              << ")\n";
}

void write_stopped_status(const fs::path& path, const std::string& command, const std::string& why, long last_step,
                          double t_last, double t_end, const fs::path& folder, const StoppedCheckpoint& checkpoint) {
  write_file_atomically(path, [&](std::ostream& f) {
    f << "# This run stopped before t_end. Every file here holds the steps up to last_step, complete;\n"
      << (checkpoint.step >= 0
              ? "# nothing after it. `resume` continues it from its checkpoint (bitwise as if never stopped).\n"
              : "# nothing after it. No checkpoint: the run is repeated from its config.toml.\n")
      << "complete = false\n"
      << "stopped = " << toml_string(why) << "\n"
      << "last_step = " << last_step << "\n"
      << "t_last = " << format_value(t_last) << "\n"
      << "t_end = " << format_value(t_end) << "\n";
    if (checkpoint.step >= 0)
      f << "checkpoint_step = " << checkpoint.step << "\n"
        << "checkpoint_t = " << format_value(checkpoint.t) << "\n"
        << "resume = " << toml_string("hmlattice " + command + " --resume " + folder.string()) << "\n";
    f << "rerun = "
      << toml_string("hmlattice " + command + " " + (folder / "config.toml").string() + " --out <new folder>") << "\n";
  });
}

}  // namespace hm::core
