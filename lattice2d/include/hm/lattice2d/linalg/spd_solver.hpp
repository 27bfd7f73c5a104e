#pragma once
/// \file
/// One small interface for the sparse symmetric positive definite systems of the lattice model (the
/// beam mechanics of Section 2.1 and the flow network of Section 2.2): factorise or set up a matrix A,
/// give it new values on the same pattern, solve A x = b, and apply a symmetric low-rank modification
/// A <- A + sigma W W^T (sigma = +1 update, -1 downdate) when a beam breaks or a contact opens or closes.
///
/// Two implementations behind it (docs/lattice.md, "Solving"):
///  - CholmodSolver (default): CHOLMOD's sparse LDL' with a fill-reducing ordering, kept for the
///    whole run and modified in place by cholmod_updown; refactorised after a set number of
///    modifications or when a solve's relative residual exceeds a tolerance.
///  - PcgSolver: Eigen's preconditioned conjugate gradients, warm-started from the previous solution;
///    a modification only changes the stored matrix (the preconditioner is rebuilt lazily). For
///    cross-checking.
/// Numerical trouble (a non-positive pivot, no convergence) is reported by info(), Eigen style, never
/// thrown. Dimensionless; the interface knows nothing about beams.
#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "hm/core/enum_names.hpp"
#include "hm/core/state_archive.hpp"

namespace hm::lattice2d {

/// The solver strategies.
enum class SpdSolverKind {
  cholmod,  ///< sparse LDL' factor with rank-k updates/downdates (default)
  pcg,      ///< preconditioned conjugate gradients (cross-check)
};
constexpr auto enum_names(SpdSolverKind) {
  return core::enum_table<SpdSolverKind>({{SpdSolverKind::cholmod, "cholmod"}, {SpdSolverKind::pcg, "pcg"}});
}

/// Fill-reducing orderings of the CHOLMOD factor.
enum class CholmodOrdering {
  nested_dissection,  ///< CHOLMOD's NESDIS (METIS bisection + constrained minimum degree); default
  metis,              ///< plain METIS nested dissection
  amd,                ///< approximate minimum degree
  automatic,          ///< cholmod_analyze's own choice (tries AMD, then METIS/NESDIS if AMD fills badly)
};

/// Preconditioners of PcgSolver.
enum class PcgPreconditioner {
  incomplete_cholesky,  ///< Eigen::IncompleteCholesky (zero-fill-ish, diagonal shift on breakdown); default
  jacobi,               ///< diagonal
};

/// Options of both solvers. Every default is set here (Ceres style).
struct SpdSolverOptions {
  // --- CholmodSolver -----------------------------------------------------------------------------
  /// Fill-reducing ordering. Our choice: nested dissection, the best fill for 2D meshes.
  CholmodOrdering ordering = CholmodOrdering::nested_dissection;
  /// Factorise supernodally (BLAS-3, fast) and convert to the simplicial LDL' that cholmod_updown
  /// needs; false factorises simplicial LDL' directly. Our choice by measurement (docs/lattice.md).
  bool supernodal_factorization = true;
  /// Refactorise from the stored matrix after this many modify() calls (bounds round-off growth in
  /// the modified factor). Allowed: >= 1.
  int max_modifications = 2000;
  /// After every solve, ||A x - b|| / ||b|| is computed from the stored A; above this the factor is
  /// rebuilt and the solve repeated once (CholmodSolver), or the solve is reported as failed.
  /// Allowed: 0 < residual_tolerance < 1.
  double residual_tolerance = 1e-8;
  /// Whether solve() checks that residual (CholmodSolver). false: the caller checks its solves, as the
  /// flow network does when it refines a solve with an older factor against a newer matrix.
  bool check_residual = true;
  /// A pivot D_kk <= pivot_tolerance * max_k D_kk of the (modified) LDL' factor is reported as
  /// Eigen::NumericalIssue (a singular or indefinite matrix). Allowed: 0 <= pivot_tolerance < 1.
  double pivot_tolerance = 1e-13;
  /// Whether a factorisation checks its pivots against pivot_tolerance. false: only CHOLMOD's own
  /// verdict counts (its LDL' factorises an indefinite matrix without one), for a caller that detects a
  /// bad matrix by what it means, as the flow network's small-strain check does for inverted triangles.
  bool check_pivots = true;
  /// Keep the forward solution y = L^-1 P b of the last right-hand side and carry it through every
  /// modification (cholmod_updown_solve); a re-solve with the same b then needs only the backward
  /// half (D L^T x = y), about half the solve. Our choice by measurement (docs/lattice.md).
  bool reuse_forward_solve = true;
  /// Do the two triangular solves on all OpenMP threads (OMP_NUM_THREADS), the elimination tree cut
  /// into independent subtrees; false uses CHOLMOD's one-thread solves.
  /// The result does not depend on the number of threads (bitwise). Our choice by measurement
  /// (docs/lattice.md).
  bool parallel_triangular_solve = true;

  // --- PcgSolver ---------------------------------------------------------------------------------
  /// Preconditioner of PcgSolver. Our choice: incomplete Cholesky (2.4x fewer iterations than Jacobi
  /// at N = 2000, see docs/lattice.md).
  PcgPreconditioner preconditioner = PcgPreconditioner::incomplete_cholesky;
  /// Relative residual ||A x - b|| / ||b|| at which CG stops (Eigen's tolerance). Allowed: (0, 1).
  double cg_tolerance = 1e-10;
  /// CG iteration cap; 0 = the matrix dimension. Allowed: >= 0.
  int cg_max_iterations = 0;
  /// Start CG from the previous solution when the size matches (warm start). Our choice: true.
  bool warm_start = true;

  /// Throws hm::InputError "solver_options.field = value, allowed: rule".
  void validate() const;
};

/// What the last operation did (Ceres' Summary in small).
struct SpdSolveReport {
  Eigen::ComputationInfo info = Eigen::Success;
  double relative_residual = 0.0;   ///< ||A x - b|| / ||b|| of the last solve (0 for b = 0)
  int iterations = 0;               ///< CG iterations of the last solve (0 for CHOLMOD)
  bool refactorized = false;        ///< the last solve rebuilt the factor (residual too large)
  int n_factorizations = 0;         ///< numeric factorisations since construction (compute() keeps the count)
  int n_modifications = 0;          ///< modify() calls since the last factorisation
  int n_update_failures = 0;        ///< modify() calls whose factor update failed and fell back to refactorize(),
                                    ///< since construction
  int matrix_revision = 0;          ///< changes of A (compute, modify) since construction: a solve A^-1 g kept
                                    ///< by a caller is current while this is unchanged
  std::string last_update_failure;  ///< the last such failure: CHOLMOD's status, rank, sign, modifications before it
  std::string message;              ///< human-readable reason when info != Success
};

/// What SpdSolver::save_state keeps.
enum class StateScope {
  whole,       ///< everything: a checkpoint, restored into any solver made with the same options
  step_start,  ///< the state at this solver's last begin_step(), restored into this solver only: a
               ///< CholmodSolver's factor is not copied, its changes since are undone (FactorUndoLog)
};

/// Abstract sparse SPD solver. Usage: compute(A); x = solve(b); modify(W, -1); x = solve(b); ...
/// The solver keeps its own copy of A (both triangles), updated by modify(), for residual checks.
/// Limits: real double only; A must be SPD for success (a singular A gives info() = NumericalIssue).
class SpdSolver {
 public:
  using Matrix = Eigen::SparseMatrix<double>;  // column-major, both triangles stored
  virtual ~SpdSolver() = default;

  /// Analyse (ordering, symbolic) and factorise / set up for A. A square, symmetric, both triangles.
  virtual void compute(const Matrix& A) = 0;
  /// New values on the pattern of the last compute(): the factor / preconditioner is rebuilt for A with
  /// the ordering kept (a matrix assembled anew on a fixed pattern, as the flow network's every pass).
  /// Without an earlier compute(), or for another pattern, it is compute(A).
  virtual void update_values(const Matrix& A) = 0;
  /// x with A x = b for the current A. On failure info() != Success and x is unspecified.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
  /// A <- A + sigma W W^T, sigma = +1 or -1, W n x k (k small, e.g. <= 3; any k works).
  /// Entries of W W^T outside A's sparsity pattern are inserted (slower; keep them inside).
  virtual void modify(const Matrix& W, int sigma) = 0;
  /// Rebuild the numeric factor / preconditioner from the stored A (ordering kept).
  virtual void refactorize() = 0;
  /// Status of the last compute/modify/solve (Eigen::Success, NumericalIssue, NoConvergence).
  Eigen::ComputationInfo info() const { return report_.info; }
  const SpdSolveReport& report() const { return report_; }
  /// The current matrix A (after all modifications).
  const Matrix& matrix() const { return matrix_; }
  Eigen::Index rows() const { return matrix_.rows(); }
  virtual std::string name() const = 0;
  /// Marks the state a failed coupled step returns to (StateScope::step_start). A CholmodSolver logs
  /// its factor's changes from here instead of having the factor copied, and makes here the
  /// refactorisation that max_modifications calls for, never inside a step.
  virtual void begin_step() {}
  /// Frees the factor before a new A is assembled for compute(), which would free it anyway: the
  /// assembly then never holds both (at N = 1e6 the factor is 5.6 GB). Inside a step it is kept for a
  /// return to the step's start.
  virtual void discard_factor() {}
  /// The state (matrix, factor or preconditioner, warm start, counters), for checkpoints (whole) and a
  /// step's start. A solver made with the same options that restores it continues bitwise as this one
  /// would.
  virtual void save_state(core::StateWriter& w, StateScope scope) const = 0;
  /// Throws hm::InputError for a state written by other code (core::StateReader).
  virtual void restore_state(core::StateReader& r) = 0;

 protected:
  /// A += sigma W W^T on the stored copy, in place where the pattern allows.
  void add_low_rank(const Matrix& W, int sigma);
  /// ||A x - b|| / ||b|| with the stored A (||b|| = 0: ||A x||).
  double relative_residual(const Eigen::VectorXd& x, const Eigen::VectorXd& b) const;

  Matrix matrix_;
  SpdSolveReport report_;
};

/// The lock every CHOLMOD symbolic analysis holds. Its nested-dissection and METIS orderings draw on
/// METIS's process-wide random generator, which is not thread-safe: two analyses at once (two
/// benchmarks of `hmlattice verify --jobs 2`) change each other's ordering, and with it the factor's
/// round-off, so a run's bits would depend on what else the process was doing. The analysis is a small
/// part of a factorisation; the numeric factorisations still run side by side.
std::mutex& cholmod_analysis_mutex();

/// CHOLMOD LDL' with cholmod_updown (SuiteSparse 5.12). One cholmod_common per solver; every CHOLMOD
/// object is owned RAII. W's rows are permuted with the factor's ordering internally.
/// Limits: the factor's fill is fixed by the first ordering; modifications inside A's pattern keep it.
class CholmodSolver final : public SpdSolver {
 public:
  explicit CholmodSolver(const SpdSolverOptions& options = {});
  ~CholmodSolver() override;
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  void compute(const Matrix& A) override;
  void update_values(const Matrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override;
  void modify(const Matrix& W, int sigma) override;
  void refactorize() override;
  std::string name() const override { return "cholmod"; }
  void begin_step() override;
  void discard_factor() override;
  void save_state(core::StateWriter& w, StateScope scope) const override;
  void restore_state(core::StateReader& r) override;

  /// Name of the ordering the analysis used ("nesdis", "metis", "amd", ...).
  std::string ordering_used() const;
  /// Nonzeros of the factor L (with its diagonal).
  double factor_nonzeros() const;

 private:
  Eigen::VectorXd parallel_solve(const Eigen::VectorXd& b);  // options_.parallel_triangular_solve
  bool analyse(const Matrix& A);  // ordering and symbolic factor of A's pattern; false: report_ says why
  void restore_factor(core::StateReader& r, Eigen::Index n_rows);  // restore_state's factor, read in place
  bool restore_step_factor();  // restore_state's factor of the step's start (false: it had none)
  void release_factor();       // frees the factor, or keeps it aside while it is a step's start
  struct Impl;
  std::unique_ptr<Impl> impl_;
  SpdSolverOptions options_;
};

/// Eigen::ConjugateGradient with an incomplete-Cholesky or Jacobi preconditioner, warm start.
/// Limits: the iteration count grows with the condition number (~sqrt(cond)); no factor reuse.
class PcgSolver final : public SpdSolver {
 public:
  explicit PcgSolver(const SpdSolverOptions& options = {});
  ~PcgSolver() override;
  PcgSolver(const PcgSolver&) = delete;
  PcgSolver& operator=(const PcgSolver&) = delete;

  void compute(const Matrix& A) override;
  void update_values(const Matrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override;
  void modify(const Matrix& W, int sigma) override;
  void refactorize() override;
  std::string name() const override { return "pcg"; }
  void save_state(core::StateWriter& w, StateScope scope) const override;
  void restore_state(core::StateReader& r) override;
  /// Forget the previous solution (the next solve starts from x = 0).
  void clear_warm_start() { previous_.resize(0); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  SpdSolverOptions options_;
  Eigen::VectorXd previous_;
  bool stale_ = true;  // preconditioner out of date with matrix_
};

/// A solver of the given kind (options validated; throws hm::InputError).
std::unique_ptr<SpdSolver> make_spd_solver(SpdSolverKind kind, const SpdSolverOptions& options = {});

}  // namespace hm::lattice2d
