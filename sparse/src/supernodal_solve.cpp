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
// subtrees run concurrently. Forward, a group adds only to its own rows;
// then one pass in order adds every supernode's rows in the top part and
// solves the top, so each entry of x receives the same sums in the same
// order as in the serial solve (the kernels compute each row of W alone).
// Backward, the top goes first, then the groups, each reading only rows
// already final. Hence bit-identical results for every thread count.
#include <thread>

#include "gab/sparse/supernodal.h"
#include "solve_kernels.h"

namespace gab {
namespace {

// Forward step of supernode s: the diagonal solve (when `diagonal`), then
// the rows below in [from, to).
void forward_step(const SymbolicFactor& f, const solve_detail::SolveKernels& kern,
                  const double* values, int32_t s, bool diagonal, int32_t from, int32_t to,
                  double* x, int32_t nrhs, int32_t ldx, double* work) {
  const int32_t k = f.cols(s), m = f.rows(s), rows = to - from;
  const double* l = values + f.value_ptr[s];
  double* x1 = x + f.first_col[s];
  if (diagonal) kern.trsm_lower(k, nrhs, l, m, x1, ldx);
  if (rows <= 0) return;
  kern.gemm_nn_neg(rows, k, nrhs, l + k + from, m, x1, ldx, work);
  const int32_t* below = f.row_ind.data() + f.row_ptr[s] + k + from;
  for (int32_t r = 0; r < nrhs; ++r) {
    double* xr = x + static_cast<int64_t>(r) * ldx;
    const double* wr = work + static_cast<int64_t>(r) * rows;
    for (int32_t t = 0; t < rows; ++t) xr[below[t]] += wr[t];
  }
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

// Runs body(g) for the schedule's groups 0..threads-1 concurrently.
template <class F>
void run_groups(int32_t threads, const F& body) {
  std::thread pool[kMaxFactorThreads];
  for (int32_t g = 1; g < threads; ++g) pool[g] = std::thread([&body, g] { body(g); });
  body(0);
  for (int32_t g = 1; g < threads; ++g) pool[g].join();
}

}  // namespace

void solve_lower_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level) {
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    forward_step(f, kern, values, s, true, 0, f.rows(s) - f.cols(s), x, nrhs, ldx, work);
  }
}

void solve_upper_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level) {
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  for (int32_t s = f.num_supernodes - 1; s >= 0; --s) {
    backward_step(f, kern, values, s, x, nrhs, ldx, work);
  }
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
  run_groups(threads, [&](int32_t g) {
    for (int32_t i = plan.group_ptr[g]; i < plan.group_ptr[g + 1]; ++i) {
      const int32_t s = plan.order[i];
      forward_step(f, kern, values, s, true, 0, plan.own_rows[s], x, nrhs, ldx,
                   work + g * per_thread);
    }
  });
  // In order: the top supernodes whole, the others' rows in the top.
  int32_t next_top = plan.group_ptr[threads];
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    const int32_t p = f.rows(s) - f.cols(s);
    const bool top = next_top < plan.group_ptr[threads + 1] && plan.order[next_top] == s;
    if (top) ++next_top;
    if (top || plan.own_rows[s] < p) {
      forward_step(f, kern, values, s, top, top ? 0 : plan.own_rows[s], p, x, nrhs, ldx, work);
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
