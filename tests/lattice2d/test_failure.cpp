#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "approx.hpp"
#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/io/break_log.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;

namespace {

// Hand-made beam stresses: only sigma_1, sigma_3 (and the crack-tip factor, for the log) enter.
BeamStress stresses(const std::vector<std::pair<double, double>>& s13) {
  const int n = static_cast<int>(s13.size());
  BeamStress s{Eigen::Matrix3Xd::Zero(3, n), Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd::Ones(n)};
  for (int e = 0; e < n; ++e) {
    s.sigma_1[e] = s13[static_cast<std::size_t>(e)].first;
    s.sigma_3[e] = s13[static_cast<std::size_t>(e)].second;
  }
  return s;
}

BeamStrengths constant_strengths(int n, double t_u, double c_u, double friction = 0.9) {
  return {Eigen::VectorXd::Constant(n, t_u), Eigen::VectorXd::Constant(n, c_u), friction};
}

constexpr double T = 2e-4, C = 3.33e-3;  // Table 1 over E
// Eq. 11 with mu_i = 0.9: K = [(1 + 0.81)^(1/2) + 0.9]^2 = 5.0417.
const double K09 = std::pow(std::sqrt(1.81) + 0.9, 2);

}  // namespace

TEST_CASE("Break selection picks the beam most over its threshold, with its mode", "[lattice2d]") {
  // Beam 0: 0.5 T_u, safe. Beam 1: sigma_1 = 1.5 T_u -> tensile, ratio 1.5 (Coulomb only 0.45).
  // Beam 2: sigma_1 = 0.5 T_u, sigma_3 = K sigma_1 - 1.3 C_u -> shear, ratio 1.3 (tensile 0.5).
  // Beam 3: confined, sigma_1 = -0.05 C_u, sigma_3 = -1.2 C_u: |sigma_3| > C_u but Eq. 11 gives
  //         sigma_CC = (1.2 - 0.05 K) C_u = 0.948 C_u, no failure (the confinement of Fig. 3).
  const BeamStress s =
      stresses({{0.5 * T, 0.0}, {1.5 * T, 0.0}, {0.5 * T, K09 * 0.5 * T - 1.3 * C}, {-0.05 * C, -1.2 * C}});
  const BeamStrengths strengths = constant_strengths(4, T, C);
  const FailureField field = evaluate_failure(s, strengths);
  CHECK(field.mode[0] == FailureMode::none);
  CHECK(field.ratio[0] == hm::test::roundoff(0.5));
  CHECK(field.mode[1] == FailureMode::tensile);
  CHECK(field.ratio[1] == hm::test::roundoff(1.5));
  CHECK(field.mode[2] == FailureMode::shear);
  CHECK(field.ratio[2] == hm::test::roundoff(1.3));
  CHECK(field.mode[3] == FailureMode::none);
  CHECK(field.ratio[3] == hm::test::roundoff(1.2 - 0.05 * K09));

  BreakCandidate pick = select_beam_to_break(s, strengths);
  CHECK(pick.found());
  CHECK(pick.beam == 1);
  CHECK(pick.mode == FailureMode::tensile);
  CHECK(pick.ratio == hm::test::roundoff(1.5));
  CHECK(pick.max_ratio == hm::test::roundoff(1.5));

  SECTION("a broken beam is never selected, however high its stress") {
    const std::vector<BeamState> states{BeamState::intact, BeamState::open, BeamState::intact, BeamState::intact};
    pick = select_beam_to_break(s, strengths, states);
    CHECK(pick.beam == 2);
    CHECK(pick.mode == FailureMode::shear);
    CHECK(pick.ratio == hm::test::roundoff(1.3));
    CHECK(evaluate_failure(s, strengths, states).ratio[1] == 0.0);
    const std::vector<BeamState> contact{BeamState::intact, BeamState::contact, BeamState::contact, BeamState::intact};
    pick = select_beam_to_break(s, strengths, contact);
    CHECK_FALSE(pick.found());
    CHECK(pick.max_ratio == hm::test::roundoff(1.2 - 0.05 * K09));
  }
  SECTION("per-beam strengths: a weaker beam can win at lower stress") {
    BeamStrengths weak = strengths;
    weak.compressive[2] = 0.8 * C;  // beam 2's Coulomb ratio becomes 1.3 / 0.8 = 1.625 > 1.5
    pick = select_beam_to_break(s, weak);
    CHECK(pick.beam == 2);
    CHECK(pick.ratio == hm::test::roundoff(1.3 / 0.8));
  }
  SECTION("friction enters through Eq. 11: mu_i = 0 gives sigma_CC = sigma_1 - sigma_3") {
    const BeamStrengths frictionless = constant_strengths(4, T, C, 0.0);
    CHECK(evaluate_failure(s, frictionless).ratio[3] == hm::test::roundoff(1.15));
    CHECK(evaluate_failure(s, frictionless).mode[3] == FailureMode::shear);
  }
}

TEST_CASE("Exactly at the threshold a beam fails, ties go to the lowest index, none when all are safe", "[lattice2d]") {
  const BeamStrengths strengths = constant_strengths(5, T, C);
  // Uniaxial compression at C_u (ratio 1 exactly: sigma_CC = -sigma_3) and two equal tensile ratios 1.2.
  const BeamStress s = stresses({{0.0, -C}, {0.3 * T, 0.0}, {1.2 * T, 0.0}, {0.0, 0.0}, {1.2 * T, 0.0}});
  const BreakCandidate pick = select_beam_to_break(s, strengths);
  CHECK(pick.beam == 2);
  CHECK(evaluate_failure(s, strengths).mode[0] == FailureMode::shear);
  CHECK(evaluate_failure(s, strengths).ratio[0] == hm::test::roundoff(1.0));
  const BreakCandidate only_threshold =
      select_beam_to_break(stresses({{0.0, -C}, {0.1 * T, 0.0}}), constant_strengths(2, T, C));
  CHECK(only_threshold.beam == 0);
  const BreakCandidate none =
      select_beam_to_break(stresses({{0.9 * T, 0.0}, {0.2 * T, -0.1 * C}}), constant_strengths(2, T, C));
  CHECK_FALSE(none.found());
  CHECK(none.beam == -1);
  CHECK(none.mode == FailureMode::none);
  CHECK(none.max_ratio == hm::test::roundoff(0.9));
  CHECK(hm::core::name_of(FailureMode::shear) == "shear");
}

TEST_CASE("Break events are logged with position and written as CSV", "[lattice2d]") {
  LatticeSpec spec;
  spec.domain = DomainShape::rectangle;
  spec.n_particles = 600;
  const Lattice lattice = generate_lattice(spec);
  std::vector<std::pair<double, double>> s13(static_cast<std::size_t>(lattice.n_beams()), {0.0, 0.0});
  s13[42] = {2.0 * T, -0.5 * T};
  BeamStress s = stresses(s13);
  s.crack_tip_factor[42] = 1.25;
  const BreakCandidate pick = select_beam_to_break(s, constant_strengths(lattice.n_beams(), T, C));
  REQUIRE(pick.beam == 42);
  const BreakEvent event = make_break_event(lattice, s, pick, 0.75, 3);
  const auto [i, j] = lattice.beams[42];
  CHECK(event.sequence == 3);
  CHECK(event.particle_i == i);
  CHECK(event.particle_j == j);
  CHECK((event.position - 0.5 * (lattice.points.col(i) + lattice.points.col(j))).norm() == 0.0);
  CHECK(event.load == 0.75);
  CHECK(event.sigma_1 == 2.0 * T);
  CHECK(event.sigma_3 == -0.5 * T);
  CHECK(event.crack_tip_factor == 1.25);
  CHECK(event.mode == FailureMode::tensile);

  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("hm-test-breaklog-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  BreakEvent second = event;
  second.sequence = 4;
  second.mode = FailureMode::shear;
  write_break_log(dir / "breaks.csv", {event, second}, "time");
  const std::vector<std::string> lines = hm::test::lines_of(dir / "breaks.csv");
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] == "sequence,beam,particle_i,particle_j,x,y,time,sigma_1,sigma_3,ratio,crack_tip_factor,mode");
  std::stringstream row(lines[1]);
  std::vector<std::string> cells;
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  REQUIRE(cells.size() == 12);
  CHECK(cells[0] == "3");
  CHECK(cells[1] == "42");
  CHECK(std::stod(cells[4]) == Approx(event.position.x()).epsilon(1e-9));  // 10 significant digits
  CHECK(std::stod(cells[6]) == 0.75);
  CHECK(std::stod(cells[7]) == Approx(2.0 * T).epsilon(1e-9));
  CHECK(cells[11] == "tensile");
  CHECK(lines[2].substr(lines[2].rfind(',') + 1) == "shear");
  CHECK_FALSE(std::filesystem::exists(dir / "breaks.csv.partial"));

  // Read back: the same events to the 10 written digits.
  const std::vector<BreakEvent> back = read_break_log(dir / "breaks.csv");
  REQUIRE(back.size() == 2);
  CHECK(back[0].sequence == 3);
  CHECK(back[0].beam == 42);
  CHECK(back[0].particle_i == i);
  CHECK(back[0].particle_j == j);
  CHECK((back[0].position - event.position).norm() <= 1e-9 * event.position.norm());
  CHECK(back[0].load == 0.75);
  CHECK(back[0].sigma_1 == Approx(2.0 * T).epsilon(1e-9));
  CHECK(back[0].crack_tip_factor == 1.25);
  CHECK(back[0].mode == FailureMode::tensile);
  CHECK(back[1].mode == FailureMode::shear);
  // A damaged log names the file and line.
  {
    std::ofstream(dir / "bad.csv") << lines[0] << "\n" << lines[1] << "\n3,42,1,2,0.5,x,0.1,1,1,1,1,tensile\n";
    CHECK_THROWS_WITH(read_break_log(dir / "bad.csv"), Catch::Contains("bad.csv:3: not a number"));
    std::ofstream(dir / "bad.csv") << "beam,mode\n";
    CHECK_THROWS_WITH(read_break_log(dir / "bad.csv"), Catch::Contains("bad.csv:1: header"));
    std::ofstream(dir / "bad.csv") << lines[0] << "\n" << lines[1].substr(0, lines[1].rfind(',')) << ",bent\n";
    CHECK_THROWS_WITH(read_break_log(dir / "bad.csv"),
                      Catch::Contains("bad.csv:2: mode = 'bent', allowed: tensile, shear"));
    CHECK_THROWS_WITH(read_break_log(dir / "none.csv"), Catch::Contains("none.csv"));
  }

  // A folder that does not exist: an error naming the path, no file left behind.
  CHECK_THROWS_WITH(write_break_log(dir / "missing" / "breaks.csv", {event}), Catch::Contains("missing"));
  CHECK_FALSE(std::filesystem::exists(dir / "missing"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("The tooth log is read back as written, and a damaged one names its file and line", "[fracture]") {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("hm-test-toothlog-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  ToothEvent first;
  first.sequence = 0, first.beam = 17, first.load = 1.25e-4, first.tooth = 0, first.stiffness_factor = 0.5;
  first.axial_stress = 2.72e-4, first.ratio = 1.0123456789, first.energy = 3.1e-12;
  ToothEvent last = first;
  last.sequence = 1, last.tooth = 9, last.stiffness_factor = 0.0, last.load = 2.5e-4;
  write_tooth_log(dir / "teeth.csv", {first, last}, "time");
  const std::vector<ToothEvent> back = read_tooth_log(dir / "teeth.csv");
  REQUIRE(back.size() == 2);
  CHECK(back[0].sequence == 0);
  CHECK(back[0].beam == 17);
  CHECK(back[0].load == 1.25e-4);
  CHECK(back[0].tooth == 0);
  CHECK(back[0].stiffness_factor == 0.5);
  CHECK(back[0].axial_stress == 2.72e-4);
  CHECK(back[0].ratio == Approx(1.0123456789).epsilon(1e-9));  // 10 significant digits
  CHECK(back[0].energy == 3.1e-12);
  CHECK(back[1].tooth == 9);
  CHECK(back[1].stiffness_factor == 0.0);
  CHECK(back[1].load == 2.5e-4);
  const std::vector<std::string> lines = hm::test::lines_of(dir / "teeth.csv");
  std::ofstream(dir / "bad.csv") << lines[0] << "\n" << lines[1] << "\n1,17,2.5e-4,9,0\n";
  CHECK_THROWS_WITH(read_tooth_log(dir / "bad.csv"), Catch::Contains("bad.csv:3: 5 columns, expected 8"));
  std::ofstream(dir / "bad.csv") << lines[0] << "\n1,17,2.5e-4,nine,0,1,1,1\n";
  CHECK_THROWS_WITH(read_tooth_log(dir / "bad.csv"), Catch::Contains("bad.csv:2: not a number"));
  std::ofstream(dir / "breaks.csv")
      << "sequence,beam,particle_i,particle_j,x,y,time,sigma_1,sigma_3,ratio,crack_tip_factor,mode\n";
  CHECK_THROWS_WITH(read_tooth_log(dir / "breaks.csv"), Catch::Contains("breaks.csv:1: header"));
  CHECK_THROWS_WITH(read_tooth_log(dir / "none.csv"), Catch::Contains("none.csv"));
  std::filesystem::remove_all(dir);
}
