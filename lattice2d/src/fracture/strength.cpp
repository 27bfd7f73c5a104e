#include "hm/lattice2d/fracture/strength.hpp"

#include <cmath>
#include <random>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

void StrengthSpec::validate() const {
  using namespace hm::core;
  require_positive(tensile_strength, "tensile_strength");
  require_positive(compressive_strength, "compressive_strength");
  require_non_negative(friction, "friction");
  require_half_open(width, "width", 0.0, 1.0);
  require_closed(weibull_modulus, "weibull_modulus", 1.0, 1000.0);
}

namespace {

// Uniform in the open interval (0, 1) from the top 53 bits: (k + 1/2) 2^-53 is never 0 or 1, so the
// Weibull quantile below stays finite and positive.
double open_unit(std::mt19937_64& rng) {
  const std::uint64_t k = rng() >> 11;
  return (static_cast<double>(k) + 0.5) * 0x1.0p-53;
}

// Relative strength (mean 1) from one uniform number.
double relative_strength(const StrengthSpec& spec, double u) {
  switch (spec.distribution) {
    case StrengthDistribution::none: return 1.0;
    case StrengthDistribution::uniform: return 1.0 + spec.width * (2.0 * u - 1.0);
    case StrengthDistribution::weibull: {
      const double m = spec.weibull_modulus;
      // Quantile (-ln(1 - U))^(1/m) of the unit-scale Weibull, divided by its mean Gamma(1 + 1/m).
      return std::pow(-std::log1p(-u), 1.0 / m) / std::tgamma(1.0 + 1.0 / m);
    }
  }
  return 1.0;
}

}  // namespace

BeamStrengths draw_beam_strengths(const StrengthSpec& spec, int n_beams) {
  spec.validate();
  hm::core::require_at_least(n_beams, "n_beams", 0);
  BeamStrengths out{Eigen::VectorXd(n_beams), Eigen::VectorXd(n_beams), spec.friction};
  std::mt19937_64 rng(spec.seed);
  for (int e = 0; e < n_beams; ++e) {
    const double t = relative_strength(spec, open_unit(rng));
    const double c = spec.correlated ? t : relative_strength(spec, open_unit(rng));
    out.tensile[e] = spec.tensile_strength * t;
    out.compressive[e] = spec.compressive_strength * c;
  }
  return out;
}

RelativeMoments relative_strength_moments(const StrengthSpec& spec) {
  switch (spec.distribution) {
    case StrengthDistribution::none: return {1.0, 0.0};
    case StrengthDistribution::uniform: return {1.0, spec.width / std::sqrt(3.0)};
    case StrengthDistribution::weibull: {
      const double g1 = std::tgamma(1.0 + 1.0 / spec.weibull_modulus);
      const double g2 = std::tgamma(1.0 + 2.0 / spec.weibull_modulus);
      return {1.0, std::sqrt(g2 / (g1 * g1) - 1.0)};
    }
  }
  return {1.0, 0.0};
}

}  // namespace hm::lattice2d
