#pragma once
// How many threads the BLAS behind CHOLMOD may use in the `hmlattice` program.
namespace hm::cases {

/// Sets OpenBLAS to one thread unless the user chose (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS): the
/// toolkit's own OpenMP loops (triangular solves, stress scans) and CHOLMOD's use the cores, and Debian's
/// default OpenBLAS (libopenblas0-pthread) keeps its worker threads spinning on sched_yield after each
/// call. Measured at N = 1e5 on 2 cores: numeric factorisation 3.1 s with two BLAS threads, 3.0 s with
/// one; the Fig. 12 run to step 72 1550 s with two, 1506 s with one; with a second job on the machine
/// two BLAS threads made the factorisation 24.7 s instead of ~4 s (README). Does nothing with another BLAS.
/// Returns whether it set the threads.
bool limit_blas_threads();

}  // namespace hm::cases
