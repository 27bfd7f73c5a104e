#include "linalg/factor_undo_log.hpp"

#include <algorithm>
#include <stdexcept>

namespace hm::lattice2d {

void FactorUndoLog::clear() {
  for (const int j : column_) kept_[static_cast<std::size_t>(j)] = 0;
  column_.clear();
  start_.clear();
  rows_.clear();
  values_.clear();
}

void FactorUndoLog::before_update(const cholmod_factor& L, const cholmod_sparse& C) {
  if (kept_.size() != L.n) {
    clear();
    kept_.assign(L.n, 0);
  }
  const auto* Lp = static_cast<const int*>(L.p);
  const auto* Li = static_cast<const int*>(L.i);
  const auto* Lx = static_cast<const double*>(L.x);
  const auto* Lnz = static_cast<const int*>(L.nz);
  const auto* Cp = static_cast<const int*>(C.p);
  const auto* Ci = static_cast<const int*>(C.i);
  // Column j's rows are sorted with its diagonal first, so its parent in the elimination tree is its
  // second row. A kept column's ancestors are kept too (each path is followed to the root or to a kept
  // column), so a path stops at the first kept column.
  for (std::size_t k = 0; k < C.ncol; ++k)
    for (int q = Cp[k]; q < Cp[k + 1]; ++q)
      for (int j = Ci[q]; j >= 0 && !kept_[static_cast<std::size_t>(j)]; j = Lnz[j] > 1 ? Li[Lp[j] + 1] : -1) {
        kept_[static_cast<std::size_t>(j)] = 1;
        column_.push_back(j);
        start_.push_back(static_cast<std::int64_t>(rows_.size()));
        rows_.insert(rows_.end(), Li + Lp[j], Li + Lp[j] + Lnz[j]);
        values_.insert(values_.end(), Lx + Lp[j], Lx + Lp[j] + Lnz[j]);
      }
}

void FactorUndoLog::undo(cholmod_factor& L) {
  auto* Lp = static_cast<int*>(L.p);
  auto* Li = static_cast<int*>(L.i);
  auto* Lx = static_cast<double*>(L.x);
  auto* Lnz = static_cast<int*>(L.nz);
  for (std::size_t c = 0; c < column_.size(); ++c) {
    const int j = column_[c];
    const std::int64_t begin = start_[c];
    const std::int64_t end = c + 1 < column_.size() ? start_[c + 1] : static_cast<std::int64_t>(rows_.size());
    const int count = static_cast<int>(end - begin);
    // An update only adds entries to a column (CHOLMOD keeps the ones that become zero), and a column
    // that grew was given room for all of them: the old content fits where the column is now.
    if (static_cast<std::size_t>(j) >= L.n || Lnz[j] < count)
      throw std::logic_error("FactorUndoLog::undo: not the factor the columns were kept from");
    Lnz[j] = count;
    std::copy(rows_.begin() + begin, rows_.begin() + end, Li + Lp[j]);
    std::copy(values_.begin() + begin, values_.begin() + end, Lx + Lp[j]);
  }
  clear();
}

}  // namespace hm::lattice2d
