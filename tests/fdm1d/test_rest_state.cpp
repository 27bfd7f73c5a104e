// The 1D model from a rest state under an isotropic in-situ stress (RestState).
#include <catch2/catch.hpp>

#include <cmath>

#include "hm/analytic/breakdown_insitu.hpp"
#include "hm/analytic/lame.hpp"
#include "hm/analytic/physical_parameters.hpp"
#include "hm/core/input_error.hpp"
#include "hm/fdm1d/fdm1d.hpp"
#include "hm/fdm1d/wall_failure.hpp"

using namespace hm::fdm1d;

namespace {

Fdm1dNumerics short_run() {
  Fdm1dNumerics n;
  n.n_r = 200;
  n.t_end = 0.01;
  n.output_times = {0.005};
  return n;
}

}  // namespace

TEST_CASE("From rest under an isotropic in-situ stress the 1D model adds Lame's effective rest state", "[fdm1d]") {
  const auto params = hm::analytic::table1_borehole(0.5, 0.01);
  const double b = params.material.b, S = 3e-4, p0 = 1e-4;
  const Fdm1dResult plain = run_fdm1d(params, short_run()), rested = run_fdm1d(params, short_run(), RestState{S, p0});
  // Wall pressure (1 - b) p0 and outer pressure S - b p0 on the effective stress.
  const hm::analytic::LameCylinder lame((1.0 - b) * p0, S - b * p0, params.R_i, 1.0, params.material.nu);
  REQUIRE(plain.borehole.size() == rested.borehole.size());
  for (std::size_t k = 0; k < plain.borehole.size(); k += 10) {
    const auto &a = plain.borehole[k], &r = rested.borehole[k];
    const auto wall = lame.state(params.R_i);
    CHECK(r.p_h == a.p_h);                                                // the flow is the increment's: untouched
    CHECK(r.sigma_r - a.sigma_r == Approx(wall.sigma_r).epsilon(1e-12));  // one addition's round-off
    CHECK(r.sigma_theta - a.sigma_theta == Approx(wall.sigma_theta).epsilon(1e-12));
    CHECK(r.sigma_z - a.sigma_z == Approx(wall.sigma_z).epsilon(1e-12));
  }
  const auto &ps = plain.snapshots.back(), &rs = rested.snapshots.back();
  for (std::size_t i = 0; i < rested.r.size(); i += 20)
    CHECK(rs.u_r[i] - ps.u_r[i] == Approx(lame.state(rested.r[i]).u_r).epsilon(1e-10));
  // At rest the total radial stress at the wall is -p0 and at r = 1 it is -S (effective + b p).
  CHECK(rested.borehole.front().sigma_r - b * p0 == Approx(-p0).epsilon(1e-12));
  CHECK(rs.sigma_r.back() - b * (rs.p.back() + p0) == Approx(-S).epsilon(1e-9));
}

TEST_CASE("Zero rest state is the run without it bit for bit, and bad values are refused", "[fdm1d]") {
  const auto params = hm::analytic::table1_borehole(0.5, 0.01);
  const Fdm1dResult a = run_fdm1d(params, short_run()), z = run_fdm1d(params, short_run(), RestState{});
  CHECK(a.borehole.back().sigma_theta == z.borehole.back().sigma_theta);
  CHECK(a.snapshots.back().u_r == z.snapshots.back().u_r);
  REQUIRE_THROWS_WITH(run_fdm1d(params, short_run(), RestState{-1e-4, 0.0}),
                      "S = -1e-04, allowed: >= 0 (compression positive)");
  REQUIRE_THROWS_WITH(run_fdm1d(params, short_run(), RestState{0.0, -1e-4}),
                      "p0 = -1e-04, allowed: >= 0 (compression positive)");
}

TEST_CASE("Confinement raises the 1D breakdown pressure by the wall's rest hoop compression", "[fdm1d]") {
  // The wall fails in tension on the hoop stress, linear in the loads: confining with S adds
  // -2 S / (1 - R_i^2) to it (Lame, p0 = 0), so p_h at failure rises by that over the hoop stress per
  // unit p_h, which changes in time; the check: failure comes later and at a higher pressure.
  auto params = hm::analytic::table1_borehole(0.5, 0.01);
  Fdm1dNumerics n = short_run();
  n.t_end = 0.2;
  const WallFailure free = first_wall_failure(run_fdm1d(params, n), params);
  const WallFailure confined = first_wall_failure(run_fdm1d(params, n, RestState{5e-5, 0.0}), params);
  REQUIRE(free.failed);
  REQUIRE(confined.failed);
  CHECK(confined.t > free.t);
  CHECK(confined.p_h > free.p_h);
}
