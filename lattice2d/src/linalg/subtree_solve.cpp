#include "linalg/subtree_solve.hpp"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <queue>
#include <utility>

namespace hm::lattice2d {

namespace {

struct FactorView {
  int n;
  const int* p;
  const int* i;
  const int* nz;
  const double* x;
  explicit FactorView(const cholmod_factor& L)
      : n(static_cast<int>(L.n)),
        p(static_cast<const int*>(L.p)),
        i(static_cast<const int*>(L.i)),
        nz(static_cast<const int*>(L.nz)),
        x(static_cast<const double*>(L.x)) {
    assert(!L.is_super && !L.is_ll && L.xtype == CHOLMOD_REAL && "SubtreeSolve: simplicial LDL' factor");
  }
  // Parent in the elimination tree: the first row below the diagonal (row indices sorted), -1 at a root.
  int parent(int j) const { return nz[j] > 1 ? i[p[j] + 1] : -1; }
};

// Longest-processing-time assignment of subtrees (weights w) to kGroups groups; returns each one's group
// and the largest group load.
std::pair<std::vector<int>, std::int64_t> assign_groups(const std::vector<int>& roots,
                                                        const std::vector<std::int64_t>& w, int n_groups) {
  std::vector<int> order(roots.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const auto wa = w[static_cast<std::size_t>(roots[static_cast<std::size_t>(a)])];
    const auto wb = w[static_cast<std::size_t>(roots[static_cast<std::size_t>(b)])];
    return wa != wb ? wa > wb : roots[static_cast<std::size_t>(a)] < roots[static_cast<std::size_t>(b)];
  });
  std::vector<std::int64_t> load(static_cast<std::size_t>(n_groups), 0);
  std::vector<int> group(roots.size());
  for (int k : order) {
    const auto g = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    group[static_cast<std::size_t>(k)] = static_cast<int>(g);
    load[g] += w[static_cast<std::size_t>(roots[static_cast<std::size_t>(k)])];
  }
  return {group, *std::max_element(load.begin(), load.end())};
}

// Columns (ascending) grouped into blocks of up to four consecutive ones that chain and share their
// rows below the block: column c+1 is c's parent and c has one row more.
std::vector<SubtreeSolve::Block> blocks_of(const FactorView& f, const std::vector<int>& columns) {
  std::vector<SubtreeSolve::Block> blocks;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const int c = columns[k];
    if (!blocks.empty()) {
      SubtreeSolve::Block& b = blocks.back();
      const int last = b.first + b.size - 1;
      if (b.size < 4 && c == last + 1 && f.parent(last) == c && f.nz[last] == f.nz[c] + 1) {
        ++b.size;
        continue;
      }
    }
    blocks.push_back({c, 1});
  }
  return blocks;
}

// Work of each column (its nonzeros) and of the subtree below it, and each column's children
// (children[child_start[j] .. child_start[j + 1]) of column j).
struct TreeWork {
  std::vector<std::int64_t> work;
  std::vector<int> child_start, children;
  std::int64_t total = 0;
};

TreeWork tree_work(const FactorView& f, const std::vector<int>& parent) {
  const auto n = static_cast<std::size_t>(f.n);
  TreeWork t;
  t.work.assign(n, 0);
  t.child_start.assign(n + 1, 0);
  for (std::size_t j = 0; j < n; ++j) {
    t.work[j] += f.nz[j];
    t.total += f.nz[j];
    const int pj = parent[j];
    assert((pj < 0 || static_cast<std::size_t>(pj) > j) && "SubtreeSolve: a parent follows its children");
    if (pj >= 0) {
      t.work[static_cast<std::size_t>(pj)] += t.work[j];
      ++t.child_start[static_cast<std::size_t>(pj) + 1];
    }
  }
  for (std::size_t j = 0; j < n; ++j) t.child_start[j + 1] += t.child_start[j];
  t.children.resize(static_cast<std::size_t>(t.child_start[n]));
  std::vector<int> next(t.child_start.begin(), t.child_start.end() - 1);
  for (std::size_t j = 0; j < n; ++j)
    if (parent[j] >= 0)
      t.children[static_cast<std::size_t>(next[static_cast<std::size_t>(parent[j])]++)] = static_cast<int>(j);
  return t;
}

// The columns of the best cut's top. Cut: move the heaviest subtree's root to the top, again and
// again, until the subtrees split evenly into the groups or the top holds a tenth of the work (a tree
// that does not split, e.g. a chain); keep the cut with the least estimated time, top + largest group.
std::vector<int> best_top(const FactorView& f, const std::vector<int>& parent, const TreeWork& t) {
  std::priority_queue<std::pair<std::int64_t, int>> frontier;
  for (std::size_t j = 0; j < parent.size(); ++j)
    if (parent[j] < 0) frontier.emplace(t.work[j], static_cast<int>(j));
  std::int64_t top_work = 0, best_time = t.total + 1;
  std::vector<int> roots, expanded;
  std::size_t best_expansions = 0;
  while (!frontier.empty()) {
    if (static_cast<int>(frontier.size()) >= SubtreeSolve::kGroups) {
      auto copy = frontier;
      roots.clear();
      for (; !copy.empty(); copy.pop()) roots.push_back(copy.top().second);
      const std::int64_t max_load = assign_groups(roots, t.work, SubtreeSolve::kGroups).second;
      if (top_work + max_load < best_time) {
        best_time = top_work + max_load;
        best_expansions = expanded.size();
      }
      if (static_cast<double>(max_load) <= 1.02 * static_cast<double>(t.total - top_work) / SubtreeSolve::kGroups)
        break;
    }
    if (top_work > t.total / 10) break;
    const int j = frontier.top().second;
    frontier.pop();
    expanded.push_back(j);
    top_work += f.nz[j];
    for (int c = t.child_start[static_cast<std::size_t>(j)]; c < t.child_start[static_cast<std::size_t>(j) + 1]; ++c)
      frontier.emplace(t.work[static_cast<std::size_t>(t.children[static_cast<std::size_t>(c)])],
                       t.children[static_cast<std::size_t>(c)]);
  }
  expanded.resize(best_expansions);
  return expanded;
}

}  // namespace

void SubtreeSolve::update(const cholmod_factor& L, bool only_modified) {
  const FactorView f(L);
  const auto n = static_cast<std::size_t>(f.n);
  // Updates and downdates only ever add entries to L's columns (CHOLMOD keeps numerical zeros), and a
  // column moves only when it grows: the same column counts are the same pattern, so the tree's check
  // (a read of every column's first entry, scattered through L: ~4 ms at N = 1e5) is not needed.
  if (only_modified && nz_.size() == n && std::equal(nz_.begin(), nz_.end(), f.nz)) return;
  // The blocks depend on the column counts too (an update may add fill without changing the tree).
  bool same = parent_.size() == n;
  for (int j = 0; same && j < f.n; ++j)
    same = parent_[static_cast<std::size_t>(j)] == f.parent(j) && nz_[static_cast<std::size_t>(j)] == f.nz[j];
  if (same) return;
  parent_.resize(n);
  nz_.assign(f.nz, f.nz + n);
  for (int j = 0; j < f.n; ++j) parent_[static_cast<std::size_t>(j)] = f.parent(j);

  const TreeWork t = tree_work(f, parent_);
  const std::int64_t total = t.total;
  // The best cut: its top, and as subtrees every other column whose parent is in the top (or none).
  std::vector<char> is_top(n, 0);
  std::int64_t top_work = 0;
  for (const int j : best_top(f, parent_, t)) {
    is_top[static_cast<std::size_t>(j)] = 1;
    top_work += f.nz[j];
  }
  std::vector<int> roots;
  for (std::size_t j = 0; j < n; ++j)
    if (!is_top[j] && (parent_[j] < 0 || is_top[static_cast<std::size_t>(parent_[j])]))
      roots.push_back(static_cast<int>(j));
  const auto [group_of_root, max_load] = assign_groups(roots, t.work, kGroups);

  // Label every column with its group and its subtree's root (parents before children).
  std::vector<int> group(n, -1);
  subtree_root_.assign(n, -1);
  for (std::size_t k = 0; k < roots.size(); ++k) {
    group[static_cast<std::size_t>(roots[k])] = group_of_root[k];
    subtree_root_[static_cast<std::size_t>(roots[k])] = roots[k];
  }
  for (int j = f.n - 1; j >= 0; --j) {
    const auto u = static_cast<std::size_t>(j);
    if (is_top[u] || subtree_root_[u] >= 0) continue;
    const auto pj = static_cast<std::size_t>(parent_[u]);
    group[u] = group[pj];
    subtree_root_[u] = subtree_root_[pj];
  }
  top_.clear();
  top_slot_.assign(n, -1);
  std::array<std::vector<int>, kGroups> group_columns;
  for (std::size_t j = 0; j < n; ++j) {
    if (is_top[j]) {
      top_slot_[j] = static_cast<int>(top_.size());
      top_.push_back(static_cast<int>(j));
    } else {
      group_columns[static_cast<std::size_t>(group[j])].push_back(static_cast<int>(j));
    }
  }
  for (auto& buffer : to_top_) buffer.assign(top_.size(), 0.0);
  top_blocks_ = blocks_of(f, top_);
  for (std::size_t g = 0; g < group_.size(); ++g) group_[g] = blocks_of(f, group_columns[g]);
  parallel_ = total >= kParallelNonzeros;
  top_share_ = total > 0 ? static_cast<double>(top_work) / static_cast<double>(total) : 0.0;
  const double mean = static_cast<double>(total - top_work) / kGroups;
  imbalance_ = mean > 0.0 ? static_cast<double>(max_load) / mean : 1.0;
}

namespace {

// A block of K consecutive columns j..j+K-1 that form a chain in the tree and share their rows below
// the block (CHOLMOD's "dynamic supernodes"): the rows' indices and x at them are read once for K
// columns. Column j+m holds: D, then rows j+m+1..j+K-1, then the shared rows R.
template <int K>
void forward_block(const FactorView& f, int j, double* x, int root, const std::vector<int>& top_slot, double* to_top) {
  for (int m = 0; m < K; ++m)
    for (int mm = m + 1; mm < K; ++mm) x[j + mm] -= f.x[f.p[j + m] + (mm - m)] * x[j + m];
  const int last = j + K - 1, n_shared = f.nz[last] - 1;
  const int* rows = f.i + f.p[last] + 1;
  const double* column[K];
  double xj[K];
  for (int m = 0; m < K; ++m) {
    column[m] = f.x + f.p[j + m] + (K - m);
    xj[m] = x[j + m];
  }
  for (int t = 0; t < n_shared; ++t) {
    double v = 0.0;
    for (int m = 0; m < K; ++m) v += column[m][t] * xj[m];
    const int r = rows[t];
    if (r <= root)
      x[r] -= v;
    else
      to_top[top_slot[static_cast<std::size_t>(r)]] -= v;
  }
}

template <int K>
void backward_block(const FactorView& f, int j, double* x) {
  const int last = j + K - 1, n_shared = f.nz[last] - 1;
  const int* rows = f.i + f.p[last] + 1;
  const double* column[K];
  for (int m = 0; m < K; ++m) column[m] = f.x + f.p[j + m] + (K - m);
  // K >= 2 sums are independent chains already; a single column gets four partial sums.
  constexpr int kSums = K == 1 ? 4 : K;
  double s[kSums] = {};
  int t = 0;
  if constexpr (K == 1) {
    for (; t + 3 < n_shared; t += 4)
      for (int k = 0; k < 4; ++k) s[k] += column[0][t + k] * x[rows[t + k]];
    for (; t < n_shared; ++t) s[0] += column[0][t] * x[rows[t]];
    s[0] = (s[0] + s[1]) + (s[2] + s[3]);
  } else {
    for (; t < n_shared; ++t) {
      const double xr = x[rows[t]];
      for (int m = 0; m < K; ++m) s[m] += column[m][t] * xr;
    }
  }
  for (int m = K - 1; m >= 0; --m) {
    double v = x[j + m] / f.x[f.p[j + m]] - s[m];
    for (int mm = m + 1; mm < K; ++mm) v -= f.x[f.p[j + m] + (mm - m)] * x[j + mm];
    x[j + m] = v;
  }
}

}  // namespace

void SubtreeSolve::forward(const cholmod_factor& L, double* x) {
  const FactorView f(L);
  assert(parent_.size() == static_cast<std::size_t>(f.n) && "SubtreeSolve: update(L) before solving");
  const auto run = [&](const std::vector<Block>& blocks, double* to_top) {
    for (const Block& b : blocks) {
      const int root = to_top ? subtree_root_[static_cast<std::size_t>(b.first)] : f.n;
      switch (b.size) {
        case 1: forward_block<1>(f, b.first, x, root, top_slot_, to_top); break;
        case 2: forward_block<2>(f, b.first, x, root, top_slot_, to_top); break;
        case 3: forward_block<3>(f, b.first, x, root, top_slot_, to_top); break;
        default: forward_block<4>(f, b.first, x, root, top_slot_, to_top); break;
      }
    }
  };
#pragma omp parallel for schedule(static) if (parallel_)
  for (int g = 0; g < kGroups; ++g) {
    std::vector<double>& to_top = to_top_[static_cast<std::size_t>(g)];
    std::fill(to_top.begin(), to_top.end(), 0.0);
    run(group_[static_cast<std::size_t>(g)], to_top.data());
  }
  for (std::size_t t = 0; t < top_.size(); ++t) {
    double s = x[top_[t]];
    for (const auto& to_top : to_top_) s += to_top[t];
    x[top_[t]] = s;
  }
  run(top_blocks_, nullptr);
}

void SubtreeSolve::backward(const cholmod_factor& L, double* x) const {
  const FactorView f(L);
  assert(parent_.size() == static_cast<std::size_t>(f.n) && "SubtreeSolve: update(L) before solving");
  const auto run = [&](const std::vector<Block>& blocks) {
    for (auto b = blocks.rbegin(); b != blocks.rend(); ++b) {
      switch (b->size) {
        case 1: backward_block<1>(f, b->first, x); break;
        case 2: backward_block<2>(f, b->first, x); break;
        case 3: backward_block<3>(f, b->first, x); break;
        default: backward_block<4>(f, b->first, x); break;
      }
    }
  };
  run(top_blocks_);
#pragma omp parallel for schedule(static) if (parallel_)
  for (int g = 0; g < kGroups; ++g) run(group_[static_cast<std::size_t>(g)]);
}

void SubtreeSolve::solve(const cholmod_factor& L, const double* b, double* x) {
  update(L);
  const auto* perm = static_cast<const int*>(L.Perm);
  work_.resize(L.n);
  for (std::size_t k = 0; k < L.n; ++k) work_[k] = b[perm[k]];
  forward(L, work_.data());
  backward(L, work_.data());
  for (std::size_t k = 0; k < L.n; ++k) x[perm[k]] = work_[k];
}

}  // namespace hm::lattice2d
