// limit_blas_threads: OpenBLAS on one thread unless the user chose (blas_threads.hpp).
#include <dlfcn.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "hm/case/blas_threads.hpp"

namespace {

using SetThreads = void (*)(int);
using GetThreads = int (*)();

}  // namespace

TEST_CASE("limit_blas_threads puts OpenBLAS on one thread and leaves a user's choice alone", "[blas]") {
  // hmlattice loads the BLAS through CHOLMOD; this test executable does not use CHOLMOD, so load the
  // same libblas.so.3 (Debian's alternative: OpenBLAS, scripts/install-deps.sh) as the program has it.
  REQUIRE(dlopen("libblas.so.3", RTLD_NOW | RTLD_GLOBAL) != nullptr);
  auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  REQUIRE(set != nullptr);
  REQUIRE(get != nullptr);
  const char* omp = std::getenv("OMP_NUM_THREADS");  // ctest sets it to 1
  const std::string omp_saved = omp ? omp : "";
  ::unsetenv("OMP_NUM_THREADS");
  ::unsetenv("OPENBLAS_NUM_THREADS");

  set(2);
  CHECK(hm::cases::limit_blas_threads());
  CHECK(get() == 1);

  set(2);
  const int chosen = get();  // 2 on this 2-core machine (OpenBLAS caps it at its own maximum)
  ::setenv("OPENBLAS_NUM_THREADS", "2", 1);
  CHECK_FALSE(hm::cases::limit_blas_threads());
  CHECK(get() == chosen);
  ::unsetenv("OPENBLAS_NUM_THREADS");

  set(1);
  if (!omp_saved.empty()) ::setenv("OMP_NUM_THREADS", omp_saved.c_str(), 1);
}
