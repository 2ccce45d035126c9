// Multifrontal supernodal Cholesky (Duff & Reid 1983; Liu, "The multifrontal
// method for sparse matrix solution", SIAM Review 1992).
//
// Supernodes are visited in (post)order. Each one's front is its factor
// block (rows x cols, stored in place in the factor) plus an update matrix
// for the rows below it. A front is assembled from A's entries and the
// update matrices of its children (extend-add through relative indices),
// then partially factored: POTRF on the diagonal block, TRSM below it, and
// one SYRK that forms its own update matrix, a lower triangle packed in
// column panels (half the room of a square). A wide supernode stored as a
// chain of panels (SymbolicFactor::continued) is one front whose columns
// lie in several blocks; it is factored by blocks (factor_front). Update
// matrices live on two stacks sharing one buffer, at offsets the schedule fixed
// (factor_schedule.h), so nothing is allocated here: even-depth supernodes
// push at the low end, odd-depth ones at the high end. A parent's children
// therefore sit on top of the other stack than the one its own update goes
// to, so the parent's update is formed in place while the children's are
// read, then the children are popped — no copy (a single stack would need a
// memmove per front). Chosen over
// left-looking because each supernode then does one large SYRK instead of
// one small GEMM per descendant, which keeps the SIMD kernel busy.
//
// With several threads, each factors whole subtrees of the schedule on its
// own stacks; the top part follows, its large kernel calls shared by the
// whole team (kernel_team.h); see factor_schedule.h.
#include <atomic>
#include <cstring>
#include <string>
#include <thread>

#include "gab/sparse/supernodal.h"
#include "factor/kernel_team.h"
#include "factor/start_thread.h"

namespace gab {

int64_t factor_workspace_doubles(const FactorSchedule& plan) { return plan.stack_doubles(); }

int64_t factor_workspace_ints(const SymbolicFactor& f, const FactorSchedule& plan) {
  // per thread: map (n) + relative indices and their run ends (2 * max rows)
  return plan.threads * (static_cast<int64_t>(f.n) + 2 * static_cast<int64_t>(f.max_front_rows));
}

namespace {

struct FrontContext {
  const SymbolicFactor& f;
  const FactorSchedule& plan;
  const double* a;  // A's values
  const DenseKernels& kern;
  double* values;
  double* work;
};

// Assembles and partially factors one front: supernode s1, or the chain of
// panels s0..s1 (SymbolicFactor::continued) cut from one supernode. A
// chain's panels hold the front's columns in consecutive blocks, panel t
// its columns' rows from its own first column on (ld rows(t)); the front is
// factored by blocks, right-looking: each panel's POTRF and TRSM, then its
// SYRK and GEMM into the later panels, and its SYRK into the front's update
// matrix. A single supernode is the same steps with one panel. map, rel and
// run_end are this thread's. Returns -1, or the supernode whose pivot failed
// (its column offset in *bad_col).
int32_t factor_front(const FrontContext& ctx, int32_t s0, int32_t s1, int32_t* map, int32_t* rel,
                     int32_t* run_end, int32_t* bad_col) {
  const SymbolicFactor& f = ctx.f;
  double* const values = ctx.values;
  const int32_t first = f.first_col[s0];
  const int32_t k = f.first_col[s1 + 1] - first, m = f.rows(s0), p = m - k;  // the front's
  const int32_t* rows = f.row_ind.data() + f.row_ptr[s0];
  std::memset(values + f.value_ptr[s0], 0, sizeof(double) * static_cast<size_t>(f.value_ptr[s1 + 1] - f.value_ptr[s0]));
  for (int32_t t = 0; t < m; ++t) map[rows[t]] = t;
  for (int32_t s = s0; s <= s1; ++s) {
    double* block = values + f.value_ptr[s];
    for (int64_t q = f.a_ptr[s]; q < f.a_ptr[s + 1]; ++q) block[f.a_dest[q]] += ctx.a[f.a_order[q]];
  }
  // Front column c at front row r (r >= c): in the panel holding c, which
  // starts at front row and column `off`.
  auto column = [&](int32_t c) {
    const int32_t s = f.supernode_of[first + c], off = f.first_col[s] - first;
    return values + f.value_ptr[s] + static_cast<int64_t>(c - off) * f.rows(s) - off;
  };

  // Update matrices are packed lower triangles (dense_kernels.h).
  double* update = ctx.work + ctx.plan.update_offset[s1];
  for (int32_t j = 0; j < p; ++j) {
    std::memset(packed_lower_column(update, p, j) + j, 0, sizeof(double) * (p - j));
  }
  // Children in increasing order, whichever group left their updates; a
  // panel's previous panel is part of this front, not a child.
  for (int32_t s = s0; s <= s1; ++s) {
    for (int32_t c = ctx.plan.child_head[s]; c != -1; c = ctx.plan.child_next[c]) {
      if (f.continues(c)) continue;
      const int32_t kc = f.cols(c), pc = f.rows(c) - kc;
      const double* cu = ctx.work + ctx.plan.update_offset[c];
      const int32_t* crows = f.row_ind.data() + f.row_ptr[c] + kc;
      for (int32_t t = 0; t < pc; ++t) rel[t] = map[crows[t]];
      // A child's rows mostly land on runs of consecutive front rows; add
      // each run as one contiguous (vectorizable) loop instead of a scatter.
      for (int32_t u = pc - 1; u >= 0; --u) {
        run_end[u] = (u + 1 < pc && rel[u + 1] == rel[u] + 1) ? run_end[u + 1] : u + 1;
      }
      for (int32_t t = 0; t < pc; ++t) {
        const double* src = packed_lower_column(cu, pc, t);
        const int32_t col = rel[t];
        double* dst = col < k ? column(col) : packed_lower_column(update, p, col - k) - k;
        for (int32_t u = t; u < pc;) {
          const int32_t end = run_end[u];
          double* d = dst + rel[u] - u;
          for (int32_t w = u; w < end; ++w) d[w] += src[w];
          u = end;
        }
      }
    }
  }

  for (int32_t s = s0; s <= s1; ++s) {
    const int32_t ks = f.cols(s), ms = f.rows(s), off = f.first_col[s] - first;
    double* block = values + f.value_ptr[s];
    const int32_t bad = ctx.kern.potrf(ks, block, ms);
    if (bad >= 0) {
      *bad_col = bad;
      return s;
    }
    if (ms == ks) continue;
    ctx.kern.trsm_right_lower_trans(ms - ks, ks, block, ms, block + ks, ms);
    for (int32_t t = s + 1; t <= s1; ++t) {
      const int32_t kt = f.cols(t), mt = f.rows(t);
      const double* l = block + (f.first_col[t] - first - off);  // this panel's rows from t's first
      double* target = values + f.value_ptr[t];
      ctx.kern.syrk_lower_sub(kt, ks, l, ms, target, mt);
      if (mt > kt) ctx.kern.gemm_nt_sub(mt - kt, kt, ks, l + kt, ms, l, ms, target + kt, mt);
    }
    if (p > 0) ctx.kern.syrk_lower_sub_packed(p, ks, block + (k - off), ms, update);
  }
  return -1;
}

// Assembles and partially factors the fronts of one group, in order.
// Returns the first supernode whose pivot failed (its column offset in
// *bad_col), or -1.
int32_t factor_group(const FrontContext& ctx, int32_t group, int32_t* map, int32_t* rel,
                     int32_t* run_end, int32_t* bad_col) {
  const SymbolicFactor& f = ctx.f;
  for (int32_t i = ctx.plan.group_ptr[group]; i < ctx.plan.group_ptr[group + 1]; ++i) {
    const int32_t s = ctx.plan.order[i];
    if (f.continues(s)) continue;  // factored with the rest of its chain
    const int32_t fail = factor_front(ctx, f.chain_first(s), s, map, rel, run_end, bad_col);
    if (fail != -1) return fail;
  }
  return -1;
}

}  // namespace

Status factorize_supernodal(const SymbolicFactor& f, const FactorSchedule& plan, const double* a,
                            const DenseKernels& kern, double* values, double* work, int32_t* iwork) {
  const int32_t threads = plan.threads;
  const int64_t per_thread = static_cast<int64_t>(f.n) + 2 * static_cast<int64_t>(f.max_front_rows);
  const FrontContext ctx{f, plan, a, kern, values, work};
  auto run = [&](int32_t group, int32_t thread, int32_t* bad_col) {
    int32_t* map = iwork + thread * per_thread;
    return factor_group(ctx, group, map, map + f.n, map + f.n + f.max_front_rows, bad_col);
  };

  int32_t fail = -1, bad = 0;
  if (threads == 1) {
    fail = run(0, 0, &bad);
  } else {
    // Groups 1..threads-1 on their own threads, group 0 here; then the top
    // part here, the other threads helping inside its large kernel calls.
    // The first failure in (post)order is the serial one: each group stops
    // at its first, and a front fails or not whatever ran before it.
    // The helpers wait at a gate until every one has started: a team short
    // of a member would wait for it forever. When the system refuses a
    // thread (start_thread.h) the started ones leave, and the groups and
    // the top part run here one after another: the same fronts in an order
    // the schedule allows, so the same factor.
    int32_t failed[kMaxFactorThreads], bad_cols[kMaxFactorThreads];
    dense_detail::KernelTeam team(threads);
    std::atomic<int32_t> groups_done{0};
    std::atomic<int32_t> gate{0};  // 0: wait, 1: work, -1: leave
    std::thread pool[kMaxFactorThreads];
    int32_t started = 1;
    while (started < threads && try_start_thread(&pool[started], [&, g = started] {
             int32_t state;
             while ((state = gate.load(std::memory_order_acquire)) == 0) std::this_thread::yield();
             if (state < 0) return;
             failed[g] = run(g, g, &bad_cols[g]);
             groups_done.fetch_add(1, std::memory_order_release);
             team.serve(g);
           })) {
      ++started;
    }
    const bool alone = started < threads;
    gate.store(alone ? -1 : 1, std::memory_order_release);
    if (alone) {
      for (int32_t g = 1; g < started; ++g) pool[g].join();
      for (int32_t g = 1; g < threads; ++g) failed[g] = run(g, 0, &bad_cols[g]);
    }
    failed[0] = run(0, 0, &bad_cols[0]);
    while (!alone && groups_done.load(std::memory_order_acquire) < threads - 1) std::this_thread::yield();
    for (int32_t g = 0; g < threads; ++g) {
      if (failed[g] != -1 && (fail == -1 || failed[g] < fail)) {
        fail = failed[g];
        bad = bad_cols[g];
      }
    }
    if (fail == -1 && alone) fail = run(threads, 0, &bad);
    if (fail == -1 && !alone) {
      dense_detail::LeadTeam lead(&team);
      fail = run(threads, 0, &bad);
    }
    team.stop();
    if (!alone) {
      for (int32_t g = 1; g < threads; ++g) pool[g].join();
    }
  }
  if (fail != -1) {
    const int32_t col = f.first_col[fail] + bad;
    return Status::Error(StatusCode::kNotPositiveDefinite,
                         "matrix is not positive definite: pivot " + std::to_string(col) +
                             " (original row/column " + std::to_string(f.perm[col]) +
                             ") is not positive");
  }
  return Status::Ok();
}

}  // namespace gab
