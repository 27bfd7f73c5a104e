#pragma once
// The subcommands of `hmlattice`. Each adds itself to the CLI11 app; its callback runs the
// command and stores the process exit code in `exit_code` (0 ok, 1 failed checks).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace hm::app {

void add_analytic_command(CLI::App& app, int& exit_code);
void add_verify_command(CLI::App& app, int& exit_code, const std::string& command_line);
void add_fdm1d_command(CLI::App& app, int& exit_code, const std::string& command_line);
void add_run_command(CLI::App& app, int& exit_code, const std::string& command_line);
void add_fractures_command(CLI::App& app, const std::string& command_line);
void add_case_format_command(CLI::App& app);
void add_sweep_command(CLI::App& app, int& exit_code, const std::string& command_line);

/// Checks of a command-line value, by the case files' rules: a decimal integer in [lo, hi]; a finite
/// number in [lo, hi]. The message names the value and the rule.
CLI::Validator integer_between(long long lo, long long hi);
CLI::Validator finite_between(double lo, double hi);

/// Adds --out DIR and --overwrite to a command that writes a result folder.
void add_output_options(CLI::App& cmd, std::string& out, bool& overwrite);
/// Adds --set table.key=value (repeatable): a key of the case changed on the command line, validated
/// as the file's own (CaseFile), and written into the resolved config.toml like the file's.
void add_set_option(CLI::App& cmd, std::vector<std::string>& set);
/// The result folder of a case: `out` if given, otherwise out/<case file name without extension>.
std::filesystem::path output_folder(const std::string& out, const std::string& case_file);

}  // namespace hm::app
