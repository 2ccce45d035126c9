// Rank-one updates and downdates of the supernodal factor along the
// elimination-tree path (Davis & Hager, "Modifying a sparse Cholesky
// factorization", SIMAX 1999, for the path property; Golub & Van Loan,
// "Matrix Computations", sec. 6.5.4, for the rotations).
//
// Adding w e_j (permuted index jj) as a new row of R = L^T is eliminated by
// Givens rotations: x = w e_jj; for each column c on the path, the rotation
// that zeroes x[c] against L[c, c] is applied to column c and x. x is only
// ever nonzero on the path, and within a supernode the path is the run of
// columns c0..k-1 over one dense block (PathRun). The run is done in blocks
// of kRotationBlock columns: compute that block's rotations on its small
// triangle, then apply them to every row below in one SIMD pass, so each
// stored entry of the trapezoid is read and written once
// (rotate_into_supernode). What is left of x below the supernode enters the
// parent supernode at its row rows[k] (the etree parent of the last column).
#include "gab/sparse/update.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "update/update_kernels.h"

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

// Integer workspace layout: four pieces of ns ints, one use each. Only
// union_entry must hold anything between calls (all -1); the rest is
// written before it is read.
struct IntWorkspace {
  int32_t* runs;         // supernodes of the path (downdate) or of the union of paths (batch)
  int32_t* run_entry;    // downdate: the local column where the path enters runs[i]
  int32_t* crossing;     // batch, by supernode: bit v set when vector v's path crosses it
  int32_t* union_entry;  // batch, by supernode: lowest entry column on the union, -1 off it
};

constexpr int64_t kIntPieces = 4;

IntWorkspace carve_ints(const SymbolicFactor& f, int32_t* iwork) {
  const int64_t ns = f.num_supernodes;
  IntWorkspace w;
  w.runs = iwork;
  w.run_entry = w.runs + ns;
  w.crossing = w.run_entry + ns;
  w.union_entry = w.crossing + ns;
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

// One run of an elimination-tree path: the supernode it crosses and the
// local column where it enters; it leaves by the supernode's last column.
struct PathRun {
  int32_t supernode;  // -1 past the root
  int32_t entry;
};

// The run through permuted column col.
inline PathRun path_run_at(const SymbolicFactor& f, int32_t col) {
  const int32_t s = f.supernode_of[col];
  return {s, col - f.first_col[s]};
}

// The next run up the path: it enters the parent supernode at the etree
// parent of the last column, the first row below the supernode's own.
inline PathRun next_path_run(const SymbolicFactor& f, PathRun run) {
  const int32_t s = run.supernode, k = f.cols(s);
  if (k == f.rows(s)) return {-1, -1};  // a root
  return path_run_at(f, f.row_ind[f.row_ptr[s] + k]);
}

void count_path(const SymbolicFactor& f, int32_t s, int32_t c0, UpdateStats* st) {
  const int32_t k = f.cols(s), m = f.rows(s);
  st->path_columns += k - c0;
  st->path_supernodes += 1;
  for (int32_t c = c0; c < k; ++c) st->touched += m - c;
}

// Moves x's entries on rows[from..m) to xs[from..m), leaving x zero there.
inline void gather_rows(const int32_t* rows, int32_t from, int32_t m, double* x, double* xs) {
  for (int32_t t = from; t < m; ++t) {
    xs[t] = x[rows[t]];
    x[rows[t]] = 0.0;
  }
}

// Writes xs[from..m) to x's entries on rows[from..m).
inline void scatter_rows(const int32_t* rows, int32_t from, int32_t m, const double* xs, double* x) {
  for (int32_t t = from; t < m; ++t) x[rows[t]] = xs[t];
}

// The Givens rotation that zeroes x[c] against L[c, c] (lc: column c of the
// block), applied at once to rows c+1..end-1 of column c and x (the rest of
// the rotation block's small triangle). Stores its cosine and sine.
inline void rotate_column(double* lc, double* x, int32_t c, int32_t end, double* cos_out,
                          double* sin_out) {
  const double d = lc[c], xc = x[c];
  const double r = std::sqrt(d * d + xc * xc);
  const double cq = d / r, sq = xc / r;
  *cos_out = cq;
  *sin_out = sq;
  lc[c] = r;
  x[c] = 0.0;
  for (int32_t t = c + 1; t < end; ++t) {
    const double lv = lc[t];
    lc[t] = cq * lv + sq * x[t];
    x[t] = cq * x[t] - sq * lv;
  }
}

// One vector, or a batch of up to kMaxBatch.
enum class Vectors { kOne, kBatch };

// A supernode's part of an add: rotates the na gathered vectors xs (ld
// apart; rows c0..m-1 of supernode block `block`, m x k) into its columns
// c0..k-1, kRotationBlock columns at a time. One vector is rotated at every
// column; in a batch, a vector still zero at a column (its path enters the
// supernode higher up) gets the identity without a square root.
template <Vectors kVectors>
void rotate_into_supernode(const update_detail::UpdateKernels& kern, double* block, int32_t m,
                           int32_t k, int32_t c0, int32_t na, double* xs, int32_t ld, double* cs,
                           double* sn) {
  const int32_t nv = kVectors == Vectors::kOne ? 1 : na;
  for (int32_t cb = c0; cb < k; cb += kRotationBlock) {
    const int32_t nb = k - cb < kRotationBlock ? k - cb : kRotationBlock;
    for (int32_t q = 0; q < nb; ++q) {
      const int32_t c = cb + q;
      double* lc = block + static_cast<int64_t>(c) * m;
      for (int32_t v = 0; v < nv; ++v) {
        double* xv = xs + static_cast<int64_t>(v) * ld;
        const int32_t slot = q * nv + v;
        if (kVectors == Vectors::kOne || xv[c] != 0.0) {
          rotate_column(lc, xv, c, cb + nb, &cs[slot], &sn[slot]);
        } else {
          cs[slot] = 1.0;
          sn[slot] = 0.0;
        }
      }
    }
    const int32_t below = cb + nb;
    double* rest = block + static_cast<int64_t>(cb) * m + below;
    if (kVectors == Vectors::kOne) {
      kern.rotate_rows(m - below, nb, cs, sn, rest, m, xs + below);
    } else {
      kern.rotate_rows_batch(m - below, nb, nv, cs, sn, rest, m, xs + below, ld);
    }
  }
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
  IntWorkspace iw = carve_ints(f, iwork);
  const int64_t n = f.n;
  const int32_t ld = f.max_front_rows;  // stride between gathered vectors
  int32_t count = 0;
  for (int32_t v = 0; v < nv; ++v) {
    const int32_t col = f.inverse_perm[js[v]];
    ws.x[col + v * n] += weight;
    for (PathRun run = path_run_at(f, col); run.supernode != -1; run = next_path_run(f, run)) {
      const int32_t s = run.supernode;
      if (iw.union_entry[s] < 0) {
        iw.union_entry[s] = run.entry;
        iw.crossing[s] = 0;
        iw.runs[count++] = s;
      } else {
        iw.union_entry[s] = std::min(iw.union_entry[s], run.entry);
      }
      iw.crossing[s] |= 1 << v;
    }
  }
  std::sort(iw.runs, iw.runs + count);
  for (int32_t i = 0; i < count; ++i) {
    const int32_t s = iw.runs[i], c0 = iw.union_entry[s];
    iw.union_entry[s] = -1;  // restore the "not on the union" marks
    const int32_t k = f.cols(s), m = f.rows(s);
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    int32_t active[update_detail::kMaxBatch], na = 0;  // the crossing vectors
    for (int32_t v = 0; v < nv; ++v) {
      if (iw.crossing[s] >> v & 1) active[na++] = v;
    }
    for (int32_t a = 0; a < na; ++a) {
      gather_rows(rows, c0, m, ws.x + active[a] * n, ws.xs + static_cast<int64_t>(a) * ld);
    }
    rotate_into_supernode<Vectors::kBatch>(kern, values + f.value_ptr[s], m, k, c0, na, ws.xs, ld,
                                           ws.cs, ws.sn);
    // 6 flops per rotated entry and per rotation, for each crossing vector.
    const int64_t touched_before = st->touched;
    count_path(f, s, c0, st);
    st->flops += 6.0 * na * (static_cast<double>(st->touched - touched_before) + k - c0);
    for (int32_t a = 0; a < na; ++a) {
      scatter_rows(rows, k, m, ws.xs + static_cast<int64_t>(a) * ld, ws.x + active[a] * n);
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
  return kIntPieces * static_cast<int64_t>(f.num_supernodes);
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
  const int32_t col = f.inverse_perm[j];
  ws.x[col] = weight;
  for (PathRun run = path_run_at(f, col); run.supernode != -1; run = next_path_run(f, run)) {
    const int32_t s = run.supernode, c0 = run.entry;
    const int32_t k = f.cols(s), m = f.rows(s);
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    gather_rows(rows, c0, m, ws.x, ws.xs);  // x is zero off these rows
    rotate_into_supernode<Vectors::kOne>(kern, values + f.value_ptr[s], m, k, c0, 1, ws.xs, 0,
                                         ws.cs, ws.sn);
    count_path(f, s, c0, &st);
    scatter_rows(rows, k, m, ws.xs, ws.x);  // nothing at a root: x is fully absorbed
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
  IntWorkspace iw = carve_ints(f, iwork);
  const int32_t start = f.inverse_perm[j];
  // The path, bottom-up; the rotations below walk it top-down.
  int32_t len = 0;
  for (PathRun run = path_run_at(f, start); run.supernode != -1; run = next_path_run(f, run)) {
    iw.runs[len] = run.supernode;
    iw.run_entry[len] = run.entry;
    ++len;
  }
  UpdateStats st;

  // 1. p = L^{-1} (w e_start), nonzero only on the path: forward
  //    substitution supernode by supernode, bottom-up.
  double norm2 = 0.0;
  ws.x[start] = weight;
  for (int32_t i = 0; i < len; ++i) {
    const int32_t s = iw.runs[i], c0 = iw.run_entry[i];
    const int32_t k = f.cols(s), m = f.rows(s), first = f.first_col[s];
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    const double* block = values + f.value_ptr[s];
    gather_rows(rows, c0, m, ws.x, ws.xs);
    for (int32_t c = c0; c < k; ++c) {
      const double* lc = block + static_cast<int64_t>(c) * m;
      const double pc = ws.xs[c] / lc[c];
      ws.p[first + c] = pc;
      norm2 += pc * pc;
      for (int32_t t = c + 1; t < m; ++t) ws.xs[t] -= lc[t] * pc;
    }
    scatter_rows(rows, k, m, ws.xs, ws.x);
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
    const int32_t s = iw.runs[i], first = f.first_col[s];
    for (int32_t c = f.cols(s) - 1; c >= iw.run_entry[i]; --c) {
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
    const int32_t s = iw.runs[i], c0 = iw.run_entry[i];
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
    scatter_rows(rows, c0, m, ws.xs, ws.carry);
    // Keep the diagonal positive (a column's sign is free: L L^T is unchanged).
    for (int32_t c = c0; c < k; ++c) {
      double* lc = block + static_cast<int64_t>(c) * m;
      if (lc[c] < 0.0) {
        for (int32_t t = c; t < m; ++t) lc[t] = -lc[t];
      }
    }
  }
  for (int32_t i = 0; i < len; ++i) {
    for (int64_t q = f.row_ptr[iw.runs[i]] + iw.run_entry[i]; q < f.row_ptr[iw.runs[i] + 1]; ++q) {
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
