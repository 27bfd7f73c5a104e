// The [flow] defaults are consistent: a borehole case with any of its [flow] keys left out reads,
// builds its coupled model and steps. borehole_deformation's default follows borehole_storage
// (docs/flow.md): with no storage, the b dV_h term alone sets p_h and the coupling loop through the
// borehole node does not converge (docs/coupling.md, section 3), so "none" goes with "none".
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/run_case.hpp"
#include "run_command.hpp"

using hm::test::TempDir;
namespace lt = hm::lattice2d;

namespace {

// `text` without the lines that set one of `keys` (each key name is unique to [flow] in the case).
std::string without_keys(const std::string& text, const std::vector<std::string>& keys) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    bool drop = false;
    for (const std::string& k : keys) drop = drop || line.rfind(k + " =", 0) == 0;
    if (!drop) out += line + "\n";
  }
  return out;
}

}  // namespace

TEST_CASE(
    "A borehole case runs with any subset of its [flow] keys left out, borehole_deformation following "
    "borehole_storage",
    "[case]") {
  // Fig. 12's quick case: flux-boundary borehole (storage none, deformation none), factor reuse on.
  const std::string fig12 = hm::test::slurp(std::string(HM_SOURCE_DIR) + "/cases/fig12_b0.2_quick.toml");
  const std::vector<std::string> keys = {"borehole_storage", "borehole_deformation", "reuse_factorisation"};
  for (const std::string& k : keys) REQUIRE(fig12.find("\n" + k + " = ") != std::string::npos);
  TempDir dir("flow-defaults");
  for (unsigned mask = 0; mask < (1u << keys.size()); ++mask) {
    std::vector<std::string> removed;
    for (std::size_t i = 0; i < keys.size(); ++i)
      if (mask & (1u << i)) removed.push_back(keys[i]);
    const std::string text = without_keys(fig12, removed);
    std::string names;
    for (const auto& k : removed) names += k + " ";
    INFO("removed: " << names);
    dir.write("case.toml", text);
    const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");
    const bool storage_given = !(mask & 1u), deformation_given = !(mask & 2u);
    CHECK(c.flow.borehole_storage == (storage_given ? lt::BoreholeStorage::none : lt::BoreholeStorage::biot_modulus));
    // The documented rule: given, as given ("none" here); left out, "none" with storage "none" and
    // "biot" (Eq. 16 as printed) with storage "biot-modulus".
    const lt::BoreholeDeformation expected =
        deformation_given || storage_given ? lt::BoreholeDeformation::none : lt::BoreholeDeformation::biot;
    CHECK(c.flow.borehole_deformation == expected);
    CHECK(c.flow.reuse_factorisation == ((mask & 4u) ? lt::FlowParameters{}.reuse_factorisation : true));
    // The resolved config states the value and reads back to the same case.
    dir.write("config.toml", hm::cases::run_case_to_toml(c, ""));
    CHECK(hm::cases::read_run_case(dir.path / "config.toml").flow.borehole_deformation == expected);

    // Two coupled steps of the case's first dt: the diverging pairing (storage none with the b dV_h
    // term) fails already in the first step here (measured: at pass 12 the break loop had broken every
    // beam and the mechanical matrix was singular).
    const auto model = hm::cases::make_coupled_model(c);
    for (int step = 0; step < 2; ++step) {
      const lt::CoupledStepSummary s = model->step(c.stepping.dt_initial);
      INFO("step " << step << ": " << s.message);
      CHECK(s.status == lt::CoupledStatus::converged);
    }
  }
}

TEST_CASE("The water-filled borehole: storage \"fluid\" takes deformation \"full\" and [physics] E_over_Kw", "[case]") {
  std::string text = hm::test::slurp(std::string(HM_SOURCE_DIR) + "/cases/fig12_b0.2_quick.toml");
  text = without_keys(text, {"borehole_storage", "borehole_deformation"});
  const auto at = text.find("[flow]\n");
  REQUIRE(at != std::string::npos);
  text.insert(at + 7, "borehole_storage = \"fluid\"\n");
  TempDir dir("flow-fluid");
  dir.write("case.toml", text);
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "case.toml");
  CHECK(c.flow.borehole_storage == lt::BoreholeStorage::fluid);
  CHECK(c.flow.borehole_deformation == lt::BoreholeDeformation::full);
  CHECK(c.flow_parameters().E_over_Kw == hm::analytic::table1_E_over_Kw);
  const std::string config = hm::cases::run_case_to_toml(c, "");
  CHECK_THAT(config, Catch::Contains("borehole_deformation = \"full\"") && Catch::Contains("E_over_Kw = "));
  dir.write("config.toml", config);
  CHECK(hm::cases::read_run_case(dir.path / "config.toml").flow.borehole_deformation == lt::BoreholeDeformation::full);

  // Two coupled steps converge: the hole's storage keeps the loop through the borehole node stable.
  const auto model = hm::cases::make_coupled_model(c);
  for (int step = 0; step < 2; ++step) {
    const lt::CoupledStepSummary s = model->step(c.stepping.dt_initial);
    INFO("step " << step << ": " << s.message);
    CHECK(s.status == lt::CoupledStatus::converged);
  }

  // A given E_over_Kw is used; a non-positive one is refused by table, key and rule.
  auto with_kw = text;
  with_kw.insert(with_kw.find("[physics]\n") + 10, "E_over_Kw = 9\n");
  dir.write("kw.toml", with_kw);
  CHECK(hm::cases::read_run_case(dir.path / "kw.toml").flow_parameters().E_over_Kw == 9.0);
  with_kw.replace(with_kw.find("E_over_Kw = 9"), 13, "E_over_Kw = 0");
  dir.write("bad.toml", with_kw);
  CHECK_THROWS_WITH(hm::cases::read_run_case(dir.path / "bad.toml"),
                    Catch::Contains("[physics]") && Catch::Contains("E_over_Kw = 0") && Catch::Contains("> 0"));
}

TEST_CASE("The cubic law's aperture defaults to the jump along the crack's normal, the other laws' to the axial opening",
          "[case]") {
  const std::string fig14 = hm::test::slurp(std::string(HM_SOURCE_DIR) + "/cases/fig14_b0.2_quick.toml");
  TempDir dir("flow-aperture");
  dir.write("iota.toml", fig14);
  const hm::cases::RunCase iota = hm::cases::read_run_case(dir.path / "iota.toml");
  CHECK(iota.flow.fracture_flow.aperture == lt::CrackAperture::axial);
  std::string cubic = fig14;
  const auto at = cubic.find("[flow]\n");
  REQUIRE(at != std::string::npos);
  cubic.insert(at + 7, "fracture_flow = \"cubic\"\nrock_permeability = 1e-14\n");
  cubic.replace(cubic.find("\niota = 1e3") + 1, 10, "iota = 1.0");
  dir.write("cubic.toml", cubic);
  const hm::cases::RunCase c = hm::cases::read_run_case(dir.path / "cubic.toml");
  CHECK(c.flow.fracture_flow.aperture == lt::CrackAperture::crack_normal);
  // The resolved config states it and reads back to it.
  const std::string config = hm::cases::run_case_to_toml(c, "");
  CHECK_THAT(config, Catch::Contains("crack_aperture = \"crack_normal\""));
  dir.write("config.toml", config);
  CHECK(hm::cases::read_run_case(dir.path / "config.toml").flow.fracture_flow.aperture == lt::CrackAperture::crack_normal);
  // Given, as given.
  cubic.insert(at + 7, "crack_aperture = \"axial\"\n");
  dir.write("axial.toml", cubic);
  CHECK(hm::cases::read_run_case(dir.path / "axial.toml").flow.fracture_flow.aperture == lt::CrackAperture::axial);
}
