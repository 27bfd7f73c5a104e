// hmlattice analytic insitu and breakdown --SH/--Sh as a user types them: printed values against the
// library, and bad input refused with one line, exit code 2 and nothing printed.
#include <catch2/catch.hpp>

#include <string>

#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/core/csv_writer.hpp"
#include "run_command.hpp"

using hm::core::csv_number;
using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::TempDir;

TEST_CASE("hmlattice analytic insitu prints the library values with r outer and theta inner", "[verification][cli]") {
  TempDir dir("cli-insitu");
  const auto r = run_hmlattice("analytic insitu --SH 3e-3 --Sh 1e-3 --pw 2e-3 --r 0.138,1 --theta 0,90", dir.path);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  const hm::analytic::InSituAnnulus sol({3e-3, 1e-3, 0.0}, 2e-3, 0.138, 0.25);
  const auto wall_H = sol.state(0.138, 0.0);
  // Row 2 is r = 0.138, theta = 0; the printed value is the library's in the CSV format (10 digits).
  const std::string row2 = "0.138,0," + csv_number(wall_H.sigma_r) + "," + csv_number(wall_H.sigma_theta) + "," +
                           csv_number(wall_H.sigma_rtheta) + "\n";
  CHECK(r.out.rfind("r,theta,sigma_r,sigma_theta,sigma_rtheta\n" + row2, 0) == 0);
  CHECK(count_lines(r.out) == 5);
}

TEST_CASE("hmlattice analytic breakdown --SH --Sh prints one row per b and formula", "[verification][cli]") {
  TempDir dir("cli-breakdown-insitu");
  const auto r = run_hmlattice("analytic breakdown --b 1,0.5 --SH 3e-3 --Sh 2e-3", dir.path);
  REQUIRE(r.exit_code == 0);
  // Hubbert-Willis by hand at b = 1: 3 S_h - S_H + T_u = 6e-3 - 3e-3 + 2e-4 = 3.2e-3 (p0 = 0: b drops out).
  const hm::analytic::FarFieldStress far{3e-3, 2e-3, 0.0};
  hm::analytic::BreakdownParameters m;
  std::string expected = "formula,b,p_b,theta_deg\n";
  for (double b : {1.0, 0.5}) {
    m.b = b;
    expected += "hubbert_willis," + csv_number(b) +
                ",0.0032,0\n"
                "haimson_fairhurst," +
                csv_number(b) + "," + csv_number(hm::analytic::haimson_fairhurst_breakdown(far, m).p_w) +
                ",0\nannulus_jacketed," + csv_number(b) + "," +
                csv_number(hm::analytic::annulus_jacketed_breakdown(far, m, 0.138).p_w) + ",0\n";
  }
  CHECK(r.out == expected);
}

TEST_CASE("Bad in-situ input is refused with one line and nothing printed", "[verification][cli]") {
  TempDir dir("cli-insitu-bad");
  const auto refused = [&](const std::string& args, const std::string& must_mention) {
    const auto r = run_hmlattice(args, dir.path);
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find(must_mention) != std::string::npos);
    CHECK(r.out.empty());
  };
  refused("analytic insitu --SH 1e-3 --Sh 2e-3 --r 0.5 --theta 0", "S_h = 0.002, allowed: 0 <= S_h <= S_H (0.001)");
  refused("analytic insitu --SH 3e-3 --Sh 1e-3 --r 0.5,0.1 --theta 0", "r = 0.1, allowed: 0.138 <= r <= 1");
  refused("analytic breakdown --SH 3e-3 --Sh 2e-3 --b 1.5", "b = 1.5, allowed: 0 <= b <= 1");
  refused("analytic breakdown --b 1 --SH 1e308 --Sh 1e308",
          "p_b = inf for formula = hubbert_willis: the inputs overflow double precision");
  refused("analytic breakdown --b 1 --SH 3e-3", "--SH requires --Sh");
  refused("analytic breakdown --b 1 --SH 1e-3 --Sh 2e-3", "S_h = 0.002, allowed: 0 <= S_h <= S_H (0.001)");
  CHECK(dir.is_empty());
}
