// Reading cases: defaults, unknown keys, malformed TOML, and SI input converted to the same
// dimensionless parameters as the equivalent dimensionless input.
#include <catch2/catch.hpp>

#include "approx.hpp"
#include "hm/analytic/biot_modulus.hpp"
#include "hm/case/case_file.hpp"
#include "hm/core/input_error.hpp"
#include "run_command.hpp"

using hm::cases::CaseFile;
using hm::cases::read_physics;
using hm::test::TempDir;

namespace {

hm::cases::CasePhysics physics_of(const TempDir& dir, const std::string& toml) {
  dir.write("case.toml", toml);
  CaseFile file(dir.path / "case.toml");
  auto root = file.root();
  auto physics = read_physics(root);
  root.reject_unknown();
  return physics;
}

std::string error_of(const TempDir& dir, const std::string& toml) {
  try {
    physics_of(dir, toml);
  } catch (const hm::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("An empty [physics] table gives the validated defaults, E/M by Eq. 22", "[verification][config]") {
  TempDir dir("case-defaults");
  const auto d = physics_of(dir, "[physics]\n").parameters;
  CHECK(d.Q == 0.01);
  CHECK(d.material.b == 0.5);
  CHECK(d.material.E_over_M == hm::test::roundoff(hm::analytic::E_over_M_table1(0.5, 0.25)));
  CHECK(d.R_i == 0.138);
}

TEST_CASE("E/M follows the case's own b when not given", "[verification][config]") {
  TempDir dir("case-eom");
  const auto d = physics_of(dir, "[physics]\nb = 0.2\n").parameters;
  CHECK(d.material.E_over_M == hm::test::roundoff(hm::analytic::E_over_M_table1(0.2, 0.25)));
}

TEST_CASE("Table 1 physical values give the same parameters as their dimensionless form", "[verification][config]") {
  TempDir dir("case-si");
  // Table 1 with k = 1e-14 m^2, q = 1e-3 m^2/s: Q = mu q/(k E) = 1e-6/1e-4 = 0.01, t_s = mu R^2/(k E) = 10 s.
  const auto si = physics_of(dir,
                             "[physics_si]\nE = 1e10\nnu = 0.25\nk = 1e-14\nk_f = 1e-11\nmu = 1e-3\n"
                             "q = 1e-3\nR = 1\nR_i = 0.138\nporosity = 1e-3\nK_w = 2.2e9\nb = 0.5\n"
                             "T_u = 2e6\nC_u = 3.33e7\nmu_i = 0.9\n");
  const auto dimless = physics_of(dir,
                                  "[physics]\nQ = 0.01\niota = 1000\nb = 0.5\nnu = 0.25\nR_i = 0.138\n"
                                  "tensile_strength = 2e-4\ncompressive_strength = 3.33e-3\nfriction = 0.9\n");
  const auto& a = si.parameters;
  const auto& b = dimless.parameters;
  CHECK(a.Q == hm::test::roundoff(b.Q));
  CHECK(a.iota == hm::test::roundoff(b.iota));
  CHECK(a.material.E_over_M == hm::test::roundoff(b.material.E_over_M));
  CHECK(a.tensile_strength == hm::test::roundoff(b.tensile_strength));
  CHECK(a.compressive_strength == hm::test::roundoff(b.compressive_strength));
  CHECK(a.R_i == hm::test::roundoff(b.R_i));
  REQUIRE(si.scales);
  CHECK(si.scales->time_s == hm::test::roundoff(10.0));
}

TEST_CASE("Case errors name the file, the table, the key, the value and the rule", "[verification][config]") {
  TempDir dir("case-errors");
  const std::string file = (dir.path / "case.toml").string();
  SECTION("unknown key") {
    CHECK_THAT(error_of(dir, "[physics]\nQ = 0.01\nbiot = 0.5\n"),
               Catch::StartsWith(file + ": [physics] unknown key 'biot', allowed: ") && Catch::Contains("b, "));
  }
  SECTION("unknown table") {
    CHECK_THAT(error_of(dir, "[physics]\n[phisics]\nQ = 1\n"), Catch::StartsWith(file + ": unknown key 'phisics'"));
  }
  SECTION("out of range") {
    CHECK(error_of(dir, "[physics]\nb = 1.5\n") == file + ": [physics] b = 1.5, allowed: 0 <= b <= 1");
    CHECK(error_of(dir, "[physics]\nnu = 0.5\n") == file + ": [physics] nu = 0.5, allowed: 0 < nu < 0.5");
    CHECK(error_of(dir, "[physics]\nR_i = 1\n") == file + ": [physics] R_i = 1, allowed: 0 <= R_i < 1");
    CHECK(error_of(dir, "[physics_si]\nk = 0\n") == file + ": [physics_si] k = 0, allowed: k > 0");
    CHECK(error_of(dir, "[physics_si]\nR_i = 2\nR = 1\n") == file + ": [physics_si] R_i = 2, allowed: 0 <= R_i < 1");
  }
  SECTION("wrong type") {
    CHECK(error_of(dir, "[physics]\nQ = \"high\"\n") == file + ": [physics] Q = \"high\", allowed: a finite number");
  }
  SECTION("an integer beyond 64 bits is invalid TOML, not the nearest limit") {
    CHECK(error_of(dir, "[physics]\nQ = 9223372036854775808\n") ==
          file + ": [physics] Q = 9223372036854775808, allowed: an integer within 64 bits (-2^63 ... 2^63 - 1)");
    CHECK(error_of(dir, "[physics]\nQ = -9_223_372_036_854_775_809\n") ==
          file + ": [physics] Q = -9_223_372_036_854_775_809, allowed: an integer within 64 bits (-2^63 ... 2^63 - 1)");
    // The limit itself is an integer: refused only by Q's own rule.
    CHECK(error_of(dir, "[physics]\nQ = 9223372036854775807\n") ==
          file + ": [physics] Q = 9223372036854775808, allowed: 0 <= Q <= 1e+06");
  }
  SECTION("nan and inf are numbers to TOML, never a case's value") {
    CHECK(error_of(dir, "[physics]\nQ = nan\n") == file + ": [physics] Q = nan, allowed: a finite number");
    CHECK(error_of(dir, "[physics]\nb = -inf\n") == file + ": [physics] b = -inf, allowed: a finite number");
    CHECK(error_of(dir, "[physics_si]\nq = +inf\n") == file + ": [physics_si] q = inf, allowed: a finite number");
  }
  SECTION("both physics tables") {
    CHECK(error_of(dir, "[physics]\n[physics_si]\n") ==
          file + ": both [physics] and [physics_si] given, allowed: exactly one of them");
  }
  SECTION("malformed TOML gives the line") {
    CHECK_THAT(error_of(dir, "[physics]\nQ = 0.01\nb = = 3\n"), Catch::StartsWith(file + ":3: malformed TOML: "));
  }
  SECTION("missing file") {
    CHECK_THROWS_WITH(CaseFile(dir.path / "nope.toml"), Catch::Contains("nope.toml: no such case file"));
  }
}
