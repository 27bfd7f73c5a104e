// The notes files of verification/notes/: one note per paragraph, shared by a quick and a paper
// benchmark of one kind, none for a benchmark without a file.
#include <catch2/catch.hpp>

#include <string>

#include "benchmark_notes.hpp"

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
