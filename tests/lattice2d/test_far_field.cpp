#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Dense>

#include "hm/analytic/insitu_annulus.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/lattice2d/mechanics/far_field.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::make_lattice;

namespace {

constexpr double degree = std::numbers::pi / 180.0;

Lattice borehole(long long n, std::uint64_t seed = 1) {
  LatticeSpec spec = hm::test::spec_of(DomainShape::annulus, n, seed);
  spec.inner_radius = 0.138;
  return generate_lattice(spec);
}

// Sum of the nodal forces and of their moments about the origin.
Eigen::Vector3d resultant(const Lattice& l, const Eigen::VectorXd& f) {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int i = 0; i < l.n_particles(); ++i) {
    const Eigen::Vector2d x = l.points.col(i), fi = f.segment<2>(dof_index(i, 0));
    r += Eigen::Vector3d(fi.x(), fi.y(), x.x() * fi.y() - x.y() * fi.x() + f[dof_index(i, 2)]);
  }
  return r;
}

// The dry lattice under the far field against InSituAnnulus with the calibrated E and nu.
DisplacementError far_field_error(const Lattice& l, const hm::analytic::FarFieldStress& far) {
  BoundaryConditions bc;
  bc.outer_stress = far_field_tensor(far);
  BeamMechanics m(l, calibrated_beam_parameters(), bc);
  REQUIRE(m.solve().is_converged());
  const ElasticConstants cal = calibrated_continuum();
  const hm::analytic::InSituAnnulus exact(far, 0.0, l.spec.inner_radius, cal.poisson_ratio);
  return displacement_error(l, m.displacement(), annulus_displacement(l, exact, cal.youngs_modulus));
}

}  // namespace

TEST_CASE("The far-field tensor has -S_H along theta_H and -S_h across it", "[lattice2d]") {
  const hm::analytic::FarFieldStress far{3e-4, 1e-4, 30 * degree};
  const Eigen::Matrix2d s = far_field_tensor(far);
  const Eigen::Vector2d e_H(std::cos(30 * degree), std::sin(30 * degree)), e_h(-e_H.y(), e_H.x());
  CHECK((s * e_H + 3e-4 * e_H).norm() < 1e-19);  // round-off of products of O(1e-4)
  CHECK((s * e_h + 1e-4 * e_h).norm() < 1e-19);
  CHECK(s(0, 1) == s(1, 0));
}

TEST_CASE("An outer stress loads the boundary with its own traction", "[lattice2d]") {
  const Lattice l = borehole(2000);
  SECTION("any constant tensor: self-equilibrated, so a free lattice needs no support") {
    BoundaryConditions bc;
    bc.outer_stress << -3e-4, 1e-4, 1e-4, -2e-4;
    BeamMechanics m(l, calibrated_beam_parameters(), bc);
    const Eigen::Vector3d r = resultant(l, m.loads());
    // The polygon's closed sum of L m vanishes, and lumping half to each end is the segment's exact
    // force and moment: what is left is round-off over ~200 segments of O(3e-4 L).
    CHECK(r.cwiseAbs().maxCoeff() < 1e-15 * m.loads().cwiseAbs().maxCoeff() * 200);
    CHECK(m.loads().cwiseAbs().maxCoeff() > 0.0);
  }
  SECTION("-P I is an outer pressure P") {
    BoundaryConditions by_stress, by_pressure;
    by_stress.outer_stress = -2e-4 * Eigen::Matrix2d::Identity();
    by_pressure.outer_pressure = 2e-4;
    const BeamMechanics a(l, calibrated_beam_parameters(), by_stress), b(l, calibrated_beam_parameters(), by_pressure);
    CHECK((a.loads() - b.loads()).cwiseAbs().maxCoeff() < 1e-15 * b.loads().cwiseAbs().maxCoeff());
  }
  SECTION("zero: the loads of no outer stress, bit for bit") {
    BoundaryConditions zero, pressure_only;
    zero.outer_stress = Eigen::Matrix2d::Zero();
    zero.inner_pressure = pressure_only.inner_pressure = 1e-4;
    const BeamMechanics a(l, calibrated_beam_parameters(), zero), b(l, calibrated_beam_parameters(), pressure_only);
    CHECK(a.loads() == b.loads());
    CHECK(zero.is_unloaded() == false);
    CHECK(BoundaryConditions{}.is_unloaded());
  }
}

TEST_CASE("Bad outer stresses are rejected naming the field", "[lattice2d]") {
  const Lattice l = borehole(1000);
  BoundaryConditions bc;
  SECTION("not symmetric") {
    bc.outer_stress << -1e-4, 1e-5, 0.0, -1e-4;
    REQUIRE_THROWS_WITH(bc.validate(l),
                        "boundary_conditions.outer_stress(0,1) = 1e-05, allowed: equal to "
                        "outer_stress(1,0) = 0");
  }
  SECTION("not finite") {
    bc.outer_stress(1, 1) = std::nan("");
    REQUIRE_THROWS_AS(bc.validate(l), hm::InputError);
  }
  SECTION("on a held boundary") {
    bc.outer = BoundarySupport::fixed;
    bc.outer_stress(0, 0) = -1e-4;
    REQUIRE_THROWS_WITH(bc.validate(l),
                        "boundary_conditions.outer_stress = (-1e-04, 0, 0), allowed: 0 unless outer "
                        "= 'free' (a held boundary takes no traction)");
  }
  SECTION("far field: S_h > S_H, negative p0, b outside [0, 1]") {
    REQUIRE_THROWS_AS(add_far_field_loads({1e-4, 2e-4, 0.0}, 0.0, 0.5, DomainShape::annulus, bc), hm::InputError);
    REQUIRE_THROWS_WITH(add_far_field_loads({2e-4, 1e-4, 0.0}, -1e-5, 0.5, DomainShape::annulus, bc),
                        "p0 = -1e-05, allowed: >= 0 (compression positive)");
    REQUIRE_THROWS_WITH(add_far_field_loads({2e-4, 1e-4, 0.0}, 0.0, 1.5, DomainShape::annulus, bc),
                        "b = 1.5, allowed: 0 <= b <= 1");
  }
}

TEST_CASE("At rest the beams carry the effective far field: -S + b p0 outside, (1 - b) p0 on the wall", "[lattice2d]") {
  BoundaryConditions bc;
  add_far_field_loads({3e-4, 1e-4, 0.0}, 5e-5, 0.4, DomainShape::annulus, bc);
  CHECK(bc.outer_stress(0, 0) == Approx(-3e-4 + 0.4 * 5e-5).epsilon(1e-15));
  CHECK(bc.outer_stress(1, 1) == Approx(-1e-4 + 0.4 * 5e-5).epsilon(1e-15));
  CHECK(bc.inner_pressure == Approx(0.6 * 5e-5).epsilon(1e-15));
  BoundaryConditions disk;
  add_far_field_loads({3e-4, 1e-4, 0.0}, 5e-5, 0.4, DomainShape::disk, disk);
  CHECK(disk.inner_pressure == 0.0);
}

TEST_CASE("A free annulus under an anisotropic far field converges to the finite-annulus solution", "[lattice2d]") {
  // S_H = 3 S_h at 30 degrees: the n = 2 (Michell) part is as large as the Lame part.
  const hm::analytic::FarFieldStress far{3e-4, 1e-4, 30 * degree};
  const DisplacementError coarse = far_field_error(borehole(2500), far), fine = far_field_error(borehole(10000), far);
  INFO("N = 2500: rms " << coarse.rms << ", max " << coarse.max << "; N = 1e4: rms " << fine.rms << ", max "
                        << fine.max);
  // Measured (seed 1): rms 2.04% / 0.73%, max 5.2% / 2.6% of max |u| at N = 2500 / 1e4, largest at
  // the wall like the Lame benchmark's (docs/lattice.md: the wall row is a boundary layer of O(h)).
  // Bounds: the N = 1e4 values with a margin of 1.5; and the error must fall with the spacing at
  // least like first order (h ~ N^-1/2 halves from 2500 to 1e4: a factor 2; measured 2.8; 1.5 asked).
  CHECK(fine.rms < 0.011);
  CHECK(fine.max < 0.04);
  CHECK(coarse.rms > 1.5 * fine.rms);
}
