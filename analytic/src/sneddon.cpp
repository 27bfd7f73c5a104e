#include "hm/analytic/sneddon.hpp"

#include <cmath>
#include <numbers>

namespace hm::analytic {

double SneddonCrack::max_half_aperture() const { return 2.0 * (1.0 - nu * nu) * p * c; }

double SneddonCrack::half_aperture(double x) const {
  if (std::abs(x) >= c) return 0.0;
  return max_half_aperture() * std::sqrt(1.0 - (x / c) * (x / c));
}

double SneddonCrack::crack_volume() const { return std::numbers::pi * c * max_half_aperture(); }

}  // namespace hm::analytic
