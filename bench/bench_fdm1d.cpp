// Speed of the radial 1D model: one Fig. 10 run (n_r = 400, t* = 0..1) and its Odeint reference.
//   build/bench/bench_fdm1d
#include <benchmark/benchmark.h>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/fdm1d/fdm1d.hpp"
#include "hm/fdm1d/odeint_reference.hpp"

namespace {

hm::analytic::DimensionlessParameters fig10() {
  hm::analytic::DimensionlessParameters d;
  d.material.E_over_M = hm::analytic::E_over_M_table1(d.material.b, d.material.nu);
  return d;
}

void BM_fdm1d_fig10(benchmark::State& state) {
  hm::fdm1d::Fdm1dNumerics n;
  n.n_r = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(hm::fdm1d::run_fdm1d(fig10(), n));
}
BENCHMARK(BM_fdm1d_fig10)->Arg(100)->Arg(400)->Arg(1600)->Unit(benchmark::kMillisecond);

void BM_fdm1d_odeint(benchmark::State& state) {
  hm::fdm1d::Fdm1dNumerics n;
  n.n_r = static_cast<int>(state.range(0));
  n.t_end = 0.1;
  n.output_times = {0.1};
  for (auto _ : state) benchmark::DoNotOptimize(hm::fdm1d::run_fdm1d_odeint(fig10(), n));
}
BENCHMARK(BM_fdm1d_odeint)->Arg(60)->Arg(200)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
