// See blas_threads.hpp.
#include "hm/case/blas_threads.hpp"

#include <dlfcn.h>

#include <cstdlib>

namespace hm::cases {

bool limit_blas_threads() {
  if (std::getenv("OPENBLAS_NUM_THREADS") || std::getenv("OMP_NUM_THREADS")) return false;
  // Looked up at run time: the BLAS is whichever libblas.so.3 Debian's alternatives select.
  using SetThreads = void (*)(int);
  auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (!set) return false;
  set(1);
  return true;
}

}  // namespace hm::cases
