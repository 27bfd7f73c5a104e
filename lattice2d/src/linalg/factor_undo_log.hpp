#pragma once
/// Takes a simplicial LDL' factor back to an earlier state after cholmod_updown changed it, without a
/// copy of the factor.
///
/// Why: a coupled step that fails is retried from its start, which needs the factor of the step's
/// start. A copy of it was most of a large run's memory (5.6 GB of the 6.5 GB state at N = 1e6). An
/// update or downdate L D L' +- C C' changes only the columns of L in the nonzero pattern of L^-1 C: the
/// paths from C's rows to the root of L's elimination tree (Davis & Hager 1999, SIAM J. Matrix Anal.
/// Appl. 20:606; the fill it adds to a column comes from that pattern too). Those columns, kept as they
/// were before their first change, are all that differs.
///
/// What undo() restores is each kept column's content (count, row indices, values) at the column's
/// current place: CHOLMOD may have moved a column that grew, so the layout (p, next, prev, free space)
/// can differ from the earlier one, but solves and updates read each column through p and nz, so the
/// arithmetic after an undo is bitwise that of the earlier factor.
#include <cstdint>
#include <vector>

#include <cholmod.h>

namespace hm::lattice2d {

class FactorUndoLog {
 public:
  /// Forgets what was kept: the factor as it is now is the one undo() returns to.
  void clear();
  /// Before cholmod_updown(C, L) (C in L's permuted order): keeps the columns of L that the update
  /// will change and that are not kept yet.
  void before_update(const cholmod_factor& L, const cholmod_sparse& C);
  /// Writes the kept columns back into L, the factor they were kept from (whose columns have only
  /// grown since), and forgets them.
  void undo(cholmod_factor& L);

 private:
  std::vector<int> column_;          // kept columns, in the order kept
  std::vector<std::int64_t> start_;  // where each one's rows and values begin in rows_, values_
  std::vector<int> rows_;
  std::vector<double> values_;
  std::vector<char> kept_;  // per column of L: kept already
};

}  // namespace hm::lattice2d
