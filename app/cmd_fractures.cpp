// hmlattice fractures <run folder> [--link particle|triangle]
//
// Recomputes fractures.csv and fracture_summary.csv of a finished `hmlattice run` (fracture enabled)
// from its config.toml and breaks.csv, with the given rule for which broken beams form one fracture
// (docs/fracture_statistics.md); config.toml records the rule. Minutes instead of re-running the case.
// Example:
//   hmlattice fractures out/fig12_b0.2 --link triangle
#include <iostream>

#include "commands.hpp"
#include "hm/case/fracture_reanalysis.hpp"

namespace hm::app {

void add_fractures_command(CLI::App& app, const std::string& command_line) {
  struct Args {
    std::string run_dir, link = hm::core::name_of(lattice2d::FractureStatisticsOptions{}.link);
  };
  auto a = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("fractures", "Recompute the fracture statistics of a finished run");
  cmd->add_option("run", a->run_dir, "output folder of `hmlattice run` with [fracture] enabled")->required();
  cmd->add_option("--link", a->link, "broken beams of one fracture share a 'particle' or a 'triangle'")->capture_default_str();
  cmd->callback([a, command_line] {
    const auto link = core::from_name<lattice2d::FractureLink>(a->link, "--link");
    const auto done = cases::recompute_fracture_statistics(a->run_dir, link, command_line);
    std::cout << "fractures: " << done.n_breaks << " breaks, " << done.n_snapshots << " snapshots, fracture_link = "
              << a->link << "\nResults: " << a->run_dir << "/{fractures,fracture_summary}.csv, config.toml\n";
  });
}

}  // namespace hm::app
