#pragma once
/// The two triangular solves with a simplicial LDL' CHOLMOD factor, spread over OpenMP threads.
///
/// Why: at N = 1e5 the mechanical back-substitutions are about half of a Fig. 12 run, CHOLMOD's
/// simplicial solves use one core, and one solve does not saturate the memory bandwidth (two
/// concurrent solves run at the speed of one). cholmod_updown needs the simplicial factor, so the
/// (BLAS, multithreaded) supernodal solve is not available.
///
/// How: column j of L holds the ancestors of j in the elimination tree. The tree is cut into
/// kGroups groups of whole subtrees of about equal work (nonzeros of L) plus the "top", the
/// ancestors of the cut subtrees. Forward (L y = b): each group eliminates its own columns; what
/// they send to top rows is summed per group and added in group order; then the top, on one thread.
/// Backward (D L^T x = y): the top first, then each group, which only reads its own rows and the
/// top's. The arithmetic depends on the partition, never on the number of threads: the same factor
/// and right-hand side give bitwise the same x on one or many cores.
#include <array>
#include <cstdint>
#include <vector>

#include <cholmod.h>

namespace hm::lattice2d {

class SubtreeSolve {
 public:
  /// Two groups, one per core of this project's 2-core target: fixed, not the thread count, so that
  /// the arithmetic is the same on every machine. At N = 1e5 the top holds 4% of L, the groups split
  /// the rest evenly (four groups would put 10% in the top for no gain on two cores).
  static constexpr int kGroups = 2;
  /// Below this many nonzeros (N ~ 5000 particles) the groups run one after the other on the calling
  /// thread: waking a second thread costs more than it saves, and the many small solves of a quick
  /// run would fight with other processes for the cores. Same arithmetic either way.
  static constexpr std::int64_t kParallelNonzeros = 200'000;

  /// Rebuilds the partition if L's elimination tree differs from the one it was built for (an O(n)
  /// check; the tree changes at a factorisation, and at a modification only if it adds fill).
  /// `only_modified`: L is the factor of the last call, since changed by cholmod_updown alone, so a
  /// check of its column counts suffices. L must be a simplicial LDL' factor with sorted row indices
  /// (CHOLMOD's simplicial form).
  void update(const cholmod_factor& L, bool only_modified = false);
  /// x := L^-1 x, x in the factor's (permuted) order, L unit lower triangular.
  void forward(const cholmod_factor& L, double* x);
  /// x := L^-T D^-1 x.
  void backward(const cholmod_factor& L, double* x) const;
  /// x := A^-1 b for A = P^T L D L^T P (CHOLMOD_A): update, permute, forward, backward, permute back.
  /// b and x hold L.n entries and may not overlap.
  void solve(const cholmod_factor& L, const double* b, double* x);

  /// Columns first..first+size-1 (size <= 4) solved together: a chain sharing its rows below.
  struct Block {
    int first;
    int size;
  };

  /// Share of L's nonzeros in the top (solved on one thread).
  double top_share() const { return top_share_; }
  /// Largest group's nonzeros over the mean group's (1 = perfect balance).
  double imbalance() const { return imbalance_; }

 private:
  std::vector<int> parent_;                          // elimination tree the partition was built for
  std::vector<int> nz_;                              // column counts it was built for
  std::vector<int> top_;                             // top columns, ascending
  std::vector<Block> top_blocks_;                    // the top's blocks, ascending
  std::vector<int> top_slot_;                        // row -> position in top_, -1 if not top
  std::array<std::vector<Block>, kGroups> group_;    // each group's blocks, ascending
  std::vector<int> subtree_root_;                    // column -> root of its cut subtree (rows above are top)
  std::array<std::vector<double>, kGroups> to_top_;  // forward: each group's updates of top rows
  std::vector<double> work_;                         // solve(): the permuted right-hand side
  bool parallel_ = false;                            // L has at least kParallelNonzeros
  double top_share_ = 0.0, imbalance_ = 1.0;
};

}  // namespace hm::lattice2d
