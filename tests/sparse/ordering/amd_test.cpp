// Approximate minimum degree ordering: validity of the permutation on many inputs,
// fill quality against natural order and known-good values, dense-row postponement,
// determinism, and the predictions in AmdInfo against a brute-force symbolic
// factorization. Self-contained: the oracles below are deliberately simple.
#include "gab/sparse/amd.h"
#include "gab/sparse/amd_graph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace gab {
namespace {

using Edge = std::pair<int32_t, int32_t>;

// Lower triangle (pattern only) of the graph's adjacency; with_diagonal adds the
// diagonal. Duplicate edges and self loops are dropped.
CscMatrix lower_from_edges(int32_t n, const std::vector<Edge>& edges, bool with_diagonal = true) {
  std::vector<std::vector<int32_t>> cols(static_cast<size_t>(n));
  for (const Edge& e : edges) {
    const int32_t i = std::max(e.first, e.second), j = std::min(e.first, e.second);
    if (i != j) cols[j].push_back(i);
  }
  CscMatrix a;
  a.nrows = a.ncols = n;
  a.colptr.assign(static_cast<size_t>(n) + 1, 0);
  for (int32_t j = 0; j < n; ++j) {
    std::vector<int32_t>& c = cols[j];
    if (with_diagonal) c.push_back(j);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    a.rowind.insert(a.rowind.end(), c.begin(), c.end());
    a.colptr[j + 1] = static_cast<int32_t>(a.rowind.size());
  }
  return a;
}

std::vector<Edge> grid_edges(int32_t nx, int32_t ny) {
  std::vector<Edge> e;
  for (int32_t y = 0; y < ny; ++y) {
    for (int32_t x = 0; x < nx; ++x) {
      const int32_t v = y * nx + x;
      if (x + 1 < nx) e.emplace_back(v, v + 1);
      if (y + 1 < ny) e.emplace_back(v, v + nx);
    }
  }
  return e;
}

// Edge graph of a triangulated nx x ny grid (one diagonal per quad).
std::vector<std::vector<int32_t>> triangulated_grid(int32_t nx, int32_t ny) {
  std::vector<std::vector<int32_t>> adj(static_cast<size_t>(nx) * ny);
  auto link = [&](int32_t a, int32_t b) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  };
  for (int32_t y = 0; y < ny; ++y) {
    for (int32_t x = 0; x < nx; ++x) {
      const int32_t v = y * nx + x;
      if (x + 1 < nx) link(v, v + 1);
      if (y + 1 < ny) link(v, v + nx);
      if (x + 1 < nx && y + 1 < ny) link(v, v + nx + 1);
    }
  }
  return adj;
}

// Pattern of L^T L for the mesh Laplacian L: vertices at edge distance <= 2, plus the
// diagonal (the matrix gab factors).
CscMatrix distance2_lower(const std::vector<std::vector<int32_t>>& adj) {
  const int32_t n = static_cast<int32_t>(adj.size());
  CscMatrix a;
  a.nrows = a.ncols = n;
  a.colptr.assign(static_cast<size_t>(n) + 1, 0);
  std::vector<int32_t> mark(static_cast<size_t>(n), -1), rows;
  for (int32_t j = 0; j < n; ++j) {
    rows.clear();
    auto add = [&](int32_t v) {
      if (v >= j && mark[v] != j) {
        mark[v] = j;
        rows.push_back(v);
      }
    };
    add(j);
    for (int32_t u : adj[j]) {
      add(u);
      for (int32_t w : adj[u]) add(w);
    }
    std::sort(rows.begin(), rows.end());
    a.rowind.insert(a.rowind.end(), rows.begin(), rows.end());
    a.colptr[j + 1] = static_cast<int32_t>(a.rowind.size());
  }
  return a;
}

// Minimal ASCII OFF reader: the edge graph of the faces. Empty on any problem.
std::vector<std::vector<int32_t>> read_off_edge_graph(const std::string& path) {
  std::ifstream in(path);
  std::string magic;
  int64_t nv = 0, nf = 0, ne = 0;
  if (!(in >> magic >> nv >> nf >> ne) || magic != "OFF" || nv <= 0 || nv > (1 << 24)) return {};
  double coord;
  for (int64_t k = 0; k < 3 * nv; ++k) {
    if (!(in >> coord)) return {};
  }
  std::vector<std::vector<int32_t>> adj(static_cast<size_t>(nv));
  std::vector<int32_t> face;
  for (int64_t f = 0; f < nf; ++f) {
    int32_t count = 0;
    if (!(in >> count) || count < 0 || count > 64) return {};
    face.resize(static_cast<size_t>(count));
    for (int32_t& v : face) {
      if (!(in >> v) || v < 0 || v >= nv) return {};
    }
    for (int32_t k = 0; k < count; ++k) {
      const int32_t a = face[k], b = face[(k + 1) % count];
      if (a != b) {
        adj[a].push_back(b);
        adj[b].push_back(a);
      }
    }
  }
  for (auto& list : adj) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return adj;
}

std::vector<Edge> random_edges(int32_t n, int64_t m, std::mt19937* rng) {
  std::vector<Edge> e;
  if (n < 2) return e;
  std::uniform_int_distribution<int32_t> pick(0, n - 1);
  for (int64_t k = 0; k < m; ++k) e.emplace_back(pick(*rng), pick(*rng));
  return e;
}

// Column counts of the Cholesky factor of P A P^T (incl. diagonal), perm[k] = original
// index of pivot k: elimination tree by Liu's algorithm with path compression, then each
// row's pattern as its row subtree (walk from every A(k, j), j < k, up to k).
std::vector<int64_t> factor_column_counts(const CscMatrix& lower, const std::vector<int32_t>& perm) {
  const int32_t n = lower.ncols;
  std::vector<int32_t> inv(static_cast<size_t>(n));
  for (int32_t k = 0; k < n; ++k) inv[perm[k]] = k;
  std::vector<std::vector<int32_t>> row(static_cast<size_t>(n));  // row k: j < k
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      int32_t a = inv[lower.rowind[p]], b = inv[j];
      if (a == b) continue;
      if (a < b) std::swap(a, b);
      row[a].push_back(b);
    }
  }
  std::vector<int32_t> parent(static_cast<size_t>(n), -1), ancestor(static_cast<size_t>(n), -1);
  for (int32_t k = 0; k < n; ++k) {
    for (int32_t j : row[k]) {
      for (int32_t r = j; r != -1 && r < k;) {
        const int32_t next = ancestor[r];
        ancestor[r] = k;
        if (next == -1) parent[r] = k;
        r = next;
      }
    }
  }
  std::vector<int64_t> count(static_cast<size_t>(n), 1);
  std::vector<int32_t> mark(static_cast<size_t>(n), -1);
  for (int32_t k = 0; k < n; ++k) {
    mark[k] = k;
    for (int32_t j : row[k]) {
      for (int32_t r = j; mark[r] != k; r = parent[r]) {
        mark[r] = k;
        ++count[r];
      }
    }
  }
  return count;
}

int64_t factor_nnz(const CscMatrix& lower, const std::vector<int32_t>& perm) {
  int64_t total = 0;
  for (int64_t c : factor_column_counts(lower, perm)) total += c;
  return total;
}

// Second, independent oracle for small n: eliminate on explicit adjacency sets.
int64_t factor_nnz_by_elimination(const CscMatrix& lower, const std::vector<int32_t>& perm) {
  const int32_t n = lower.ncols;
  std::vector<std::set<int32_t>> adj(static_cast<size_t>(n));
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t i = lower.rowind[p];
      if (i != j) {
        adj[i].insert(j);
        adj[j].insert(i);
      }
    }
  }
  int64_t total = 0;
  for (int32_t k = 0; k < n; ++k) {
    const int32_t v = perm[k];
    const std::vector<int32_t> nbrs(adj[v].begin(), adj[v].end());
    total += 1 + static_cast<int64_t>(nbrs.size());
    for (int32_t a : nbrs) {
      adj[a].erase(v);
      for (int32_t b : nbrs) {
        if (a != b) adj[a].insert(b);
      }
    }
    adj[v].clear();
  }
  return total;
}

std::vector<int32_t> identity(int32_t n) {
  std::vector<int32_t> p(static_cast<size_t>(n));
  for (int32_t i = 0; i < n; ++i) p[i] = i;
  return p;
}

// Orders `a`, checks the permutation and that the predictions match the ordering's true
// factor (exactly without dense rows, as upper bounds with them); returns nnz(L).
int64_t order_and_check(const CscMatrix& a, const AmdOptions& options = AmdOptions(),
                        std::vector<int32_t>* perm_out = nullptr) {
  std::vector<int32_t> perm;
  AmdInfo info;
  const Status s = amd_order(a, &perm, options, &info);
  EXPECT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(is_permutation(perm, a.ncols));
  if (!is_permutation(perm, a.ncols)) return -1;
  EXPECT_EQ(info.n, a.ncols);
  const std::vector<int64_t> counts = factor_column_counts(a, perm);
  int64_t nnz = 0;
  double flops = 0.0;
  for (int64_t c : counts) {
    nnz += c;
    flops += static_cast<double>(c) * static_cast<double>(c);
  }
  if (info.dense_rows == 0) {
    EXPECT_EQ(info.nnz_L_estimate, nnz);
    EXPECT_DOUBLE_EQ(info.flops_estimate, flops);
  } else {
    EXPECT_GE(info.nnz_L_estimate, nnz);
    EXPECT_GE(info.flops_estimate, flops);
  }
  if (perm_out != nullptr) *perm_out = perm;
  return nnz;
}

TEST(AmdTest, EmptyMatrix) {
  CscMatrix a;
  a.colptr = {0};
  std::vector<int32_t> perm = {7};
  AmdInfo info;
  info.n = 99;
  ASSERT_TRUE(amd_order(a, &perm, AmdOptions(), &info).ok());
  EXPECT_TRUE(perm.empty());
  EXPECT_EQ(info.n, 0);
  EXPECT_EQ(info.nnz_L_estimate, 0);
}

TEST(AmdTest, TinyMatrices) {
  EXPECT_EQ(order_and_check(lower_from_edges(1, {})), 1);
  EXPECT_EQ(order_and_check(lower_from_edges(1, {}, /*with_diagonal=*/false)), 1);
  EXPECT_EQ(order_and_check(lower_from_edges(2, {})), 2);
  EXPECT_EQ(order_and_check(lower_from_edges(2, {{0, 1}})), 3);
  EXPECT_EQ(order_and_check(lower_from_edges(2, {{1, 0}}, false)), 3);
  EXPECT_EQ(order_and_check(lower_from_edges(3, {{0, 1}, {1, 2}, {0, 2}})), 6);
}

TEST(AmdTest, DiagonalOnlyAndEmptyColumns) {
  EXPECT_EQ(order_and_check(lower_from_edges(50, {})), 50);
  EXPECT_EQ(order_and_check(lower_from_edges(50, {}, false)), 50);
  // A path 0-1-...-9 plus isolated vertices 10..29 with no entries at all.
  std::vector<Edge> e;
  for (int32_t i = 0; i + 1 < 10; ++i) e.emplace_back(i, i + 1);
  EXPECT_EQ(order_and_check(lower_from_edges(30, e, false)), 30 + 9);
}

TEST(AmdTest, TestOraclesAgree) {
  std::mt19937 rng(11);
  for (int t = 0; t < 200; ++t) {
    const int32_t n = 1 + static_cast<int32_t>(rng() % 40);
    const CscMatrix a = lower_from_edges(n, random_edges(n, rng() % (3 * n + 1), &rng));
    std::vector<int32_t> perm = identity(n);
    std::shuffle(perm.begin(), perm.end(), rng);
    EXPECT_EQ(factor_nnz(a, perm), factor_nnz_by_elimination(a, perm));
  }
}

TEST(AmdTest, RandomGraphsGivePermutationsAndExactPredictions) {
  std::mt19937 rng(2024);
  for (int t = 0; t < 400; ++t) {
    const int32_t n = 1 + static_cast<int32_t>(rng() % 120);
    const int64_t m = static_cast<int64_t>(rng() % (6 * static_cast<uint32_t>(n) + 1));
    const CscMatrix a = lower_from_edges(n, random_edges(n, m, &rng), rng() % 2 == 0);
    AmdOptions options;
    options.aggressive = rng() % 2 == 0;
    // Low thresholds (the floor of 16 entries) make some rows of the denser graphs dense.
    const double dense_choices[] = {10.0, -1.0, 1.0, 0.5};
    options.dense = dense_choices[t % 4];
    std::vector<int32_t> perm;
    const int64_t nnz = order_and_check(a, options, &perm);
    if (n <= 60) {
      EXPECT_EQ(nnz, factor_nnz_by_elimination(a, perm));
    }
  }
}

// amd_order_graph (the nested-dissection leaves' entry) on the full sorted
// lists gives exactly amd_order's permutation on the lower triangle.
TEST(AmdTest, GraphEntryGivesTheSamePermutation) {
  std::mt19937 rng(77);
  for (int t = 0; t < 200; ++t) {
    const int32_t n = 1 + static_cast<int32_t>(rng() % 150);
    const int64_t m = static_cast<int64_t>(rng() % (8 * static_cast<uint32_t>(n) + 1));
    const CscMatrix a = lower_from_edges(n, random_edges(n, m, &rng), rng() % 2 == 0);
    const CscMatrix full = symmetric_graph(a);
    AmdOptions options;
    options.aggressive = rng() % 2 == 0;
    options.dense = t % 3 == 0 ? 1.0 : 10.0;  // some rows dense with the floor of 16
    std::vector<int32_t> expected, got;
    ASSERT_TRUE(amd_order(a, &expected, options).ok());
    for (int32_t v = 0; v < n; ++v) {
      ASSERT_TRUE(std::is_sorted(full.rowind.begin() + full.colptr[v], full.rowind.begin() + full.colptr[v + 1]));
    }
    ASSERT_TRUE(amd_order_graph(n, full.colptr.data(), full.rowind.data(), &got, options).ok());
    EXPECT_EQ(got, expected) << "graph " << t;
  }
}

// The halo entry's graph: `inner` vertices with their lists, then the halo
// with only its inner neighbours (what the nested-dissection leaves pass).
struct HaloGraph {
  std::vector<int32_t> xadj, adj;
};

HaloGraph halo_graph(const CscMatrix& full, int32_t inner) {
  HaloGraph h;
  const int32_t n = full.ncols;
  h.xadj.push_back(0);
  for (int32_t v = 0; v < n; ++v) {
    for (int32_t p = full.colptr[v]; p < full.colptr[v + 1]; ++p) {
      if (v < inner || full.rowind[p] < inner) h.adj.push_back(full.rowind[p]);
    }
    h.xadj.push_back(static_cast<int32_t>(h.adj.size()));
  }
  return h;
}

// A path 0 - 1 - 2 - 3 - 4 with a halo vertex at one end: minimum degree
// eats the path from its free end, so the vertex next to the halo is the
// last pivot, at whichever end the halo sits (AMD on the path alone cannot
// know which end that is). The halo vertex is never a pivot.
TEST(AmdTest, HaloPushesItsNeighboursLast) {
  for (const int32_t end : {0, 4}) {
    std::vector<Edge> e = {{1, 0}, {2, 1}, {3, 2}, {4, 3}, {5, end}};
    const CscMatrix full = symmetric_graph(lower_from_edges(6, e));
    const HaloGraph h = halo_graph(full, 5);
    std::vector<int32_t> perm;
    ASSERT_TRUE(amd_order_graph_with_halo(6, 5, h.xadj.data(), h.adj.data(), &perm).ok());
    ASSERT_EQ(perm.size(), 5u);
    EXPECT_EQ(perm.back(), end);
    std::vector<int32_t> sorted = perm;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, identity(5));
  }
}

// On random graphs whose last vertices are a halo (ordered after the rest
// and joined among themselves too), ordering the inner vertices with the
// halo in view gives the whole matrix less fill than AMD on the inner
// vertices alone; each result is a permutation of the inner vertices.
TEST(AmdTest, HaloOrderingFillsLessThanOrderingThePieceAlone) {
  std::mt19937 rng(2024);
  int64_t with_halo = 0, alone = 0;
  for (int t = 0; t < 150; ++t) {
    const int32_t inner = 5 + static_cast<int32_t>(rng() % 60);
    const int32_t halo = 1 + static_cast<int32_t>(rng() % 20);
    const int32_t n = inner + halo;
    const int64_t m = static_cast<int64_t>(rng() % (4 * static_cast<uint32_t>(n) + 1));
    const CscMatrix a = lower_from_edges(n, random_edges(n, m, &rng));
    const CscMatrix full = symmetric_graph(a);
    const HaloGraph h = halo_graph(full, inner);
    std::vector<int32_t> perm;
    ASSERT_TRUE(amd_order_graph_with_halo(n, inner, h.xadj.data(), h.adj.data(), &perm).ok());
    std::vector<int32_t> sorted = perm;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, identity(inner)) << "graph " << t;
    // The piece alone: its induced subgraph.
    const HaloGraph piece = halo_graph(full, inner);
    std::vector<int32_t> sub_xadj{0}, sub_adj;
    for (int32_t v = 0; v < inner; ++v) {
      for (int32_t p = piece.xadj[v]; p < piece.xadj[v + 1]; ++p) {
        if (piece.adj[p] < inner) sub_adj.push_back(piece.adj[p]);
      }
      sub_xadj.push_back(static_cast<int32_t>(sub_adj.size()));
    }
    std::vector<int32_t> plain;
    ASSERT_TRUE(amd_order_graph(inner, sub_xadj.data(), sub_adj.data(), &plain).ok());
    for (int32_t v = inner; v < n; ++v) {
      perm.push_back(v);
      plain.push_back(v);
    }
    with_halo += factor_nnz_by_elimination(a, perm);
    alone += factor_nnz_by_elimination(a, plain);
  }
  EXPECT_LT(with_halo, alone);  // 41,788 against 44,147 when written
}

TEST(AmdTest, ForestsHaveNoFill) {
  // Minimum degree eliminates leaves first; a leaf creates no fill. The approximate
  // degrees are exact on trees, so AMD must find a no-fill ordering.
  std::mt19937 rng(3);
  for (int t = 0; t < 50; ++t) {
    const int32_t n = 2 + static_cast<int32_t>(rng() % 500);
    std::vector<Edge> e;
    for (int32_t v = 1; v < n; ++v) {
      if (rng() % 10 != 0) e.emplace_back(v, static_cast<int32_t>(rng() % v));  // else a new root
    }
    EXPECT_EQ(order_and_check(lower_from_edges(n, e)), n + static_cast<int64_t>(e.size()));
  }
}

TEST(AmdTest, DisjointCliquesHaveNoFill) {
  std::vector<Edge> e;
  int32_t base = 0;
  int64_t expected = 0;
  for (int32_t size : {1, 2, 5, 17, 3, 40, 8}) {
    for (int32_t i = 0; i < size; ++i) {
      for (int32_t j = 0; j < i; ++j) e.emplace_back(base + i, base + j);
    }
    expected += static_cast<int64_t>(size) * (size + 1) / 2;
    base += size;
  }
  // Shuffle the vertex numbering so that blocks interleave.
  std::mt19937 rng(5);
  std::vector<int32_t> relabel = identity(base);
  std::shuffle(relabel.begin(), relabel.end(), rng);
  for (Edge& x : e) x = {relabel[x.first], relabel[x.second]};
  EXPECT_EQ(order_and_check(lower_from_edges(base, e)), expected);
}

TEST(AmdTest, CompleteBipartiteEliminatesLargeSideFirst) {
  // K_{3,100}: the vertices of degree 3 go first (3 entries each below the diagonal),
  // the 3 hubs (degree 100) last: optimum 103 + 300 + 3. Minimum degree may take the hub
  // supervariable once it ties with the last 3 leaves (degree 3 each): at most 9 more.
  std::vector<Edge> e;
  for (int32_t hub = 0; hub < 3; ++hub) {
    for (int32_t v = 3; v < 103; ++v) e.emplace_back(hub, v);
  }
  std::vector<int32_t> perm;
  const int64_t nnz = order_and_check(lower_from_edges(103, e), AmdOptions(), &perm);
  EXPECT_GE(nnz, 103 + 300 + 3);
  EXPECT_LE(nnz, 103 + 300 + 3 + 9);
  for (int32_t hub = 0; hub < 3; ++hub) {
    EXPECT_NE(std::find(perm.end() - 6, perm.end(), hub), perm.end()) << hub;
  }
}

TEST(AmdTest, GridFillFarBelowNaturalAndNearKnownGood) {
  const CscMatrix a = lower_from_edges(60 * 60, grid_edges(60, 60));
  const int64_t natural = factor_nnz(a, identity(a.ncols));
  const int64_t amd = order_and_check(a);
  EXPECT_LT(amd * 3, natural);
  // SuiteSparse AMD 2.4.6 (default options) gives 59,765 here; natural order 216,059.
  EXPECT_LE(amd, 59765 * 102 / 100);
}

TEST(AmdTest, TwoRingMeshFillFarBelowNaturalAndNearKnownGood) {
  // Row-by-row numbering is already banded, a strong baseline for natural order.
  const CscMatrix a = distance2_lower(triangulated_grid(100, 100));
  const int64_t natural = factor_nnz(a, identity(a.ncols));
  const int64_t amd = order_and_check(a);
  EXPECT_LT(amd * 2, natural);
  // SuiteSparse AMD 2.4.6 (default options) gives 860,023 here; natural order 1,999,700.
  EXPECT_LE(amd, 860023 * 102 / 100);
  // Aggressive absorption changes little on such graphs; both must be good.
  AmdOptions plain;
  plain.aggressive = false;
  EXPECT_LE(order_and_check(a, plain), 860023 * 105 / 100);
}

TEST(AmdTest, RealMeshMatchesReferenceFill) {
  const std::string path = std::string(GAB_SHARED_MESHES) + "/nefertiti.off";
  const auto adj = read_off_edge_graph(path);
  if (adj.empty()) {
    GTEST_SKIP() << "mesh not available: " << path;
  }
  const CscMatrix a = distance2_lower(adj);
  ASSERT_EQ(a.ncols, 49971);
  ASSERT_EQ(a.nnz(), 535108);
  // SuiteSparse AMD gives nnz(L) = 6,168,085 (incl. diagonal) on this matrix.
  const int64_t amd = order_and_check(a);
  EXPECT_LE(amd, 6168085 * 102 / 100);
}

TEST(AmdTest, DenseRowsAreOrderedLast) {
  const int32_t g = 40, n = g * g;
  std::vector<Edge> e = grid_edges(g, g);
  const std::vector<int32_t> dense = {7, 500, 1234};
  std::mt19937 rng(9);
  for (int32_t d : dense) {
    for (int32_t k = 0; k < n / 2; ++k) e.emplace_back(d, static_cast<int32_t>(rng() % n));
  }
  const CscMatrix a = lower_from_edges(n, e);
  std::vector<int32_t> perm;
  AmdInfo info;
  ASSERT_TRUE(amd_order(a, &perm, AmdOptions(), &info).ok());
  ASSERT_TRUE(is_permutation(perm, n));
  EXPECT_EQ(info.dense_rows, 3);
  EXPECT_EQ(std::vector<int32_t>(perm.end() - 3, perm.end()), dense);
  const int64_t with_dense = order_and_check(a);
  // Without postponement the dense rows are ordered like any other row: still valid,
  // and postponing them should not lose.
  AmdOptions keep;
  keep.dense = -1.0;
  ASSERT_TRUE(amd_order(a, &perm, keep, &info).ok());
  EXPECT_EQ(info.dense_rows, 0);
  EXPECT_LE(with_dense, order_and_check(a, keep) * 105 / 100);
}

TEST(AmdTest, DenseThresholdIsMaxOf16AndDenseTimesSqrtN) {
  // n = 400: with dense = 1 the threshold is max(16, 20) = 20 off-diagonal entries.
  // Hub 0 has 20 neighbours (kept), hub 1 has 21 (postponed).
  std::vector<Edge> e;
  for (int32_t v = 2; v < 22; ++v) e.emplace_back(0, v);
  for (int32_t v = 100; v < 121; ++v) e.emplace_back(1, v);
  const CscMatrix a = lower_from_edges(400, e);
  AmdOptions options;
  options.dense = 1.0;
  std::vector<int32_t> perm;
  AmdInfo info;
  ASSERT_TRUE(amd_order(a, &perm, options, &info).ok());
  EXPECT_EQ(info.dense_rows, 1);
  EXPECT_EQ(perm.back(), 1);
  // With dense = 0.5 the floor of 16 applies: both hubs are dense.
  options.dense = 0.5;
  ASSERT_TRUE(amd_order(a, &perm, options, &info).ok());
  EXPECT_EQ(info.dense_rows, 2);
  EXPECT_EQ(std::vector<int32_t>(perm.end() - 2, perm.end()), (std::vector<int32_t>{0, 1}));
  order_and_check(a, options);
}

TEST(AmdTest, AllRowsDense) {
  // A clique of 300: every row exceeds max(16, 10 sqrt(300)) = 173 entries.
  std::vector<Edge> e;
  for (int32_t i = 0; i < 300; ++i) {
    for (int32_t j = 0; j < i; ++j) e.emplace_back(i, j);
  }
  std::vector<int32_t> perm;
  AmdInfo info;
  EXPECT_EQ(order_and_check(lower_from_edges(300, e), AmdOptions(), &perm), 300 * 301 / 2);
  ASSERT_TRUE(amd_order(lower_from_edges(300, e), &perm, AmdOptions(), &info).ok());
  EXPECT_EQ(info.dense_rows, 300);
  EXPECT_EQ(info.nnz_L_estimate, 300 * 301 / 2);
}

TEST(AmdTest, Deterministic) {
  std::mt19937 rng(77);
  const CscMatrix a = lower_from_edges(3000, random_edges(3000, 9000, &rng));
  std::vector<int32_t> first, second;
  AmdInfo i1, i2;
  ASSERT_TRUE(amd_order(a, &first, AmdOptions(), &i1).ok());
  const CscMatrix copy = a;
  ASSERT_TRUE(amd_order(copy, &second, AmdOptions(), &i2).ok());
  EXPECT_EQ(first, second);
  EXPECT_EQ(i1.nnz_L_estimate, i2.nnz_L_estimate);
  EXPECT_EQ(i1.compressions, i2.compressions);
}

TEST(AmdTest, GarbageCollectionKeepsTheGraph) {
  // Random graphs of average degree ~20 fill fast and overflow the elbow room.
  std::mt19937 rng(123);
  int32_t compressions = 0;
  for (int32_t n : {500, 2000}) {
    const CscMatrix a = lower_from_edges(n, random_edges(n, 10 * int64_t{n}, &rng));
    order_and_check(a);
    std::vector<int32_t> perm;
    AmdInfo info;
    ASSERT_TRUE(amd_order(a, &perm, AmdOptions(), &info).ok());
    compressions += info.compressions;
  }
  EXPECT_GT(compressions, 0);
}

TEST(AmdTest, RejectsMalformedInput) {
  std::vector<int32_t> perm;
  CscMatrix a = lower_from_edges(4, {{0, 1}, {2, 3}});
  EXPECT_EQ(amd_order(a, nullptr).code(), StatusCode::kInvalidArgument);

  CscMatrix rect = a;
  rect.nrows = 5;
  EXPECT_EQ(amd_order(rect, &perm).code(), StatusCode::kInvalidArgument);

  CscMatrix short_colptr = a;
  short_colptr.colptr.pop_back();
  EXPECT_EQ(amd_order(short_colptr, &perm).code(), StatusCode::kInvalidArgument);

  CscMatrix upper = lower_from_edges(3, {});
  upper.rowind = {0, 0, 1, 2};  // column 1 holds row 0: above the diagonal
  upper.colptr = {0, 1, 3, 4};
  EXPECT_EQ(amd_order(upper, &perm).code(), StatusCode::kInvalidArgument);

  CscMatrix unsorted = lower_from_edges(3, {});
  unsorted.rowind = {2, 0, 1, 2};
  unsorted.colptr = {0, 2, 3, 4};
  EXPECT_EQ(amd_order(unsorted, &perm).code(), StatusCode::kInvalidArgument);

  CscMatrix duplicate = lower_from_edges(3, {});
  duplicate.rowind = {0, 2, 2, 1, 2};
  duplicate.colptr = {0, 3, 4, 5};
  EXPECT_EQ(amd_order(duplicate, &perm).code(), StatusCode::kInvalidArgument);

  CscMatrix out_of_range = lower_from_edges(3, {});
  out_of_range.rowind[2] = 3;
  EXPECT_EQ(amd_order(out_of_range, &perm).code(), StatusCode::kInvalidArgument);

  CscMatrix truncated = a;
  truncated.rowind.resize(truncated.rowind.size() - 1);
  EXPECT_EQ(amd_order(truncated, &perm).code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace gab
