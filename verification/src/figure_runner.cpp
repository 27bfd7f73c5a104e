#include "figure_runner.hpp"

#include <cstdlib>
#include <fstream>

namespace hm::verification {

namespace fs = std::filesystem;

std::string figure_python() {
  if (const char* env = std::getenv("HMLATTICE_PYTHON"); env && *env) return env;
  return HM_PYTHON;
}

namespace {
std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}
}  // namespace

std::string draw_figure(const Figure& figure, const fs::path& data_dir, const fs::path& figure_dir) {
  const std::string python = figure_python();
  if (python.empty()) return "no python3 with matplotlib and numpy (run scripts/install-deps.sh)";
  const fs::path script = fs::path(HM_SOURCE_DIR) / "figures" / figure.script;
  // The script's output goes beside its folder, not into it: the script may only write into a new or
  // empty folder or one that holds the toolkit's marker (figures/hmplot.py).
  const fs::path log = figure_dir.parent_path() / (figure_dir.filename().string() + "." + figure.file + ".log");
  const std::string cmd = shell_quote(python) + " " + shell_quote(script.string()) + " --data " +
                          shell_quote((data_dir / figure.data_subdir).string()) + " --out " +
                          shell_quote(figure_dir.string()) + " > " + shell_quote(log.string()) + " 2>&1";
  const int rc = std::system(cmd.c_str());
  if (rc != 0 || !fs::exists(figure_dir / figure.file)) {
    const std::string why = last_line(log);
    return "figure script " + figure.script + " failed" + (why.empty() ? "" : ": " + why);
  }
  fs::remove(log);
  return "";
}

}  // namespace hm::verification
