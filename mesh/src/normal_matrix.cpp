// Assembly of L^T L + w^2 E^T E. Row k of L is r_k = deg(k) e_k - sum of
// e_u over the neighbours u of k, so M = sum_k r_k r_k^T: column j of M
// gathers r_k[j] * r_k over the k in the closed neighbourhood of j.
#include "gab/mesh/normal_matrix.h"

#include <algorithm>
#include <exception>
#include <string>
#include <system_error>
#include <thread>

#include "gab/mesh/edge_graph.h"

namespace gab {

namespace {

// Calls f(k, v) for every k in j's closed neighbourhood (j first, then its
// neighbours: where r_k[j] != 0) and every v >= j in k's closed
// neighbourhood, in a fixed order (the sums' order, hence their bits).
template <typename F>
void for_each_two_ring_entry(const EdgeGraph& graph, int32_t j, F f) {
  for (int32_t q = graph.offsets[j] - 1; q < graph.offsets[j + 1]; ++q) {
    const int32_t k = q < graph.offsets[j] ? j : graph.neighbors[q];
    for (int32_t p = graph.offsets[k] - 1; p < graph.offsets[k + 1]; ++p) {
      const int32_t v = p < graph.offsets[k] ? k : graph.neighbors[p];
      if (v >= j) f(k, v);
    }
  }
}

// Below this many columns a second thread costs more than it saves.
constexpr int32_t kColumnsWorthASecondThread = 20000;

// work(0, split) here and work(split, n) on a second thread (none when
// split == n, or when the system refuses one: an address-space cap maps
// each stack; then both here). What the other thread raises (its
// allocations failing) is rethrown here after the join. Built without
// exceptions (the web decoder, which asks for one thread), a plain thread.
template <typename F>
void on_two_threads(int32_t split, int32_t n, const F& work) {
#if !defined(__cpp_exceptions)
  std::thread other;
  if (split < n) other = std::thread([&work, split, n] { work(split, n); });
  work(0, split);
  if (other.joinable()) other.join();
#else
  std::exception_ptr error;
  std::thread other;
  if (split < n) {
    try {
      other = std::thread([&work, &error, split, n] {
        try {
          work(split, n);
        } catch (...) {
          error = std::current_exception();
        }
      });
    } catch (const std::system_error&) {
      split = n;
    }
  }
  try {
    work(0, split);
  } catch (...) {
    if (other.joinable()) other.join();
    throw;
  }
  if (other.joinable()) other.join();
  if (error) std::rethrow_exception(error);
#endif
}

}  // namespace

Status assemble_normal_matrix(const EdgeGraph& graph, const std::vector<int32_t>& anchors,
                              double weight, CscMatrix* lower, int32_t threads) {
  const int32_t n = graph.num_vertices();
  std::vector<double> diag_extra(n, 0.0);
  for (int32_t a : anchors) {
    if (a < 0 || a >= n) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "anchor " + std::to_string(a) + " is not a vertex (n = " + std::to_string(n) + ")");
    }
    if (diag_extra[a] != 0.0) {
      return Status::Error(StatusCode::kInvalidArgument, "anchor " + std::to_string(a) + " given twice");
    }
    diag_extra[a] = weight * weight;
  }
  // Two passes over the 2-rings: the first counts each column's rows so
  // the arrays are allocated once (growing them entry by entry spent most
  // of the assembly in copies and page faults: igea 0.13 s -> 0.045 s).
  // Columns are independent, so each pass may split them between two
  // threads (each with its own scratch) without changing a bit.
  CscMatrix m;
  m.nrows = m.ncols = n;
  m.colptr.assign(n + 1, 0);
  const int32_t split = threads >= 2 && n >= kColumnsWorthASecondThread ? n / 2 : n;
  auto count_rows = [&graph, &m](int32_t first, int32_t last) {
    std::vector<int32_t> mark(graph.num_vertices(), -1);
    for (int32_t j = first; j < last; ++j) {
      mark[j] = j;
      int32_t rows = 1;
      for_each_two_ring_entry(graph, j, [&](int32_t, int32_t v) {
        if (mark[v] != j) {
          mark[v] = j;
          ++rows;
        }
      });
      m.colptr[j + 1] = rows;  // a count for now
    }
  };
  on_two_threads(split, n, count_rows);
  int64_t nnz = 0;
  for (int32_t j = 0; j < n; ++j) {
    nnz += m.colptr[j + 1];
    if (nnz > INT32_MAX) {
      return Status::Error(StatusCode::kOverflow, "normal matrix has more than 2^31-1 entries");
    }
    m.colptr[j + 1] = static_cast<int32_t>(nnz);
  }
  m.rowind.resize(static_cast<size_t>(nnz));
  m.values.resize(static_cast<size_t>(nnz));
  auto fill_columns = [&graph, &m, &diag_extra](int32_t first, int32_t last) {
    std::vector<int32_t> mark(graph.num_vertices(), -1);
    std::vector<double> acc(graph.num_vertices(), 0.0);
    auto coefficient = [&graph](int32_t k, int32_t v) {  // r_k[v]
      return v == k ? static_cast<double>(graph.degree(k)) : -1.0;
    };
    for (int32_t j = first; j < last; ++j) {
      int32_t* rows = m.rowind.data() + m.colptr[j];
      int32_t count = 0;
      mark[j] = j;
      rows[count++] = j;
      for_each_two_ring_entry(graph, j, [&](int32_t k, int32_t v) {
        if (mark[v] != j) {
          mark[v] = j;
          rows[count++] = v;
        }
        acc[v] += coefficient(k, v) * coefficient(k, j);
      });
      std::sort(rows, rows + count);
      acc[j] += diag_extra[j];
      double* values = m.values.data() + m.colptr[j];
      for (int32_t t = 0; t < count; ++t) {
        values[t] = acc[rows[t]];
        acc[rows[t]] = 0.0;
      }
    }
  };
  on_two_threads(split, n, fill_columns);
  *lower = std::move(m);
  return Status::Ok();
}

std::vector<int32_t> benchmark_anchors(const EdgeGraph& graph, int32_t k0) {
  const int32_t n = graph.num_vertices();
  std::vector<int32_t> anchors;
  std::vector<char> is_anchor(n, 0);
  for (int64_t j = 0; j < k0 && n > 0; ++j) {
    const int32_t v = static_cast<int32_t>(j * n / k0);
    if (!is_anchor[v]) {
      is_anchor[v] = 1;
      anchors.push_back(v);
    }
  }
  int32_t ncomp = 0;
  const std::vector<int32_t> comp = connected_components(graph, &ncomp);
  std::vector<char> covered(ncomp, 0);
  for (int32_t a : anchors) covered[comp[a]] = 1;
  for (int32_t v = 0; v < n; ++v) {  // first vertex met in a component is its smallest
    if (!covered[comp[v]]) {
      covered[comp[v]] = 1;
      anchors.push_back(v);
    }
  }
  return anchors;
}

std::vector<int32_t> benchmark_update_sequence(int32_t n, const std::vector<int32_t>& initial, int64_t count) {
  std::vector<char> anchored(n, 0);
  int64_t free_vertices = n;
  for (int32_t a : initial) {
    free_vertices -= anchored[a] ? 0 : 1;
    anchored[a] = 1;
  }
  std::vector<int32_t> seq;
  count = std::min<int64_t>(count, free_vertices);
  for (uint64_t t = 1; static_cast<int64_t>(seq.size()) < count; ++t) {
    const int32_t v = static_cast<int32_t>((t * 2654435761ull) % static_cast<uint64_t>(n));
    if (anchored[v]) continue;
    anchored[v] = 1;
    seq.push_back(v);
  }
  return seq;
}

std::vector<double> anchor_right_hand_sides(const Mesh& mesh, const std::vector<int32_t>& anchors,
                                            double weight) {
  const int32_t n = mesh.num_vertices();
  std::vector<double> b(static_cast<size_t>(n) * 3, 0.0);
  for (int32_t a : anchors) {
    for (int c = 0; c < 3; ++c) b[a + static_cast<size_t>(c) * n] = weight * weight * mesh.positions[3 * static_cast<size_t>(a) + c];
  }
  return b;
}

}  // namespace gab
