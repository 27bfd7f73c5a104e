// An enum's names table gives its names, parses them back and names the field and the allowed
// values when a name is not in it.
#include <catch2/catch.hpp>
#include <string>

#include "hm/core/enum_names.hpp"

namespace phase {

enum class Phase { solid, liquid, gas };
constexpr auto enum_names(Phase) {
  return hm::core::enum_table<Phase>({{Phase::solid, "solid"}, {Phase::liquid, "liquid"}, {Phase::gas, "gas"}});
}

}  // namespace phase

using hm::core::from_name;
using hm::core::name_of;
using phase::Phase;

TEST_CASE("An enum's names table names, parses and rejects naming the field", "[core]") {
  CHECK(name_of(Phase::liquid) == "liquid");
  CHECK(name_of(static_cast<Phase>(7)) == "unknown(7)");
  CHECK(hm::core::enum_values<Phase>() == std::vector<Phase>{Phase::solid, Phase::liquid, Phase::gas});
  for (Phase p : hm::core::enum_values<Phase>()) CHECK(from_name<Phase>(name_of(p), "phase") == p);
  CHECK_THROWS_WITH(from_name<Phase>("plasma", "fluid.phase"), "fluid.phase = 'plasma', allowed: solid, liquid, gas");
  // Names are exact: no case folding, no prefixes.
  CHECK_THROWS_AS(from_name<Phase>("Solid", "phase"), hm::InputError);
  CHECK_THROWS_AS(from_name<Phase>("", "phase"), hm::InputError);
  // A subset of the values: the others are refused, and the message lists only the subset.
  CHECK(from_name<Phase>("gas", "phase", {Phase::liquid, Phase::gas}) == Phase::gas);
  CHECK_THROWS_WITH(from_name<Phase>("solid", "phase", {Phase::liquid, Phase::gas}),
                    "phase = 'solid', allowed: liquid, gas");
}
