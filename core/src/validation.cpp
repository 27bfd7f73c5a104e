#include "hm/core/validation.hpp"

#include <algorithm>
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
// A FieldError for `name`, split into the field and its element ("probe_radii[3]": "probe_radii", "[3]").
[[noreturn]] void fail(std::string_view name, const std::string& value, const std::string& rule) {
  const std::size_t bracket = name.find('[');
  const bool element = bracket != std::string_view::npos && name.back() == ']';
  throw FieldError(std::string(element ? name.substr(0, bracket) : name),
                   std::string(element ? name.substr(bracket) : std::string_view()), value, rule);
}
}  // namespace

void require_finite(double value, std::string_view name) {
  if (!std::isfinite(value)) fail(name, format_value(value), "a finite number");
}
void require_positive(double value, std::string_view name) {
  if (!(value > 0.0) || !std::isfinite(value)) fail(name, format_value(value), "{} > 0");
}
void require_non_negative(double value, std::string_view name) {
  if (!(value >= 0.0) || !std::isfinite(value)) fail(name, format_value(value), "{} >= 0");
}
void require_open(double value, std::string_view name, double lo, double hi) {
  if (!(value > lo && value < hi)) fail(name, format_value(value), format_value(lo) + " < {} < " + format_value(hi));
}
void require_closed(double value, std::string_view name, double lo, double hi) {
  if (!(value >= lo && value <= hi))
    fail(name, format_value(value), format_value(lo) + " <= {} <= " + format_value(hi));
}
void require_half_open(double value, std::string_view name, double lo, double hi) {
  if (!(value >= lo && value < hi)) fail(name, format_value(value), format_value(lo) + " <= {} < " + format_value(hi));
}
void require_at_least(long long value, std::string_view name, long long minimum) {
  if (value < minimum) fail(name, std::to_string(value), "{} >= " + std::to_string(minimum));
}

void require_feasible_stepping(double dt_initial, double dt_growth, double dt_max, double t_end) {
  if (t_end > SteppingLimits::max_t_end)
    fail("t_end", format_value(t_end), "t_end <= 1e6 (t* over the diffusion time; steady by t* ~ 10)");
  if (dt_initial < SteppingLimits::min_dt_over_t_end * t_end)
    fail("dt_initial", format_value(dt_initial),
         "dt_initial >= 1e-12 t_end = " + format_value(SteppingLimits::min_dt_over_t_end * t_end));
  long long steps = 0;
  for (double t = 0.0, dt = dt_initial; t < t_end && steps <= SteppingLimits::max_steps; ++steps) {
    t += dt;
    dt = std::min(dt * dt_growth, dt_max);
  }
  if (steps > SteppingLimits::max_steps)
    fail("dt_initial", format_value(dt_initial),
         "a stepping of at most 1e6 steps; with dt_growth = " + format_value(dt_growth) +
             ", dt_max = " + format_value(dt_max) + " and t_end = " + format_value(t_end) +
             " it takes more (raise dt_growth or dt_max)");
}

}  // namespace hm::core
