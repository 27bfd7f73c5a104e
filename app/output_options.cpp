// The --out and --overwrite options shared by every command that writes a result folder.
#include "commands.hpp"

namespace hm::app {

void add_output_options(CLI::App& cmd, std::string& out, bool& overwrite) {
  cmd.add_option("--out", out,
                 "output folder [default: out/<case name>]: a new or empty folder, or an earlier result with "
                 "--overwrite");
  cmd.add_flag("--overwrite", overwrite, "replace the output folder if it holds an earlier hmlattice result");
}

std::filesystem::path output_folder(const std::string& out, const std::string& case_file) {
  return out.empty() ? std::filesystem::path("out") / std::filesystem::path(case_file).stem()
                     : std::filesystem::path(out);
}

}  // namespace hm::app
