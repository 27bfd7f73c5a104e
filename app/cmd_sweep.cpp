// hmlattice sweep expand <sweep case.toml> [--out DIR] [--overwrite]
// hmlattice sweep collect DIR --runs RUNS
//
// Parameter studies. `expand` turns a case with a [sweep] table (lists of values for some keys,
// docs/case-format.md) into one resolved case file per combination, named after its values, and
// DIR/index.csv; every combination is validated as a case before anything is written. Run each with
// `hmlattice run` (or `fdm1d`) into RUNS/<name>, by hand or through the Snakemake workflow in
// workflow/. `collect` prints, as CSV, one row per combination: its values, the status of its run
// folder (complete, incomplete, missing), wall time, breakdown and final fracture statistics.
// Examples:
//   hmlattice sweep expand cases/sweep_fig18_quick.toml --out out/fig18/cases
//   hmlattice run out/fig18/cases/b=0.2_Q=0.01_seed=1.toml --out out/fig18/runs/b=0.2_Q=0.01_seed=1
//   hmlattice sweep collect out/fig18/cases --runs out/fig18/runs > out/fig18/results.csv
#include <iostream>
#include <sstream>

#include "commands.hpp"
#include "hm/case/sweep.hpp"
#include "hm/case/sweep_collect.hpp"
#include "hm/core/interrupt.hpp"
#include "hm/core/result_folder.hpp"

namespace hm::app {

namespace {

struct SweepArgs {
  std::string case_file, out, folder, runs;
  bool overwrite = false;
  long long max_combinations = cases::default_max_combinations;
};

void expand(const SweepArgs& a, const std::string& command_line, int& exit_code) {
  // 1. The output folder first: a refused --out is reported before any case is read.
  core::ResultFolder out(output_folder(a.out, a.case_file), "--out", a.overwrite, command_line);
  // 2. Every combination, each read and validated by its model's reader; an error or Ctrl-C (SIGTERM)
  //    discards the folder.
  const core::InterruptRequest interrupt;
  const cases::SweepExpansion sweep =
      cases::expand_sweep(a.case_file, out.path(), a.max_combinations, [&] { return interrupt.signal() != 0; });
  if (sweep.stopped) {
    std::cerr << "hmlattice sweep expand: interrupted by " << interrupt.signal_name() << " after "
              << sweep.combinations.size() << " of " << sweep.n_planned << " combinations; nothing written\n";
    exit_code = interrupt.exit_code();
    return;
  }
  // 3. Everything appears at once.
  out.commit();
  std::cout << "sweep: " << sweep.combinations.size() << " " << sweep.model << " cases over";
  for (const cases::SweepAxis& axis : sweep.axes) std::cout << " " << axis.key << " (" << axis.values.size() << ")";
  std::cout << "\nResults: " << out.target().string() << "/{" << cases::sweep_index_name
            << ", <name>.toml}; run each with"
            << " hmlattice " << sweep.command << " <name>.toml --out <runs>/<name>\n";
}

void collect(const SweepArgs& a) {
  // Built whole before printing: an error leaves no half table on stdout.
  std::ostringstream csv;
  const cases::SweepCollectCounts n = cases::collect_sweep(a.folder, a.runs, csv);
  std::cout << csv.str();
  std::cerr << "sweep collect: " << n.complete + n.incomplete + n.missing + n.other_case
            << " combinations: " << n.complete << " complete, " << n.incomplete << " incomplete, " << n.missing
            << " missing"
            << (n.other_case > 0 ? ", " + std::to_string(n.other_case) +
                                       " of another case (status 'other case': made before the sweep changed? remove "
                                       "them to have them redone)"
                                 : std::string())
            << "\n";
}

}  // namespace

void add_sweep_command(CLI::App& app, int& exit_code, const std::string& command_line) {
  auto a = std::make_shared<SweepArgs>();
  auto* cmd = app.add_subcommand("sweep", "Parameter studies: expand a [sweep] case, collect its runs' results");
  cmd->require_subcommand(1);
  auto* ex =
      cmd->add_subcommand("expand", "Write one resolved case per combination of a case's [sweep] lists, and index.csv");
  ex->add_option("case", a->case_file, "case file (TOML) with a [sweep] table")->required();
  add_output_options(*ex, a->out, a->overwrite);
  ex->add_option("--max-combinations", a->max_combinations,
                 "refuse a sweep of more combinations than this (default " +
                     std::to_string(cases::default_max_combinations) + ")")
      ->check(integer_between(1, 1000000000));
  ex->callback([a, command_line, &exit_code] { expand(*a, command_line, exit_code); });
  auto* co = cmd->add_subcommand("collect", "Print one CSV row per combination with its run's status and results");
  co->add_option("folder", a->folder, "folder written by hmlattice sweep expand")->required();
  co->add_option("--runs", a->runs, "folder holding one run folder per combination, named as its case")->required();
  co->callback([a] { collect(*a); });
}

}  // namespace hm::app
