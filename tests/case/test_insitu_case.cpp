// A 2D case under an in-situ far field ([mechanics] S_H, S_h, theta_H, p0): zero reproduces the
// unstressed model bit for bit, and the rest state is the one the keys describe.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/run_case.hpp"
#include "run_command.hpp"

using hm::test::slurp;
using hm::test::TempDir;

namespace {

// The Fig. 12 quick case (b = 0.2, N = 3000) to t* = 5e-4, without VTK, with `mechanics` added to
// its [mechanics] table.
std::string short_fig12_case(const std::string& mechanics) {
  return hm::test::edited(slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml"),
                          {{"t_end = 0.0272", "t_end = 0.0005"},
                           {"times = [0.0045, 0.009, 0.0272]", "times = [0.0005]"},
                           {"vtk = true", "vtk = false"},
                           {"outer = \"free\"\n", "outer = \"free\"\n" + mechanics}});
}

// The beams it breaks, in order, as the model before in-situ stress existed broke them (the
// program at commit 342ed45 on this case: its breaks.csv).
const std::vector<int> breaks_without_insitu_stress = {
    606,  582,  585,  909,  912,  611,  609,  765,  766,  644,  648,  1499, 1500, 1889, 1023, 2019, 1892, 1584, 1585,
    1587, 2717, 1767, 1769, 1890, 2334, 612,  616,  711,  2779, 3114, 3113, 2894, 632,  637,  3154, 3362, 4344, 4345,
    4396, 4397, 2337, 3595, 3982, 3984, 5130, 849,  844,  1237, 1885, 2152, 2248, 2279, 2280, 2735, 3265, 2879, 2880,
    2882, 4998, 6498, 6629, 7465, 7867, 7869, 3364, 4011, 5065, 5764, 5522, 5523, 6260, 8768, 8268, 8265, 8362, 5852,
    8361, 3985, 4313, 4439, 5001, 6294, 4853, 5445, 5362, 5363, 5810, 5854, 5232, 5233, 5234, 5374, 5983, 6421, 8443,
    8499, 5813, 7711, 6419, 638,  6878, 8261, 8257, 6883, 7192, 7189, 1166, 1449, 1447, 1627, 2218, 2640, 2694, 3049,
    7400, 6999, 4571, 5004, 5182, 4386, 8045, 7798, 7198, 5527, 5528, 5946, 6492, 7200, 7458, 6930, 7223, 6903, 6592};

struct ShortRun {
  std::vector<int> beams;
  Eigen::VectorXd pressure, displacement;
};

ShortRun run_case_text(const std::string& text) {
  TempDir dir("insitu-case");
  dir.write("case.toml", text);
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");
  auto model = hm::cases::make_coupled_model(c);
  REQUIRE(model->run(c.stepping).is_ok());
  ShortRun r{{}, model->pressure(), model->displacement()};
  for (const auto& e : model->break_log()) r.beams.push_back(e.beam);
  return r;
}

}  // namespace

TEST_CASE("Zero in-situ stress reproduces the model without it bit for bit", "[case][fracture]") {
  const ShortRun absent = run_case_text(short_fig12_case(""));
  const ShortRun zero = run_case_text(short_fig12_case("S_H = 0.0\nS_h = 0.0\ntheta_H = 40.0\np0 = 0.0\n"));
  CHECK(absent.beams == breaks_without_insitu_stress);
  CHECK(zero.beams == absent.beams);
  CHECK(zero.pressure == absent.pressure);
  CHECK(zero.displacement == absent.displacement);
}

TEST_CASE("The case's in-situ keys become the rest state's effective loads", "[case]") {
  TempDir dir("insitu-keys");
  dir.write("case.toml", short_fig12_case("S_H = 3e-4\nS_h = 1e-4\ntheta_H = 90.0\np0 = 5e-5\n"));
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");
  const hm::lattice2d::BoundaryConditions bc = c.boundary_conditions();
  // S_H along y: sigma_yy = -S_H + b p0, sigma_xx = -S_h + b p0 (b = 0.2); the wall (1 - b) p0.
  CHECK(bc.outer_stress(1, 1) == Approx(-3e-4 + 0.2 * 5e-5).epsilon(1e-14));
  CHECK(bc.outer_stress(0, 0) == Approx(-1e-4 + 0.2 * 5e-5).epsilon(1e-14));
  CHECK(std::abs(bc.outer_stress(0, 1)) < 1e-19);  // cos 90 degrees in floating point: 6e-17 x (S_H - S_h)
  CHECK(bc.inner_pressure == Approx(0.8 * 5e-5).epsilon(1e-14));
  // The resolved config names the keys, and reads back to the same state.
  const std::string toml = hm::cases::run_case_to_toml(c, "");
  CHECK_THAT(toml, Catch::Contains("S_H = 3e-04") && Catch::Contains("theta_H = 90") && Catch::Contains("p0 = 5e-05"));
}
