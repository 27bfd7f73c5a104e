// Benchmarks of the dry lattice (elastic): filled in by the lattice2d work (issue 4).
#include "hm/verification/benchmark.hpp"

namespace hm::verification {

void add_lattice2d_elastic_benchmarks(std::vector<Benchmark>& /*into*/) {}

}  // namespace hm::verification
