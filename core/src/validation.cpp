#include "hm/core/validation.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "hm/core/input_error.hpp"

namespace hm::core {

std::string format_value(double value) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc() ? std::string(buf, end) : std::to_string(value);
}

namespace {
[[noreturn]] void fail(std::string_view name, const std::string& value, const std::string& rule) {
  throw InputError(std::string(name) + " = " + value + ", allowed: " + rule);
}
std::string n(std::string_view name) { return std::string(name); }
}  // namespace

void require_finite(double value, std::string_view name) {
  if (!std::isfinite(value)) fail(name, format_value(value), "a finite number");
}
void require_positive(double value, std::string_view name) {
  if (!(value > 0.0) || !std::isfinite(value)) fail(name, format_value(value), n(name) + " > 0");
}
void require_non_negative(double value, std::string_view name) {
  if (!(value >= 0.0) || !std::isfinite(value)) fail(name, format_value(value), n(name) + " >= 0");
}
void require_open(double value, std::string_view name, double lo, double hi) {
  if (!(value > lo && value < hi))
    fail(name, format_value(value), format_value(lo) + " < " + n(name) + " < " + format_value(hi));
}
void require_closed(double value, std::string_view name, double lo, double hi) {
  if (!(value >= lo && value <= hi))
    fail(name, format_value(value), format_value(lo) + " <= " + n(name) + " <= " + format_value(hi));
}
void require_half_open(double value, std::string_view name, double lo, double hi) {
  if (!(value >= lo && value < hi))
    fail(name, format_value(value), format_value(lo) + " <= " + n(name) + " < " + format_value(hi));
}
void require_at_least(long long value, std::string_view name, long long minimum) {
  if (value < minimum) fail(name, std::to_string(value), n(name) + " >= " + std::to_string(minimum));
}

}  // namespace hm::core
