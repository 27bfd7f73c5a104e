// A validate() error keeps the field apart from its text, so that the case layer names the key the
// user wrote without rewriting the message.
#include <catch2/catch.hpp>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

TEST_CASE("A range check throws a FieldError that renders under the struct's name or under another", "[core]") {
  try {
    hm::core::require_closed(2.5, "probe_radii[3]", 0.1, 1.0);
    FAIL("no exception");
  } catch (const hm::FieldError& e) {
    CHECK(e.field() == "probe_radii");
    CHECK(std::string(e.what()) == "probe_radii[3] = 2.5, allowed: 0.1 <= probe_radii[3] <= 1");
    // Every mention of the field in the rule takes the new name, with its element.
    CHECK(e.message_as("probes") == "probes[3] = 2.5, allowed: 0.1 <= probes[3] <= 1");
  }
  try {
    hm::core::require_positive(-1.0, "t_end");
    FAIL("no exception");
  } catch (const hm::FieldError& e) {
    CHECK(e.field() == "t_end");
    CHECK(std::string(e.what()) == "t_end = -1, allowed: t_end > 0");
  }
  // A FieldError is bad input like any other.
  CHECK_THROWS_AS(hm::core::require_at_least(0, "n", 1), hm::InputError);
}
