// The notes files of verification/notes/: one note per paragraph, shared by a quick and a paper
// benchmark of one kind, none for a benchmark without a file.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include "benchmark_notes.hpp"
#include "hm/verification/benchmark.hpp"

using hm::verification::benchmark_notes;

TEST_CASE("A benchmark's notes are its notes file's paragraphs, shared by its quick and paper tiers",
          "[verification][notes]") {
  const auto quick = benchmark_notes("lattice2d.fig18_quick");
  REQUIRE(quick.size() == 3);
  CHECK(quick.front().rfind("Three models of one breakdown. ", 0) == 0);
  CHECK(quick.front().find('\n') == std::string::npos);  // a paragraph's lines joined into one note
  CHECK(quick.front().find("  ") == std::string::npos);
  CHECK(benchmark_notes("lattice2d.fig18") == quick);
  CHECK(benchmark_notes("lattice2d.no_such_benchmark").empty());
}

TEST_CASE("Every notes file belongs to a benchmark (a misspelt name would be read by none)", "[verification][notes]") {
  namespace fs = std::filesystem;
  std::set<std::string> ids;
  for (const hm::verification::Benchmark& b : hm::verification::all_benchmarks()) ids.insert(b.id);
  int n_files = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(HM_SOURCE_DIR) / "verification" / "notes")) {
    const std::string stem = entry.path().stem().string();
    if (entry.path().extension() != ".md" || stem == "README") continue;
    ++n_files;
    INFO(entry.path().filename().string());
    CHECK((ids.count(stem) + ids.count(stem + "_quick")) > 0);
    CHECK_FALSE(benchmark_notes(stem).empty());
  }
  CHECK(n_files >= 14);  // the 14 files of today; fewer means the folder was not found
}
