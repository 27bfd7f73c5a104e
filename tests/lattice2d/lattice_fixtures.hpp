#pragma once
// Lattices the lattice2d tests build over and over: a spec or a generated lattice of a given
// domain, size and seed, everything else at LatticeSpec's defaults.
#include <cstdint>

#include "hm/lattice2d/lattice.hpp"

namespace hm::test {

inline hm::lattice2d::LatticeSpec spec_of(hm::lattice2d::DomainShape shape, long long n, std::uint64_t seed = 1) {
  hm::lattice2d::LatticeSpec spec;
  spec.domain = shape;
  spec.n_particles = n;
  spec.seed = seed;
  return spec;
}

inline hm::lattice2d::Lattice make_lattice(hm::lattice2d::DomainShape shape, long long n, std::uint64_t seed = 1) {
  return hm::lattice2d::generate_lattice(spec_of(shape, n, seed));
}

}  // namespace hm::test
