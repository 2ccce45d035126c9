// Supernodal triangular solves with several right-hand sides at once.
//
// Forward (L y = b), supernode by supernode in order: solve with the dense
// diagonal block, form W = -(block below) * (solved part) in a small dense
// buffer, add W to the rows below (scatter). Backward (L^T x = y) in
// reverse order: gather the rows below into W, subtract (block below)^T W,
// solve with the transposed diagonal block. The dense kernels treat every
// right-hand side in the same sweep, so L streams from memory once per
// direction (the solves are memory-bound).
//
// With a schedule of several threads (factor_schedule.h) the groups' whole
// subtrees run concurrently. Forward, a group adds only to its own rows and
// keeps its products for the rows in the top part; then one pass in order
// adds those and solves the top, so each entry of x receives the same sums
// in the same order as in the serial solve (the kernels compute each row of
// W alone).
// Backward, the top goes first, then the groups, each reading only rows
// already final. Hence bit-identical results for every thread count.
#include <thread>

#include "gab/sparse/supernodal.h"
#include "factor/start_thread.h"
#include "kernels/solve_kernels.h"

namespace gab {
namespace {

// Adds W (rows x nrhs, ld rows) to x's rows below supernode s's columns,
// starting at its below-row `from`.
void scatter_add(const SymbolicFactor& f, int32_t s, int32_t from, int32_t rows, const double* w,
                 double* x, int32_t nrhs, int32_t ldx) {
  const int32_t* below = f.row_ind.data() + f.row_ptr[s] + f.cols(s) + from;
  for (int32_t r = 0; r < nrhs; ++r) {
    double* xr = x + static_cast<int64_t>(r) * ldx;
    const double* wr = w + static_cast<int64_t>(r) * rows;
    for (int32_t t = 0; t < rows; ++t) xr[below[t]] += wr[t];
  }
}

// Forward step of supernode s: the diagonal solve, then its first `rows`
// rows below.
void forward_step(const SymbolicFactor& f, const solve_detail::SolveKernels& kern,
                  const double* values, int32_t s, int32_t rows, double* x, int32_t nrhs,
                  int32_t ldx, double* work) {
  const int32_t k = f.cols(s), m = f.rows(s);
  const double* l = values + f.value_ptr[s];
  double* x1 = x + f.first_col[s];
  kern.trsm_lower(k, nrhs, l, m, x1, ldx);
  if (rows <= 0) return;
  kern.gemm_nn_neg(rows, k, nrhs, l + k, m, x1, ldx, work);
  scatter_add(f, s, 0, rows, work, x, nrhs, ldx);
}

void backward_step(const SymbolicFactor& f, const solve_detail::SolveKernels& kern,
                   const double* values, int32_t s, double* x, int32_t nrhs, int32_t ldx,
                   double* work) {
  const int32_t k = f.cols(s), m = f.rows(s), p = m - k;
  const double* l = values + f.value_ptr[s];
  double* x1 = x + f.first_col[s];
  if (p > 0) {
    const int32_t* below = f.row_ind.data() + f.row_ptr[s] + k;
    for (int32_t r = 0; r < nrhs; ++r) {
      const double* xr = x + static_cast<int64_t>(r) * ldx;
      double* wr = work + static_cast<int64_t>(r) * p;
      for (int32_t t = 0; t < p; ++t) wr[t] = xr[below[t]];
    }
    kern.gemm_tn_sub(p, k, nrhs, l + k, m, work, x1, ldx);
  }
  kern.trsm_lower_trans(k, nrhs, l, m, x1, ldx);
}

// Runs body(g) for the schedule's groups 0..threads-1 concurrently; a
// group whose thread the system refuses (start_thread.h) runs here after
// group 0 (the groups are independent subtrees).
template <class F>
void run_groups(int32_t threads, const F& body) {
  std::thread pool[kMaxFactorThreads];
  bool started[kMaxFactorThreads] = {};
  for (int32_t g = 1; g < threads; ++g) started[g] = try_start_thread(&pool[g], [&body, g] { body(g); });
  body(0);
  for (int32_t g = 1; g < threads; ++g) {
    if (started[g]) {
      pool[g].join();
    } else {
      body(g);
    }
  }
}

}  // namespace

void solve_lower_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level) {
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    forward_step(f, kern, values, s, f.rows(s) - f.cols(s), x, nrhs, ldx, work);
  }
}

void solve_upper_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level) {
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  for (int32_t s = f.num_supernodes - 1; s >= 0; --s) {
    backward_step(f, kern, values, s, x, nrhs, ldx, work);
  }
}

int64_t solve_scheduled_work(const SymbolicFactor& f, const FactorSchedule& plan, int32_t nrhs) {
  const int64_t top_rows = plan.threads > 1 ? plan.top_rows_ptr.back() : 0;
  return (static_cast<int64_t>(plan.threads) * f.max_front_rows + top_rows) * nrhs;
}

void solve_lower_scheduled(const SymbolicFactor& f, const FactorSchedule& plan,
                           const double* values, double* x, int32_t nrhs, int32_t ldx,
                           double* work, SimdLevel level) {
  const int32_t threads = plan.threads;
  if (threads == 1) {
    solve_lower_supernodal(f, values, x, nrhs, ldx, work, level);
    return;
  }
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  const int64_t per_thread = static_cast<int64_t>(f.max_front_rows) * nrhs;
  // Each group supernode's products for its rows in the top part wait here
  // (they only need its own solved columns, so the groups form them).
  double* top_w = work + threads * per_thread;
  run_groups(threads, [&](int32_t g) {
    for (int32_t i = plan.group_ptr[g]; i < plan.group_ptr[g + 1]; ++i) {
      const int32_t s = plan.order[i];
      const int32_t k = f.cols(s), m = f.rows(s), own = plan.own_rows[s];
      forward_step(f, kern, values, s, own, x, nrhs, ldx, work + g * per_thread);
      if (own < m - k) {
        kern.gemm_nn_neg(m - k - own, k, nrhs, values + f.value_ptr[s] + k + own, m,
                         x + f.first_col[s], ldx, top_w + plan.top_rows_ptr[s] * nrhs);
      }
    }
  });
  // In order, as the serial solve adds them: the groups' waiting products
  // and the top supernodes whole.
  int32_t next_top = plan.group_ptr[threads];
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    const bool top = next_top < plan.group_ptr[threads + 1] && plan.order[next_top] == s;
    if (top) {
      ++next_top;
      forward_step(f, kern, values, s, f.rows(s) - f.cols(s), x, nrhs, ldx, work);
    } else if (plan.top_rows_ptr[s + 1] > plan.top_rows_ptr[s]) {
      scatter_add(f, s, plan.own_rows[s],
                  static_cast<int32_t>(plan.top_rows_ptr[s + 1] - plan.top_rows_ptr[s]),
                  top_w + plan.top_rows_ptr[s] * nrhs, x, nrhs, ldx);
    }
  }
}

void solve_upper_scheduled(const SymbolicFactor& f, const FactorSchedule& plan,
                           const double* values, double* x, int32_t nrhs, int32_t ldx,
                           double* work, SimdLevel level) {
  const int32_t threads = plan.threads;
  if (threads == 1) {
    solve_upper_supernodal(f, values, x, nrhs, ldx, work, level);
    return;
  }
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  const int64_t per_thread = static_cast<int64_t>(f.max_front_rows) * nrhs;
  for (int32_t i = plan.group_ptr[threads + 1] - 1; i >= plan.group_ptr[threads]; --i) {
    backward_step(f, kern, values, plan.order[i], x, nrhs, ldx, work);
  }
  run_groups(threads, [&](int32_t g) {
    for (int32_t i = plan.group_ptr[g + 1] - 1; i >= plan.group_ptr[g]; --i) {
      backward_step(f, kern, values, plan.order[i], x, nrhs, ldx, work + g * per_thread);
    }
  });
}

}  // namespace gab
