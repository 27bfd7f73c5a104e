// The --out and --overwrite options shared by every command that writes a result folder.
#include "commands.hpp"

namespace hm::app {

void add_output_options(CLI::App& cmd, std::string& out, bool& overwrite) {
  cmd.add_option("--out", out,
                 "output folder [default: out/<case name>]: a new or empty folder, or an earlier result with "
                 "--overwrite");
  cmd.add_flag("--overwrite", overwrite, "replace the output folder if it holds an earlier hmlattice result");
}

void add_set_option(CLI::App& cmd, std::vector<std::string>& set) {
  // One value per --set (a TOML array holds no spaces it needs), so that the case file may follow it.
  cmd.add_option("--set", set,
                 "change one key of the case, e.g. --set physics.Q=3e-3 --set 'fracture.law=\"sawtooth\"' "
                 "(a TOML value; checked like the file's; repeatable)")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

std::filesystem::path output_folder(const std::string& out, const std::string& case_file) {
  return out.empty() ? std::filesystem::path("out") / std::filesystem::path(case_file).stem()
                     : std::filesystem::path(out);
}

}  // namespace hm::app
