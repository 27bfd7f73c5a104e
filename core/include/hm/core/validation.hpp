#pragma once
/// \file
/// One-line range checks for validate() methods: each throws hm::FieldError, whose message is
/// "name = value, allowed: rule" (the Ceres IsValid style); a name "field[k]" is field "field", element "[k]".
#include <string>
#include <string_view>

namespace hm::core {

/// The value formatted as the user would write it (shortest round-trip form).
std::string format_value(double value);

void require_finite(double value, std::string_view name);
void require_positive(double value, std::string_view name);                         ///< value > 0
void require_non_negative(double value, std::string_view name);                     ///< value >= 0
void require_open(double value, std::string_view name, double lo, double hi);       ///< lo < value < hi
void require_closed(double value, std::string_view name, double lo, double hi);     ///< lo <= value <= hi
void require_half_open(double value, std::string_view name, double lo, double hi);  ///< lo <= value < hi
/// Integer count at least `minimum`.
void require_at_least(long long value, std::string_view name, long long minimum);

/// Limits of a geometric time stepping (dt_initial, growing by dt_growth up to dt_max, to t_end),
/// for both models; times are t* (over the diffusion time t_s). The borehole problems are steady
/// by t* ~ 10, so t_end above 1e6 is a typo; a first step below 1e-12 t_end loses dt in t + dt
/// (16 digits) or never grows (5e-324 x 1.05 == 5e-324); more than 1e6 steps would not finish.
struct SteppingLimits {
  static constexpr double max_t_end = 1e6;
  static constexpr double min_dt_over_t_end = 1e-12;
  static constexpr long long max_steps = 1000000;
};
/// Throws a FieldError (t_end or dt_initial) when the stepping breaks a limit; the message gives the
/// number of steps it would take. Call after each value is checked on its own.
void require_feasible_stepping(double dt_initial, double dt_growth, double dt_max, double t_end);

}  // namespace hm::core
