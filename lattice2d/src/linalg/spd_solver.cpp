#include "hm/lattice2d/linalg/spd_solver.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/IterativeLinearSolvers>
#include <cholmod.h>

#include "hm/core/input_error.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/core/validation.hpp"
#include "linalg/factor_undo_log.hpp"
#include "linalg/subtree_solve.hpp"

namespace hm::lattice2d {

void SpdSolverOptions::validate() const {
  using namespace hm::core;
  require_at_least(max_modifications, "solver_options.max_modifications", 1);
  require_open(residual_tolerance, "solver_options.residual_tolerance", 0.0, 1.0);
  require_half_open(pivot_tolerance, "solver_options.pivot_tolerance", 0.0, 1.0);
  require_open(cg_tolerance, "solver_options.cg_tolerance", 0.0, 1.0);
  require_at_least(cg_max_iterations, "solver_options.cg_max_iterations", 0);
}

// ------------------------------------------------------------------------------------------------
// SpdSolver

void SpdSolver::add_low_rank(const Matrix& W, int sigma) {
  assert(W.rows() == matrix_.rows() && "modify: W must have as many rows as A");
  assert((sigma == 1 || sigma == -1) && "modify: sigma must be +1 or -1");
  ++report_.matrix_revision;
  for (int c = 0; c < W.outerSize(); ++c)
    for (Matrix::InnerIterator p(W, c); p; ++p)
      for (Matrix::InnerIterator q(W, c); q; ++q) matrix_.coeffRef(p.row(), q.row()) += sigma * p.value() * q.value();
  if (!matrix_.isCompressed()) matrix_.makeCompressed();
}

double SpdSolver::relative_residual(const Eigen::VectorXd& x, const Eigen::VectorXd& b) const {
  // A is symmetric with both triangles stored: entry k of A x is column k's dot product with x, a
  // gather with rows independent. A fixed number of row chunks (summed in order) run on the threads
  // for a large A: the same bits on any number of threads.
  assert(matrix_.isCompressed());
  constexpr int kChunks = SubtreeSolve::kGroups;
  const auto n = static_cast<int>(matrix_.cols());
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  const double* value = matrix_.valuePtr();
  std::array<double, kChunks> r2{};
#pragma omp parallel for schedule(static) if (matrix_.nonZeros() >= SubtreeSolve::kParallelNonzeros)
  for (int chunk = 0; chunk < kChunks; ++chunk) {
    double sum = 0.0;
    for (int k = chunk * n / kChunks; k < (chunk + 1) * n / kChunks; ++k) {
      double ax = 0.0;
      for (int q = outer[k]; q < outer[k + 1]; ++q) ax += value[q] * x[inner[q]];
      sum += (ax - b[k]) * (ax - b[k]);
    }
    r2[static_cast<std::size_t>(chunk)] = sum;
  }
  double total = 0.0;
  for (double part : r2) total += part;
  const double r = std::sqrt(total), nb = b.norm();
  return nb > 0.0 ? r / nb : r;
}

// ------------------------------------------------------------------------------------------------
// CholmodSolver

// RAII owners of CHOLMOD objects; each needs the solver's cholmod_common to be freed. A named
// namespace, not an anonymous one: CholmodSolver::Impl, declared in the header, holds them.
namespace cholmod_owners {

struct SparseDeleter {
  cholmod_common* common;
  void operator()(cholmod_sparse* a) const { cholmod_free_sparse(&a, common); }
};
struct FactorDeleter {
  cholmod_common* common;
  void operator()(cholmod_factor* f) const { cholmod_free_factor(&f, common); }
};
struct DenseDeleter {
  cholmod_common* common;
  void operator()(cholmod_dense* d) const { cholmod_free_dense(&d, common); }
};
using SparsePtr = std::unique_ptr<cholmod_sparse, SparseDeleter>;
using FactorPtr = std::unique_ptr<cholmod_factor, FactorDeleter>;
using DensePtr = std::unique_ptr<cholmod_dense, DenseDeleter>;

}  // namespace cholmod_owners
using namespace cholmod_owners;

struct CholmodSolver::Impl {
  // The common is declared first so it outlives (is destroyed after) the objects that use it.
  struct Common {
    cholmod_common c;
    Common() {
      cholmod_start(&c);
      c.print = 0;  // trouble is reported through info(), not printed to stderr
    }
    ~Common() { cholmod_finish(&c); }
    Common(const Common&) = delete;
    Common& operator=(const Common&) = delete;
  } common;
  FactorPtr symbolic{nullptr, FactorDeleter{&common.c}};  // from cholmod_analyze, never numeric
  FactorPtr factor{nullptr, FactorDeleter{&common.c}};    // simplicial LDL' (after conversion)
  std::vector<int> inverse_permutation;                   // row r of A is row pinv[r] of L
  // The pattern `symbolic` was analysed on (the matrix of the last compute(); modifications may have
  // grown A's pattern since): a restored solver re-analyses it for the same ordering.
  std::vector<int> analysed_outer, analysed_inner;
  double lnz = 0.0;
  bool factor_ok = false;  // the factor is numerically usable (last factorise/modify succeeded)
  // Forward solution y = L^-1 P b of `forward_b`, kept current through modifications.
  DensePtr forward{nullptr, DenseDeleter{&common.c}};
  DensePtr zero_delta{nullptr, DenseDeleter{&common.c}};  // DeltaB = 0 for cholmod_updown_solve
  Eigen::VectorXd forward_b;
  SubtreeSolve subtree;          // multithreaded triangular solves (options.parallel_triangular_solve)
  bool subtree_current = false;  // subtree's partition checked against the current factor
  // The factor has only been modified (updates and downdates) since the partition's last check, so
  // its columns can only have grown: a check of the column counts suffices.
  bool subtree_only_modified = false;
  Eigen::VectorXd work;  // backward solve in the factor's order
  // The factor of the last begin_step() (a coupled step's start), without a copy of it: `set_aside`
  // once a refactorisation or a new analysis replaced it inside the step, else the current factor;
  // either with `undo`'s columns written back.
  bool recording = false;         // begin_step() was called: the factor's changes are logged
  std::int64_t step = 0;          // begin_step() calls: a step's saved state names its step
  bool step_factor = false;       // the step began with a numeric factor
  bool step_factor_lost = false;  // an update failed inside CHOLMOD after its columns were logged
  FactorUndoLog undo;
  FactorPtr set_aside{nullptr, FactorDeleter{&common.c}};

  cholmod_common* c() { return &common.c; }

  // Lower triangle of the (symmetric, both triangles) Eigen matrix as a CHOLMOD stype = -1 matrix.
  SparsePtr to_cholmod_lower(const Matrix& A) {
    const int n = static_cast<int>(A.rows());
    std::size_t nnz = 0;
    for (int j = 0; j < n; ++j)
      for (Matrix::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j) ++nnz;
    SparsePtr S(cholmod_allocate_sparse(n, n, nnz, 1, 1, -1, CHOLMOD_REAL, c()), SparseDeleter{c()});
    if (!S) return S;
    auto* p = static_cast<int*>(S->p);
    auto* i = static_cast<int*>(S->i);
    auto* x = static_cast<double*>(S->x);
    int k = 0;
    for (int j = 0; j < n; ++j) {
      p[j] = k;
      for (Matrix::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j) {
          i[k] = static_cast<int>(it.row());
          x[k] = it.value();
          ++k;
        }
    }
    p[n] = k;
    return S;
  }
};

CholmodSolver::CholmodSolver(const SpdSolverOptions& options) : impl_(std::make_unique<Impl>()), options_(options) {
  options_.validate();
}

namespace {

/// A fresh report for a new matrix that keeps the solver's lifetime counters: a caller that counts
/// factorisations over a run (CoupledStepSummary) must not see them restart when the matrix is rebuilt.
SpdSolveReport report_keeping_totals(const SpdSolveReport& old) {
  SpdSolveReport r;
  r.n_factorizations = old.n_factorizations;
  r.n_update_failures = old.n_update_failures;
  r.last_update_failure = old.last_update_failure;
  r.matrix_revision = old.matrix_revision + 1;  // a new matrix
  return r;
}

/// The smallest and largest pivot of a simplicial LDL' factor (D leads each column of L). A zero or
/// negative pivot slips through a factorisation and a downdate alike, without an error; a pivot far
/// below the largest means a matrix singular to round-off.
struct PivotRange {
  double min = INFINITY, max = 0.0;
  bool acceptable(double tolerance) const { return min > tolerance * max; }
};

PivotRange ldl_pivots(const cholmod_factor& L) {
  const auto* p = static_cast<const int*>(L.p);
  const auto* x = static_cast<const double*>(L.x);
  PivotRange d;
  for (std::size_t j = 0; j < L.n; ++j) {
    d.min = std::min(d.min, x[p[j]]);
    d.max = std::max(d.max, x[p[j]]);
  }
  return d;
}

// The pivots where they are checked; an unchecked factor (the flow's, every pass) is not scanned.
PivotRange checked_pivots(const cholmod_factor& L, bool check) { return check ? ldl_pivots(L) : PivotRange{}; }

// A numeric simplicial LDL' factor with int indices: the form cholmod_updown keeps and a state saves. A
// factorisation that failed can leave CHOLMOD's factor symbolic (no values) or in another form.
bool numeric_ldl(const cholmod_factor* L) {
  return L != nullptr && !L->is_super && !L->is_ll && L->xtype == CHOLMOD_REAL && L->itype == CHOLMOD_INT &&
         L->x != nullptr && L->nz != nullptr;
}

}  // namespace

CholmodSolver::~CholmodSolver() = default;

void CholmodSolver::compute(const Matrix& A) {
  assert(A.rows() == A.cols() && "compute: A must be square");
  matrix_ = A;
  matrix_.makeCompressed();
  report_ = report_keeping_totals(report_);
  impl_->analysed_outer.assign(matrix_.outerIndexPtr(), matrix_.outerIndexPtr() + matrix_.outerSize() + 1);
  impl_->analysed_inner.assign(matrix_.innerIndexPtr(), matrix_.innerIndexPtr() + matrix_.nonZeros());
  if (analyse(matrix_)) refactorize();
}

void CholmodSolver::update_values(const Matrix& A) {
  const bool same_pattern = impl_->symbolic && A.isCompressed() && A.rows() == matrix_.rows() &&
                            A.cols() == matrix_.cols() &&
                            static_cast<std::size_t>(A.nonZeros()) == impl_->analysed_inner.size() &&
                            std::equal(impl_->analysed_outer.begin(), impl_->analysed_outer.end(), A.outerIndexPtr()) &&
                            std::equal(impl_->analysed_inner.begin(), impl_->analysed_inner.end(), A.innerIndexPtr());
  if (!same_pattern) return compute(A);
  matrix_ = A;  // the analysed pattern (a modification may have grown the stored one since)
  report_ = report_keeping_totals(report_);
  refactorize();
}

std::mutex& cholmod_analysis_mutex() {
  static std::mutex m;
  return m;
}

bool CholmodSolver::analyse(const Matrix& A) {
  cholmod_common* c = impl_->c();
  c->final_ll = 0;
  c->supernodal = options_.supernodal_factorization ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
  c->postorder = 1;
  switch (options_.ordering) {
    case CholmodOrdering::nested_dissection:
      c->nmethods = 1;
      c->method[0].ordering = CHOLMOD_NESDIS;
      break;
    case CholmodOrdering::metis:
      c->nmethods = 1;
      c->method[0].ordering = CHOLMOD_METIS;
      break;
    case CholmodOrdering::amd:
      c->nmethods = 1;
      c->method[0].ordering = CHOLMOD_AMD;
      break;
    case CholmodOrdering::automatic: c->nmethods = 0; break;
  }
  release_factor();
  impl_->symbolic.reset();
  SparsePtr S = impl_->to_cholmod_lower(A);
  if (S) {
    const std::lock_guard<std::mutex> lock(cholmod_analysis_mutex());
    impl_->symbolic.reset(cholmod_analyze(S.get(), c));
  }
  if (!impl_->symbolic) {
    report_.info = Eigen::NumericalIssue;
    report_.message = "cholmod_analyze failed (status " + std::to_string(c->status) + ")";
    return false;
  }
  impl_->lnz = c->lnz;
  const int n = static_cast<int>(A.rows());
  const auto* perm = static_cast<const int*>(impl_->symbolic->Perm);
  impl_->inverse_permutation.assign(static_cast<std::size_t>(n), 0);
  for (int k = 0; k < n; ++k) impl_->inverse_permutation[static_cast<std::size_t>(perm[k])] = k;
  return true;
}

namespace {

// The report's fields, saved or restored (Archive: core::StateWriter with a const report, or StateReader).
template <class Archive, class Report>
void transfer_report(Archive& a, Report& r) {
  a.io("report.info", r.info);
  a.io("report.relative_residual", r.relative_residual);
  a.io("report.iterations", r.iterations);
  a.io("report.refactorized", r.refactorized);
  a.io("report.n_factorizations", r.n_factorizations);
  a.io("report.n_modifications", r.n_modifications);
  a.io("report.n_update_failures", r.n_update_failures);
  a.io("report.last_update_failure", r.last_update_failure);
  a.io("report.matrix_revision", r.matrix_revision);
  a.io("report.message", r.message);
}

template <class T>
const T* elements(const void* data) {
  return static_cast<const T*>(data);
}

template <class T>
void copy_into(void* data, const std::vector<T>& v) {
  std::copy(v.begin(), v.end(), static_cast<T*>(data));
}

}  // namespace

void CholmodSolver::save_state(core::StateWriter& w, StateScope scope) const {
  w.put("cholmod.scope", scope);
  if (scope == StateScope::step_start) w.put("cholmod.step", impl_->step);
  w.put_sparse("cholmod.matrix", matrix_);
  transfer_report(w, report_);
  w.put("cholmod.analysed_outer", impl_->analysed_outer);
  w.put("cholmod.analysed_inner", impl_->analysed_inner);
  w.put("cholmod.factor_ok", impl_->factor_ok);
  if (scope == StateScope::whole) {
    // The simplicial LDL' factor as CHOLMOD holds it after updates: its column layout (p, nz, next,
    // prev) depends on how columns grew, so every array is kept, not just L's entries. Any other
    // form is saved as absent, and the restored solver factorises again, as this one would.
    const cholmod_factor* L = numeric_ldl(impl_->factor.get()) ? impl_->factor.get() : nullptr;
    w.put("cholmod.has_factor", L != nullptr);
    if (L) {
      const std::size_t n = L->n;
      w.put("L.n", n);
      w.put("L.minor", L->minor);
      w.put("L.nzmax", L->nzmax);
      w.put("L.ordering", L->ordering);
      w.put("L.is_monotonic", L->is_monotonic);
      w.put("L.Perm", elements<int>(L->Perm), n);
      w.put("L.ColCount", elements<int>(L->ColCount), n);
      w.put("L.p", elements<int>(L->p), n + 1);
      w.put("L.i", elements<int>(L->i), L->nzmax);
      w.put("L.x", elements<double>(L->x), L->nzmax);
      w.put("L.nz", elements<int>(L->nz), n);
      w.put("L.next", elements<int>(L->next), n + 2);
      w.put("L.prev", elements<int>(L->prev), n + 2);
    }
  }
  w.put("cholmod.has_forward", impl_->forward != nullptr);
  if (impl_->forward) {
    w.put("forward.y", elements<double>(impl_->forward->x), impl_->forward->nrow);
    w.put("forward.b", impl_->forward_b);
  }
}

void CholmodSolver::begin_step() {
  impl_->recording = false;
  impl_->set_aside.reset();
  impl_->undo.clear();
  // Due by max_modifications: made at a step's start, so that a step never needs the factor it
  // replaced, and a retried step refactorises where a run that took the shorter step directly does.
  if (impl_->factor && report_.n_modifications >= options_.max_modifications) refactorize();
  impl_->recording = true;
  impl_->step_factor = numeric_ldl(impl_->factor.get());
  impl_->step_factor_lost = false;
  ++impl_->step;
}

void CholmodSolver::discard_factor() { release_factor(); }

void CholmodSolver::release_factor() {
  if (impl_->recording && impl_->step_factor && !impl_->step_factor_lost && !impl_->set_aside)
    impl_->set_aside = std::move(impl_->factor);
  impl_->factor.reset();
  impl_->factor_ok = false;
  impl_->forward.reset();
  impl_->subtree_current = false;
  impl_->subtree_only_modified = false;
}

namespace {

// The saved factor's arrays index one another and the matrix: a damaged checkpoint whose checksum
// still matches must be refused here, before CHOLMOD follows an index out of its arrays.
void check_factor_arrays(const cholmod_factor& L, Eigen::Index n_rows, const std::string& source) {
  const auto fail = [&](const std::string& what) {
    throw InputError(source + ": the mechanics factor is inconsistent (" + what + ")");
  };
  const long n = static_cast<long>(L.n), nzmax = static_cast<long>(L.nzmax);
  if (n != n_rows) fail("L.n = " + std::to_string(n) + ", the matrix has " + std::to_string(n_rows) + " rows");
  if (static_cast<long>(L.minor) > n) fail("L.minor > n");
  const auto* perm = static_cast<const int*>(L.Perm);
  const auto* p = static_cast<const int*>(L.p);
  const auto* i = static_cast<const int*>(L.i);
  const auto* nz = static_cast<const int*>(L.nz);
  const auto* next = static_cast<const int*>(L.next);
  const auto* prev = static_cast<const int*>(L.prev);
  std::vector<bool> seen(static_cast<std::size_t>(n), false);
  for (long j = 0; j < n; ++j) {
    if (perm[j] < 0 || perm[j] >= n || seen[static_cast<std::size_t>(perm[j])]) fail("L.Perm is not a permutation");
    seen[static_cast<std::size_t>(perm[j])] = true;
    if (p[j] < 0 || nz[j] < 1 || static_cast<long>(p[j]) + nz[j] > nzmax)
      fail("column " + std::to_string(j) + " out of L");
    if (i[p[j]] != j) fail("column " + std::to_string(j) + " does not start on its diagonal");
    for (int k = p[j] + 1; k < p[j] + nz[j]; ++k)
      if (i[k] <= j || i[k] >= n) fail("row index out of range in column " + std::to_string(j));
  }
  for (long j = 0; j < n + 2; ++j)
    if (next[j] < -1 || next[j] > n + 1 || prev[j] < -1 || prev[j] > n + 1) fail("column list out of range");
}

}  // namespace

void CholmodSolver::restore_state(core::StateReader& r) {
  StateScope scope = StateScope::whole;
  r.get("cholmod.scope", scope);
  if (scope == StateScope::step_start) {
    std::int64_t step = 0;
    r.get("cholmod.step", step);
    if (!impl_->recording || step != impl_->step)
      throw std::logic_error("CholmodSolver::restore_state: the start of step " + std::to_string(step) +
                             ", restored into a solver that is not in it");
  } else if (scope != StateScope::whole) {
    throw InputError(r.source() + ": at 'cholmod.scope': not a state this build writes");
  } else {  // a whole state replaces the factor that any step's log refers to
    impl_->recording = false;
    impl_->set_aside.reset();
    impl_->undo.clear();
  }
  r.get_sparse("cholmod.matrix", matrix_);
  transfer_report(r, report_);
  std::vector<int> outer, inner;
  r.get("cholmod.analysed_outer", outer);
  r.get("cholmod.analysed_inner", inner);
  bool factor_ok = false, has_factor = false, has_forward = false;
  r.get("cholmod.factor_ok", factor_ok);
  if (scope == StateScope::whole) r.get("cholmod.has_factor", has_factor);
  const auto n_rows = static_cast<Eigen::Index>(outer.size()) - 1;
  if (n_rows != matrix_.rows())
    throw InputError(r.source() + ": at 'cholmod.analysed_outer': a pattern of " + std::to_string(n_rows) +
                     " rows for a matrix of " + std::to_string(matrix_.rows()));
  core::check_compressed_pattern(outer.data(), inner.data(), n_rows, n_rows, inner.size(), r.source(),
                                 "cholmod.analysed_inner");
  // The ordering is a function of the pattern: analysing the same one gives the same symbolic factor,
  // so a step's snapshot, whose pattern is this solver's, keeps it (an analysis costs seconds at 1e6).
  if (!impl_->symbolic || outer != impl_->analysed_outer || inner != impl_->analysed_inner) {
    impl_->analysed_outer = std::move(outer);
    impl_->analysed_inner = std::move(inner);
    const std::vector<double> ones(impl_->analysed_inner.size(), 1.0);
    const Matrix analysed =
        Eigen::Map<const Matrix>(n_rows, n_rows, static_cast<Eigen::Index>(ones.size()), impl_->analysed_outer.data(),
                                 impl_->analysed_inner.data(), ones.data());
    const SpdSolveReport report = report_;
    if (!analyse(analysed)) throw std::runtime_error("restoring the mechanics solver: " + report_.message);
    report_ = report;
  }
  impl_->subtree_current = false;
  impl_->subtree_only_modified = false;
  if (scope == StateScope::step_start)
    has_factor = restore_step_factor();
  else if (has_factor)
    restore_factor(r, n_rows);
  else
    impl_->factor.reset();
  impl_->factor_ok = factor_ok && has_factor;
  r.get("cholmod.has_forward", has_forward);
  if (has_forward) {
    // The arrays are read into storage of the right size, kept when it has it: a restore holds one
    // factor and its snapshot, never two factors (4 GB each at N = 1e6).
    if (!impl_->forward || impl_->forward->nrow != static_cast<std::size_t>(n_rows))
      impl_->forward.reset(cholmod_allocate_dense(n_rows, 1, n_rows, CHOLMOD_REAL, impl_->c()));
    if (!impl_->forward) throw std::runtime_error("restoring the mechanics solver: out of memory");
    r.get("forward.y", static_cast<double*>(impl_->forward->x), static_cast<std::size_t>(n_rows));
    r.get("forward.b", impl_->forward_b);
    if (impl_->forward_b.size() != matrix_.rows()) throw InputError(r.source() + ": at 'forward.b': wrong size");
  } else {
    impl_->forward.reset();
  }
}

namespace {

// The saved arrays of a factor into L (of the saved n and nzmax), checked.
void read_factor_arrays(core::StateReader& r, cholmod_factor& L, std::size_t minor, Eigen::Index n_rows) {
  const std::size_t n = L.n, nzmax = L.nzmax;
  L.minor = minor;
  r.get("L.ordering", L.ordering);
  r.get("L.is_monotonic", L.is_monotonic);
  r.get("L.Perm", static_cast<int*>(L.Perm), n);
  r.get("L.ColCount", static_cast<int*>(L.ColCount), n);
  r.get("L.p", static_cast<int*>(L.p), n + 1);
  r.get("L.i", static_cast<int*>(L.i), nzmax);
  r.get("L.x", static_cast<double*>(L.x), nzmax);
  r.get("L.nz", static_cast<int*>(L.nz), n);
  r.get("L.next", static_cast<int*>(L.next), n + 2);
  r.get("L.prev", static_cast<int*>(L.prev), n + 2);
  check_factor_arrays(L, n_rows, r.source());
}

}  // namespace

bool CholmodSolver::restore_step_factor() {
  FactorPtr& L = impl_->factor;
  if (impl_->set_aside) L = std::move(impl_->set_aside);
  if (!impl_->step_factor) {
    L.reset();
  } else if (!impl_->step_factor_lost) {
    impl_->undo.undo(*L);
  } else {
    // CHOLMOD failed inside an update (out of memory while a column grew) and may have left the
    // factor symbolic: the step's factor is rebuilt from its matrix, the same to round-off.
    const SpdSolveReport report = report_;
    impl_->recording = false;
    refactorize();
    impl_->recording = true;
    if (report_.info != Eigen::Success) throw std::runtime_error("restoring a step's start: " + report_.message);
    report_ = report;
  }
  impl_->undo.clear();
  impl_->step_factor_lost = false;
  return impl_->step_factor;
}

void CholmodSolver::restore_factor(core::StateReader& r, Eigen::Index n_rows) {
  cholmod_common* c = impl_->c();
  std::size_t n = 0, minor = 0, nzmax = 0;
  r.get("L.n", n);
  r.get("L.minor", minor);
  r.get("L.nzmax", nzmax);
  if (n != static_cast<std::size_t>(n_rows))
    throw InputError(r.source() + ": the mechanics factor is inconsistent (L.n = " + std::to_string(n) +
                     ", the matrix has " + std::to_string(n_rows) + " rows)");
  // A numeric simplicial LDL' of the right size, whose arrays are then overwritten with the saved
  // ones: the current factor when it is one (a step's snapshot), else a new one.
  cholmod_factor* current = impl_->factor.get();
  if (!(current && !current->is_super && !current->is_ll && current->xtype == CHOLMOD_REAL &&
        current->itype == CHOLMOD_INT && current->n == n && current->nzmax == nzmax && current->nz && current->next &&
        current->prev && current->ColCount)) {
    impl_->factor.reset();  // before the new one is made: never two factors at once
    FactorPtr L(cholmod_allocate_factor(n, c), FactorDeleter{c});
    if (!L || !cholmod_change_factor(CHOLMOD_REAL, 0, 0, 1, 1, L.get(), c) ||
        !cholmod_reallocate_factor(nzmax, L.get(), c))
      throw std::runtime_error("restoring the mechanics solver: out of memory for its factor");
    impl_->factor = std::move(L);
  }
  cholmod_factor& L = *impl_->factor;
  try {  // a damaged state leaves no factor, never one whose arrays index out of themselves
    read_factor_arrays(r, L, minor, n_rows);
  } catch (...) {
    impl_->factor.reset();
    throw;
  }
}

void CholmodSolver::refactorize() {
  cholmod_common* c = impl_->c();
  report_.n_modifications = 0;
  if (!impl_->symbolic) {
    report_.info = Eigen::InvalidInput;
    report_.message = "refactorize before compute";
    return;
  }
  release_factor();
  impl_->factor.reset(cholmod_copy_factor(impl_->symbolic.get(), c));
  SparsePtr S = impl_->to_cholmod_lower(matrix_);
  bool ok = impl_->factor && S && cholmod_factorize(S.get(), impl_->factor.get(), c);
  ++report_.n_factorizations;
  if (!ok || c->status == CHOLMOD_NOT_POSDEF) {
    report_.info = Eigen::NumericalIssue;
    report_.message = "cholmod_factorize: matrix not positive definite at column " +
                      std::to_string(impl_->factor ? static_cast<long>(impl_->factor->minor) : -1L);
    return;
  }
  // cholmod_updown needs a simplicial LDL' factor: convert a supernodal LL' one once here.
  if (!cholmod_change_factor(CHOLMOD_REAL, 0, 0, 1, 1, impl_->factor.get(), c)) {
    report_.info = Eigen::NumericalIssue;
    report_.message = "cholmod_change_factor to simplicial LDL' failed";
    return;
  }
  report_.info = Eigen::Success;
  report_.message.clear();
  if (const PivotRange d = checked_pivots(*impl_->factor, options_.check_pivots);
      !d.acceptable(options_.pivot_tolerance)) {
    report_.info = Eigen::NumericalIssue;
    report_.message = "LDL' pivot " + hm::core::format_value(d.min) + " <= pivot_tolerance * max pivot " +
                      hm::core::format_value(d.max) + ": matrix singular or indefinite";
  }
  impl_->factor_ok = report_.info == Eigen::Success;
}

void CholmodSolver::modify(const Matrix& W, int sigma) {
  add_low_rank(W, sigma);
  if (!impl_->factor) {
    report_.info = Eigen::InvalidInput;
    report_.message = "modify before compute";
    return;
  }
  // Inside a coupled step the refactorisation that is due waits for the next step's start
  // (begin_step), so that the step's start stays the factor with its logged columns written back.
  if (++report_.n_modifications >= options_.max_modifications && !impl_->recording) {
    refactorize();
    return;
  }
  cholmod_common* c = impl_->c();
  const int n = static_cast<int>(W.rows()), k = static_cast<int>(W.cols());
  // C = P W: row r of W goes to row pinv[r] (cholmod_updown works on the permuted factor), columns
  // sorted by row as CHOLMOD requires.
  std::vector<std::pair<int, double>> column;
  SparsePtr C(cholmod_allocate_sparse(n, k, W.nonZeros(), 1, 1, 0, CHOLMOD_REAL, c), SparseDeleter{c});
  if (!C) {
    report_.info = Eigen::NumericalIssue;
    report_.message = "cholmod_allocate_sparse failed";
    return;
  }
  auto* p = static_cast<int*>(C->p);
  auto* i = static_cast<int*>(C->i);
  auto* x = static_cast<double*>(C->x);
  int nz = 0;
  for (int j = 0; j < k; ++j) {
    p[j] = nz;
    column.clear();
    for (Matrix::InnerIterator it(W, j); it; ++it)
      column.emplace_back(impl_->inverse_permutation[static_cast<std::size_t>(it.row())], it.value());
    std::sort(column.begin(), column.end());
    for (const auto& [row, value] : column) {
      i[nz] = row;
      x[nz] = value;
      ++nz;
    }
  }
  p[k] = nz;
  impl_->factor_ok = false;
  impl_->subtree_current = false;
  if (impl_->recording && impl_->step_factor && !impl_->set_aside) impl_->undo.before_update(*impl_->factor, *C);
  bool ok;
  if (impl_->forward) {
    // DeltaB must have the factor's size: a compute() on a matrix of another size (the mechanics
    // holds a rotation) left the old one, and every update then failed with CHOLMOD_INVALID.
    if (!impl_->zero_delta || impl_->zero_delta->nrow != static_cast<std::size_t>(n))
      impl_->zero_delta.reset(cholmod_zeros(static_cast<std::size_t>(n), 1, CHOLMOD_REAL, c));
    ok = impl_->zero_delta && cholmod_updown_solve(sigma > 0 ? 1 : 0, C.get(), impl_->factor.get(),
                                                   impl_->forward.get(), impl_->zero_delta.get(), c);
  } else {
    ok = cholmod_updown(sigma > 0 ? 1 : 0, C.get(), impl_->factor.get(), c);
  }
  if (!ok) {
    // Out of memory while a column of L grows (W outside A's pattern), or a bad argument: A itself
    // is current (add_low_rank above), so rebuild the factor from it.
    report_.last_update_failure = "cholmod_updown" + std::string(impl_->forward ? "_solve" : "") + " status " +
                                  std::to_string(c->status) + ", rank " + std::to_string(k) + ", sigma " +
                                  std::to_string(sigma) + ", after " + std::to_string(report_.n_modifications - 1) +
                                  " modifications";
    impl_->forward.reset();
    ++report_.n_update_failures;
    if (impl_->recording && !impl_->set_aside) impl_->step_factor_lost = true;
    refactorize();
    return;
  }
  // Only the pivots on the modified path change, but an O(n) scan is cheap against a solve.
  if (const PivotRange d = checked_pivots(*impl_->factor, options_.check_pivots);
      !d.acceptable(options_.pivot_tolerance)) {
    report_.info = Eigen::NumericalIssue;
    report_.message =
        "LDL' pivot " + hm::core::format_value(d.min) + " after a low-rank modification: matrix singular or indefinite";
  } else {
    report_.info = Eigen::Success;
    report_.message.clear();
  }
  impl_->factor_ok = report_.info == Eigen::Success;
}

Eigen::VectorXd CholmodSolver::solve(const Eigen::VectorXd& b) {
  assert(b.size() == matrix_.rows() && "solve: b has the wrong size");
  report_.refactorized = false;
  report_.iterations = 0;
  if (!impl_->factor_ok) {
    if (report_.info == Eigen::Success) report_.info = Eigen::InvalidInput;
    if (report_.message.empty()) report_.message = "solve without a valid factor";
    return Eigen::VectorXd::Constant(b.size(), NAN);
  }
  cholmod_common* c = impl_->c();
  auto run = [&]() {
    cholmod_dense B{};
    B.nrow = B.d = static_cast<std::size_t>(b.size());
    B.ncol = 1;
    B.nzmax = B.nrow;
    B.x = const_cast<double*>(b.data());  // CHOLMOD does not write B
    B.xtype = CHOLMOD_REAL;
    B.dtype = CHOLMOD_DOUBLE;
    DensePtr X{nullptr, DenseDeleter{c}};
    if (options_.parallel_triangular_solve) {
      return parallel_solve(b);
    } else if (!options_.reuse_forward_solve) {
      X.reset(cholmod_solve(CHOLMOD_A, impl_->factor.get(), &B, c));
    } else {
      // x = P^T (D L^T)^-1 y with y = L^-1 P b, y kept for the next re-solve with the same b.
      if (!impl_->forward || impl_->forward_b.size() != b.size() || impl_->forward_b != b) {
        impl_->forward.reset();
        DensePtr PB(cholmod_solve(CHOLMOD_P, impl_->factor.get(), &B, c), DenseDeleter{c});
        if (PB) impl_->forward.reset(cholmod_solve(CHOLMOD_L, impl_->factor.get(), PB.get(), c));
        impl_->forward_b = b;
      }
      if (impl_->forward) {
        DensePtr Y(cholmod_solve(CHOLMOD_DLt, impl_->factor.get(), impl_->forward.get(), c), DenseDeleter{c});
        if (Y) X.reset(cholmod_solve(CHOLMOD_Pt, impl_->factor.get(), Y.get(), c));
      }
    }
    Eigen::VectorXd x = Eigen::VectorXd::Constant(b.size(), NAN);
    if (X) x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(X->x), b.size());
    return x;
  };
  Eigen::VectorXd x = run();
  report_.info = Eigen::Success;
  report_.message.clear();
  if (!options_.check_residual) return x;
  report_.relative_residual = relative_residual(x, b);
  if (!(report_.relative_residual <= options_.residual_tolerance)) {
    // Round-off accumulated by many updates/downdates: rebuild the factor from A and try once more.
    refactorize();
    report_.refactorized = true;
    if (report_.info == Eigen::Success) {
      x = run();
      report_.relative_residual = relative_residual(x, b);
    }
    if (report_.info == Eigen::Success && !(report_.relative_residual <= options_.residual_tolerance)) {
      report_.info = Eigen::NumericalIssue;
      report_.message = "relative residual " + hm::core::format_value(report_.relative_residual) +
                        " > residual_tolerance after refactorisation (ill-conditioned matrix?)";
    }
  }
  return x;
}

Eigen::VectorXd CholmodSolver::parallel_solve(const Eigen::VectorXd& b) {
  // The same steps as CHOLMOD_P, _L, _DLt, _Pt, with SubtreeSolve's triangular solves.
  const cholmod_factor& L = *impl_->factor;
  const auto* perm = static_cast<const int*>(L.Perm);
  const Eigen::Index n = b.size();
  if (!impl_->subtree_current) {
    impl_->subtree.update(L, impl_->subtree_only_modified);
    impl_->subtree_current = true;
    impl_->subtree_only_modified = true;
  }
  if (!options_.reuse_forward_solve || !impl_->forward || impl_->forward_b.size() != n || impl_->forward_b != b) {
    impl_->forward.reset(
        cholmod_allocate_dense(static_cast<std::size_t>(n), 1, static_cast<std::size_t>(n), CHOLMOD_REAL, impl_->c()));
    if (!impl_->forward) return Eigen::VectorXd::Constant(n, NAN);
    auto* y = static_cast<double*>(impl_->forward->x);
    for (Eigen::Index k = 0; k < n; ++k) y[k] = b[perm[k]];
    impl_->subtree.forward(L, y);
    impl_->forward_b = b;
  }
  impl_->work = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(impl_->forward->x), n);
  impl_->subtree.backward(L, impl_->work.data());
  Eigen::VectorXd x(n);
  for (Eigen::Index k = 0; k < n; ++k) x[perm[k]] = impl_->work[k];
  return x;
}

std::string CholmodSolver::ordering_used() const {
  if (!impl_->symbolic) return "none";
  switch (impl_->symbolic->ordering) {
    case CHOLMOD_NATURAL: return "natural";
    case CHOLMOD_GIVEN: return "given";
    case CHOLMOD_AMD: return "amd";
    case CHOLMOD_METIS: return "metis";
    case CHOLMOD_NESDIS: return "nesdis";
    case CHOLMOD_COLAMD: return "colamd";
    case CHOLMOD_POSTORDERED: return "postordered";
    default: return "unknown";
  }
}

double CholmodSolver::factor_nonzeros() const { return impl_->lnz; }

// ------------------------------------------------------------------------------------------------
// PcgSolver

struct PcgSolver::Impl {
  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>> ichol;
  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>> jacobi;
};

PcgSolver::PcgSolver(const SpdSolverOptions& options) : impl_(std::make_unique<Impl>()), options_(options) {
  options_.validate();
}

PcgSolver::~PcgSolver() = default;

void PcgSolver::compute(const Matrix& A) {
  matrix_ = A;
  matrix_.makeCompressed();
  report_ = report_keeping_totals(report_);
  previous_.resize(0);
  refactorize();
}

void PcgSolver::update_values(const Matrix& A) {
  if (A.rows() != matrix_.rows() || A.nonZeros() != matrix_.nonZeros()) return compute(A);
  matrix_ = A;
  matrix_.makeCompressed();
  ++report_.matrix_revision;
  refactorize();
}

void PcgSolver::refactorize() {
  report_.n_modifications = 0;
  ++report_.n_factorizations;
  Eigen::ComputationInfo info;
  if (options_.preconditioner == PcgPreconditioner::incomplete_cholesky) {
    impl_->ichol.compute(matrix_);
    info = impl_->ichol.info();
  } else {
    impl_->jacobi.compute(matrix_);
    info = impl_->jacobi.info();
  }
  report_.info = info;
  report_.message = info == Eigen::Success ? "" : "preconditioner set-up failed";
  stale_ = false;
}

void PcgSolver::modify(const Matrix& W, int sigma) {
  add_low_rank(W, sigma);
  ++report_.n_modifications;
  stale_ = true;  // rebuilt at the next solve, so several modifications cost one set-up
}

void PcgSolver::save_state(core::StateWriter& w, StateScope) const {  // its state is small: whole
  w.put_sparse("pcg.matrix", matrix_);
  transfer_report(w, report_);
  w.put("pcg.previous", previous_);
  w.put("pcg.stale", stale_);
}

void PcgSolver::restore_state(core::StateReader& r) {
  r.get_sparse("pcg.matrix", matrix_);
  transfer_report(r, report_);
  r.get("pcg.previous", previous_);
  r.get("pcg.stale", stale_);
  if (!stale_) {  // the preconditioner is a function of the matrix: rebuild it without counting
    const SpdSolveReport report = report_;
    refactorize();
    report_ = report;
  }
}

Eigen::VectorXd PcgSolver::solve(const Eigen::VectorXd& b) {
  assert(b.size() == matrix_.rows() && "solve: b has the wrong size");
  report_.refactorized = false;
  if (stale_) {
    refactorize();
    report_.refactorized = true;
  }
  if (report_.info != Eigen::Success && report_.info != Eigen::NoConvergence)
    return Eigen::VectorXd::Constant(b.size(), NAN);
  const Eigen::Index max_it = options_.cg_max_iterations > 0 ? options_.cg_max_iterations : matrix_.rows();
  const bool warm = options_.warm_start && previous_.size() == b.size() && previous_.allFinite();
  const Eigen::VectorXd guess = warm ? previous_ : Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd x;
  Eigen::ComputationInfo info;
  if (options_.preconditioner == PcgPreconditioner::incomplete_cholesky) {
    auto& cg = impl_->ichol;
    cg.setTolerance(options_.cg_tolerance).setMaxIterations(max_it);
    x = cg.solveWithGuess(b, guess);
    info = cg.info();
    report_.iterations = static_cast<int>(cg.iterations());
  } else {
    auto& cg = impl_->jacobi;
    cg.setTolerance(options_.cg_tolerance).setMaxIterations(max_it);
    x = cg.solveWithGuess(b, guess);
    info = cg.info();
    report_.iterations = static_cast<int>(cg.iterations());
  }
  report_.relative_residual = relative_residual(x, b);
  report_.info = info;
  report_.message = info == Eigen::Success
                        ? ""
                        : "CG stopped after " + std::to_string(report_.iterations) +
                              " iterations at relative residual " + hm::core::format_value(report_.relative_residual);
  if (info == Eigen::Success) previous_ = x;
  return x;
}

// ------------------------------------------------------------------------------------------------

std::unique_ptr<SpdSolver> make_spd_solver(SpdSolverKind kind, const SpdSolverOptions& options) {
  if (kind == SpdSolverKind::pcg) return std::make_unique<PcgSolver>(options);
  return std::make_unique<CholmodSolver>(options);
}

}  // namespace hm::lattice2d
