// The Cholesky object: buffers and permutations around the supernodal kernels.
#include "gab/sparse/cholesky.h"

#include <algorithm>
#include <string>

#include "gab/sparse/dense_kernels.h"
#include "gab/sparse/factor_schedule.h"
#include "gab/sparse/large_buffer.h"
#include "gab/sparse/supernodal.h"
#include "gab/sparse/update.h"

namespace gab {
namespace {

// Update stacks at least this large are released after each factorization.
constexpr size_t kReleasedStackBytes = size_t{128} << 20;

}  // namespace

struct Cholesky::State {
  SymbolicFactor symbolic;
  FactorSchedule schedule;        // the factorization's split (flops)
  FactorSchedule solve_schedule;  // the solves' split (entries)
  const DenseKernels* kernels = nullptr;
  bool analyzed = false;
  bool factorized = false;
  LargeBuffer<double> values;
  // The multifrontal update stacks during factorize(), the updaters'
  // workspace between factorizations (see update_workspace_doubles): an
  // encoder that factors and then adds anchors needs the two in turn, and
  // at 2.4M vertices each is 0.2 GB.
  LargeBuffer<double> work;
  LargeBuffer<int32_t> iwork;
  LargeBuffer<double> solve_rhs;  // permuted right-hand sides
  LargeBuffer<double> solve_work;
  LargeBuffer<int32_t> update_iwork;
  PagePopulator populator;  // after the buffers: stops before they are freed
  bool update_ready = false;

  Status prepare_update();
  Status prepare_update_workspace();
};

Cholesky::Cholesky() : state_(new State) {}
Cholesky::~Cholesky() = default;

void Cholesky::set_kernels(const DenseKernels& kernels) { state_->kernels = &kernels; }

const char* Cholesky::simd_level() const {
  const DenseKernels* kernels = state_->kernels != nullptr ? state_->kernels : &dense_kernels();
  return simd_level_name(kernels->level);
}
bool Cholesky::factorized() const { return state_->factorized; }
const SymbolicFactor& Cholesky::symbolic() const { return state_->symbolic; }
const FactorSchedule& Cholesky::schedule() const { return state_->schedule; }
const FactorSchedule& Cholesky::solve_schedule() const { return state_->solve_schedule; }
const double* Cholesky::values() const { return state_->values.data(); }
double* Cholesky::mutable_values() { return state_->values.data(); }
Status Cholesky::prepare_updates() { return state_->prepare_update(); }

Status Cholesky::analyze(const CscMatrix& lower, const AnalyzeOptions& options) {
  State& s = *state_;
  s.analyzed = s.factorized = false;
  s.populator.finish();  // the buffers may move
  GAB_RETURN_IF_ERROR(analyze_structure(lower, options, &s.symbolic));
  if (s.symbolic.stored_L > options.max_factor_entries) {
    return Status::Error(StatusCode::kResourceExhausted,
                         "the factor would exceed " + std::to_string(options.max_factor_entries) + " entries");
  }
  const int64_t values = s.symbolic.value_ptr[s.symbolic.num_supernodes];
  s.schedule = plan_factor_schedule(s.symbolic, options.threads);
  // The solves split the tree by their own work (entries, not flops): the
  // flops' split leaves the solves' groups unbalanced.
  s.solve_schedule = plan_factor_schedule(s.symbolic, options.threads, ScheduleBalance::kSolveEntries);
  const int64_t work = factor_workspace_doubles(s.schedule);
  // Only the stacks' part is faulted in below; the rest waits for updates.
  if (!s.values.reserve(values) || !s.work.reserve(std::max(work, update_workspace_doubles(s.symbolic))) ||
      !s.iwork.reserve(factor_workspace_ints(s.symbolic, s.schedule))) {
    return Status::Error(StatusCode::kOutOfMemory,
                         "cannot allocate " + std::to_string((values + work) * 8 >> 20) +
                             " MiB for the factor and its workspace");
  }
  // With threads to spare, fault in the factor and its stacks while the
  // assembly map is built (and whatever the caller does before factorize).
  if (options.threads >= 2) {
    s.populator.start({{s.values.data(), sizeof(double) * static_cast<size_t>(values)},
                      {s.work.data(), sizeof(double) * static_cast<size_t>(work)}});
  }
  map_assembly(lower, &s.symbolic);
  // The updater's workspace waits for the first update (prepare_updates):
  // a caller that only factors and solves (a decoder that refactors) never
  // faults in the ~11 n doubles it would take beyond the stacks.
  s.update_ready = false;
  s.analyzed = true;
  return Status::Ok();
}

Status Cholesky::factorize(const CscMatrix& lower) {
  const SymbolicFactor& f = state_->symbolic;
  if (state_->analyzed &&
      (lower.ncols != f.n || lower.nnz() != f.nnz_A || lower.values.size() != lower.rowind.size())) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "matrix does not have the analyzed pattern (or has no values)");
  }
  return factorize_values(lower.values.data(), static_cast<int64_t>(lower.values.size()));
}

Status Cholesky::factorize_values(const double* a, int64_t count) {
  State& s = *state_;
  if (!s.analyzed) return Status::Error(StatusCode::kInvalidArgument, "factorize before analyze");
  if (count != s.symbolic.nnz_A || (a == nullptr && count > 0)) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "factorize_values needs the analyzed matrix's " + std::to_string(s.symbolic.nnz_A) +
                             " values, got " + std::to_string(count));
  }
  s.factorized = false;
  s.update_ready = false;  // the stacks overwrite the updaters' workspace
  s.populator.finish();
  if (s.kernels == nullptr) s.kernels = &dense_kernels();
  const Status status = factorize_supernodal(s.symbolic, s.schedule, a, *s.kernels, s.values.data(), s.work.data(),
                                             s.iwork.data());
  // Large stacks go back to the OS until the next factorization or update
  // needs them: problems this large refactor rarely, and what limits them
  // is memory (a 2.4M-vertex encoder's peak came after its factorization;
  // with its 0.25 GB of stacks gone, the factorization's own is the peak).
  // Re-faulting them costs a few percent of a factorization.
  if (static_cast<size_t>(factor_workspace_doubles(s.schedule)) * sizeof(double) >= kReleasedStackBytes) {
    s.work.release_pages();
  }
  GAB_RETURN_IF_ERROR(status);
  s.factorized = true;
  return Status::Ok();
}

Status Cholesky::solve(double* b, int32_t nrhs, int32_t ldb) {
  State& s = *state_;
  if (!s.factorized) return Status::Error(StatusCode::kInvalidArgument, "solve before factorize");
  const int32_t n = s.symbolic.n;
  if (nrhs < 0 || ldb < n) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "solve needs nrhs >= 0 and ldb >= n (" + std::to_string(n) + ")");
  }
  if (!s.solve_rhs.reserve(static_cast<int64_t>(n) * nrhs) ||
      !s.solve_work.reserve(solve_scheduled_work(s.symbolic, s.solve_schedule, nrhs))) {
    return Status::Error(StatusCode::kOutOfMemory, "cannot allocate the solve's workspace");
  }
  const int32_t* perm = s.symbolic.perm.data();
  for (int32_t r = 0; r < nrhs; ++r) {
    const double* src = b + static_cast<int64_t>(r) * ldb;
    double* dst = s.solve_rhs.data() + static_cast<int64_t>(r) * n;
    for (int32_t k = 0; k < n; ++k) dst[k] = src[perm[k]];
  }
  solve_lower_scheduled(s.symbolic, s.solve_schedule, s.values.data(), s.solve_rhs.data(), nrhs, n,
                        s.solve_work.data(), s.kernels->level);
  solve_upper_scheduled(s.symbolic, s.solve_schedule, s.values.data(), s.solve_rhs.data(), nrhs, n,
                        s.solve_work.data(), s.kernels->level);
  for (int32_t r = 0; r < nrhs; ++r) {
    const double* src = s.solve_rhs.data() + static_cast<int64_t>(r) * n;
    double* dst = b + static_cast<int64_t>(r) * ldb;
    for (int32_t k = 0; k < n; ++k) dst[perm[k]] = src[k];
  }
  return Status::Ok();
}

Status Cholesky::State::prepare_update_workspace() {
  // work (reserved by analyze) is large enough for the doubles.
  if (!update_iwork.reserve(update_workspace_ints(symbolic))) {
    return Status::Error(StatusCode::kOutOfMemory, "cannot allocate the updater's workspace");
  }
  // The updates keep these invariants (see update.h); a factorization
  // breaks them.
  const int64_t zeros = update_workspace_zero_prefix(symbolic);
  std::fill_n(work.data(), zeros, 0.0);
  const int64_t ints = update_workspace_ints(symbolic);
  for (int64_t i = 0; i < ints; ++i) update_iwork.data()[i] = -1;
  update_ready = true;
  return Status::Ok();
}

Status Cholesky::State::prepare_update() {
  if (!factorized) return Status::Error(StatusCode::kInvalidArgument, "update before factorize");
  return update_ready ? Status::Ok() : prepare_update_workspace();
}

Status Cholesky::add_anchor(int32_t j, double weight, UpdateStats* stats) {
  State& s = *state_;
  GAB_RETURN_IF_ERROR(s.prepare_update());
  return add_anchor_supernodal(s.symbolic, s.values.data(), j, weight, s.kernels->level,
                               s.work.data(), stats);
}

Status Cholesky::add_anchors(const int32_t* j, int32_t count, double weight, UpdateStats* stats) {
  State& s = *state_;
  GAB_RETURN_IF_ERROR(s.prepare_update());
  return add_anchors_supernodal(s.symbolic, s.values.data(), j, count, weight, s.kernels->level,
                                s.work.data(), s.update_iwork.data(), stats);
}

Status Cholesky::remove_anchor(int32_t j, double weight, UpdateStats* stats) {
  State& s = *state_;
  GAB_RETURN_IF_ERROR(s.prepare_update());
  return remove_anchor_supernodal(s.symbolic, s.values.data(), j, weight, s.kernels->level,
                                  s.work.data(), s.update_iwork.data(), stats);
}

}  // namespace gab
