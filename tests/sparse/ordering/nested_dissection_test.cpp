// Nested-dissection ordering: the result is a permutation; every separator of
// the tree separates its children on the graph; the tree's column ranges tile
// the permutation; the factor with the ordering solves systems; disconnected,
// tiny, dense-row and path graphs; determinism; the separator bound on an
// update's cost (by hand on a path, and against the true path on a grid).
#include "gab/sparse/nested_dissection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gab/sparse/cholesky.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

using testing_util::grid_laplacian;
using testing_util::random_spd;

// Lower triangle with unit off-diagonals and a dominant diagonal (SPD) for a
// graph given by edges.
CscMatrix spd_from_edges(int32_t n, const std::vector<std::pair<int32_t, int32_t>>& edges) {
  std::vector<Triplet> t;
  std::vector<double> degree(static_cast<size_t>(n), 0.0);
  for (const auto& e : edges) {
    t.push_back({std::max(e.first, e.second), std::min(e.first, e.second), -1.0});
    degree[e.first] += 1.0;
    degree[e.second] += 1.0;
  }
  for (int32_t i = 0; i < n; ++i) t.push_back({i, i, degree[i] + 1.0});
  CscMatrix a;
  EXPECT_TRUE(csc_from_triplets(n, n, t, &a).ok());
  return a;
}

// SPD matrix coupling the grid points up to two steps apart: the 2-ring
// pattern of the mesh matrices L^T L.
CscMatrix two_ring_grid(int32_t nx, int32_t ny) {
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t y = 0; y < ny; ++y) {
    for (int32_t x = 0; x < nx; ++x) {
      for (int32_t dy = 0; dy <= 2; ++dy) {
        for (int32_t dx = -2; dx <= 2; ++dx) {
          if (dy == 0 && dx <= 0) continue;
          if (std::abs(dx) + dy > 2) continue;
          const int32_t x2 = x + dx, y2 = y + dy;
          if (x2 < 0 || x2 >= nx || y2 >= ny) continue;
          edges.emplace_back(y * nx + x, y2 * nx + x2);
        }
      }
    }
  }
  return spd_from_edges(nx * ny, edges);
}

// Checks everything the ordering promises about perm and tree on `lower`.
void expect_valid_dissection(const CscMatrix& lower, const std::vector<int32_t>& perm,
                             const SeparatorTree& tree) {
  const int32_t n = lower.ncols;
  ASSERT_TRUE(is_permutation(perm, n));
  const std::vector<int32_t> position = invert_permutation(perm);
  const size_t count = tree.nodes.size();
  ASSERT_EQ(tree.child_ptr.size(), count + 1);
  // column_node names the node owning each pivot.
  ASSERT_EQ(static_cast<int32_t>(tree.column_node.size()), n);
  for (size_t s = 0; s < count; ++s) {
    for (int32_t k = tree.nodes[s].first; k < tree.nodes[s].first + tree.nodes[s].size; ++k) {
      EXPECT_EQ(tree.column_node[k], static_cast<int32_t>(s)) << "pivot " << k;
    }
  }
  // The roots' subtrees, and each node's children's subtrees followed by its
  // own columns, tile their ranges exactly.
  int32_t next = 0;
  for (size_t s = 0; s < count; ++s) {
    const SeparatorTree::Node& node = tree.nodes[s];
    if (node.parent < 0) {
      EXPECT_EQ(node.subtree_first, next) << "root " << s;
      next = node.first + node.size;
    } else {
      EXPECT_GT(node.parent, static_cast<int32_t>(s)) << "children before parents";
    }
    int32_t inner = node.subtree_first;
    for (int32_t c = tree.child_ptr[s]; c < tree.child_ptr[s + 1]; ++c) {
      const SeparatorTree::Node& child = tree.nodes[tree.children[c]];
      EXPECT_EQ(child.parent, static_cast<int32_t>(s));
      EXPECT_EQ(child.subtree_first, inner);
      inner = child.first + child.size;
    }
    EXPECT_EQ(inner, node.first) << "node " << s;
    if (node.leaf) {
      EXPECT_EQ(tree.child_ptr[s + 1], tree.child_ptr[s]);
    }
  }
  EXPECT_EQ(next, n);

  // Separation: label every column with the child subtree of s holding it;
  // an edge between two columns below s must stay within one child.
  for (size_t s = 0; s < count; ++s) {
    const int32_t kids = tree.child_ptr[s + 1] - tree.child_ptr[s];
    if (kids < 2) continue;
    std::vector<int32_t> child_of(static_cast<size_t>(n), -1);
    for (int32_t c = tree.child_ptr[s]; c < tree.child_ptr[s + 1]; ++c) {
      const SeparatorTree::Node& child = tree.nodes[tree.children[c]];
      for (int32_t k = child.subtree_first; k < child.first + child.size; ++k) child_of[k] = c;
    }
    for (int32_t j = 0; j < n; ++j) {
      for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
        const int32_t a = child_of[position[lower.rowind[p]]], b = child_of[position[j]];
        if (a >= 0 && b >= 0) {
          ASSERT_EQ(a, b) << "edge " << lower.rowind[p] << "-" << j << " crosses separator " << s;
        }
      }
    }
  }
}

std::vector<int32_t> order_checked(const CscMatrix& lower, const NestedDissectionOptions& options = {}) {
  std::vector<int32_t> perm;
  SeparatorTree tree;
  const Status s = nested_dissection_order(lower, &perm, options, &tree);
  EXPECT_TRUE(s.ok()) << s.message();
  expect_valid_dissection(lower, perm, tree);
  return perm;
}

// Relative residual of A x = b solved by Cholesky with the given ordering.
double solve_residual(const CscMatrix& lower, const std::vector<int32_t>& perm) {
  AnalyzeOptions options;
  options.ordering = Ordering::kGiven;
  options.given_perm = perm;
  Cholesky chol;
  EXPECT_TRUE(chol.analyze(lower, options).ok());
  EXPECT_TRUE(chol.factorize(lower).ok());
  const int32_t n = lower.ncols;
  std::vector<double> x_true(static_cast<size_t>(n)), b(static_cast<size_t>(n));
  for (int32_t i = 0; i < n; ++i) x_true[i] = std::sin(0.37 * i) + 1.0;
  symmetric_lower_matvec(lower, x_true.data(), b.data());
  std::vector<double> x = b;
  EXPECT_TRUE(chol.solve(x.data(), 1, n).ok());
  double err = 0.0, norm = 0.0;
  for (int32_t i = 0; i < n; ++i) {
    err = std::max(err, std::abs(x[i] - x_true[i]));
    norm = std::max(norm, std::abs(x_true[i]));
  }
  return err / norm;
}

TEST(NestedDissection, GridSeparatorsSeparateAndFactorSolves) {
  const CscMatrix a = grid_laplacian(60, 50);
  const std::vector<int32_t> perm = order_checked(a);
  EXPECT_LT(solve_residual(a, perm), 1e-10);
}

TEST(NestedDissection, TwoRingGridDissectsBeyondOneLeaf) {
  const CscMatrix a = two_ring_grid(50, 40);
  std::vector<int32_t> perm;
  SeparatorTree tree;
  ASSERT_TRUE(nested_dissection_order(a, &perm, {}, &tree).ok());
  expect_valid_dissection(a, perm, tree);
  int32_t separators = 0;
  for (const SeparatorTree::Node& node : tree.nodes) separators += !node.leaf;
  EXPECT_GE(separators, 3);
  EXPECT_LT(solve_residual(a, perm), 1e-10);
}

TEST(NestedDissection, RandomMatricesWithSmallLeaves) {
  NestedDissectionOptions options;
  options.leaf_size = 8;
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    const CscMatrix a = random_spd(300 + 50 * seed, 3.0, seed);
    const std::vector<int32_t> perm = order_checked(a, options);
    EXPECT_LT(solve_residual(a, perm), 1e-10) << "seed " << seed;
  }
}

TEST(NestedDissection, GridFillBelowNaturalOrder) {
  // A 2D grid's nested dissection has O(n log n) fill; natural (banded) order O(n^1.5).
  const CscMatrix a = grid_laplacian(80, 80);
  const std::vector<int32_t> perm = order_checked(a);
  AnalyzeOptions nd_options, natural;
  nd_options.ordering = Ordering::kGiven;
  nd_options.given_perm = perm;
  natural.ordering = Ordering::kNatural;
  SymbolicFactor f_nd, f_natural;
  ASSERT_TRUE(analyze(a, nd_options, &f_nd).ok());
  ASSERT_TRUE(analyze(a, natural, &f_natural).ok());
  EXPECT_LT(f_nd.nnz_L, f_natural.nnz_L * 3 / 4);
}

TEST(NestedDissection, DisconnectedComponentsAreOrderedSeparately) {
  NestedDissectionOptions options;
  options.leaf_size = 10;
  const CscMatrix a = random_spd(600, 2.5, 7, /*dense_rows=*/0, /*blocks=*/5);
  std::vector<int32_t> perm;
  SeparatorTree tree;
  ASSERT_TRUE(nested_dissection_order(a, &perm, options, &tree).ok());
  expect_valid_dissection(a, perm, tree);
  int32_t roots = 0;
  for (const SeparatorTree::Node& node : tree.nodes) roots += node.parent < 0;
  EXPECT_GE(roots, 5);
  EXPECT_LT(solve_residual(a, perm), 1e-10);
}

TEST(NestedDissection, TinyGraphs) {
  for (int32_t n : {0, 1, 2, 3}) {
    std::vector<std::pair<int32_t, int32_t>> edges;
    for (int32_t i = 0; i + 1 < n; ++i) edges.emplace_back(i, i + 1);
    const CscMatrix a = spd_from_edges(n, edges);
    const std::vector<int32_t> perm = order_checked(a);
    EXPECT_EQ(static_cast<int32_t>(perm.size()), n);
  }
}

TEST(NestedDissection, IsolatedVerticesWithoutDiagonal) {
  CscMatrix a;  // 4 x 4, no entries at all
  a.nrows = a.ncols = 4;
  a.colptr.assign(5, 0);
  const std::vector<int32_t> perm = order_checked(a);
  EXPECT_EQ(perm.size(), 4u);
}

TEST(NestedDissection, DenseRowsAreOrderedLast) {
  // A 2-ring grid plus two rows coupled to every vertex.
  const int32_t side = 30, n = side * side + 2;
  const CscMatrix grid = two_ring_grid(side, side);
  std::vector<Triplet> t;
  for (int32_t j = 0; j < grid.ncols; ++j) {
    for (int32_t p = grid.colptr[j]; p < grid.colptr[j + 1]; ++p) t.push_back({grid.rowind[p], j, grid.values[p]});
  }
  for (int32_t d = side * side; d < n; ++d) {
    for (int32_t j = 0; j < d; ++j) t.push_back({d, j, 0.01});
    t.push_back({d, d, 1000.0});
  }
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(n, n, t, &a).ok());
  const std::vector<int32_t> perm = order_checked(a);
  EXPECT_TRUE((perm[n - 2] == n - 2 && perm[n - 1] == n - 1));
  EXPECT_LT(solve_residual(a, perm), 1e-10);
}

// Three grids hanging from one hub vertex: any balanced separator holds the
// hub and leaves a side made of two whole grids, disconnected. The sides of a
// separator are not split into components (only the whole graph is), so
// this side is dissected as one graph: its separators must still separate.
TEST(NestedDissection, DisconnectedSideIsStillDissected) {
  const int32_t side = 14, cells = side * side, hub = 3 * cells;
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t grid = 0; grid < 3; ++grid) {
    const int32_t base = grid * cells;
    for (int32_t y = 0; y < side; ++y) {
      for (int32_t x = 0; x < side; ++x) {
        const int32_t v = base + y * side + x;
        if (x + 1 < side) edges.emplace_back(v, v + 1);
        if (y + 1 < side) edges.emplace_back(v, v + side);
      }
    }
    edges.emplace_back(base, hub);  // one corner of each grid touches the hub
  }
  const CscMatrix a = spd_from_edges(hub + 1, edges);
  for (int32_t leaf : {10, 40, 200}) {
    NestedDissectionOptions options;
    options.leaf_size = leaf;
    options.coarsest_size = 20;
    const std::vector<int32_t> perm = order_checked(a, options);
    EXPECT_LT(solve_residual(a, perm), 1e-10) << "leaf " << leaf;
  }
}

TEST(NestedDissection, LongPathIsCutInTheMiddle) {
  const int32_t n = 5000;
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t i = 0; i + 1 < n; ++i) edges.emplace_back(i, i + 1);
  const CscMatrix a = spd_from_edges(n, edges);
  std::vector<int32_t> perm;
  SeparatorTree tree;
  ASSERT_TRUE(nested_dissection_order(a, &perm, {}, &tree).ok());
  expect_valid_dissection(a, perm, tree);
  // A path's best separator is one vertex near the middle.
  const SeparatorTree::Node& root = tree.nodes.back();
  EXPECT_EQ(root.size, 1);
  EXPECT_GT(perm[n - 1], n / 4);
  EXPECT_LT(perm[n - 1], 3 * n / 4);
  EXPECT_LT(solve_residual(a, perm), 1e-10);
}

TEST(NestedDissection, CliqueFallsBackToOneLeaf) {
  const int32_t n = 300;  // above leaf_size, no separator exists
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = i + 1; j < n; ++j) edges.emplace_back(i, j);
  NestedDissectionOptions options;
  options.dense = -1.0;  // keep every row in the graph
  const std::vector<int32_t> perm = order_checked(spd_from_edges(n, edges), options);
  EXPECT_EQ(static_cast<int32_t>(perm.size()), n);
}

TEST(NestedDissection, SameInputSamePermutation) {
  const CscMatrix a = two_ring_grid(45, 45);
  std::vector<int32_t> first, second;
  ASSERT_TRUE(nested_dissection_order(a, &first).ok());
  ASSERT_TRUE(nested_dissection_order(a, &second).ok());
  EXPECT_EQ(first, second);
}

// The sides of a separator dissected on other threads give the permutation
// and tree of one thread: each piece draws from its own generator stream.
TEST(NestedDissection, ThreadsGiveTheSamePermutationAndTree) {
  const CscMatrix a = two_ring_grid(90, 80);
  NestedDissectionOptions options;
  options.leaf_size = 100;
  options.thread_size = 300;  // fork down to pieces of a few hundred vertices
  options.thread_entries = 2000;  // and contract even small coarse graphs on two threads
  options.runs_from = 1000;   // and take several coarsenings per separator
  std::vector<int32_t> serial;
  SeparatorTree serial_tree;
  ASSERT_TRUE(nested_dissection_order(a, &serial, options, &serial_tree).ok());
  expect_valid_dissection(a, serial, serial_tree);
  ASSERT_GE(serial_tree.nodes.size(), 15u);  // deep enough for 4 threads to fork twice
  for (int32_t threads : {2, 3, 4}) {
    options.threads = threads;
    std::vector<int32_t> perm;
    SeparatorTree tree;
    ASSERT_TRUE(nested_dissection_order(a, &perm, options, &tree).ok());
    EXPECT_EQ(perm, serial) << threads << " threads";
    ASSERT_EQ(tree.nodes.size(), serial_tree.nodes.size()) << threads << " threads";
    for (size_t s = 0; s < tree.nodes.size(); ++s) {
      const SeparatorTree::Node &x = tree.nodes[s], &y = serial_tree.nodes[s];
      EXPECT_TRUE(x.first == y.first && x.size == y.size && x.subtree_first == y.subtree_first &&
                  x.parent == y.parent && x.leaf == y.leaf)
          << "node " << s << ", " << threads << " threads";
    }
    EXPECT_EQ(tree.children, serial_tree.children);
    EXPECT_EQ(tree.column_node, serial_tree.column_node);
  }
}

// Every refinement scheme and the several-coarsenings search give separators
// that separate, on meshes and on random sparse graphs.
TEST(NestedDissection, RefinementSchemesGiveValidDissections) {
  const CscMatrix grid = two_ring_grid(60, 55);
  for (bool one_sided : {false, true}) {
    for (int32_t runs : {1, 4}) {
      // The one-sided passes with and without the closing two-sided pass.
      for (int32_t polish_from : one_sided ? std::vector<int32_t>{0, 1 << 30} : std::vector<int32_t>{1 << 30}) {
        NestedDissectionOptions options;
        options.one_sided_refinement = one_sided;
        options.polish_from = polish_from;
        options.runs = runs;
        options.runs_from = 500;
        options.leaf_size = 60;
        const std::vector<int32_t> perm = order_checked(grid, options);
        EXPECT_LT(solve_residual(grid, perm), 1e-10) << one_sided << " " << runs << " " << polish_from;
        for (uint32_t seed = 1; seed <= 3; ++seed) {
          const CscMatrix a = random_spd(700 + 100 * seed, 3.0, seed);
          const std::vector<int32_t> random_perm = order_checked(a, options);
          EXPECT_LT(solve_residual(a, random_perm), 1e-10)
              << one_sided << " " << runs << " " << polish_from << " seed " << seed;
        }
      }
    }
  }
}

// Seven vertices in a row, dissected down to single vertices: the middle one
// (3) is the root separator, 1 and 5 the next ones, 0, 2, 4, 6 the leaves.
TEST(SeparatorBound, SevenVertexPathByHand) {
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t i = 0; i + 1 < 7; ++i) edges.emplace_back(i, i + 1);
  const CscMatrix a = spd_from_edges(7, edges);
  NestedDissectionOptions options;
  options.leaf_size = 1;  // pieces of up to 2 vertices are leaves: the 3-vertex sides are cut again
  std::vector<int32_t> perm;
  SeparatorTree tree;
  ASSERT_TRUE(nested_dissection_order(a, &perm, options, &tree).ok());
  expect_valid_dissection(a, perm, tree);
  ASSERT_EQ(tree.nodes.size(), 7u);
  EXPECT_EQ(perm[6], 3);
  ASSERT_EQ(static_cast<int32_t>(tree.column_node.size()), 7);
  for (int32_t k = 0; k < 7; ++k) EXPECT_EQ(tree.nodes[tree.column_node[k]].size, 1) << k;

  std::vector<int64_t> bound;
  ASSERT_TRUE(separator_update_bounds(tree, perm, &bound).ok());
  // Every node holds one column (m = 1): a node at depth d (root 0) has
  // A = d and adds 1 + d; the path from depth d sums d + 1 such terms:
  // (d + 1)(d + 2) / 2.
  EXPECT_EQ(bound[3], 1);   // the root
  EXPECT_EQ(bound[1], 3);   // 2 + 1
  EXPECT_EQ(bound[5], 3);
  for (int32_t leaf : {0, 2, 4, 6}) EXPECT_EQ(bound[leaf], 6) << leaf;  // 3 + 2 + 1
}

// The bound holds for every vertex of a 2-ring grid: the entries of L on
// the elimination-tree path from the vertex's column never exceed it.
TEST(SeparatorBound, BoundsTheTouchedEntriesOfEveryUpdate) {
  const CscMatrix a = two_ring_grid(60, 50);
  NestedDissectionOptions options;
  options.leaf_size = 64;
  std::vector<int32_t> perm;
  SeparatorTree tree;
  ASSERT_TRUE(nested_dissection_order(a, &perm, options, &tree).ok());
  std::vector<int64_t> bound;
  ASSERT_TRUE(separator_update_bounds(tree, perm, &bound).ok());

  AnalyzeOptions given;
  given.ordering = Ordering::kGiven;
  given.given_perm = perm;
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a, given).ok());
  const SymbolicFactor& f = chol.symbolic();
  int64_t tight = 0;
  for (int32_t v = 0; v < a.ncols; ++v) {
    int64_t touched = 0;
    for (int32_t c = f.inverse_perm[v]; c != -1; c = f.etree.parent[c]) touched += f.column_counts[c];
    ASSERT_LE(touched, bound[v]) << "vertex " << v;
    tight = std::max(tight, 100 * touched / bound[v]);
  }
  EXPECT_GT(tight, 10);  // a bound, but not a vacuous one
}

TEST(SeparatorBound, RejectsATreeThatDoesNotFitThePermutation) {
  const CscMatrix a = two_ring_grid(20, 20);
  std::vector<int32_t> perm;
  SeparatorTree tree;
  NestedDissectionOptions options;
  options.leaf_size = 16;
  ASSERT_TRUE(nested_dissection_order(a, &perm, options, &tree).ok());
  std::vector<int64_t> bound;
  std::vector<int32_t> short_perm(perm.begin(), perm.end() - 1);
  EXPECT_EQ(separator_update_bounds(tree, short_perm, &bound).code(), StatusCode::kInvalidArgument);
  std::vector<int32_t> repeated = perm;
  repeated[0] = repeated[1];
  EXPECT_EQ(separator_update_bounds(tree, repeated, &bound).code(), StatusCode::kInvalidArgument);
  SeparatorTree bad = tree;
  bad.nodes[0].parent = 0;  // its own parent
  EXPECT_EQ(separator_update_bounds(bad, perm, &bound).code(), StatusCode::kInvalidArgument);
}

TEST(NestedDissection, RejectsEntriesAboveTheDiagonal) {
  CscMatrix a;
  a.nrows = a.ncols = 2;
  a.colptr = {0, 0, 1};
  a.rowind = {0};  // (0, 1): upper triangle
  std::vector<int32_t> perm;
  EXPECT_EQ(nested_dissection_order(a, &perm).code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace gab
