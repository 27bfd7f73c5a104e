#include <cmath>

#include "hm/verification/benchmark.hpp"

namespace hm::verification {

bool Metric::passes() const {
  if (!std::isfinite(value)) return false;
  switch (comparison) {
    case Comparison::abs_error: return std::abs(value - reference) <= tolerance;
    case Comparison::rel_error: return std::abs(value - reference) <= tolerance * std::abs(reference);
    case Comparison::at_most: return value <= tolerance;
    case Comparison::at_least: return value >= tolerance;
  }
  return false;
}

}  // namespace hm::verification
