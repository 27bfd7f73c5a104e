// Parameter types: the Table 1 -> dimensionless conversion, validation messages, vol_strain parsing,
// and the Biot-modulus numbers quoted in docs/errata.md (E5, E6).
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>

#include "approx.hpp"
#include "hm/analytic/biot_modulus.hpp"
#include "hm/analytic/physical_parameters.hpp"
#include "hm/analytic/poroelastic_parameters.hpp"
#include "hm/core/input_error.hpp"

using namespace hm::analytic;
using hm::test::roundoff;

TEST_CASE("Table 1 converts to the paper's dimensionless numbers", "[analytic]") {
  const PhysicalParameters phys;  // Table 1: E 1e10, k = k_f 1e-14, mu 1e-3, q 1e-3, R 1, b 0.5, ...
  const auto d = to_dimensionless(phys);
  // Hand computation: Q = mu q/(k E) = 1e-3 * 1e-3 / (1e-14 * 1e10) = 1e-6 / 1e-4 = 0.01.
  CHECK(d.Q == roundoff(0.01));
  CHECK(d.iota == roundoff(1.0));  // k_f/k
  // Eq. 22: E/M = Phi E/K_w + 3 (b - Phi)(1 - Phi)(1 - 2nu) = 1e-3*1e10/2.2e9 + 3*0.499*0.999*0.5
  //            = 0.00454545... + 0.7477515 = 0.75229695454...
  CHECK(d.material.E_over_M == roundoff(1e-3 * 1e10 / 2.2e9 + 3.0 * 0.499 * 0.999 * 0.5));
  CHECK(d.material.E_over_M == Approx(0.7522969545).epsilon(1e-10));  // 10 digits written above
  CHECK(d.material.b == 0.5);
  CHECK(d.material.nu == 0.25);
  CHECK(d.material.vol_strain == VolStrain::plane_strain);
  CHECK(d.R_i == roundoff(0.138));
  CHECK(d.tensile_strength == roundoff(2e-4));         // 2e6 / 1e10
  CHECK(d.compressive_strength == roundoff(3.33e-3));  // 3.33e7 / 1e10
  CHECK(d.friction == 0.9);

  const auto sc = scales_of(phys);
  CHECK(sc.length_m == 1.0);
  CHECK(sc.stress_pa == 1e10);
  CHECK(sc.time_s == roundoff(10.0));  // t_s = mu R^2/(k E) = 1e-3 / (1e-14 * 1e10) = 10 s

  SECTION("the vol_strain choice passes through") {
    CHECK(to_dimensionless(phys, VolStrain::appendix_a).material.vol_strain == VolStrain::appendix_a);
  }
}

TEST_CASE("The dimensionless defaults are Table 1 converted", "[analytic]") {
  const auto d = to_dimensionless(PhysicalParameters{});
  const DimensionlessParameters def;
  CHECK(def.Q == roundoff(d.Q));
  CHECK(def.iota == roundoff(d.iota));
  CHECK(def.R_i == roundoff(d.R_i));
  CHECK(def.tensile_strength == roundoff(d.tensile_strength));
  CHECK(def.compressive_strength == roundoff(d.compressive_strength));
  CHECK(def.friction == d.friction);
  CHECK(def.material.E_over_M == roundoff(d.material.E_over_M));
  CHECK(def.material.b == d.material.b);
  CHECK(def.material.nu == d.material.nu);
}

TEST_CASE("Scaled and unscaled inputs give the same dimensionless case", "[analytic]") {
  // Double R and R_i, multiply k and k_f by 10 and q by 10: R_i/R, Q and iota are unchanged;
  // t_s = mu R^2/(k E) scales by 4/10.
  PhysicalParameters a, b;
  b.R_si = 2.0;
  b.R_i_si = 0.276;
  b.k_si = 1e-13;
  b.k_f_si = 1e-13;
  b.q_si = 1e-2;
  const auto da = to_dimensionless(a), db = to_dimensionless(b);
  CHECK(db.R_i == roundoff(da.R_i));
  CHECK(db.Q == roundoff(da.Q));
  CHECK(db.iota == roundoff(da.iota));
  CHECK(scales_of(b).time_s == roundoff(scales_of(a).time_s * 0.4));
  SECTION("iota is k_f/k") {
    b.k_f_si = 1e-11;
    CHECK(to_dimensionless(b).iota == roundoff(100.0));
  }
  SECTION("non-default strengths, friction, nu and b are carried over, strengths over E") {
    b.E_si = 2e10;
    b.T_u_si = 3e6;
    b.C_u_si = 5e7;
    b.mu_i = 0.6;
    b.nu = 0.3;
    b.b = 0.8;
    const auto d = to_dimensionless(b);
    CHECK(d.tensile_strength == roundoff(1.5e-4));
    CHECK(d.compressive_strength == roundoff(2.5e-3));
    CHECK(d.friction == 0.6);
    CHECK(d.material.nu == 0.3);
    CHECK(d.material.b == 0.8);
    // Eq. 22 with E/K_w = 2e10/2.2e9: 1e-3 * 9.0909 + 3 * 0.799 * 0.999 * 0.4.
    CHECK(d.material.E_over_M == roundoff(1e-3 * 2e10 / 2.2e9 + 3.0 * 0.799 * 0.999 * 0.4));
    CHECK(d.Q == roundoff(0.01 * 0.5));  // Q = mu q/(k E) halves when E doubles
  }
}

TEST_CASE("Default parameters are valid", "[analytic]") {
  CHECK_NOTHROW(PhysicalParameters{}.validate());
  CHECK_NOTHROW(DimensionlessParameters{}.validate());
  CHECK_NOTHROW(PoroelasticParameters{}.validate());
}

namespace {
// The exact message: field, value and rule (the Ceres IsValid style).
void check_rejected_physical(const std::function<void(PhysicalParameters&)>& set, const std::string& message) {
  PhysicalParameters p;
  set(p);
  CHECK_THROWS_AS(p.validate(), hm::InputError);
  CHECK_THROWS_WITH(p.validate(), message);
  CHECK_THROWS_WITH(to_dimensionless(p), message);  // the conversion validates first
}
void check_rejected_dimensionless(const std::function<void(DimensionlessParameters&)>& set,
                                  const std::string& message) {
  DimensionlessParameters d;
  set(d);
  CHECK_THROWS_AS(d.validate(), hm::InputError);
  CHECK_THROWS_WITH(d.validate(), message);
}
}  // namespace

TEST_CASE("Physical parameters: each rule rejects its bad value with field, value and rule", "[analytic]") {
  using P = PhysicalParameters;
  check_rejected_physical([](P& p) { p.E_si = 0.0; }, "E = 0, allowed: E > 0");
  check_rejected_physical([](P& p) { p.nu = 0.5; }, "nu = 0.5, allowed: 0 < nu < 0.5");
  check_rejected_physical([](P& p) { p.nu = 0.0; }, "nu = 0, allowed: 0 < nu < 0.5");
  check_rejected_physical([](P& p) { p.k_si = -1e-14; }, "k = -1e-14, allowed: k > 0");
  check_rejected_physical([](P& p) { p.k_f_si = 0.0; }, "k_f = 0, allowed: k_f > 0");
  check_rejected_physical(
      [](P& p) { p.k_f_si = 1e-16; },
      "k_f = 1e-16, allowed: k_f >= k = 1e-14 (an open crack conducts at least as the rock it cuts)");
  check_rejected_physical([](P& p) { p.mu_si = 0.0; }, "mu = 0, allowed: mu > 0");
  check_rejected_physical([](P& p) { p.q_si = -1e-3; }, "q = -0.001, allowed: q >= 0");
  check_rejected_physical([](P& p) { p.R_si = 0.0; }, "R = 0, allowed: R > 0");
  check_rejected_physical([](P& p) { p.R_i_si = 1.0; }, "R_i = 1, allowed: 0 <= R_i < 1");
  check_rejected_physical([](P& p) { p.R_i_si = -0.1; }, "R_i = -0.1, allowed: 0 <= R_i < 1");
  check_rejected_physical([](P& p) { p.porosity = 1.0; }, "porosity = 1, allowed: 0 < porosity < 1");
  check_rejected_physical([](P& p) { p.K_w_si = 0.0; }, "K_w = 0, allowed: K_w > 0");
  check_rejected_physical([](P& p) { p.b = 1.5; }, "b = 1.5, allowed: 0 <= b <= 1");
  check_rejected_physical([](P& p) { p.b = -0.1; }, "b = -0.1, allowed: 0 <= b <= 1");
  check_rejected_physical([](P& p) { p.T_u_si = 0.0; }, "T_u = 0, allowed: T_u > 0");
  check_rejected_physical([](P& p) { p.C_u_si = -1.0; }, "C_u = -1, allowed: C_u > 0");
  check_rejected_physical([](P& p) { p.mu_i = -0.1; }, "mu_i = -0.1, allowed: mu_i >= 0");
  check_rejected_physical([](P& p) { p.E_si = std::nan(""); }, "E = nan, allowed: E > 0");
  // Eq. 22 with a stiff fluid and b < porosity: E/M = 0.1*0.01 + 3(0 - 0.1)(0.9)(0.5) = -0.134 < 0.
  check_rejected_physical(
      [](P& p) {
        p.K_w_si = 1e12;
        p.porosity = 0.1;
        p.b = 0.0;
      },
      "b = 0, allowed: b large enough that Eq. 22 gives M > 0 (porosity = 0.1)");
}

TEST_CASE("Dimensionless parameters: each rule rejects its bad value with field, value and rule", "[analytic]") {
  using D = DimensionlessParameters;
  check_rejected_dimensionless([](D& d) { d.material.nu = 0.5; }, "nu = 0.5, allowed: 0 < nu < 0.5");
  check_rejected_dimensionless([](D& d) { d.material.b = 1.01; }, "b = 1.01, allowed: 0 <= b <= 1");
  check_rejected_dimensionless([](D& d) { d.material.E_over_M = 0.0; }, "E_over_M = 0, allowed: E_over_M > 0");
  check_rejected_dimensionless([](D& d) { d.Q = -0.01; }, "Q = -0.01, allowed: 0 <= Q <= 1e+06");
  check_rejected_dimensionless([](D& d) { d.iota = 0.0; }, "iota = 0, allowed: 1 <= iota <= 1e+12");
  check_rejected_dimensionless([](D& d) { d.iota = 0.999; }, "iota = 0.999, allowed: 1 <= iota <= 1e+12");
  check_rejected_dimensionless([](D& d) { d.iota = 1e13; }, "iota = 1e+13, allowed: 1 <= iota <= 1e+12");
  check_rejected_dimensionless([](D& d) { d.R_i = 1.0; }, "R_i = 1, allowed: 0 <= R_i < 1");
  check_rejected_dimensionless([](D& d) { d.tensile_strength = 0.0; },
                               "tensile_strength = 0, allowed: 0 < tensile_strength <= 1 (over E, a strain at failure; "
                               "a strength in Pa belongs in a case in SI units)");
  check_rejected_dimensionless(
      [](D& d) { d.compressive_strength = -1e-3; },
      "compressive_strength = -0.001, allowed: 0 < compressive_strength <= 1 (over E, a strain "
      "at failure; a strength in Pa belongs in a case in SI units)");
  // A strength in Pa typed into the dimensionless table once ran silently without a break.
  check_rejected_dimensionless([](D& d) { d.tensile_strength = 2e6; },
                               "tensile_strength = 2e+06, allowed: 0 < tensile_strength <= 1 (over E, a strain at "
                               "failure; a strength in Pa belongs in a case in SI units)");
  check_rejected_dimensionless([](D& d) { d.friction = -1.0; }, "friction = -1, allowed: friction >= 0");
  SECTION("point injection, R_i = 0, is allowed") {
    D d;
    d.R_i = 0.0;
    CHECK_NOTHROW(d.validate());
  }
}

TEST_CASE("VolStrain's names are the case files' spellings", "[analytic]") {
  CHECK(hm::core::from_name<VolStrain>("appendix-a", "vol_strain") == VolStrain::appendix_a);
  CHECK_THROWS_WITH(hm::core::from_name<VolStrain>("plane_strain", "material.vol_strain"),
                    "material.vol_strain = 'plane_strain', allowed: plane-strain, appendix-a");
  // Eq. A5's 1/3 versus the plane-strain trace (docs/errata.md E6).
  CHECK(vol_strain_factor(VolStrain::plane_strain) == 1.0);
  CHECK(vol_strain_factor(VolStrain::appendix_a) == roundoff(1.0 / 3.0));
}

TEST_CASE("Eq. 22 and the textbook Biot modulus give the Table 1 numbers of docs/errata.md", "[analytic]") {
  // E5: E/M = Phi E/K_w + 3 (b - Phi)(1 - X)(1 - 2nu), X = Phi (Eq. 22) or b (textbook).
  // Hand values with Phi E/K_w = 1e-3 * 1e10/2.2e9 = 0.004545454...; 6 decimals as in errata.md.
  const double nu = 0.25;
  struct Row {
    double b, eq22, standard, S_eq22, S_standard;
  };
  // S = E/M + b^2 (1+nu)(1-2nu)/(1-nu) = E/M + b^2 * 0.833333 (plane strain).
  for (const Row& row :
       {Row{0.2, 0.302747, 0.243345, 0.336080, 0.276679}, Row{0.5, 0.752297, 0.378795, 0.960630, 0.587129},
        Row{0.8, 1.201847, 0.244245, 1.735180, 0.777579}}) {
    CAPTURE(row.b);
    const double eq22 = E_over_M_eq22(row.b, nu, table1_porosity, table1_E_over_Kw);
    const double standard = E_over_M_standard(row.b, nu, table1_porosity, table1_E_over_Kw);
    // 5e-7 absolute: the table is rounded to 6 decimals.
    CHECK(eq22 == Approx(row.eq22).margin(5e-7));
    CHECK(standard == Approx(row.standard).margin(5e-7));
    CHECK(E_over_M_table1(row.b, nu) == roundoff(eq22));
    PoroelasticParameters m;
    m.b = row.b;
    m.E_over_M = eq22;
    CHECK(storage_coefficient(m) == Approx(row.S_eq22).margin(5e-7));
    m.E_over_M = standard;
    CHECK(storage_coefficient(m) == Approx(row.S_standard).margin(5e-7));
  }
  // E6: with Eq. 22 at b = 0.5, Eq. A5's 1/3 lowers S from 0.960630 to 0.821741.
  PoroelasticParameters m;
  m.vol_strain = VolStrain::appendix_a;
  CHECK(storage_coefficient(m) == Approx(0.821741).margin(5e-7));
  // The two relations agree where they should: b = Phi (no solid term) ...
  CHECK(E_over_M_eq22(1e-3, nu, 1e-3, 4.5) == roundoff(E_over_M_standard(1e-3, nu, 1e-3, 4.5)));
  // ... and at b = 1 only the textbook one reduces to the fluid term Phi E/K_w.
  CHECK(E_over_M_standard(1.0, nu, 1e-3, 4.5) == roundoff(1e-3 * 4.5));
  CHECK(E_over_M_eq22(1.0, nu, 1e-3, 4.5) > 1.0);
}

TEST_CASE("The Table 1 borehole case takes E/M from Eq. 22 at its own b", "[analytic]") {
  const auto d = hm::analytic::table1_borehole(0.2, 0.05, hm::analytic::VolStrain::appendix_a);
  CHECK(d.Q == 0.05);
  CHECK(d.material.b == 0.2);
  CHECK(d.material.nu == 0.25);
  CHECK(d.R_i == 0.138);
  CHECK(d.material.vol_strain == hm::analytic::VolStrain::appendix_a);
  // Eq. 22 by hand: 1e-3 * 1e10/2.2e9 + 3 (0.2 - 1e-3)(1 - 1e-3)(1 - 0.5) = 4.5454545e-3 + 0.2982015 = 0.3027469545.
  CHECK(d.material.E_over_M == Approx(0.3027469545454545).epsilon(1e-12));  // round-off
  CHECK_NOTHROW(d.validate());
}
