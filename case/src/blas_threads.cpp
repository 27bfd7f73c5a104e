// See blas_threads.hpp.
#include "hm/case/blas_threads.hpp"

#include <dlfcn.h>

namespace hm::cases {

namespace {

// Looked up at run time: the BLAS is whichever libblas.so.3 Debian's alternatives select.
template <class Function>
Function openblas(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

}  // namespace

bool limit_blas_threads() {
  auto set = openblas<void (*)(int)>("openblas_set_num_threads");
  if (!set) return false;
  set(1);
  return true;
}

BlasInEffect blas_in_effect() {
  BlasInEffect b;
  if (auto config = openblas<char* (*)()>("openblas_get_config")) b.library = config();
  if (auto core = openblas<char* (*)()>("openblas_get_corename")) b.core = core();
  if (auto threads = openblas<int (*)()>("openblas_get_num_threads")) b.threads = threads();
  return b;
}

}  // namespace hm::cases
