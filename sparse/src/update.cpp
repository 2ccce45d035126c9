// Rank-one updates and downdates of the supernodal factor along the
// elimination-tree path (Davis & Hager, "Modifying a sparse Cholesky
// factorization", SIMAX 1999, for the path property; Golub & Van Loan,
// "Matrix Computations", sec. 6.5.4, for the rotations).
//
// Adding w e_j (permuted index jj) as a new row of R = L^T is eliminated by
// Givens rotations: x = w e_jj; for each column c on the path, the rotation
// that zeroes x[c] against L[c, c] is applied to column c and x. x is only
// ever nonzero on the path, and within a supernode the path is the run of
// columns c0..k-1 over one dense block. The run is done in blocks of
// kRotationBlock columns: compute that block's rotations on its small
// triangle, then apply them to every row below in one SIMD pass, so each
// stored entry of the trapezoid is read and written once. What is left of x
// below the supernode enters the parent supernode at its row rows[k] (the
// etree parent of the last column).
#include "gab/sparse/update.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "update_kernels.h"

namespace gab {

namespace {

constexpr int32_t kRotationBlock = 16;

// Room for one block of rotations (batch: one per column and vector), or
// one per row of the largest supernode.
int64_t rotation_slots(const SymbolicFactor& f) {
  return std::max<int64_t>(f.max_front_rows, kRotationBlock * update_detail::kMaxBatch);
}

// Workspace layout (doubles): x (n * kMaxBatch) | carry | p | sines (n
// each), then xs (kMaxBatch per row of the largest supernode), cs, sn. x
// and carry are zero between calls; the rest is written before it is read.
struct Workspace {
  double* x;      // the rotated-in rows, indexed by (permuted) row, n apart
  double* carry;  // downdate: each row's running value between supernodes
  double* p;      // downdate: L^{-1} w e_j, then the cosines, by column
  double* sines;  // downdate: the sines, by column
  double* xs;     // x gathered on the current supernode's rows
  double* cs;     // a block of rotations
  double* sn;
};

Workspace carve(const SymbolicFactor& f, double* work) {
  Workspace w;
  w.x = work;
  w.carry = w.x + static_cast<int64_t>(f.n) * update_detail::kMaxBatch;
  w.p = w.carry + f.n;
  w.sines = w.p + f.n;
  w.xs = w.sines + f.n;
  w.cs = w.xs + static_cast<int64_t>(f.max_front_rows) * update_detail::kMaxBatch;
  w.sn = w.cs + rotation_slots(f);
  return w;
}

Status check_anchor(const SymbolicFactor& f, int32_t j, double weight) {
  if (j < 0 || j >= f.n) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "anchor " + std::to_string(j) + " is not a row (n = " + std::to_string(f.n) + ")");
  }
  if (!(weight != 0.0) || !std::isfinite(weight)) {
    return Status::Error(StatusCode::kInvalidArgument, "anchor weight must be finite and nonzero");
  }
  return Status::Ok();
}

// The path's supernodes bottom-up and the column where the path enters each
// (local index). Returns the count. O(path supernodes).
int32_t path_supernodes(const SymbolicFactor& f, int32_t col, int32_t* supernode, int32_t* entry) {
  int32_t count = 0;
  while (true) {
    const int32_t s = f.supernode_of[col];
    supernode[count] = s;
    entry[count] = col - f.first_col[s];
    ++count;
    const int32_t k = f.cols(s);
    if (k == f.rows(s)) return count;
    col = f.row_ind[f.row_ptr[s] + k];  // etree parent of the last column
  }
}

void count_path(const SymbolicFactor& f, int32_t s, int32_t c0, UpdateStats* st) {
  const int32_t k = f.cols(s), m = f.rows(s);
  st->path_columns += k - c0;
  st->path_supernodes += 1;
  for (int32_t c = c0; c < k; ++c) st->touched += m - c;
}

// Up to kMaxBatch anchors in one sweep over the union of their paths. The
// union's supernodes are visited in increasing order (a postorder: every
// child before its parent); in each, only the vectors whose paths cross it
// take part (the others are zero on its columns: their rotations would be
// the identity), the run starts at the lowest column where any of them
// enters, and a vector that is still zero at a column gets the identity.
void add_batch(const SymbolicFactor& f, double* values, const int32_t* js, int32_t nv,
               double weight, SimdLevel level, double* work, int32_t* iwork, UpdateStats* st) {
  const update_detail::UpdateKernels& kern = update_detail::update_kernels(level);
  Workspace ws = carve(f, work);
  const int64_t n = f.n;
  const int32_t ld = f.max_front_rows;  // stride between gathered vectors
  // Integer workspace: list (ns) | entry marks (ns, -1 between calls) |
  // crossing masks (ns, set when a supernode joins the union; the downdate
  // uses this slice for its path).
  int32_t* list = iwork;
  int32_t* entry = iwork + f.num_supernodes;  // per supernode; -1 when not on the union
  int32_t* crossing = iwork + 2 * f.num_supernodes;  // bit v: v's path crosses it
  int32_t count = 0;
  for (int32_t v = 0; v < nv; ++v) {
    int32_t col = f.inverse_perm[js[v]];
    ws.x[col + v * n] += weight;
    while (true) {
      const int32_t s = f.supernode_of[col];
      const int32_t c0 = col - f.first_col[s];
      if (entry[s] < 0) {
        entry[s] = c0;
        crossing[s] = 0;
        list[count++] = s;
      } else {
        entry[s] = std::min(entry[s], c0);
      }
      crossing[s] |= 1 << v;
      const int32_t k = f.cols(s);
      if (k == f.rows(s)) break;
      col = f.row_ind[f.row_ptr[s] + k];
    }
  }
  std::sort(list, list + count);
  for (int32_t i = 0; i < count; ++i) {
    const int32_t s = list[i], c0 = entry[s];
    entry[s] = -1;  // restore the "not on the union" marks
    const int32_t k = f.cols(s), m = f.rows(s);
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    double* block = values + f.value_ptr[s];
    int32_t active[update_detail::kMaxBatch], na = 0;  // the crossing vectors
    for (int32_t v = 0; v < nv; ++v) {
      if (crossing[s] >> v & 1) active[na++] = v;
    }
    for (int32_t a = 0; a < na; ++a) {
      double* xv = ws.x + active[a] * n;
      double* xs = ws.xs + static_cast<int64_t>(a) * ld;
      for (int32_t t = c0; t < m; ++t) {
        xs[t] = xv[rows[t]];
        xv[rows[t]] = 0.0;
      }
    }
    for (int32_t cb = c0; cb < k; cb += kRotationBlock) {
      const int32_t nb = k - cb < kRotationBlock ? k - cb : kRotationBlock;
      for (int32_t q = 0; q < nb; ++q) {
        const int32_t c = cb + q;
        double* lc = block + static_cast<int64_t>(c) * m;
        for (int32_t v = 0; v < na; ++v) {
          double* xs = ws.xs + static_cast<int64_t>(v) * ld;
          const double d = lc[c], xc = xs[c];
          double cq = 1.0, sq = 0.0;
          if (xc != 0.0) {
            const double r = std::sqrt(d * d + xc * xc);
            cq = d / r;
            sq = xc / r;
            lc[c] = r;
            xs[c] = 0.0;
            for (int32_t t = c + 1; t < cb + nb; ++t) {
              const double lv = lc[t];
              lc[t] = cq * lv + sq * xs[t];
              xs[t] = cq * xs[t] - sq * lv;
            }
          }
          ws.cs[q * na + v] = cq;
          ws.sn[q * na + v] = sq;
        }
      }
      const int32_t below = cb + nb;
      kern.rotate_rows_batch(m - below, nb, na, ws.cs, ws.sn,
                             block + static_cast<int64_t>(cb) * m + below, m, ws.xs + below, ld);
    }
    // 6 flops per rotated entry and per rotation, for each crossing vector.
    const int64_t touched_before = st->touched;
    count_path(f, s, c0, st);
    st->flops += 6.0 * na * (static_cast<double>(st->touched - touched_before) + k - c0);
    if (k == m) continue;
    for (int32_t a = 0; a < na; ++a) {
      double* xv = ws.x + active[a] * n;
      const double* xs = ws.xs + static_cast<int64_t>(a) * ld;
      for (int32_t t = k; t < m; ++t) xv[rows[t]] = xs[t];
    }
  }
}

}  // namespace

int64_t update_workspace_doubles(const SymbolicFactor& f) {
  return (update_detail::kMaxBatch + 3) * static_cast<int64_t>(f.n) +
         static_cast<int64_t>(f.max_front_rows) * update_detail::kMaxBatch + 2 * rotation_slots(f);
}

int64_t update_workspace_zero_prefix(const SymbolicFactor& f) {
  return (update_detail::kMaxBatch + 1) * static_cast<int64_t>(f.n);
}

int64_t update_workspace_ints(const SymbolicFactor& f) {
  return 3 * static_cast<int64_t>(f.num_supernodes);
}

Status add_anchors_supernodal(const SymbolicFactor& f, double* values, const int32_t* js,
                              int32_t count, double weight, SimdLevel level, double* work,
                              int32_t* iwork, UpdateStats* stats) {
  for (int32_t i = 0; i < count; ++i) GAB_RETURN_IF_ERROR(check_anchor(f, js[i], weight));
  UpdateStats total;
  for (int32_t done = 0; done < count; done += update_detail::kMaxBatch) {
    const int32_t nv = std::min<int32_t>(update_detail::kMaxBatch, count - done);
    UpdateStats st;
    add_batch(f, values, js + done, nv, weight, level, work, iwork, &st);
    total.path_columns += st.path_columns;
    total.path_supernodes += st.path_supernodes;
    total.touched += st.touched;
    total.flops += st.flops;
  }
  if (stats != nullptr) *stats = total;
  return Status::Ok();
}

Status add_anchor_supernodal(const SymbolicFactor& f, double* values, int32_t j, double weight,
                             SimdLevel level, double* work, UpdateStats* stats) {
  GAB_RETURN_IF_ERROR(check_anchor(f, j, weight));
  const update_detail::UpdateKernels& kern = update_detail::update_kernels(level);
  Workspace ws = carve(f, work);
  UpdateStats st;
  int32_t col = f.inverse_perm[j];
  ws.x[col] = weight;
  while (true) {
    const int32_t s = f.supernode_of[col];
    const int32_t k = f.cols(s), m = f.rows(s), c0 = col - f.first_col[s];
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    double* block = values + f.value_ptr[s];
    // Gather x's part on this supernode's rows (it is zero elsewhere).
    for (int32_t t = c0; t < m; ++t) {
      ws.xs[t] = ws.x[rows[t]];
      ws.x[rows[t]] = 0.0;
    }
    for (int32_t cb = c0; cb < k; cb += kRotationBlock) {
      const int32_t nb = k - cb < kRotationBlock ? k - cb : kRotationBlock;
      // The block's rotations, each applied at once to the rest of the
      // block's own small triangle.
      for (int32_t q = 0; q < nb; ++q) {
        const int32_t c = cb + q;
        double* lc = block + static_cast<int64_t>(c) * m;
        const double d = lc[c], xc = ws.xs[c];
        const double r = std::sqrt(d * d + xc * xc);
        const double cq = d / r, sq = xc / r;
        ws.cs[q] = cq;
        ws.sn[q] = sq;
        lc[c] = r;
        ws.xs[c] = 0.0;
        for (int32_t t = c + 1; t < cb + nb; ++t) {
          const double lv = lc[t];
          lc[t] = cq * lv + sq * ws.xs[t];
          ws.xs[t] = cq * ws.xs[t] - sq * lv;
        }
      }
      const int32_t below = cb + nb;
      kern.rotate_rows(m - below, nb, ws.cs, ws.sn, block + static_cast<int64_t>(cb) * m + below, m,
                       ws.xs + below);
    }
    count_path(f, s, c0, &st);
    if (k == m) break;  // a root: x is fully absorbed
    for (int32_t t = k; t < m; ++t) ws.x[rows[t]] = ws.xs[t];
    col = rows[k];
  }
  // 6 flops per rotated entry, plus a square root and two divisions per column.
  st.flops = 6.0 * static_cast<double>(st.touched) + 6.0 * st.path_columns;
  if (stats != nullptr) *stats = st;
  return Status::Ok();
}

Status remove_anchor_supernodal(const SymbolicFactor& f, double* values, int32_t j,
                                double weight, SimdLevel level, double* work, int32_t* iwork,
                                UpdateStats* stats) {
  GAB_RETURN_IF_ERROR(check_anchor(f, j, weight));
  const update_detail::UpdateKernels& kern = update_detail::update_kernels(level);
  Workspace ws = carve(f, work);
  // The first and third slices of the integer workspace (the second holds
  // the batch update's -1 marks and must not be touched).
  int32_t* path = iwork;                           // supernodes, bottom-up
  int32_t* entry = iwork + 2 * f.num_supernodes;   // local entry column in each
  const int32_t start = f.inverse_perm[j];
  const int32_t len = path_supernodes(f, start, path, entry);
  UpdateStats st;

  // 1. p = L^{-1} (w e_start), nonzero only on the path: forward
  //    substitution supernode by supernode, bottom-up.
  double norm2 = 0.0;
  ws.x[start] = weight;
  for (int32_t i = 0; i < len; ++i) {
    const int32_t s = path[i], c0 = entry[i];
    const int32_t k = f.cols(s), m = f.rows(s), first = f.first_col[s];
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    const double* block = values + f.value_ptr[s];
    for (int32_t t = c0; t < m; ++t) {
      ws.xs[t] = ws.x[rows[t]];
      ws.x[rows[t]] = 0.0;
    }
    for (int32_t c = c0; c < k; ++c) {
      const double* lc = block + static_cast<int64_t>(c) * m;
      const double pc = ws.xs[c] / lc[c];
      ws.p[first + c] = pc;
      norm2 += pc * pc;
      for (int32_t t = c + 1; t < m; ++t) ws.xs[t] -= lc[t] * pc;
    }
    for (int32_t t = k; t < m; ++t) ws.x[rows[t]] = ws.xs[t];
    count_path(f, s, c0, &st);
  }
  // The root supernode absorbs everything: x is zero again here.
  // M - w^2 e e^T is positive definite iff ||p|| < 1; keep a margin so the
  // new factor is not hopelessly ill-conditioned. Nothing has changed yet.
  if (!(norm2 < 1.0 - 1e-12)) {
    return Status::Error(StatusCode::kNotPositiveDefinite,
                         "removing anchor " + std::to_string(j) +
                             " would leave a matrix that is not positive definite");
  }

  // 2. The rotations (LINPACK dchdd): from the top of the path down,
  //    (alpha, p_c) -> (r, 0), alpha starting at sqrt(1 - ||p||^2).
  double alpha = std::sqrt(1.0 - norm2);
  for (int32_t i = len - 1; i >= 0; --i) {
    const int32_t s = path[i], first = f.first_col[s];
    for (int32_t c = f.cols(s) - 1; c >= entry[i]; --c) {
      const double pc = ws.p[first + c];
      const double r = std::sqrt(alpha * alpha + pc * pc);
      ws.p[first + c] = alpha / r;  // now the cosine
      ws.sines[first + c] = pc / r;
      alpha = r;
    }
  }

  // 3. Every row t of L gets, for the path columns c <= t in decreasing
  //    order, (L[t,c], xx) <- (cos L[t,c] - sin xx, cos xx + sin L[t,c])
  //    with xx starting at 0. A row's columns decrease from the top of the
  //    path down, so walk the supernodes top-down and carry xx per row.
  for (int32_t i = len - 1; i >= 0; --i) {
    const int32_t s = path[i], c0 = entry[i];
    const int32_t k = f.cols(s), m = f.rows(s), first = f.first_col[s];
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    double* block = values + f.value_ptr[s];
    const double* cosv = ws.p + first;
    const double* sinv = ws.sines + first;
    for (int32_t t = c0; t < m; ++t) ws.xs[t] = ws.carry[rows[t]];
    // Own columns (rows of the run's triangle): the diagonal first.
    for (int32_t t = c0; t < k; ++t) {
      double xx = ws.xs[t];
      for (int32_t c = t; c >= c0; --c) {
        double* lct = block + static_cast<int64_t>(c) * m + t;
        const double lv = *lct;
        *lct = cosv[c] * lv - sinv[c] * xx;
        xx = cosv[c] * xx + sinv[c] * lv;
      }
      ws.xs[t] = xx;
    }
    kern.rotate_rows_reverse(m - k, k - c0, cosv + c0, sinv + c0,
                             block + static_cast<int64_t>(c0) * m + k, m, ws.xs + k);
    // Every row of this supernode may meet more path columns lower down.
    for (int32_t t = c0; t < m; ++t) ws.carry[rows[t]] = ws.xs[t];
    // Keep the diagonal positive (a column's sign is free: L L^T is unchanged).
    for (int32_t c = c0; c < k; ++c) {
      double* lc = block + static_cast<int64_t>(c) * m;
      if (lc[c] < 0.0) {
        for (int32_t t = c; t < m; ++t) lc[t] = -lc[t];
      }
    }
  }
  for (int32_t i = 0; i < len; ++i) {
    for (int64_t q = f.row_ptr[path[i]] + entry[i]; q < f.row_ptr[path[i] + 1]; ++q) {
      ws.carry[f.row_ind[q]] = 0.0;
    }
  }
  // Two passes over the path: the solve (2 flops per entry) and the
  // rotations (6 per entry), plus the per-column square roots.
  st.flops = 8.0 * static_cast<double>(st.touched) + 8.0 * st.path_columns;
  st.touched *= 2;
  if (stats != nullptr) *stats = st;
  return Status::Ok();
}

}  // namespace gab
