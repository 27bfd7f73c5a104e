// A coupled step that fails to converge and is retried with half the step must leave no trace: the
// run with halvings breaks exactly what a run that took the accepted steps directly breaks.
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

// The Fig. 12 quick case (b = 0.2) on N = 2000 with one long fixed step (1e-3, the first breaks fall in
// the first step) and a pass cap of 15: the first attempts break hundreds of beams at once and do not
// converge within the cap, so run() halves; the halved steps converge.
std::string halving_case() {
  return hm::test::edited(slurp(std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml"),
                          {{"n_particles = 3000", "n_particles = 2000"},
                           {"dt_initial = 1e-5\ndt_growth = 1.2\ndt_max = 5e-4\nt_end = 0.0272",
                            "dt_initial = 1e-3\ndt_growth = 1\ndt_max = 1e-3\nt_end = 0.006"},
                           {"times = [0.0045, 0.009, 0.0272]", "times = [0.006]"},
                           {"vtk = true", "vtk = false"},
                           {"displacement_tolerance = 1e-4", "displacement_tolerance = 1e-4\nmax_iterations = 15"}});
}

bool same_events(const hm::lattice2d::BreakEvent& a, const hm::lattice2d::BreakEvent& b) {
  return a.sequence == b.sequence && a.beam == b.beam && a.load == b.load && a.sigma_1 == b.sigma_1 &&
         a.sigma_3 == b.sigma_3 && a.ratio == b.ratio && a.crack_tip_factor == b.crack_tip_factor && a.mode == b.mode;
}

}  // namespace

TEST_CASE("A rejected coupled step leaves no trace: halvings break what the halved steps break directly",
          "[case][fracture]") {
  TempDir dir("step-rollback");
  dir.write("case.toml", halving_case());
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");

  auto halved = hm::cases::make_coupled_model(c);
  std::vector<double> accepted_dt;
  const auto run = halved->run(
      c.stepping, [&](const hm::lattice2d::CoupledModel&, const hm::lattice2d::CoupledStepSummary& s, bool) {
        if (s.dt > 0.0) accepted_dt.push_back(s.dt);
      });
  REQUIRE(run.is_ok());
  // The setting must exercise the retry, with breaks in the rejected attempts.
  REQUIRE(run.n_step_halvings >= 2);
  REQUIRE(halved->n_broken() > 50);

  auto direct = hm::cases::make_coupled_model(c);
  for (const double dt : accepted_dt) {
    const auto s = direct->step(dt);
    REQUIRE(s.is_ok());
  }

  // Bit for bit: the same beams in the same order at the same loads, the same fields at the end.
  const auto& a = halved->break_log();
  const auto& b = direct->break_log();
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    INFO("break " << k);
    CHECK(same_events(a[k], b[k]));
  }
  CHECK(halved->time() == direct->time());
  CHECK((halved->pressure().array() == direct->pressure().array()).all());
  CHECK((halved->displacement().array() == direct->displacement().array()).all());
}
