#pragma once
/// \file
/// Seeded random beam strengths (Section 2.1: "natural heterogeneities in the grain structure are
/// described by a random distribution of material properties"; the paper gives no distribution).
/// Dimensionless: strengths over E. Our distributions and default: docs/lattice.md, "Strength
/// heterogeneity".
///
/// Reproducible: std::mt19937_64 and our own mapping of its top 53 bits to (0, 1); no std
/// distributions (their output differs between standard libraries). Same spec and n_beams give
/// identical strengths; only std::log/std::pow (Weibull) could differ in the last ulp between libms.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "hm/core/enum_names.hpp"

namespace hm::lattice2d {

/// Shape of the per-beam strength distribution.
enum class StrengthDistribution {
  none,     ///< every beam has exactly T_u and C_u
  uniform,  ///< mean x (1 + width (2U - 1)), U uniform in (0, 1): bounded in mean x [1 - width, 1 + width]
  weibull,  ///< Weibull with modulus m, scaled so the mean is T_u (C_u): unbounded below, weakest-link size effect
};
constexpr auto enum_names(StrengthDistribution) {
  return core::enum_table<StrengthDistribution>({{StrengthDistribution::none, "none"},
                                                 {StrengthDistribution::uniform, "uniform"},
                                                 {StrengthDistribution::weibull, "weibull"}});
}

/// Failure parameters of the beams (Section 2.1, Eq. 11, Table 1) and their heterogeneity.
struct StrengthSpec {
  /// T_u/E, mean uniaxial tensile strength (Table 1: 2e6 Pa / 1e10 Pa). Allowed: > 0.
  double tensile_strength = 2.0e-4;
  /// C_u/E, mean uniaxial compressive strength (Eq. 11; Table 1: 3.33e7 Pa / 1e10 Pa). Allowed: > 0.
  double compressive_strength = 3.33e-3;
  /// mu_i, internal friction coefficient of Eq. 11 (Table 1: 0.9), the same for every beam. Allowed: >= 0.
  double friction = 0.9;
  /// Distribution of the per-beam strengths. Our choice uniform; see docs/lattice.md.
  StrengthDistribution distribution = StrengthDistribution::uniform;
  /// uniform only: relative half-width, strengths in mean x [1 - width, 1 + width] (standard deviation
  /// width/sqrt(3)). Our choice 0.05; see docs/lattice.md. Allowed: 0 <= width < 1.
  double width = 0.05;
  /// weibull only: Weibull modulus m (coefficient of variation ~1.2/m for large m; m = 10 gives 12%).
  /// Allowed: 1 <= weibull_modulus <= 1000.
  double weibull_modulus = 10.0;
  /// true: one random number per beam scales both strengths (a weak bond is weak in tension and in
  /// shear); false: independent draws. Our choice true; see docs/lattice.md.
  bool correlated = true;
  /// Seed of the std::mt19937_64 stream, independent of the lattice seed. Any value.
  std::uint64_t seed = 1;

  /// Throws hm::InputError "field = value, allowed: rule" on the first violated rule.
  void validate() const;
};

/// Per-beam strengths, indexed like Lattice::beams.
struct BeamStrengths {
  Eigen::VectorXd tensile;      ///< T_u of each beam, > 0
  Eigen::VectorXd compressive;  ///< C_u of each beam, > 0
  double friction = 0.9;        ///< mu_i (Eq. 11), copied from the spec

  int n_beams() const { return static_cast<int>(tensile.size()); }
};

/// Draws the strengths of n_beams beams (validates `spec` first; throws hm::InputError).
/// Draw order: beam 0, 1, ...; with correlated = false the tensile draw of a beam precedes its
/// compressive draw. Strengths are strictly positive for every distribution.
BeamStrengths draw_beam_strengths(const StrengthSpec& spec, int n_beams);

/// Mean and standard deviation of the relative strength (strength / mean) of a distribution: 1 and
/// 0 (none), 1 and width/sqrt(3) (uniform), 1 and sqrt(Gamma(1+2/m)/Gamma(1+1/m)^2 - 1) (weibull).
struct RelativeMoments {
  double mean;
  double standard_deviation;
};
RelativeMoments relative_strength_moments(const StrengthSpec& spec);

}  // namespace hm::lattice2d
