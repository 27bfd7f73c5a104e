// hmlattice case-format: print the case-file reference (markdown) to stdout.
#include <iostream>

#include "commands.hpp"
#include "hm/case/case_format.hpp"

namespace hm::app {

void add_case_format_command(CLI::App& app) {
  CLI::App* cmd =
      app.add_subcommand("case-format", "Print the case-file reference: every key, default and rule (markdown)");
  cmd->callback([] { std::cout << cases::case_format_reference(); });
}

}  // namespace hm::app
