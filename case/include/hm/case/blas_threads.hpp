#pragma once
// How many threads the BLAS behind CHOLMOD may use in the `hmlattice` program, and what of the BLAS and
// OpenMP is in effect (written to every config.toml's [provenance]).
#include <string>

namespace hm::cases {

/// Puts OpenBLAS on one thread, whatever OPENBLAS_NUM_THREADS or OMP_NUM_THREADS say. Bits: with two
/// OpenBLAS threads the supernodal factorisation's sums are split differently from run to run and
/// results differ at ~1e-9 between identical runs; one thread gives the same bits every time. Speed:
/// the toolkit's own OpenMP loops (triangular solves, stress scans) and CHOLMOD's use the cores, and
/// Debian's default OpenBLAS (libopenblas0-pthread) keeps its worker threads spinning on sched_yield
/// after each call. Measured at N = 1e5 on 2 cores: numeric factorisation 3.1 s with two BLAS threads,
/// 3.0 s with one; the Fig. 12 run to step 72 1550 s with two, 1506 s with one; with a second job on the
/// machine two BLAS threads made the factorisation 24.7 s instead of ~4 s (README). Does nothing with
/// another BLAS. Returns whether it set the threads.
bool limit_blas_threads();

/// The BLAS as loaded in this process. OpenBLAS (found by dlsym): its build string, the kernel set its
/// dynamic dispatch chose for this CPU (another kernel rounds differently), its threads; otherwise
/// "unknown" and threads = -1.
struct BlasInEffect {
  std::string library = "unknown";  ///< openblas_get_config(), e.g. "OpenBLAS 0.3.21 DYNAMIC_ARCH ..."
  std::string core = "unknown";     ///< openblas_get_corename(), e.g. "Haswell"
  int threads = -1;                 ///< openblas_get_num_threads()
};
BlasInEffect blas_in_effect();

}  // namespace hm::cases
