// The figure specs (verification/specs/): every file reads, names scripts and cases that exist, picks
// the paper's reading of each panel, and a spec with a mistake is refused with a message naming it.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include "figure_specs.hpp"
#include "hm/core/input_error.hpp"
#include "hm/verification/benchmark.hpp"
#include "run_command.hpp"

using namespace hm::verification;
using hm::test::TempDir;
namespace fs = std::filesystem;

namespace {
const fs::path kSource = HM_SOURCE_DIR;

std::string refusal(const TempDir& dir, const std::string& text) {
  dir.write("bad.toml", text);
  try {
    read_figure_spec(dir.path / "bad.toml");
  } catch (const hm::InputError& e) {
    return e.what();
  }
  return "accepted";
}

const std::string kReading = "[[reading]]\nfractures = 2\nquote = \"two\"\n";
}  // namespace

TEST_CASE("Every figure spec reads and names figure scripts and cases that exist", "[verification][specs]") {
  const std::vector<FigureSpec>& specs = figure_specs();
  std::set<std::string> ids;
  for (const FigureSpec& s : specs) ids.insert(s.id);
  CHECK(ids == std::set<std::string>{"fig12", "fig14", "fig16", "fig17", "fig19"});
  for (const FigureSpec& s : specs) {
    INFO(s.id);
    CHECK_FALSE(s.readings.empty());
    if (s.runner == FigureRunner::none) continue;
    CHECK_FALSE(s.plots.empty());
    for (const PlotSpec& p : s.plots) CHECK(fs::is_regular_file(kSource / "figures" / p.script));
    if (s.runner == FigureRunner::borehole_pair)
      for (const std::string b : {"0.2", "0.8"}) {
        CHECK(fs::is_regular_file(kSource / "cases" / (s.id + "_b" + b + "_quick.toml")));
        CHECK(fs::is_regular_file(kSource / "cases" / "paper" / (s.id + "_b" + b + ".toml")));
      }
    if (s.runner == FigureRunner::refinement) {
      CHECK(fs::is_regular_file(kSource / "cases" / s.quick_sweep));
      CHECK(fs::is_regular_file(kSource / "cases" / s.paper_sweep));
    }
  }
}

TEST_CASE("The reading of a panel is chosen by its Biot coefficient and resolution", "[verification][specs]") {
  // The paper's counts (Sections 3.3-3.6), as the specs transcribe them.
  CHECK(paper_reading("fig12", 0.2).fractures == 3);
  CHECK(paper_reading("fig12", 0.8).fractures == 7);
  CHECK(paper_reading("fig12", 0.8).fractures_text() == "7, all at r = 1");
  CHECK(paper_reading("fig16", 0.2).fractures_text() == "4, 1 at r = 1");
  CHECK(paper_reading("fig16", 0.8).secondary == PaperReading::Secondary::between_primaries);
  CHECK(paper_reading("fig17", 0.2).backflow_into_borehole);
  CHECK(paper_reading("fig19", 0.5, 684).fractures == 2);
  CHECK(paper_reading("fig19", 0.5, 3000).fractures == 4);
  const FigureSpec& fig14 = figure_spec("fig14");
  REQUIRE(fig14.unbroken_until);
  CHECK(*fig14.unbroken_until == 4.5e-3);
  CHECK(*fig14.panel(0.2).u_r_above_1d);
  CHECK_FALSE(*fig14.panel(0.8).u_r_above_1d);
  CHECK(fig14.figures("fig14_quick", "quick tier").front().caption.rfind("Fig. 14 (quick tier): ", 0) == 0);
  CHECK_THROWS_AS(figure_spec("fig99"), std::logic_error);
}

TEST_CASE("The figure benchmarks are the specs' runners", "[verification][specs]") {
  std::set<std::string> quick, paper;
  for (const Benchmark& b : all_benchmarks()) (b.tier == Tier::quick ? quick : paper).insert(b.id);
  int runners = 0;
  for (const FigureSpec& s : figure_specs()) {
    if (s.runner == FigureRunner::none) continue;  // fig12: its benchmark is code
    INFO(s.id);
    ++runners;
    CHECK(quick.count("lattice2d." + s.id + "_quick") == 1);
    CHECK(paper.count("lattice2d." + s.id) == 1);
  }
  CHECK(runners == 4);
}

TEST_CASE("A figure spec with a mistake is refused, naming file, table, key, value and rule", "[verification][specs]") {
  const TempDir dir("figure-specs");
  const std::string bad = (dir.path / "bad.toml").string();
  CHECK(refusal(dir, "figure = \"Fig. 9\"\n" + kReading) == "accepted");
  CHECK(refusal(dir, kReading) == bad + ": figure is missing or not a string, allowed: a string (required)");
  CHECK(refusal(dir, "figure = \"Fig. 9\"\n") == bad + ": no [[reading]], allowed: one or more readings of the paper");
  CHECK(refusal(dir, "figure = \"Fig. 9\"\n" + kReading + "secondary = \"sometimes\"\n") ==
        bad +
            ": [reading[0]] secondary = \"sometimes\", allowed: one of \"none\", \"at_outer_boundary\", "
            "\"between_primaries\"");
  CHECK(refusal(dir, "figure = \"Fig. 9\"\n" + kReading + "reaching_outer = \"most\"\n") ==
        bad + ": [reading[0]] reaching_outer = \"most\", allowed: a count >= 0 or \"all\" (absent: not stated)");
  CHECK(refusal(dir, "figure = \"Fig. 9\"\n" + kReading + "fracturs = 3\n")
            .find(": [reading[0]] unknown key 'fracturs', allowed: ") != std::string::npos);
  CHECK(refusal(dir, "figure = \"Fig. 9\"\n[u_r_vs_1d]\nunbroken_until = 1e-3\n" + kReading)
            .find("without u_r_once_fractured") != std::string::npos);
  CHECK(refusal(dir, "figure = \"Fig. 9\"\n" + kReading + "[benchmark]\nrunner = \"borehole_pair\"\n") ==
        bad + ": [benchmark] paper_figures is missing or empty, allowed: the paper's figure numbers");
}
