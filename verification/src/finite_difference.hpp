#pragma once
// Fourth-order central differences, used to check closed forms against their differential
// equations independently of how the closed forms were derived. Truncation error O(h^4).
#include <functional>

namespace hm::verification {

inline double d1(const std::function<double(double)>& f, double x, double h) {
  return (f(x - 2 * h) - 8 * f(x - h) + 8 * f(x + h) - f(x + 2 * h)) / (12 * h);
}

inline double d2(const std::function<double(double)>& f, double x, double h) {
  return (-f(x - 2 * h) + 16 * f(x - h) - 30 * f(x) + 16 * f(x + h) - f(x + 2 * h)) / (12 * h * h);
}

}  // namespace hm::verification
