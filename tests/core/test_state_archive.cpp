// The checkpoint archive: values come back as the same bits, and a file of other code or a damaged one
// is refused naming the place, never misread.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hm/core/input_error.hpp"
#include "hm/core/state_archive.hpp"

using hm::core::StateReader;
using hm::core::StateWriter;

namespace {

std::uint64_t bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

}  // namespace

TEST_CASE("The state archive gives back every value bitwise", "[core]") {
  const double tiny = 5e-324, third = 1.0 / 3.0;
  const std::vector<double> reals = {third, -0.0, tiny, NAN, INFINITY};
  const std::vector<int> ints = {-7, 0, 2147483647};
  const std::vector<bool> flags = {true, false, true};
  StateWriter w;
  w.put("third", third);
  w.put("count", std::int64_t{-9007199254740993});
  w.put("flag", true);
  w.put("name", std::string("a\nb\0c", 5));
  w.put("reals", reals);
  w.put("ints", ints);
  w.put("flags", flags);
  w.put("empty", std::vector<double>{});

  StateReader r(w.bytes(), "test");
  double x = 0.0;
  std::int64_t n = 0;
  bool flag = false;
  std::string name;
  std::vector<double> reals_back;
  std::vector<int> ints_back;
  std::vector<bool> flags_back;
  std::vector<double> empty = {1.0};
  r.get("third", x);
  r.get("count", n);
  r.get("flag", flag);
  r.get("name", name);
  r.get("reals", reals_back);
  r.get("ints", ints_back);
  r.get("flags", flags_back);
  r.get("empty", empty);
  CHECK(bits(x) == bits(third));
  CHECK(n == -9007199254740993);
  CHECK(flag);
  CHECK(name == std::string("a\nb\0c", 5));
  REQUIRE(reals_back.size() == reals.size());
  for (std::size_t k = 0; k < reals.size(); ++k) CHECK(bits(reals_back[k]) == bits(reals[k]));
  CHECK(ints_back == ints);
  CHECK(flags_back == flags);
  CHECK(empty.empty());
  CHECK(r.at_end());
}

TEST_CASE("The state archive refuses another tag, another type, a truncated or altered file", "[core]") {
  StateWriter w;
  w.put("time", 0.5);
  w.put("steps", 3);
  const std::string bytes = w.bytes();

  double t = 0.0;
  StateReader other_tag(bytes, "f");
  CHECK_THROWS_WITH(other_tag.get("dt", t), Catch::Contains("f: at 'dt': found 'time' instead"));
  StateReader other_type(bytes, "f");
  int steps = 0;
  CHECK_THROWS_WITH(other_type.get("time", steps), Catch::Contains("at 'time': element type"));
  CHECK_THROWS_WITH(StateReader(bytes.substr(0, bytes.size() - 1), "f"), Catch::Contains("checksum"));
  std::string altered = bytes;
  altered[altered.size() / 2] ^= 1;
  CHECK_THROWS_AS(StateReader(altered, "f"), hm::InputError);
  CHECK_THROWS_WITH(StateReader("not a checkpoint", "f"), Catch::Contains("not a state file"));
}

TEST_CASE("A snapshot kept in memory is read in place, and its writer is cleared for the next", "[core]") {
  const double third = 1.0 / 3.0;
  StateWriter w;
  w.put("old", 1.0);
  w.clear();  // the next step's snapshot: nothing of the last one is left
  w.put("third", third);
  w.put("ints", std::vector<int>{-7, 0, 2147483647});
  StateReader r = StateReader::of_snapshot(w, "snapshot");
  double x = 0.0;
  std::vector<int> ints;
  r.get("third", x);
  r.get("ints", ints);
  CHECK(bits(x) == bits(third));
  CHECK(ints == std::vector<int>{-7, 0, 2147483647});
  CHECK(r.at_end());
  // The same tags and types are checked as in a file: a snapshot read in another order is refused.
  StateReader wrong = StateReader::of_snapshot(w, "snapshot");
  std::vector<int> none;
  CHECK_THROWS_WITH(wrong.get("ints", none), Catch::Contains("snapshot: at 'ints'"));
  // The writer's bytes for a file are unchanged by the in-place reading.
  StateReader file(w.bytes(), "file");
  file.get("third", x);
  CHECK(bits(x) == bits(third));
}

TEST_CASE("A state streamed to a file is byte for byte the one collected in memory, and measured", "[core]") {
  // Long enough that the checksum runs over many pieces, each continued from the bytes before it.
  std::vector<double> reals(10000);
  for (std::size_t k = 0; k < reals.size(); ++k) reals[k] = std::sin(0.37 * static_cast<double>(k));
  const auto put_all = [&](StateWriter& w) {
    w.put("name", std::string("case text"));
    w.put("reals", reals);
    w.put("steps", 12);
    w.put("flags", std::vector<bool>{true, false, true});
  };
  StateWriter memory;
  put_all(memory);
  std::ostringstream file;
  StateWriter streamed(file);
  put_all(streamed);
  streamed.finish();
  CHECK(file.str() == memory.bytes());
  // measure() counts what a writer would hold (the checksum aside), keeping none of it.
  CHECK(StateWriter::measure(put_all) + 4 == memory.bytes().size());
  StateReader r(file.str(), "streamed");  // its checksum holds
  std::string name;
  r.get("name", name);
  CHECK(name == "case text");
  // A streamed writer has no bytes and takes nothing after its checksum.
  CHECK_THROWS_AS(streamed.bytes(), std::logic_error);
  CHECK_THROWS_AS(streamed.put("late", 1.0), std::logic_error);
  CHECK_THROWS_AS(memory.finish(), std::logic_error);
}
