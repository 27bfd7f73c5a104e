#pragma once
// The paper's fracture figures as data: one spec file per figure in verification/specs/<id>.toml holds
// what the paper says of it (its readings, per Biot coefficient or resolution) and, for a benchmark of
// a standard kind, what that benchmark runs and draws. Adding such a benchmark is adding a spec file
// and its figure script (verification/specs/README.md has the format).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hm/verification/benchmark.hpp"
#include "paper_readings.hpp"

namespace hm::verification {

/// One reading and the panels it is for: b < b_below, b >= b_from and N < n_below, each where given.
struct PanelReading {
  PaperReading reading;
  std::optional<double> b_below, b_from;
  std::optional<long long> n_below;
  std::optional<bool> u_r_above_1d;  ///< once fractured, u_r above (true) or below the 1D model's
  bool applies(double b, long long n_particles) const;
};

/// A figure the benchmark draws; "{tier}" in the caption becomes what the tier ran.
struct PlotSpec {
  std::string script, image, caption;
};

/// The kinds of figure benchmark a spec can ask for (none: the figure's benchmark, if any, is code).
enum class FigureRunner {
  none,
  borehole_pair,  ///< cases/<id>_b{0.2,0.8}_quick.toml; cases/paper/<id>_b{0.2,0.8}.toml and a seed scatter
  refinement,     ///< a sweep over lattice.n_particles, seeds where runs are cheap
};

struct FigureSpec {
  std::string id;      ///< the file's stem, "fig14"
  std::string figure;  ///< "Fig. 14"
  std::vector<PanelReading> readings;
  std::optional<double> unbroken_until;  ///< u_r against the 1D model: unbroken up to this output time

  FigureRunner runner = FigureRunner::none;
  std::vector<std::string> paper_figures;
  std::string quick_title, quick_description, paper_title, paper_description;
  std::vector<PlotSpec> plots;
  long long scatter_particles = 0;  ///< the paper tier's seed scatter: this N (refinement: up to it)
  std::vector<unsigned long long> scatter_seeds;
  std::string quick_sweep, paper_sweep;  ///< refinement: sweep case files, relative to cases/

  /// The reading of the panel with Biot coefficient b at N particles (std::logic_error if none).
  const PanelReading& panel(double b, long long n_particles = 0) const;
  /// The plots with "{tier}" replaced, their data in subdir.
  std::vector<Figure> figures(const std::string& subdir, const std::string& tier_text) const;
};

/// Reads one spec; an error is an hm::InputError naming the file, table, key, value and rule.
FigureSpec read_figure_spec(const std::filesystem::path& file);
/// Every spec in verification/specs/, by id (read once).
const std::vector<FigureSpec>& figure_specs();
/// The spec of `id` (std::logic_error if there is none).
const FigureSpec& figure_spec(const std::string& id);

}  // namespace hm::verification
