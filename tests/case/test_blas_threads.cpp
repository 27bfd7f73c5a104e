// limit_blas_threads: OpenBLAS on one thread always; blas_in_effect (blas_threads.hpp).
#include <dlfcn.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "hm/case/blas_threads.hpp"

namespace {

using SetThreads = void (*)(int);
using GetThreads = int (*)();

}  // namespace

TEST_CASE("limit_blas_threads puts OpenBLAS on one thread whatever the environment says", "[blas]") {
  // hmlattice loads the BLAS through CHOLMOD; this test executable does not use CHOLMOD, so load the
  // same libblas.so.3 (Debian's alternative: OpenBLAS, scripts/install-deps.sh) as the program has it.
  REQUIRE(dlopen("libblas.so.3", RTLD_NOW | RTLD_GLOBAL) != nullptr);
  auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  auto get = reinterpret_cast<GetThreads>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  REQUIRE(set != nullptr);
  REQUIRE(get != nullptr);

  set(2);
  CHECK(hm::cases::limit_blas_threads());
  CHECK(get() == 1);
  // A user's OPENBLAS_NUM_THREADS does not win: two threads change the factor's bits run to run.
  const char* saved = std::getenv("OPENBLAS_NUM_THREADS");
  const std::string saved_value = saved ? saved : "";
  ::setenv("OPENBLAS_NUM_THREADS", "2", 1);
  set(2);
  CHECK(hm::cases::limit_blas_threads());
  CHECK(get() == 1);
  if (saved)
    ::setenv("OPENBLAS_NUM_THREADS", saved_value.c_str(), 1);
  else
    ::unsetenv("OPENBLAS_NUM_THREADS");

  // What the provenance records: the library as loaded, the kernels it chose, its threads now.
  const hm::cases::BlasInEffect blas = hm::cases::blas_in_effect();
  CHECK_THAT(blas.library, Catch::StartsWith("OpenBLAS"));
  CHECK(blas.core != "unknown");
  CHECK(blas.threads == 1);
}
