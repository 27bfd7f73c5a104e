// Tests of lattice2d/calibration.hpp: the elastic measurement against an exactly known lattice,
// linearity in k_n, isotropy, the search, the stored constants, and input validation.
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include <catch2/catch.hpp>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::regular_triangular_lattice;

TEST_CASE("A regular triangular lattice of nearly central beams measures the exact nu = 1/4 and E = 5 sqrt(3)/8 k_n",
          "[lattice2d]") {
  // Exact answer: affine displacement is an equilibrium of a regular triangular lattice (inversion
  // symmetry at every interior particle), so C_abcd = (1/A0) sum_3 beams (k_n L^2 n n n n + k_w terms)
  // with A0 = sqrt(3)/2 l^2: C11 = 2 sqrt(3) (3/8 k_n + k_w/4), C12 = 2 sqrt(3) (k_n/8 - k_w/4),
  // C66 = (C11 - C12)/2; for k_w -> 0 plane strain nu = 1/4 (plane stress 1/3) and
  // E = 5 sqrt(3)/8 k_n (plane stress 2 k_n / sqrt(3)).
  const Lattice lattice = regular_triangular_lattice(31, 1.0 / 30.0);
  BeamParameters beams;
  beams.normal_stiffness = 2.0;
  beams.aspect = 1e-4;  // k_w / k_n = 5e-9
  const double kn = beams.normal_stiffness, kw = beams.rotational_stiffness();
  const ElasticProperties p = measure_elastic_properties(lattice, beams);
  const double s3 = std::sqrt(3.0);
  // The free rotations of the boundary particles are not those of the affine field (their moment
  // sums do not vanish); the disturbance they send inwards is O(k_w/k_n) = 5e-9, and the solve's
  // round-off at this stiffness contrast is ~1e-12: tolerance 1e-7 relative.
  CHECK(p.c11 == Approx(2 * s3 * (3.0 / 8.0 * kn + kw / 4.0)).epsilon(1e-7));
  CHECK(p.c12 == Approx(2 * s3 * (kn / 8.0 - kw / 4.0)).epsilon(1e-7));
  CHECK(p.c66 == Approx(0.5 * (p.c11 - p.c12)).epsilon(1e-7));
  CHECK(p.poisson_ratio == Approx(0.25).margin(1e-7));
  CHECK(p.youngs_modulus == Approx(5.0 * s3 / 8.0 * kn).epsilon(1e-7));
  // Plane-stress reading of the same C: nu' = nu/(1 - nu) = 1/3, E' = E/(1 - nu^2) = 2 k_n/sqrt(3).
  CHECK(p.poisson_ratio / (1 - p.poisson_ratio) == Approx(1.0 / 3.0).margin(1e-7));
  CHECK(p.youngs_modulus / (1 - p.poisson_ratio * p.poisson_ratio) == Approx(2.0 * kn / s3).epsilon(1e-7));
  // Every interior particle carries the same stress: no scatter on a regular lattice.
  CHECK(p.scatter.maxCoeff() < 1e-6 * p.c11);
  // The boundary-reaction average is sum over all beams of F (x) L over the polygon's area: the beams
  // along the edges make it differ by O(l / side) (measured nu 0.2486 at 30 spacings): 1%.
  CHECK(p.boundary_poisson_ratio == Approx(0.25).margin(0.01));
}

TEST_CASE("Beams with bending stiffness on a regular triangular lattice measure the affine constants", "[lattice2d]") {
  const Lattice lattice = regular_triangular_lattice(41, 1.0 / 40.0);
  BeamParameters beams;  // a = 1: k_w / k_n = 1/7
  const double kn = beams.normal_stiffness, kw = beams.rotational_stiffness();
  const ElasticProperties p = measure_elastic_properties(lattice, beams);
  // The boundary particles' rotations disturb the affine field inwards (measured in the region, 0.6 of
  // the inradius at 40 spacings: C12 low by 1.7e-3 relative); 5e-3 is that with margin.
  CHECK(p.c11 == Approx(2 * std::sqrt(3.0) * (3.0 / 8.0 * kn + kw / 4.0)).epsilon(5e-3));
  CHECK(p.c12 == Approx(2 * std::sqrt(3.0) * (kn / 8.0 - kw / 4.0)).epsilon(5e-3));
  CHECK(p.poisson_ratio == Approx(0.25 - kw / (2 * kn)).margin(2e-3));
}

TEST_CASE("The measured E is linear in k_n and nu does not depend on k_n", "[lattice2d]") {
  const Lattice lattice = generate_lattice(calibration_rectangle(2500, 1.5, 4));
  BeamParameters beams = calibrated_beam_parameters();
  const ElasticProperties one = measure_elastic_properties(lattice, beams);
  beams.normal_stiffness *= 3.7;
  const ElasticProperties scaled = measure_elastic_properties(lattice, beams);
  // K scales exactly with k_n at fixed (a, nu0); only the solves' round-off differs.
  CHECK(scaled.youngs_modulus == Approx(3.7 * one.youngs_modulus).epsilon(1e-9));
  CHECK(scaled.poisson_ratio == Approx(one.poisson_ratio).epsilon(1e-9));
  CHECK(scaled.boundary_youngs_modulus == Approx(3.7 * one.boundary_youngs_modulus).epsilon(1e-9));
  CHECK(one.is_converged);
  CHECK(one.message.empty());
}

TEST_CASE("A random lattice is isotropic within its sampling error: C66 = (C11 - C12)/2", "[lattice2d]") {
  // N = 2.5e3 density, side 2 (~3200 particles, ~880 in the region). Measured over seeds 1-3:
  // shear_isotropy_error -2.2%, -0.7%, -3.4%; anisotropy <= 1.5%. The region mean carries a sampling
  // error of ~27%/sqrt(880) ~ 1% per entry, and the comparison combines three entries: 5%.
  for (std::uint64_t seed : {1, 2, 3}) {
    const ElasticProperties p = measure_elastic_properties(generate_lattice(calibration_rectangle(2500, 2.0, seed)),
                                                           calibrated_beam_parameters());
    CHECK(std::abs(p.shear_isotropy_error) < 0.05);
    CHECK(p.anisotropy < 0.05);
    // Interior (region) and boundary-reaction estimates agree: the boundary layer is thin.
    CHECK(p.youngs_modulus == Approx(p.boundary_youngs_modulus).epsilon(0.02));
  }
}

TEST_CASE("calibrate_beams hits a reachable target nu and scales k_n for E exactly", "[lattice2d]") {
  CalibrationSpec spec;
  spec.n_particles = 2000;
  spec.rectangle_side = 1.2;  // ~920 particles
  spec.seeds = {5};
  spec.target_poisson_ratio = 0.20;
  spec.target_youngs_modulus = 0.7;
  const Calibration c = calibrate_beams(spec);
  INFO(c.message);
  CHECK(c.target_poisson_reached);
  CHECK(std::abs(c.poisson_ratio_mean - 0.20) <= spec.poisson_tolerance);
  // E is linear in k_n: the one rescaling hits the target to round-off.
  CHECK(c.youngs_modulus_mean == Approx(0.7).epsilon(1e-9));
  CHECK(c.beams.beam_poisson == 0.25);
  CHECK(c.beams.aspect > spec.aspect_min);
  CHECK(c.beams.aspect < spec.aspect_max);
  CHECK(c.poisson_ratio_at_aspect_max < 0.20);
  CHECK(c.poisson_ratio_at_aspect_min > 0.20);
}

TEST_CASE("calibrate_beams reports an unreachable nu = 0.25 (uniform beams) and returns the closest end of the bracket",
          "[lattice2d]") {
  CalibrationSpec spec;
  spec.stiffness_scaling = StiffnessScaling::uniform;  // the paper's beams: nu <= ~0.224
  spec.n_particles = 2000;
  spec.rectangle_side = 1.2;
  spec.seeds = {5};
  const Calibration c = calibrate_beams(spec);
  INFO(c.message);
  CHECK_FALSE(c.target_poisson_reached);
  CHECK(c.beams.aspect == Approx(spec.aspect_min).epsilon(1e-12));
  CHECK(c.poisson_ratio_mean < 0.25 - 0.02);
  CHECK(c.message.find("NOT reached") != std::string::npos);
  CHECK(c.youngs_modulus_mean == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("Calibration inputs: defaults are valid and each bad value is rejected by name", "[lattice2d]") {
  CHECK_NOTHROW(CalibrationSpec{}.validate());
  CHECK_NOTHROW(ElasticTestOptions{}.validate());
  CHECK_NOTHROW(calibrated_beam_parameters().validate());
  auto rejects = [](auto mutate, const std::string& field) {
    CalibrationSpec spec;
    mutate(spec);
    CHECK_THROWS_WITH(spec.validate(), Catch::Contains(field));
    CHECK_THROWS_AS(spec.validate(), hm::InputError);
  };
  rejects([](CalibrationSpec& s) { s.n_particles = 100; }, "calibration.n_particles");
  rejects([](CalibrationSpec& s) { s.n_particles = 5'000'000; }, "calibration.n_particles");
  rejects([](CalibrationSpec& s) { s.rectangle_side = -1; }, "calibration.rectangle_side");
  rejects([](CalibrationSpec& s) { s.rectangle_side = 0.2; }, "calibration.rectangle_side");
  rejects([](CalibrationSpec& s) { s.seeds.clear(); }, "calibration.seeds");
  rejects([](CalibrationSpec& s) { s.target_youngs_modulus = 0; }, "calibration.target_youngs_modulus");
  rejects([](CalibrationSpec& s) { s.target_poisson_ratio = 0.5; }, "calibration.target_poisson_ratio");
  rejects([](CalibrationSpec& s) { s.beam_poisson = -1.5; }, "calibration.beam_poisson");
  rejects([](CalibrationSpec& s) { s.aspect_min = 0; }, "calibration.aspect_min");
  rejects([](CalibrationSpec& s) { s.aspect_max = 0.01; }, "calibration.aspect_max");
  rejects([](CalibrationSpec& s) { s.poisson_tolerance = 0; }, "calibration.poisson_tolerance");
  rejects([](CalibrationSpec& s) { s.max_iterations = 0; }, "calibration.max_iterations");
  rejects([](CalibrationSpec& s) { s.test.region_fraction = 1.5; }, "elastic_test.region_fraction");

  LatticeSpec annulus;
  annulus.domain = DomainShape::annulus;
  annulus.n_particles = 600;
  CHECK_THROWS_WITH(measure_elastic_properties(generate_lattice(annulus), BeamParameters{}),
                    Catch::Contains("lattice.spec.domain"));
  ElasticTestOptions tiny;
  tiny.region_fraction = 1e-6;
  CHECK_THROWS_WITH(
      measure_elastic_properties(generate_lattice(calibration_rectangle(2000, 1.0, 1)), BeamParameters{}, tiny),
      Catch::Contains("elastic_test.region_fraction"));
}

TEST_CASE("The stored beam constants give E = 1 within 2% and the documented nu on the N = 1e4 lattice",
          "[lattice2d][slow]") {
  // Regression snapshot of calibrated_beam_parameters(scaling) (2026-11-22; docs/lattice.md,
  // "Calibration"), mean over seeds 1-3: voronoi_facet (default) E = 1.0000 (sd 0.0047), nu = 0.2500
  // (sd 0.0015); uniform E = 1.0000 (sd 0.0036), nu = 0.2236 (sd 0.0009). E: the calibration's 2%. nu:
  // the calibration's 0.02 from the target 0.25 for the default, and for both a regression band of three times
  // the seed scatter (0.005, 0.002). Uniform beams cannot reach 0.25 (central-force limit ~0.224).
  struct Expected {
    StiffnessScaling scaling;
    double nu, band;
  };
  for (const Expected x :
       {Expected{StiffnessScaling::voronoi_facet, 0.25, 0.005}, Expected{StiffnessScaling::uniform, 0.2236, 0.002}}) {
    INFO("stiffness_scaling = " << hm::core::name_of(x.scaling));
    double e = 0, nu = 0;
    for (std::uint64_t seed : {1, 2, 3}) {
      const ElasticProperties p = measure_elastic_properties(generate_lattice(calibration_rectangle(10000, 2.0, seed)),
                                                             calibrated_beam_parameters(x.scaling));
      e += p.youngs_modulus / 3;
      nu += p.poisson_ratio / 3;
      // Isotropy at N = 1e4 (~3500 region particles): measured within 2.4%; sampling ~0.5% per entry.
      CHECK(std::abs(p.shear_isotropy_error) < 0.03);
    }
    CHECK(e == Approx(1.0).epsilon(0.02));
    CHECK(nu == Approx(x.nu).margin(x.band));
    CHECK(nu == Approx(calibrated_continuum(x.scaling).poisson_ratio).margin(x.band));
  }
  CHECK(std::abs(calibrated_continuum(StiffnessScaling::voronoi_facet).poisson_ratio - 0.25) <= 0.02);  // the target
  CHECK(std::abs(calibrated_continuum(StiffnessScaling::uniform).poisson_ratio - 0.25) > 0.02);  // documents the miss
}

TEST_CASE("calibrate_beams at the default spec reproduces the stored constants", "[lattice2d][slow]") {
  const Calibration c = calibrate_beams(CalibrationSpec{});
  INFO(c.message);
  const BeamParameters stored = calibrated_beam_parameters();
  // Deterministic lattices and solves: equal up to the solves' round-off (and the regula falsi's
  // stopping point, which round-off could move by one step: 1e-9 on a).
  CHECK(c.beams.normal_stiffness == Approx(stored.normal_stiffness).epsilon(1e-9));
  CHECK(c.beams.aspect == Approx(stored.aspect).epsilon(1e-9));
  CHECK(c.beams.beam_poisson == stored.beam_poisson);
  CHECK(c.beams.stiffness_scaling == stored.stiffness_scaling);
  CHECK(c.target_poisson_reached);
}

TEST_CASE("E does not depend on the point density (N = 2.5e3 and 1e4, 3 seeds)", "[lattice2d][slow]") {
  // Per-beam k_n: sigma ~ k_n eps L / L, independent of the spacing. Measured means 1.0059 (2.5e3),
  // 1.0000 (1e4), 0.9953 (4e4): a slow drift of ~0.5% per factor 4 in N. Tolerance 1.5%.
  auto mean_e = [](long long n) {
    double e = 0;
    for (std::uint64_t seed : {1, 2, 3})
      e += measure_elastic_properties(generate_lattice(calibration_rectangle(n, 2.0, seed)),
                                      calibrated_beam_parameters())
               .youngs_modulus /
           3;
    return e;
  };
  CHECK(mean_e(2500) == Approx(mean_e(10000)).epsilon(0.015));
}
