// Command-line values checked by the rules the case files follow: a number is finite, an integer is
// written as one (CLI11's own range check would call "1e3" out of range and let nan through).
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "hm/core/validation.hpp"

namespace hm::app {

CLI::Validator integer_between(long long lo, long long hi) {
  const std::string rule = "an integer, " + std::to_string(lo) + " ... " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, rule](std::string& text) -> std::string {
        long long v = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
          return text + ", allowed: " + rule;
        return {};
      },
      rule);
}

CLI::Validator finite_between(double lo, double hi) {
  const std::string rule = core::format_value(lo) + " <= value <= " + core::format_value(hi) + ", finite";
  return CLI::Validator(
      [lo, hi, rule](std::string& text) -> std::string {
        double v = 0.0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v) || v < lo || v > hi)
          return text + ", allowed: " + rule;
        return {};
      },
      rule);
}

}  // namespace hm::app
