// Multifrontal supernodal Cholesky (Duff & Reid 1983; Liu, "The multifrontal
// method for sparse matrix solution", SIAM Review 1992).
//
// Supernodes are visited in (post)order. Each one's front is its factor
// block (rows x cols, stored in place in the factor) plus an update matrix
// for the rows below it. A front is assembled from A's entries and the
// update matrices of its children (extend-add through relative indices),
// then partially factored: POTRF on the diagonal block, TRSM below it, and
// one SYRK that forms its own update matrix. Update matrices live on two
// stacks sharing one buffer sized by the analysis, so nothing is allocated
// here: even-depth supernodes push at the low end, odd-depth ones at the
// high end. A parent's children therefore sit on top of the other stack
// than the one its own update goes to, so the parent's update is formed in
// place while the children's are read, then the children are popped — no
// copy (a single stack would need a memmove per front). Chosen over
// left-looking because each supernode then does one large SYRK instead of
// one small GEMM per descendant, which keeps the SIMD kernel busy.
#include <cstring>
#include <string>

#include "gab/sparse/supernodal.h"

namespace gab {

int64_t factor_workspace_doubles(const SymbolicFactor& f) { return f.stack_peak; }

int64_t factor_workspace_ints(const SymbolicFactor& f) {
  // map (n) + relative indices and their run ends (2 * max rows) + child
  // lists and depths (3 * supernodes)
  return static_cast<int64_t>(f.n) + 2 * static_cast<int64_t>(f.max_front_rows) +
         3 * static_cast<int64_t>(f.num_supernodes);
}

Status factorize_supernodal(const SymbolicFactor& f, const CscMatrix& lower,
                            const DenseKernels& kern, double* values, double* work,
                            int32_t* iwork) {
  if (lower.ncols != f.n || lower.nnz() != f.nnz_A || lower.values.size() != lower.rowind.size()) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "matrix does not have the analyzed pattern (or has no values)");
  }
  const int32_t ns = f.num_supernodes;
  int32_t* map = iwork;                       // row -> position in the current front
  int32_t* rel = map + f.n;                   // child's rows -> positions in the front
  int32_t* run_end = rel + f.max_front_rows;  // end of the run of consecutive rel[] holding u
  int32_t* child_head = run_end + f.max_front_rows;
  int32_t* child_next = child_head + ns;
  int32_t* depth = child_next + ns;
  for (int32_t s = 0; s < ns; ++s) child_head[s] = -1;
  // Children in increasing order: the order their updates were pushed.
  for (int32_t s = ns - 1; s >= 0; --s) {
    const int32_t parent = f.supernode_parent[s];
    depth[s] = parent == -1 ? 0 : depth[parent] + 1;
    if (parent == -1) continue;
    child_next[s] = child_head[parent];
    child_head[parent] = s;
  }
  const double* a = lower.values.data();
  // Stack 0 occupies work[0, top[0]); stack 1 occupies the last top[1]
  // doubles of the f.stack_peak-sized buffer.
  int64_t top[2] = {0, 0};
  double* const work_end = work + f.stack_peak;
  for (int32_t s = 0; s < ns; ++s) {
    const int32_t k = f.cols(s), m = f.rows(s), p = m - k;
    const int64_t pp = static_cast<int64_t>(p) * p;
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    double* block = values + f.value_ptr[s];
    std::memset(block, 0, sizeof(double) * static_cast<size_t>(m) * k);
    for (int32_t t = 0; t < m; ++t) map[rows[t]] = t;
    for (int64_t q = f.a_ptr[s]; q < f.a_ptr[s + 1]; ++q) values[f.a_dest[q]] += a[f.a_order[q]];

    const int side = depth[s] & 1, child_side = 1 - side;
    double* update = side == 0 ? work + top[0] : work_end - top[1] - pp;
    for (int32_t j = 0; j < p; ++j) {
      std::memset(update + static_cast<int64_t>(j) * p + j, 0, sizeof(double) * (p - j));
    }
    // Children's updates are the top of the other stack, pushed in child
    // order; walk them from the oldest.
    int64_t children_size = 0;
    for (int32_t c = child_head[s]; c != -1; c = child_next[c]) {
      const int64_t pc = f.rows(c) - f.cols(c);
      children_size += pc * pc;
    }
    int64_t offset = top[child_side] - children_size;  // distance from the stack's base
    for (int32_t c = child_head[s]; c != -1; c = child_next[c]) {
      const int32_t kc = f.cols(c), pc = f.rows(c) - kc;
      const int64_t pcc = static_cast<int64_t>(pc) * pc;
      const double* cu = child_side == 0 ? work + offset : work_end - offset - pcc;
      const int32_t* crows = f.row_ind.data() + f.row_ptr[c] + kc;
      for (int32_t t = 0; t < pc; ++t) rel[t] = map[crows[t]];
      // A child's rows mostly land on runs of consecutive front rows; add
      // each run as one contiguous (vectorizable) loop instead of a scatter.
      for (int32_t u = pc - 1; u >= 0; --u) {
        run_end[u] = (u + 1 < pc && rel[u + 1] == rel[u] + 1) ? run_end[u + 1] : u + 1;
      }
      for (int32_t t = 0; t < pc; ++t) {
        const double* src = cu + static_cast<int64_t>(t) * pc;
        const int32_t col = rel[t];
        double* dst = col < k ? block + static_cast<int64_t>(col) * m
                              : update + static_cast<int64_t>(col - k) * p - k;
        for (int32_t u = t; u < pc;) {
          const int32_t end = run_end[u];
          double* d = dst + rel[u] - u;
          for (int32_t w = u; w < end; ++w) d[w] += src[w];
          u = end;
        }
      }
      offset += pcc;
    }
    top[child_side] -= children_size;  // pop the children

    const int32_t bad = kern.potrf(k, block, m);
    if (bad >= 0) {
      const int32_t col = f.first_col[s] + bad;
      return Status::Error(StatusCode::kNotPositiveDefinite,
                           "matrix is not positive definite: pivot " + std::to_string(col) +
                               " (original row/column " + std::to_string(f.perm[col]) +
                               ") is not positive");
    }
    if (p > 0) {
      kern.trsm_right_lower_trans(p, k, block, m, block + k, m);
      kern.syrk_lower_sub(p, k, block + k, m, update, p);
      top[side] += pp;  // push this front's update
    }
  }
  return Status::Ok();
}

}  // namespace gab
