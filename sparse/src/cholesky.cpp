// The Cholesky object: buffers and permutations around the supernodal kernels.
#include "gab/sparse/cholesky.h"

#include <string>

#include "gab/sparse/supernodal.h"

namespace gab {

Status Cholesky::analyze(const CscMatrix& lower, const AnalyzeOptions& options) {
  analyzed_ = factorized_ = false;
  populator_.finish();  // the buffers may move
  GAB_RETURN_IF_ERROR(analyze_structure(lower, options, &symbolic_));
  if (symbolic_.stored_L > options.max_factor_entries) {
    return Status::Error(StatusCode::kResourceExhausted,
                         "the factor would exceed " + std::to_string(options.max_factor_entries) + " entries");
  }
  const int64_t values = symbolic_.value_ptr[symbolic_.num_supernodes];
  schedule_ = plan_factor_schedule(symbolic_, options.threads);
  // The solves split the tree by their own work (entries, not flops): the
  // flops' split leaves the solves' groups unbalanced.
  solve_schedule_ = plan_factor_schedule(symbolic_, options.threads, ScheduleBalance::kSolveEntries);
  const int64_t work = factor_workspace_doubles(schedule_);
  if (!values_.reserve(values) || !work_.reserve(work) ||
      !iwork_.reserve(factor_workspace_ints(symbolic_, schedule_))) {
    return Status::Error(StatusCode::kOutOfMemory,
                         "cannot allocate " + std::to_string((values + work) * 8 >> 20) +
                             " MiB for the factor and its workspace");
  }
  // With threads to spare, fault in the factor and its stacks while the
  // assembly map is built (and whatever the caller does before factorize).
  if (options.threads >= 2) {
    populator_.start({{values_.data(), sizeof(double) * static_cast<size_t>(values)},
                      {work_.data(), sizeof(double) * static_cast<size_t>(work)}});
  }
  map_assembly(lower, &symbolic_);
  // The updater's workspace waits for the first update (prepare_updates):
  // a caller that only factors and solves (a decoder that refactors) would
  // otherwise fault in ~11 n doubles it never uses.
  update_ready_ = false;
  analyzed_ = true;
  return Status::Ok();
}

Status Cholesky::factorize(const CscMatrix& lower) {
  if (!analyzed_) return Status::Error(StatusCode::kInvalidArgument, "factorize before analyze");
  factorized_ = false;
  populator_.finish();
  if (kernels_ == nullptr) kernels_ = &dense_kernels();
  GAB_RETURN_IF_ERROR(factorize_supernodal(symbolic_, schedule_, lower, *kernels_, values_.data(),
                                           work_.data(), iwork_.data()));
  factorized_ = true;
  return Status::Ok();
}

Status Cholesky::solve(double* b, int32_t nrhs, int32_t ldb) {
  if (!factorized_) return Status::Error(StatusCode::kInvalidArgument, "solve before factorize");
  const int32_t n = symbolic_.n;
  if (nrhs < 0 || ldb < n) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "solve needs nrhs >= 0 and ldb >= n (" + std::to_string(n) + ")");
  }
  if (!solve_rhs_.reserve(static_cast<int64_t>(n) * nrhs) ||
      !solve_work_.reserve(solve_scheduled_work(symbolic_, solve_schedule_, nrhs))) {
    return Status::Error(StatusCode::kOutOfMemory, "cannot allocate the solve's workspace");
  }
  const int32_t* perm = symbolic_.perm.data();
  for (int32_t r = 0; r < nrhs; ++r) {
    const double* src = b + static_cast<int64_t>(r) * ldb;
    double* dst = solve_rhs_.data() + static_cast<int64_t>(r) * n;
    for (int32_t k = 0; k < n; ++k) dst[k] = src[perm[k]];
  }
  solve_lower_scheduled(symbolic_, solve_schedule_, values_.data(), solve_rhs_.data(), nrhs, n,
                        solve_work_.data(), kernels_->level);
  solve_upper_scheduled(symbolic_, solve_schedule_, values_.data(), solve_rhs_.data(), nrhs, n,
                        solve_work_.data(), kernels_->level);
  for (int32_t r = 0; r < nrhs; ++r) {
    const double* src = solve_rhs_.data() + static_cast<int64_t>(r) * n;
    double* dst = b + static_cast<int64_t>(r) * ldb;
    for (int32_t k = 0; k < n; ++k) dst[perm[k]] = src[k];
  }
  return Status::Ok();
}

Status Cholesky::prepare_update_workspace() {
  if (!update_work_.reserve(update_workspace_doubles(symbolic_)) ||
      !update_iwork_.reserve(update_workspace_ints(symbolic_))) {
    return Status::Error(StatusCode::kOutOfMemory, "cannot allocate the updater's workspace");
  }
  // The updates keep these invariants (see update.h).
  const int64_t zeros = update_workspace_zero_prefix(symbolic_);
  for (int64_t i = 0; i < zeros; ++i) update_work_.data()[i] = 0.0;
  const int64_t ints = update_workspace_ints(symbolic_);
  for (int64_t i = 0; i < ints; ++i) update_iwork_.data()[i] = -1;
  update_ready_ = true;
  return Status::Ok();
}

Status Cholesky::prepare_update() {
  if (!factorized_) return Status::Error(StatusCode::kInvalidArgument, "update before factorize");
  return update_ready_ ? Status::Ok() : prepare_update_workspace();
}

Status Cholesky::add_anchor(int32_t j, double weight, UpdateStats* stats) {
  GAB_RETURN_IF_ERROR(prepare_update());
  return add_anchor_supernodal(symbolic_, values_.data(), j, weight, kernels_->level,
                               update_work_.data(), stats);
}

Status Cholesky::add_anchors(const int32_t* j, int32_t count, double weight, UpdateStats* stats) {
  GAB_RETURN_IF_ERROR(prepare_update());
  return add_anchors_supernodal(symbolic_, values_.data(), j, count, weight, kernels_->level,
                                update_work_.data(), update_iwork_.data(), stats);
}

Status Cholesky::remove_anchor(int32_t j, double weight, UpdateStats* stats) {
  GAB_RETURN_IF_ERROR(prepare_update());
  return remove_anchor_supernodal(symbolic_, values_.data(), j, weight, kernels_->level,
                                  update_work_.data(), update_iwork_.data(), stats);
}

}  // namespace gab
