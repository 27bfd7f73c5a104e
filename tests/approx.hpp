#pragma once
/// \file
/// The project's one approximate-compare helper for identities that hold to round-off.
/// Any other tolerance is written at its assertion with the reason beside it.
#include <catch2/catch.hpp>

namespace hm::test {

/// Relative 1e-12 with an absolute floor of 1e-14: round-off for O(1) dimensionless quantities
/// computed in a handful of double operations.
inline Approx roundoff(double reference) { return Approx(reference).epsilon(1e-12).margin(1e-14); }

}  // namespace hm::test
