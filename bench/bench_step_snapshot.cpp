// What saving and restoring the whole model state costs, as a checkpoint does (and as a coupled step's
// snapshot did until the step's start stopped copying the mechanics factor, whose changes the solver
// now undoes: bench_lattice_solver measures that). CoupledModel::step saves the model at the start of
// every step and restores it when the attempt fails; the saw-tooth law's runs retry a quarter of their
// steps. The whole state holds both factors (~10 MB at N = 1e4). Measured on the Fig. 12 quick case
// with the saw-tooth law at N particles, after a few steps, saved and restored `rounds` times, the two
// ways side by side:
//  - before: a fresh StateWriter per step, its bytes with their checksum copied into a StateReader that
//    checks the checksum again;
//  - now: one StateWriter kept by the model, cleared each step (its memory kept), read in place without
//    a checksum (StateReader::of_snapshot).
//
//   build/bench/bench_step_snapshot [N] [rounds]   (defaults 10000 and 40)
//
// Prints the snapshot's size and the median time of a save and of a save with its restore, each way,
// and their ratio.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/run_case.hpp"
#include "hm/core/state_archive.hpp"

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

template <class F>
double seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 10000;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 40;
  const auto c = hm::cases::read_run_case(
      std::filesystem::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml",
      {"lattice.n_particles=" + std::to_string(n), "fracture.law=\"sawtooth\"", "fracture.fracture_energy=2.34e-9"});
  const auto model = hm::cases::make_coupled_model(c);
  for (int k = 0; k < 5; ++k) model->step(1e-5);

  std::vector<double> save_before, both_before, save_now, both_now;
  std::size_t bytes = 0;
  hm::core::StateWriter kept;
  for (int r = 0; r < rounds; ++r) {
    save_before.push_back(seconds([&] {
      hm::core::StateWriter w;
      model->save_state(w);
      bytes = w.bytes().size();
    }));
    both_before.push_back(seconds([&] {
      hm::core::StateWriter w;
      model->save_state(w);
      hm::core::StateReader snapshot(w.bytes(), "bench");
      model->restore_state(snapshot);
    }));
    save_now.push_back(seconds([&] {
      kept.clear();
      model->save_state(kept);
    }));
    both_now.push_back(seconds([&] {
      kept.clear();
      model->save_state(kept);
      hm::core::StateReader snapshot = hm::core::StateReader::of_snapshot(kept, "bench");
      model->restore_state(snapshot);
    }));
  }
  std::printf("step snapshot, N = %ld (%d particles), %.1f MB, median of %d rounds\n", n,
              model->lattice().n_particles(), static_cast<double>(bytes) / 1e6, rounds);
  std::printf("  save:            before %8.2f ms, now %8.2f ms, ratio %.2f\n", 1e3 * median(save_before),
              1e3 * median(save_now), median(save_before) / median(save_now));
  std::printf("  save + restore:  before %8.2f ms, now %8.2f ms, ratio %.2f\n", 1e3 * median(both_before),
              1e3 * median(both_now), median(both_before) / median(both_now));
}
