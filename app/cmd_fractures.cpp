// hmlattice fractures <run folder> [--link particle|triangle] [--arm-gap G] [--softened-beams link|ignore]
//
// Recomputes fractures.csv and fracture_summary.csv of a finished `hmlattice run` (fracture enabled)
// from its config.toml, breaks.csv and teeth.csv, with the given rules for which broken beams form one
// fracture (sharing a particle or a triangle, through softened beams or not) and how far apart two arms
// must be (docs/fracture_statistics.md); config.toml records the rules.
// Minutes instead of re-running the case.
// Example:
//   hmlattice fractures out/fig12_b0.2 --link triangle
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "hm/case/fracture_reanalysis.hpp"

namespace hm::app {

void add_fractures_command(CLI::App& app, const std::string& command_line) {
  struct Args {
    std::string run_dir;
    std::optional<std::string> link;
    std::optional<double> arm_gap;
    std::optional<std::string> softened;
  };
  auto a = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("fractures", "Recompute the fracture statistics of a finished run");
  cmd->add_option("run", a->run_dir, "output folder of `hmlattice run` with [fracture] enabled")->required();
  cmd->add_option("--link", a->link,
                  "broken beams of one fracture share a 'particle' or a 'triangle' (default: the run's)");
  cmd->add_option("--arm-gap", a->arm_gap,
                  "arms closer than this along the arm circle, over R, count as one in "
                  "n_arms_fixed_gap (default: the run's; 0.03 for a run without the key)");
  cmd->add_option("--softened-beams", a->softened,
                  "whether beams on their saw-tooth teeth 'link' the broken beams they touch into one fracture or "
                  "are ignored (default: the run's; link for a run without the key)");
  cmd->callback([a, command_line] {
    cases::StatisticsChange change;
    if (a->link) change.link = core::from_name<lattice2d::FractureLink>(*a->link, "--link");
    if (a->softened) change.softened = core::from_name<lattice2d::SoftenedBeams>(*a->softened, "--softened-beams");
    change.arm_gap = a->arm_gap;
    const auto done = cases::recompute_fracture_statistics(a->run_dir, change, command_line);
    std::cout << "fractures: " << done.n_breaks << " breaks, " << done.n_snapshots
              << " snapshots\nResults: " << a->run_dir
              << "/{fractures,fracture_summary}.csv, config.toml (the rules used in its [output])\n";
  });
}

}  // namespace hm::app
