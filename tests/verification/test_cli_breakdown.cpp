// hmlattice analytic breakdown as a user types it: one row per b with the library's four values in
// the CSV format, Table 1's defaults, and bad input refused with one line, exit code 2, nothing printed.
#include <catch2/catch.hpp>

#include <string>

#include "hm/analytic/breakdown_limits.hpp"
#include "hm/analytic/physical_parameters.hpp"
#include "hm/core/csv_writer.hpp"
#include "run_command.hpp"

using hm::core::csv_number;
using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::TempDir;

namespace {

std::string row_of(double b, const hm::analytic::DimensionlessParameters& d) {
  const auto l = hm::analytic::breakdown_limits(d);
  return csv_number(b) + "," + csv_number(l.q_min) + "," + csv_number(l.p_b_slow) + "," + csv_number(l.p_b_fast) + "," +
         csv_number(l.p_b_jacketed) + "\n";
}

}  // namespace

TEST_CASE("hmlattice analytic breakdown prints q_min and the three breakdown pressures per b", "[verification][cli]") {
  TempDir dir("cli-breakdown");
  const auto r = run_hmlattice("analytic breakdown --b 0.2,0.5,0.8", dir.path);
  INFO("stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  // Defaults: Table 1's nu = 0.25, R_i = 0.138, T_u/E = 2e-4, and E/M by Eq. 22 per b.
  std::string expected = "b,q_min,p_b_slow,p_b_fast,p_b_jacketed\n";
  for (const double b : {0.2, 0.5, 0.8}) expected += row_of(b, hm::analytic::table1_borehole(b));
  CHECK(r.out == expected);
  // The options reach the library.
  const auto other = run_hmlattice("analytic breakdown --b 0.5 --nu 0.3 --Ri 0.2 --Tu 1e-4", dir.path);
  REQUIRE(other.exit_code == 0);
  auto d = hm::analytic::table1_borehole(0.5);
  d.material.nu = 0.3;
  d.material.E_over_M = hm::analytic::E_over_M_table1(0.5, 0.3);
  d.R_i = 0.2;
  d.tensile_strength = 1e-4;
  CHECK(other.out == "b,q_min,p_b_slow,p_b_fast,p_b_jacketed\n" + row_of(0.5, d));
}

TEST_CASE("Bad breakdown input is refused with one line and nothing printed", "[verification][cli]") {
  TempDir dir("cli-breakdown-bad");
  const auto refused = [&](const std::string& args, const std::string& must_mention) {
    const auto r = run_hmlattice(args, dir.path);
    INFO("args: " << args << "\nstderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find(must_mention) != std::string::npos);
    CHECK(r.out.empty());
  };
  refused("analytic breakdown --b 0.2,1.5", "b = 1.5, allowed: 0 <= b <= 1");
  refused("analytic breakdown --b -0.1", "b = -0.1, allowed: 0 <= b <= 1");
  refused("analytic breakdown --b 0.2,x", "--b");
  refused("analytic breakdown --b nan", "b = nan");
  refused("analytic breakdown", "--b");
  refused("analytic breakdown --b 0.5 --nu 0.5", "nu = 0.5, allowed: 0 < nu < 0.5");
  refused("analytic breakdown --b 0.5 --Ri 0", "Ri = 0, allowed: 0 < Ri < 1");
  refused("analytic breakdown --b 0.5 --Ri 1", "Ri = 1, allowed: 0 < Ri < 1");
  refused("analytic breakdown --b 0.5 --Tu 0", "Tu = 0, allowed: Tu > 0");
  CHECK(dir.is_empty());
}
