#pragma once
/// \file
/// One-line range checks for validate() methods: each throws hm::InputError
/// "name = value, allowed: rule" (the Ceres IsValid style).
#include <string>
#include <string_view>

namespace hm::core {

/// The value formatted as the user would write it (shortest round-trip form).
std::string format_value(double value);

void require_finite(double value, std::string_view name);
void require_positive(double value, std::string_view name);      ///< value > 0
void require_non_negative(double value, std::string_view name);  ///< value >= 0
void require_open(double value, std::string_view name, double lo, double hi);    ///< lo < value < hi
void require_closed(double value, std::string_view name, double lo, double hi);  ///< lo <= value <= hi
void require_half_open(double value, std::string_view name, double lo, double hi);  ///< lo <= value < hi
/// Integer count at least `minimum`.
void require_at_least(long long value, std::string_view name, long long minimum);

}  // namespace hm::core
