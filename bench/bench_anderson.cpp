// Speed of one Anderson acceleration step (anderson_acceleration.hpp) with a full history, at the
// coupled Fig. 12 run's state sizes: pressures (triangles + borehole) and u_x, u_y, theta per particle,
// N = 1e4 (~5e4 unknowns) and N = 1e5 (~5e5), depth 10 (the paper cases' anderson_depth) and 20.
// The fixed-point map is a linear contraction with a few slow modes, like the fractured lattice's.
// Median seconds per next() over the repeats.
//   build/bench/bench_anderson            # both sizes, depths 10 and 20
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/coupled/anderson_acceleration.hpp"

using hm::lattice2d::AndersonAcceleration;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// g(x) = x* + c (x - x*) per entry, c in [0, 0.99): most modes fast, a few slow.
double seconds_per_step(Eigen::Index n, int depth, int repeats) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Eigen::VectorXd fixed_point(n), contraction(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    fixed_point[i] = uniform(rng);
    const double u = uniform(rng);
    contraction[i] = 0.99 * u * u * u * u;
  }
  AndersonAcceleration anderson(depth, 0.5);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<double> times;
  for (int k = 0; k < depth + 1 + repeats; ++k) {
    const Eigen::VectorXd g = fixed_point + contraction.cwiseProduct(x - fixed_point);
    const auto t0 = std::chrono::steady_clock::now();
    x = anderson.next(x, g);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (k > depth) times.push_back(s);  // history full
  }
  return median(times);
}

}  // namespace

int main() {
  std::printf("%10s %6s %14s\n", "unknowns", "depth", "s per next()");
  for (const Eigen::Index n : {50000, 500000})
    for (const int depth : {10, 20})
      std::printf("%10ld %6d %14.4f\n", static_cast<long>(n), depth, seconds_per_step(n, depth, 15));
  return 0;
}
