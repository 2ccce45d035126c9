// The front door of the eigensolver: checks, the shift and its factor, the
// Lanczos runs with their convergence checks and restarts, the Ritz vectors
// and their residuals. Shift-and-invert (Ericsson & Ruhe 1980; Grimes,
// Lewis & Simon 1994): Op = (A - sigma I)^{-1} has eigenvalues
// theta = 1 / (lambda - sigma), largest for A's smallest, well separated
// there; Lanczos finds an operator's extreme eigenvalues first.
//
// Restarts (Saad, "Numerical Methods for Large Eigenvalue Problems", 2nd
// ed., sec. 4.3 and 5.2, explicit restart with locking): when the basis is
// full, the converged Ritz vectors are locked (kept, and every later vector
// is orthogonalized against them) and a new run starts from the best
// unconverged ones. Unlike a thick restart this keeps the projected matrix
// a band, so its eigenvalues cost O(b m^2) and each wanted vector O(b^2 m)
// instead of a dense O(m^3) eigensolve per check.
#include "gab/sparse/symmetric_eigensolver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <numeric>
#include <string>

#include "eigensolver/band_inverse_iteration.h"
#include "eigensolver/band_tridiagonal.h"
#include "eigensolver/block_lanczos.h"
#include "eigensolver/tridiagonal_ql.h"
#include "gab/sparse/cholesky.h"
#include "gab/sparse/dense_kernels.h"

namespace gab {

namespace {

using eigen_detail::BlockLanczos;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Status invalid(const std::string& what) {
  return Status::Error(StatusCode::kInvalidArgument, "smallest_eigenpairs: " + what);
}

Status check_arguments(const CscMatrix& a, const SymmetricEigenOptions& o) {
  if (a.nrows != a.ncols) {
    return invalid("the matrix is " + std::to_string(a.nrows) + " x " + std::to_string(a.ncols) + ", not square");
  }
  GAB_RETURN_IF_ERROR(check_csc(a));
  if (a.nnz() > 0 && a.values.empty()) return invalid("the matrix has no values");
  for (int32_t j = 0; j < a.ncols; ++j) {
    for (int32_t p = a.colptr[j]; p < a.colptr[j + 1]; ++p) {
      if (!std::isfinite(a.values[p])) {
        return invalid("entry (" + std::to_string(a.rowind[p]) + ", " + std::to_string(j) + ") is not finite");
      }
    }
  }
  if (o.count < 1 || o.count > a.nrows) {
    return invalid("count " + std::to_string(o.count) + " is outside 1.." + std::to_string(a.nrows));
  }
  if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance)) return invalid("tolerance must be positive and finite");
  if (!(o.shift <= 0.0) || !std::isfinite(o.shift)) return invalid("shift must be negative (or 0: chosen)");
  if (o.block_size < 1 || o.block_size > 64) return invalid("block_size " + std::to_string(o.block_size) + " is outside 1..64");
  if (o.max_restarts < 0) return invalid("max_restarts must be >= 0");
  if (o.threads < 1) return invalid("threads must be >= 1");
  return Status::Ok();
}

// ||A||_1 of the symmetric matrix whose lower triangle is given.
double norm1(const CscMatrix& lower) {
  std::vector<double> sum(lower.ncols, 0.0);
  for (int32_t j = 0; j < lower.ncols; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t i = lower.rowind[p];
      const double v = std::abs(lower.values[p]);
      sum[j] += v;
      if (i != j) sum[i] += v;
    }
  }
  return sum.empty() ? 0.0 : *std::max_element(sum.begin(), sum.end());
}

// The lower triangle of A - sigma I (the diagonal added where missing).
Status shifted_lower(const CscMatrix& lower, double sigma, CscMatrix* out) {
  std::vector<Triplet> t;
  t.reserve(static_cast<size_t>(lower.nnz()) + lower.ncols);
  for (int32_t j = 0; j < lower.ncols; ++j) {
    t.push_back({j, j, -sigma});
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      if (lower.rowind[p] >= j) t.push_back({lower.rowind[p], j, lower.values[p]});
    }
  }
  return csc_from_triplets(lower.nrows, lower.ncols, t, out);
}

// What a check of the run found: the wanted Ritz values (descending), their
// vectors in the band's basis and whether each has converged.
struct RitzCheck {
  std::vector<double> theta;   // all of the band's eigenvalues, descending
  std::vector<double> s;       // active x want
  std::vector<char> converged;
  int32_t want = 0, converged_count = 0;
  double worst = 0.0;  // max over the checked pairs of residual bound / target
};

class Solver {
 public:
  Solver(const SymmetricEigenOptions& o, double norm, double sigma) : o_(o), norm_(norm), sigma_(sigma) {}

  Status run(Cholesky& chol, int32_t n, SymmetricEigenResult* result);

 private:
  // The run's Ritz values; vectors for the wanted ones from `first` on
  // (the rest only when all of those converged, `full`).
  void check(int32_t remaining, bool boundary_only, RitzCheck* out);
  // The pair's bound on ||A x - lambda x|| over its target (converged at <= 1).
  double residual_ratio(double theta, double estimate) const;
  // The basis size at which to check next (see its definition).
  int32_t schedule(const RitzCheck& rc, int32_t b, int32_t* last_at, double* last_log) const;
  // Locks the run's wanted pairs 0..count-1 (all converged): their Ritz
  // vectors overwrite the run's first columns, row block by row block (a
  // row of Y = Q S needs only the same row of Q), so no n x count copy.
  void lock_in_place(const RitzCheck& rc, int32_t count);
  // After all count pairs are locked: runs short Lanczos runs orthogonal to
  // them and swaps in any converged pair above the smallest locked theta.
  // Catches what one run cannot see: copies of an eigenvalue beyond the
  // block size (a graph with more components than block_size has more zero
  // eigenvalues than one block Krylov space holds).
  Status probe_for_missed(Cholesky& chol, SymmetricEigenResult* result);
  // y (n x count) = Q S[:, cols] for the listed columns of rc.s.
  void ritz_vectors(const RitzCheck& rc, const std::vector<int32_t>& cols, double* y);

  const SymmetricEigenOptions& o_;
  double norm_, sigma_;
  BlockLanczos lz_;
  std::vector<double> locked_theta_;
  std::vector<double> work_;
};

double Solver::residual_ratio(double theta, double estimate) const {
  // A x - lambda x = -(A - sigma I) r / theta for the Op-residual r, so
  // ||A x - lambda x|| <= ||A - sigma I||_1 ||r|| / theta; the target keeps
  // a factor 2 for the rounding of the vectors formed afterwards.
  const double bound = (norm_ - sigma_) * estimate / theta;
  return bound / (0.5 * o_.tolerance * norm_);
}

void Solver::check(int32_t remaining, bool boundary_only, RitzCheck* rc) {
  const int32_t m = lz_.active;
  std::vector<double> d(m), e(m);
  eigen_detail::band_to_tridiagonal(lz_.band, &work_, d.data(), e.data());
  eigen_detail::tridiagonal_eigenvalues(m, d.data(), e.data());
  rc->theta.assign(d.rbegin(), d.rend());
  // Only the upper half of the Ritz values counts as wanted: Lanczos also
  // converges at the other end of the spectrum, and in a basis barely larger
  // than `remaining` the top `remaining` Ritz values would include such
  // converged, unwanted pairs (a restart would lock them). An exhausted
  // Krylov space has only exact pairs.
  rc->want = std::min(remaining, lz_.next_width == 0 ? m : m / 2);
  const int32_t first = boundary_only ? std::max(0, rc->want - 2 * lz_.b) : 0;
  const int32_t count = rc->want - first;
  rc->s.assign(static_cast<size_t>(m) * rc->want, 0.0);
  double scale = 0.0;
  for (double t : rc->theta) scale = std::max(scale, std::abs(t));
  eigen_detail::band_eigenvectors(lz_.band, rc->theta.data() + first, count, 1e-5 * scale, o_.seed + 17,
                                  rc->s.data() + static_cast<int64_t>(first) * m);
  rc->converged.assign(rc->want, 0);
  rc->converged_count = 0;
  rc->worst = 0.0;
  for (int32_t t = first; t < rc->want; ++t) {
    const double est = lz_.residual_estimate(rc->s.data() + static_cast<int64_t>(t) * m);
    const double ratio = residual_ratio(rc->theta[t], est);
    rc->converged[t] = ratio <= 1.0;
    rc->converged_count += rc->converged[t];
    rc->worst = std::max(rc->worst, ratio);
  }
}

void Solver::ritz_vectors(const RitzCheck& rc, const std::vector<int32_t>& cols, double* y) {
  const int32_t n = lz_.n, m = lz_.active, count = static_cast<int32_t>(cols.size());
  if (count == 0) return;
  // Y = Q S is the GEMM's C -= A B^T with B = -S^T (count x m).
  std::vector<double> st(static_cast<size_t>(count) * m);
  for (int32_t c = 0; c < count; ++c) {
    const double* s = rc.s.data() + static_cast<int64_t>(cols[c]) * m;
    for (int32_t i = 0; i < m; ++i) st[c + static_cast<int64_t>(i) * count] = -s[i];
  }
  std::fill(y, y + static_cast<int64_t>(n) * count, 0.0);
  dense_kernels().gemm_nt_sub(n, count, m, lz_.column(lz_.locked), n, st.data(), count, y, n);
}

void Solver::lock_in_place(const RitzCheck& rc, int32_t count) {
  const int32_t n = lz_.n, m = lz_.active;
  std::vector<double> st(static_cast<size_t>(count) * m);
  for (int32_t c = 0; c < count; ++c) {
    for (int32_t i = 0; i < m; ++i) st[c + static_cast<int64_t>(i) * count] = -rc.s[i + static_cast<int64_t>(c) * m];
  }
  constexpr int32_t kRows = 256;
  std::vector<double> tile(static_cast<size_t>(kRows) * count);
  double* q = lz_.column(lz_.locked);
  for (int32_t r0 = 0; r0 < n; r0 += kRows) {
    const int32_t rows = std::min(kRows, n - r0);
    std::fill(tile.begin(), tile.end(), 0.0);
    dense_kernels().gemm_nt_sub(rows, count, m, q + r0, n, st.data(), count, tile.data(), rows);
    for (int32_t c = 0; c < count; ++c) {
      std::memcpy(q + static_cast<int64_t>(c) * n + r0, tile.data() + static_cast<int64_t>(c) * rows, sizeof(double) * rows);
    }
  }
  for (int32_t c = 0; c < count; ++c) locked_theta_.push_back(rc.theta[c]);
  lz_.locked += count;
}

Status Solver::probe_for_missed(Cholesky& chol, SymmetricEigenResult* result) {
  const int32_t n = lz_.n, b = lz_.b;
  const int32_t max_probes = 16 + lz_.locked / b;  // each probe that goes on swapped a pair in
  RitzCheck rc;
  std::vector<double> y;
  for (int32_t probe = 0; probe < max_probes; ++probe) {
    if (lz_.locked + 2 * b > lz_.capacity) return Status::Ok();  // no room: nothing to probe with
    const auto lowest = std::min_element(locked_theta_.begin(), locked_theta_.end());
    // Above this a probe's Ritz value is a pair the locked set misses (a
    // tie within rounding is no miss: either pair is as small).
    const double threshold = *lowest * (1.0 + 1e-9);
    lz_.start_run(nullptr, b, o_.seed + 7919 * (probe + 1));
    if (lz_.next_width == 0) return Status::Ok();  // the locked vectors span the space
    int32_t above = 0;
    for (;;) {
      if (lz_.room()) {
        const double t0 = now();
        GAB_RETURN_IF_ERROR(lz_.extend(chol));
        result->lanczos_s += now() - t0;
      }
      const double t0 = now();
      check(1, /*boundary_only=*/true, &rc);
      above = 0;
      while (above < lz_.active && rc.theta[above] > threshold) ++above;
      if (above > 0) check(above, /*boundary_only=*/false, &rc);
      result->check_s += now() - t0;
      // Ritz values only grow with the basis: none above after two blocks
      // means none to find (short of one just above the threshold).
      if (above == 0 && (lz_.active >= 2 * b || !lz_.room())) return Status::Ok();
      if (above > 0 && rc.converged_count > 0) break;
      if (!lz_.room()) return Status::Ok();  // cannot tell: keep what is locked
    }
    // Swap each converged pair above in for the lowest locked one.
    std::vector<int32_t> cols;
    for (int32_t t = 0; t < rc.want; ++t) {
      if (rc.converged[t]) cols.push_back(t);
    }
    y.assign(static_cast<size_t>(n) * cols.size(), 0.0);
    ritz_vectors(rc, cols, y.data());
    for (size_t c = 0; c < cols.size(); ++c) {
      auto low = std::min_element(locked_theta_.begin(), locked_theta_.end());
      if (rc.theta[cols[c]] <= *low) break;
      *low = rc.theta[cols[c]];
      std::memcpy(lz_.column(static_cast<int32_t>(low - locked_theta_.begin())), y.data() + static_cast<int64_t>(c) * n,
                  sizeof(double) * n);
    }
    ++result->probes;
  }
  return Status::Ok();
}

// When to check next: 10% more columns while the boundary pairs' residuals
// are still a million times their target (they stay that far for most of
// the run, then fall steeply within ~15% of the basis), 4% after that, or
// sooner where the last two checks' residuals, extrapolated geometrically,
// predict the pairs pass (the fall is faster than geometric near the end,
// so the prediction is only trusted to shorten the step). A check of the
// boundary pairs costs O(b m^2), about five blocks' work at k = 1,000.
int32_t Solver::schedule(const RitzCheck& rc, int32_t b, int32_t* last_at, double* last_log) const {
  const int32_t m = lz_.active;
  const double log_now = std::log(std::max(rc.worst, 1e-300));
  int32_t step = std::max(2 * b, rc.worst > 1e6 ? m / 10 : m / 25);
  if (*last_at >= 0 && m > *last_at && log_now > 0.0) {
    const double slope = (log_now - *last_log) / (m - *last_at);
    if (slope < 0.0) {
      const double predicted = 1.05 * log_now / -slope + b;
      step = static_cast<int32_t>(std::min<double>(std::max<double>(predicted, b), step));
    }
  }
  *last_at = m;
  *last_log = log_now;
  return m + step;
}

Status Solver::run(Cholesky& chol, int32_t n, SymmetricEigenResult* result) {
  const int32_t k = o_.count;
  const int32_t b = std::min(o_.block_size, n);
  int32_t capacity = o_.max_basis > 0 ? std::min(o_.max_basis, n) : std::min<int64_t>(n, 5 * int64_t{k} / 2 + 256);
  if (capacity < std::min(n, k + b)) {
    return Status::Error(StatusCode::kInvalidArgument, "smallest_eigenpairs: max_basis " + std::to_string(o_.max_basis) + " is below count + block_size (" +
                   std::to_string(std::min(n, k + b)) + ")");
  }
  lz_.reserve(n, b, capacity);
  lz_.start_run(nullptr, b, o_.seed);
  int32_t restarts = 0;
  RitzCheck rc;
  std::vector<double> y;
  for (;;) {
    const int32_t remaining = k - lz_.locked;
    int32_t next_check = std::min(2 * remaining + 2 * b, capacity - lz_.locked);
    int32_t last_at = -1;  // the previous boundary check: basis size, log of its worst ratio
    double last_log = 0.0;
    bool done = false;
    while (!done) {
      if (lz_.room()) {
        const double t0 = now();
        GAB_RETURN_IF_ERROR(lz_.extend(chol));
        result->lanczos_s += now() - t0;
      }
      const bool full = !lz_.room();
      if (lz_.active < next_check && !full) continue;
      const double t0 = now();
      check(remaining, /*boundary_only=*/true, &rc);
      result->check_s += now() - t0;
      const int32_t first = std::max(0, rc.want - 2 * lz_.b);
      const bool boundary_ok = rc.converged_count == rc.want - first;
      next_check = schedule(rc, b, &last_at, &last_log);
      if (!boundary_ok && !full) continue;
      const double t1 = now();
      check(remaining, /*boundary_only=*/false, &rc);
      result->check_s += now() - t1;
      if (rc.want == remaining && rc.converged_count == rc.want) done = true;
      if (!done && full) break;  // restart
    }
    if (done) {
      const double t0 = now();
      lock_in_place(rc, rc.want);
      result->vectors_s += now() - t0;
      GAB_RETURN_IF_ERROR(probe_for_missed(chol, result));
      result->vectors.assign(lz_.v.begin(), lz_.v.begin() + static_cast<int64_t>(n) * k);
      break;
    }
    // Restart: lock the converged wanted pairs, start from the best others.
    if (restarts == o_.max_restarts) {
      return Status::Error(StatusCode::kResourceExhausted,
                           "smallest_eigenpairs: " + std::to_string(lz_.locked + rc.converged_count) + " of " +
                               std::to_string(k) + " eigenpairs converged within " + std::to_string(o_.max_restarts) +
                               " restarts (basis of " + std::to_string(capacity) + " columns)");
    }
    ++restarts;
    std::vector<int32_t> lock, restart;
    for (int32_t t = 0; t < rc.want; ++t) {
      if (rc.converged[t]) lock.push_back(t);
      else if (static_cast<int32_t>(restart.size()) < b) restart.push_back(t);
    }
    std::vector<int32_t> cols(lock);
    cols.insert(cols.end(), restart.begin(), restart.end());
    y.assign(static_cast<size_t>(n) * cols.size(), 0.0);
    ritz_vectors(rc, cols, y.data());
    std::memcpy(lz_.column(lz_.locked), y.data(), sizeof(double) * n * lock.size());
    for (int32_t t : lock) locked_theta_.push_back(rc.theta[t]);
    lz_.locked += static_cast<int32_t>(lock.size());
    if (lz_.locked + b > capacity) {
      return Status::Error(StatusCode::kResourceExhausted,
                           "smallest_eigenpairs: the basis of " + std::to_string(capacity) +
                               " columns has no room left after locking " + std::to_string(lz_.locked) + " pairs");
    }
    const double* start = restart.empty() ? nullptr : y.data() + static_cast<int64_t>(n) * lock.size();
    lz_.start_run(start, restart.empty() ? b : static_cast<int32_t>(restart.size()), o_.seed + restarts);
  }
  result->restarts = restarts;
  result->solves = static_cast<int32_t>(lz_.solves);
  result->basis_columns = capacity;
  return Status::Ok();
}

}  // namespace

Status smallest_eigenpairs(const CscMatrix& given, const SymmetricEigenOptions& options,
                           SymmetricEigenResult* result) {
  GAB_RETURN_IF_ERROR(check_arguments(given, options));
  // Entries above the diagonal are ignored (the engine's convention), also
  // by the norm and the residuals' products.
  bool upper = false;
  for (int32_t j = 0; j < given.ncols && !upper; ++j) {
    upper = given.colptr[j + 1] > given.colptr[j] && given.rowind[given.colptr[j]] < j;
  }
  CscMatrix lower_only;
  if (upper) lower_only = lower_triangle(given);
  const CscMatrix& lower = upper ? lower_only : given;
  const int32_t n = lower.nrows, k = options.count;
  const double norm = norm1(lower);
  const double sigma = options.shift < 0.0 ? options.shift : (norm > 0.0 ? -1e-3 * norm : -1.0);
  const double t0 = now();
  CscMatrix shifted;
  GAB_RETURN_IF_ERROR(shifted_lower(lower, sigma, &shifted));
  Cholesky chol;
  AnalyzeOptions analyze;
  analyze.threads = options.threads;
  GAB_RETURN_IF_ERROR(chol.analyze(shifted, analyze));
  Status factored = chol.factorize(shifted);
  if (factored.code() == StatusCode::kNotPositiveDefinite) {
    return Status::Error(StatusCode::kNotPositiveDefinite,
                         "smallest_eigenpairs: A - sigma I (sigma " + std::to_string(sigma) +
                             ") is not positive definite: A is not positive semi-definite (" + factored.message() + ")");
  }
  GAB_RETURN_IF_ERROR(factored);

  *result = SymmetricEigenResult();
  result->factor_s = now() - t0;
  {
    Solver solver(options, norm, sigma);  // its basis is freed before the residuals
    GAB_RETURN_IF_ERROR(solver.run(chol, n, result));
  }
  const double t1 = now();

  // Rayleigh quotients and residuals, then ascending order.
  std::vector<double> ax(n), lambda(k), residual(k);
  for (int32_t c = 0; c < k; ++c) {
    const double* x = result->vectors.data() + static_cast<int64_t>(c) * n;
    symmetric_lower_matvec(lower, x, ax.data());
    double xx = 0.0, xax = 0.0;
    for (int32_t i = 0; i < n; ++i) {
      xx += x[i] * x[i];
      xax += x[i] * ax[i];
    }
    lambda[c] = xax / xx;
    double r = 0.0;
    for (int32_t i = 0; i < n; ++i) r += (ax[i] - lambda[c] * x[i]) * (ax[i] - lambda[c] * x[i]);
    residual[c] = std::sqrt(r / xx) / (norm > 0.0 ? norm : 1.0);
  }
  std::vector<int32_t> order(k);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return lambda[a] < lambda[b]; });
  result->values.resize(k);
  result->residuals.resize(k);
  bool sorted_already = true;
  for (int32_t c = 0; c < k; ++c) {
    result->values[c] = lambda[order[c]];
    result->residuals[c] = residual[order[c]];
    sorted_already = sorted_already && order[c] == c;
  }
  if (!sorted_already) {
    // Usually the Ritz values come in order (theta descending); a copy
    // only when locking or rounding mixed them.
    std::vector<double> sorted(static_cast<size_t>(n) * k);
    for (int32_t c = 0; c < k; ++c) {
      std::memcpy(sorted.data() + static_cast<int64_t>(c) * n, result->vectors.data() + static_cast<int64_t>(order[c]) * n,
                  sizeof(double) * n);
    }
    result->vectors.swap(sorted);
  }
  result->vectors_s += now() - t1;
  result->norm = norm;
  result->shift = sigma;
  int32_t failed = 0;
  for (double r : result->residuals) failed += !(r <= options.tolerance);
  if (failed > 0) {
    return Status::Error(StatusCode::kResourceExhausted,
                         "smallest_eigenpairs: " + std::to_string(k - failed) + " of " + std::to_string(k) +
                             " eigenpairs reached the tolerance");
  }
  return Status::Ok();
}

}  // namespace gab
