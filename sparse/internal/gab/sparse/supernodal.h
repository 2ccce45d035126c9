// Numeric supernodal Cholesky (multifrontal) and the supernodal triangular
// solves, on the analysis of symbolic.h. These are the allocation-free
// kernels: the caller supplies every buffer (sizes below); cholesky.h wraps
// them in a convenient object.
#pragma once

#include <cstdint>

#include "gab/sparse/csc.h"
#include "gab/sparse/dense_kernels.h"
#include "gab/sparse/factor_schedule.h"
#include "gab/status.h"
#include "gab/sparse/symbolic.h"

namespace gab {

// Workspace sizes, in elements, for factorize_supernodal with a schedule.
int64_t factor_workspace_doubles(const FactorSchedule& plan);  // the update stacks
int64_t factor_workspace_ints(const SymbolicFactor& f,
                              const FactorSchedule& plan);  // maps and child lists

// Numeric factorization P A P^T = L L^T. `a` holds the f.nnz_A values of
// A's lower triangle in the order of the analyzed matrix's entries (its
// values array; the pattern itself is not read). `values` receives the supernode blocks
// (f.value_ptr[f.num_supernodes] doubles); the strict upper triangle of each
// diagonal block is left unspecified. A non-positive pivot gives
// kNotPositiveDefinite naming the column in the original numbering (the
// first failing pivot in pivot order, whatever the schedule). `plan` (from
// plan_factor_schedule(f, ...)) says which threads do what; the values are
// bit-identical for every plan. Time: the factorization's flops, run in the
// dense kernels `k`, spread over plan.threads threads.
Status factorize_supernodal(const SymbolicFactor& f, const FactorSchedule& plan, const double* a,
                            const DenseKernels& k, double* values, double* work, int32_t* iwork);

// Solves L Y = B (lower) or L^T X = Y (upper) in place, in the permuted
// numbering: x is n x nrhs column-major with leading dimension ldx. `work`
// holds f.max_front_rows * nrhs doubles. `level` picks the SIMD kernels
// (clamped to the CPU's). Time O(nnz(L) * nrhs), one pass over L per
// direction for all right-hand sides together.
void solve_lower_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level);
void solve_upper_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level);

// The same solves on plan.threads threads: the schedule's subtree groups
// concurrently, the top part alone; bit-identical to the serial solves.
// `work` holds solve_scheduled_work(f, plan, nrhs) doubles.
int64_t solve_scheduled_work(const SymbolicFactor& f, const FactorSchedule& plan, int32_t nrhs);
void solve_lower_scheduled(const SymbolicFactor& f, const FactorSchedule& plan,
                           const double* values, double* x, int32_t nrhs, int32_t ldx,
                           double* work, SimdLevel level);
void solve_upper_scheduled(const SymbolicFactor& f, const FactorSchedule& plan,
                           const double* values, double* x, int32_t nrhs, int32_t ldx,
                           double* work, SimdLevel level);

}  // namespace gab
