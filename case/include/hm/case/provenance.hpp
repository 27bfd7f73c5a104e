#pragma once
/// \file
/// What is written beside every result so a run can be traced and repeated.
#include <string>

namespace hm::cases {

struct Provenance {
  std::string version;       ///< toolkit version
  std::string git_commit;    ///< source commit at build time ("<commit>-modified": uncommitted changes), or "unknown"
  std::string command_line;  ///< as typed
  std::string utc_time;      ///< ISO 8601
  std::string build_type;    ///< CMAKE_BUILD_TYPE
  // What of the build and the environment can change a result's bits besides the case: the BLAS
  // (library, the kernels chosen for this CPU, threads: blas_threads.hpp), the compiler and the C
  // library (libm's exp, log, ... differ by version in the last bit). OpenMP is recorded for the
  // record: the toolkit's own OpenMP loops are designed to give bitwise the same result on any thread
  // count (the triangular solves split the elimination tree into fixed independent halves, the
  // stress scans write one slot per beam), so no setting of it changes a number.
  std::string blas;             ///< BlasInEffect::library
  std::string blas_core;        ///< BlasInEffect::core
  int blas_threads = -1;        ///< BlasInEffect::threads; -1 unknown
  std::string omp_num_threads;  ///< the environment's OMP_NUM_THREADS, "unset" without it
  int omp_max_threads = 0;      ///< omp_get_max_threads()
  std::string omp_wait_policy;  ///< the environment's OMP_WAIT_POLICY (hmlattice sets "passive"), "unset" without it
  std::string compiler;         ///< compiler id and version
  std::string libc;             ///< gnu_get_libc_version()
};

Provenance make_provenance(const std::string& command_line);

/// A TOML fragment ([provenance] table) for resolved-config files.
std::string to_toml(const Provenance& p);

}  // namespace hm::cases
