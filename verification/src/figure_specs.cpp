// The figure specs of verification/specs/: see figure_specs.hpp.
#include "figure_specs.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "hm/case/case_file.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::verification {

namespace {

namespace fs = std::filesystem;
using cases::CaseTable;

const fs::path kSpecs = fs::path(HM_SOURCE_DIR) / "verification" / "specs";

/// A word of `choices` (default `fallback` when the key is absent); an error lists the words.
template <class T>
T choice(CaseTable& t, const std::string& key, const std::vector<std::pair<std::string, T>>& choices, T fallback) {
  if (!t.has(key)) return fallback;
  std::string allowed;
  for (const auto& [word, value] : choices) allowed += (allowed.empty() ? "\"" : ", \"") + word + "\"";
  if (!t.is_string(key)) t.fail(key + " is not a string, allowed: one of " + allowed);
  const std::string word = t.get_string(key, "");
  for (const auto& [w, value] : choices)
    if (w == word) return value;
  t.fail(key + " = \"" + core::echo(word) + "\", allowed: one of " + allowed);
}

std::string required_string(CaseTable& t, const std::string& key) {
  if (!t.is_string(key)) t.fail(key + " is missing or not a string, allowed: a string (required)");
  return t.get_string(key, "");
}

PanelReading read_reading(CaseTable& t, const std::string& figure) {
  using Secondary = PaperReading::Secondary;
  using Sign = PaperReading::FracturePressureSign;
  PanelReading r;
  PaperReading& p = r.reading;
  p.figure = figure;
  if (t.has("b_below")) r.b_below = t.get_double("b_below");
  if (t.has("b_from")) r.b_from = t.get_double("b_from");
  if (t.has("n_below")) r.n_below = t.get_int("n_below", 0);
  p.fractures = static_cast<int>(t.get_int("fractures", PaperReading::not_stated));
  if (p.fractures < 0 && p.fractures != PaperReading::not_stated)
    t.fail("fractures = " + std::to_string(p.fractures) + ", allowed: a count >= 0 (absent: not stated)");
  if (t.is_string("reaching_outer")) {
    if (t.get_string("reaching_outer", "") != "all")
      t.fail("reaching_outer = \"" + core::echo(t.get_string("reaching_outer", "")) +
             "\", allowed: a count >= 0 or \"all\" (absent: not stated)");
    p.reaching_outer = PaperReading::all;
  } else {
    p.reaching_outer = static_cast<int>(t.get_int("reaching_outer", PaperReading::not_stated));
    if (p.reaching_outer < 0 && p.reaching_outer != PaperReading::not_stated)
      t.fail("reaching_outer = " + std::to_string(p.reaching_outer) + ", allowed: a count >= 0 or \"all\"");
  }
  p.secondary = choice<Secondary>(t, "secondary",
                                  {{"none", Secondary::none},
                                   {"at_outer_boundary", Secondary::at_outer_boundary},
                                   {"between_primaries", Secondary::between_primaries}},
                                  Secondary::not_stated);
  p.pressure = choice<Sign>(t, "pressure_in_fractures",
                            {{"negative_at_every_time", Sign::negative_at_every_time},
                             {"negative_at_last_time", Sign::negative_at_last_time}},
                            Sign::not_stated);
  p.backflow_into_borehole = t.get_bool("backflow_into_borehole", false);
  p.backflow_into_domain = t.get_bool("backflow_into_domain", false);
  p.borehole_pressure_drops = t.get_bool("borehole_pressure_drops", false);
  if (t.has("u_r_once_fractured"))
    r.u_r_above_1d = choice<bool>(t, "u_r_once_fractured", {{"above", true}, {"below", false}}, false);
  p.quote = required_string(t, "quote");
  t.reject_unknown();
  return r;
}

void read_benchmark(CaseTable& t, FigureSpec& s) {
  s.runner = choice<FigureRunner>(
      t, "runner", {{"borehole_pair", FigureRunner::borehole_pair}, {"refinement", FigureRunner::refinement}},
      FigureRunner::none);
  if (s.runner == FigureRunner::none) t.fail("runner is missing, allowed: \"borehole_pair\" or \"refinement\"");
  s.paper_figures = t.get_strings("paper_figures", {});
  if (s.paper_figures.empty()) t.fail("paper_figures is missing or empty, allowed: the paper's figure numbers");
  s.quick_title = required_string(t, "quick_title");
  s.quick_description = required_string(t, "quick_description");
  s.paper_title = required_string(t, "paper_title");
  s.paper_description = required_string(t, "paper_description");
  s.scatter_particles = t.get_int("scatter_particles", 0);
  if (s.scatter_particles <= 0)
    t.fail("scatter_particles = " + std::to_string(s.scatter_particles) + ", allowed: a lattice size > 0 (required)");
  for (double seed : t.get_doubles("scatter_seeds", {})) {
    if (seed < 1 || seed != static_cast<double>(static_cast<unsigned long long>(seed)))
      t.fail("scatter_seeds holds " + core::format_value(seed) + ", allowed: seeds >= 1");
    s.scatter_seeds.push_back(static_cast<unsigned long long>(seed));
  }
  if (s.scatter_seeds.empty()) t.fail("scatter_seeds is missing or empty, allowed: lattice seeds >= 1");
  if (s.runner == FigureRunner::refinement) {
    s.quick_sweep = required_string(t, "quick_sweep");
    s.paper_sweep = required_string(t, "paper_sweep");
  }
  for (CaseTable& plot : t.tables("plot")) {
    s.plots.push_back(
        {required_string(plot, "script"), required_string(plot, "image"), required_string(plot, "caption")});
    plot.reject_unknown();
  }
  t.reject_unknown();
}

}  // namespace

bool PanelReading::applies(double b, long long n_particles) const {
  return (!b_below || b < *b_below) && (!b_from || b >= *b_from) && (!n_below || n_particles < *n_below);
}

const PanelReading& FigureSpec::panel(double b, long long n_particles) const {
  for (const PanelReading& r : readings)
    if (r.applies(b, n_particles)) return r;
  throw std::logic_error(id + ": no reading for b = " + std::to_string(b) + ", N = " + std::to_string(n_particles));
}

std::vector<Figure> FigureSpec::figures(const std::string& subdir, const std::string& tier_text) const {
  std::vector<Figure> out;
  for (const PlotSpec& p : plots) {
    std::string caption = p.caption;
    if (const auto at = caption.find("{tier}"); at != std::string::npos) caption.replace(at, 6, tier_text);
    out.push_back({p.script, p.image, caption, subdir});
  }
  return out;
}

FigureSpec read_figure_spec(const fs::path& file) {
  const cases::CaseFile parsed(file);
  CaseTable root = parsed.root();
  FigureSpec s;
  s.id = file.stem().string();
  s.figure = required_string(root, "figure");
  for (CaseTable& r : root.tables("reading")) s.readings.push_back(read_reading(r, s.figure));
  if (s.readings.empty()) root.fail("no [[reading]], allowed: one or more readings of the paper");
  if (root.has("u_r_vs_1d")) {
    CaseTable u = root.table("u_r_vs_1d");
    s.unbroken_until = u.get_double("unbroken_until");
    u.reject_unknown();
    for (const PanelReading& r : s.readings)
      if (!r.u_r_above_1d)
        root.fail(
            "a [[reading]] without u_r_once_fractured, allowed: \"above\" or \"below\" in "
            "every reading when [u_r_vs_1d] is given");
  }
  if (root.has("benchmark")) {
    CaseTable b = root.table("benchmark");
    read_benchmark(b, s);
  }
  root.reject_unknown();
  return s;
}

const std::vector<FigureSpec>& figure_specs() {
  static const std::vector<FigureSpec> specs = [] {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(kSpecs))
      if (entry.path().extension() == ".toml") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::vector<FigureSpec> out;
    for (const fs::path& f : files) out.push_back(read_figure_spec(f));
    return out;
  }();
  return specs;
}

const FigureSpec& figure_spec(const std::string& id) {
  for (const FigureSpec& s : figure_specs())
    if (s.id == id) return s;
  throw std::logic_error("no figure spec " + id + ".toml in " + kSpecs.string());
}

}  // namespace hm::verification
