#include "hm/verification/benchmark.hpp"

namespace hm::verification {

const std::vector<Benchmark>& all_benchmarks() {
  static const std::vector<Benchmark> registry = [] {
    std::vector<Benchmark> all;
    add_analytic_benchmarks(all);
    add_fdm1d_benchmarks(all);
    add_lattice2d_elastic_benchmarks(all);
    add_lattice2d_fracture_benchmarks(all);
    add_lattice2d_propagation_benchmarks(all);
    add_lattice2d_kgd_transition_benchmarks(all);
    add_lattice2d_fracture_energy_benchmarks(all);
    add_lattice2d_coupled_benchmarks(all);
    add_lattice2d_vs_fdm1d_benchmarks(all);
    add_lattice2d_borehole_fracture_benchmarks(all);
    add_lattice2d_paper_figure_benchmarks(all);
    add_insitu_benchmarks(all);
    add_breakdown_benchmarks(all);
    return all;
  }();
  return registry;
}

}  // namespace hm::verification
