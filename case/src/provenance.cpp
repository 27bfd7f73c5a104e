#include "hm/case/provenance.hpp"

#include <gnu/libc-version.h>
#include <omp.h>

#include <cstdlib>
#include <sstream>

#include "git_commit.hpp"
#include "hm/case/blas_threads.hpp"
#include "hm/core/toml_text.hpp"

namespace hm::cases {

Provenance make_provenance(const std::string& command_line) {
  Provenance p;
  p.version = HM_VERSION;
  p.git_commit = kGitCommit;
  p.command_line = command_line;
  p.utc_time = core::utc_now();
  p.build_type = HM_BUILD_TYPE;
  const BlasInEffect blas = blas_in_effect();
  p.blas = blas.library;
  p.blas_core = blas.core;
  p.blas_threads = blas.threads;
  const char* omp = std::getenv("OMP_NUM_THREADS");
  p.omp_num_threads = omp ? omp : "unset";
  p.omp_max_threads = omp_get_max_threads();
  const char* wait = std::getenv("OMP_WAIT_POLICY");
  p.omp_wait_policy = wait ? wait : "unset";
#if defined(__clang__)
  p.compiler = "clang " __clang_version__;
#elif defined(__GNUC__)
  p.compiler = "gcc " __VERSION__;
#else
  p.compiler = "unknown";
#endif
  p.libc = std::string("glibc ") + gnu_get_libc_version();
  return p;
}

std::string to_toml(const Provenance& p) {
  std::ostringstream os;
  os << "[provenance]\n"
     << "version = " << core::toml_string(p.version) << "\n"
     << "git_commit = " << core::toml_string(p.git_commit) << "\n"
     << "command_line = " << core::toml_string(p.command_line) << "\n"
     << "utc_time = " << core::toml_string(p.utc_time) << "\n"
     << "build_type = " << core::toml_string(p.build_type) << "\n"
     << "blas = " << core::toml_string(p.blas) << "\n"
     << "blas_core = " << core::toml_string(p.blas_core) << "\n"
     << "blas_threads = " << (p.blas_threads >= 0 ? std::to_string(p.blas_threads) : core::toml_string("unknown"))
     << "\n"
     << "omp_num_threads = " << core::toml_string(p.omp_num_threads) << "\n"
     << "omp_max_threads = " << p.omp_max_threads << "\n"
     << "omp_wait_policy = " << core::toml_string(p.omp_wait_policy) << "\n"
     << "compiler = " << core::toml_string(p.compiler) << "\n"
     << "libc = " << core::toml_string(p.libc) << "\n";
  return os.str();
}

}  // namespace hm::cases
