#include <catch2/catch.hpp>

#include <cmath>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/fracture/strength.hpp"

using namespace hm::lattice2d;

namespace {

struct Sample {
  double mean;
  double standard_deviation;
};

Sample sample_of(const Eigen::VectorXd& x) {
  const double mean = x.mean();
  return {mean, std::sqrt((x.array() - mean).square().sum() / static_cast<double>(x.size() - 1))};
}

StrengthSpec spec_of(StrengthDistribution d) {
  StrengthSpec spec;
  spec.distribution = d;
  return spec;
}

}  // namespace

TEST_CASE("Strength spec: defaults valid, every bad field rejected by name", "[lattice2d]") {
  REQUIRE_NOTHROW(StrengthSpec{}.validate());
  const auto rejects = [](auto mutate, const char* message) {
    StrengthSpec spec;
    mutate(spec);
    CHECK_THROWS_AS(spec.validate(), hm::InputError);
    CHECK_THROWS_WITH(spec.validate(), Catch::Contains(message));
    CHECK_THROWS_WITH(draw_beam_strengths(spec, 10), Catch::Contains(message));
  };
  rejects([](StrengthSpec& s) { s.tensile_strength = -2e-4; }, "tensile_strength = -2e-04");
  rejects([](StrengthSpec& s) { s.compressive_strength = 0.0; }, "compressive_strength = 0");
  rejects([](StrengthSpec& s) { s.friction = -0.1; }, "friction = -0.1");
  rejects([](StrengthSpec& s) { s.width = 1.0; }, "width = 1");
  rejects([](StrengthSpec& s) { s.width = -0.01; }, "width = -0.01");
  rejects([](StrengthSpec& s) { s.weibull_modulus = 0.5; }, "weibull_modulus = 0.5");
  rejects([](StrengthSpec& s) { s.tensile_strength = std::nan(""); }, "tensile_strength");
  CHECK_THROWS_WITH(draw_beam_strengths(StrengthSpec{}, -1), Catch::Contains("n_beams = -1"));
}

TEST_CASE("Same seed gives identical strengths, another seed different ones", "[lattice2d]") {
  for (auto d : {StrengthDistribution::uniform, StrengthDistribution::weibull}) {
    StrengthSpec spec = spec_of(d);
    spec.correlated = false;
    const BeamStrengths a = draw_beam_strengths(spec, 5000), b = draw_beam_strengths(spec, 5000);
    CHECK(a.tensile == b.tensile);  // bitwise
    CHECK(a.compressive == b.compressive);
    spec.seed = 2;
    const BeamStrengths c = draw_beam_strengths(spec, 5000);
    CHECK((a.tensile.array() != c.tensile.array()).count() == 5000);
    // A longer draw starts with the shorter one (per-beam order): adding beams does not reshuffle.
    spec.seed = 1;
    CHECK(draw_beam_strengths(spec, 7000).tensile.head(5000) == a.tensile);
  }
}

TEST_CASE("Strengths are a stored regression snapshot of the default spec", "[lattice2d]") {
  // Regression snapshot, 2026-11-22, hmlattice after commit 2688db3: StrengthSpec{} (uniform, width 0.05,
  // seed 1), first three beams. Our own 53-bit mapping of std::mt19937_64 (whose output the standard
  // fixes), so these must hold bitwise on any conforming platform; tolerance is round-off.
  const BeamStrengths s = draw_beam_strengths(StrengthSpec{}, 3);
  CHECK(s.tensile[0] == hm::test::roundoff(0.00019267753288025065));
  CHECK(s.tensile[1] == hm::test::roundoff(0.00019272814072732395));
  CHECK(s.tensile[2] == hm::test::roundoff(0.00019902429807689079));
}

TEST_CASE("'none' gives exactly T_u and C_u, 'uniform' is bounded with the documented mean and width", "[lattice2d]") {
  const int n = 100000;
  SECTION("none") {
    const BeamStrengths s = draw_beam_strengths(spec_of(StrengthDistribution::none), 100);
    CHECK((s.tensile.array() == StrengthSpec{}.tensile_strength).all());
    CHECK((s.compressive.array() == StrengthSpec{}.compressive_strength).all());
    CHECK(s.friction == 0.9);
  }
  SECTION("uniform") {
    StrengthSpec spec = spec_of(StrengthDistribution::uniform);
    spec.width = 0.2;
    const BeamStrengths s = draw_beam_strengths(spec, n);
    const Eigen::VectorXd rel = s.tensile / spec.tensile_strength;
    CHECK(rel.minCoeff() > 1.0 - spec.width);
    CHECK(rel.maxCoeff() < 1.0 + spec.width);
    const Sample x = sample_of(rel);
    const RelativeMoments m = relative_strength_moments(spec);
    CHECK(m.standard_deviation == hm::test::roundoff(0.2 / std::sqrt(3.0)));
    // Statistical: standard error of the mean sd/sqrt(n) = 3.7e-4; of the sd, sd sqrt((kurtosis - 1)/(4n))
    // with kurtosis 1.8 for a uniform = 1.6e-4. Tolerances are 5 standard errors.
    CHECK(x.mean == Approx(1.0).margin(5 * m.standard_deviation / std::sqrt(n)));
    CHECK(x.standard_deviation ==
          Approx(m.standard_deviation).margin(5 * m.standard_deviation * std::sqrt(0.8 / (4.0 * n))));
    // Correlated (default): one draw scales both strengths.
    CHECK((s.compressive / spec.compressive_strength - rel).cwiseAbs().maxCoeff() < 1e-15);
  }
  SECTION("uniform, independent draws for C_u") {
    StrengthSpec spec = spec_of(StrengthDistribution::uniform);
    spec.correlated = false;
    const BeamStrengths s = draw_beam_strengths(spec, n);
    const Eigen::VectorXd t = s.tensile / spec.tensile_strength, c = s.compressive / spec.compressive_strength;
    // Statistical: the sample correlation of independent draws is ~N(0, 1/n), so |r| < 5/sqrt(n) = 0.016.
    const double r = ((t.array() - t.mean()) * (c.array() - c.mean())).sum() /
                     std::sqrt((t.array() - t.mean()).square().sum() * (c.array() - c.mean()).square().sum());
    CHECK(std::abs(r) < 5.0 / std::sqrt(n));
    CHECK(c.mean() == Approx(1.0).margin(5 * 0.05 / std::sqrt(3.0 * n)));  // 5 standard errors
  }
}

TEST_CASE("'weibull' has mean T_u and the Weibull coefficient of variation", "[lattice2d]") {
  const int n = 100000;
  for (double m : {3.0, 10.0}) {
    StrengthSpec spec = spec_of(StrengthDistribution::weibull);
    spec.weibull_modulus = m;
    const BeamStrengths s = draw_beam_strengths(spec, n);
    CHECK(s.tensile.minCoeff() > 0.0);
    const Sample x = sample_of(s.tensile / spec.tensile_strength);
    const RelativeMoments moments = relative_strength_moments(spec);
    INFO("m = " << m << ": sample mean " << x.mean << ", sd " << x.standard_deviation << ", expected sd "
                << moments.standard_deviation);
    // Statistical: 5 standard errors; for the sd, the kurtosis of a Weibull is 2.7 (m = 3) and 3.6 (m = 10),
    // so its standard error is below sd sqrt(3/(4n)).
    CHECK(x.mean == Approx(1.0).margin(5 * moments.standard_deviation / std::sqrt(n)));
    CHECK(x.standard_deviation ==
          Approx(moments.standard_deviation).margin(5 * moments.standard_deviation * std::sqrt(3.0 / (4.0 * n))));
  }
  // Closed form for m = 1 (exponential): coefficient of variation 1.
  StrengthSpec exponential = spec_of(StrengthDistribution::weibull);
  exponential.weibull_modulus = 1.0;
  CHECK(relative_strength_moments(exponential).standard_deviation == hm::test::roundoff(1.0));
}
