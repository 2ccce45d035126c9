// Block Lanczos with full reorthogonalization (Golub & Underwood 1977;
// Golub & Van Loan, sec. 10.3.6 and 10.1; Parlett, ch. 13). Each step:
//   W = Op Q_j                          (solves with the Cholesky factor)
//   A_j = Q_j^T W, W -= Q_j A_j + Q_{j-1} B_j^T   (the three-term recurrence)
//   W -= V (V^T W) over the whole basis, locked vectors included
//   W = Q_{j+1} B_{j+1}                 (QR by Gram-Schmidt, with deflation)
// The recurrence is the first orthogonalization pass and the full one the
// second ("twice is enough", Kahan-Parlett; DGKS's test adds a third when a
// column still lost more than half its norm). The full passes are the
// process's dominant cost, 2 n m^2 flops for a basis of m columns: V^T W
// with the basis kernels, each streaming V once.
#include "eigensolver/block_lanczos.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gab/sparse/dense_kernels.h"
#include "gab/sparse/splitmix64.h"
#include "eigensolver/basis_kernels.h"

namespace gab {
namespace eigen_detail {

namespace {

double dot(int32_t n, const double* x, const double* y) {
  double s = 0.0;
  for (int32_t i = 0; i < n; ++i) s += x[i] * y[i];
  return s;
}

// Below this fraction of its norm before projection, what is left of a
// column is rounding: the direction is already in the basis (deflation).
constexpr double kDeflation = 1e-12;

}  // namespace

void BlockLanczos::reserve(int32_t n_, int32_t b_, int32_t capacity_) {
  n = n_;
  b = b_;
  capacity = capacity_;
  v.assign(static_cast<size_t>(n) * capacity, 0.0);
  next.assign(static_cast<size_t>(n) * b, 0.0);
  work.assign(static_cast<size_t>(n) * b, 0.0);
  coupling.assign(static_cast<size_t>(b) * b, 0.0);
  proj.assign(static_cast<size_t>(capacity) * b, 0.0);
  projt.assign(static_cast<size_t>(b) * b, 0.0);
  diag.assign(static_cast<size_t>(b) * b, 0.0);
  correction.assign(static_cast<size_t>(b) * b, 0.0);
  coupling_prev.assign(static_cast<size_t>(b) * b, 0.0);
  norms.assign(static_cast<size_t>(3) * b, 0.0);
  band.b = b;
  band.data.assign(static_cast<size_t>(b + 1) * capacity, 0.0);
}

void BlockLanczos::start_run(const double* start, int32_t width, uint64_t seed) {
  active = 0;
  last_start = 0;
  band.m = 0;
  std::fill(band.data.begin(), band.data.end(), 0.0);
  width = std::min(width, b);
  if (start != nullptr) {
    std::memcpy(work.data(), start, sizeof(double) * n * width);
  } else {
    SplitMix64 rng(seed);
    for (int64_t i = 0; i < static_cast<int64_t>(n) * width; ++i) work[i] = rng.uniform() - 0.5;
  }
  for (int32_t c = 0; c < width; ++c) norms[c] = std::sqrt(dot(n, &work[static_cast<int64_t>(c) * n], &work[static_cast<int64_t>(c) * n]));
  orthonormalize(work.data(), width, locked, norms.data(), 0, nullptr);
}

void BlockLanczos::orthonormalize(double* x, int32_t count, int32_t cols, const double* base,
                                  int32_t diag_first, double* diag_correction) {
  const BasisKernels& bk = basis_kernels(dense_kernels().level);
  double* before = norms.data() + b;
  double* after = norms.data() + 2 * b;
  for (int32_t c = 0; c < count; ++c) before[c] = std::sqrt(dot(n, x + static_cast<int64_t>(c) * n, x + static_cast<int64_t>(c) * n));
  for (int pass = 0; pass < 2 && cols > 0; ++pass) {
    bk.project(n, cols, count, v.data(), x, proj.data(), cols);  // proj = V^T x
    bk.subtract(n, cols, count, v.data(), proj.data(), cols, x);  // x -= V proj
    if (diag_correction != nullptr) {
      for (int32_t c = 0; c < count; ++c) {
        for (int32_t r = 0; r < count; ++r) diag_correction[r + c * b] += proj[diag_first + r + static_cast<int64_t>(c) * cols];
      }
    }
    bool again = false;
    for (int32_t c = 0; c < count; ++c) {
      after[c] = std::sqrt(dot(n, x + static_cast<int64_t>(c) * n, x + static_cast<int64_t>(c) * n));
      if (after[c] < 0.5 * before[c]) again = true;
      before[c] = after[c];
    }
    if (!again) break;
  }
  // QR among the block's own columns: Gram-Schmidt twice per column.
  std::fill(coupling.begin(), coupling.end(), 0.0);
  next_width = 0;
  for (int32_t c = 0; c < count; ++c) {
    double* xc = x + static_cast<int64_t>(c) * n;
    for (int pass = 0; pass < 2; ++pass) {
      for (int32_t r = 0; r < next_width; ++r) {
        const double* qr = next.data() + static_cast<int64_t>(r) * n;
        const double h = dot(n, qr, xc);
        coupling[r + c * b] += h;
        for (int32_t i = 0; i < n; ++i) xc[i] -= h * qr[i];
      }
    }
    const double nu = std::sqrt(dot(n, xc, xc));
    if (!(nu > kDeflation * base[c]) || cols + next_width >= n) continue;  // deflated
    double* q = next.data() + static_cast<int64_t>(next_width) * n;
    for (int32_t i = 0; i < n; ++i) q[i] = xc[i] / nu;
    coupling[next_width + c * b] = nu;
    ++next_width;
  }
}

Status BlockLanczos::extend(Cholesky& chol) {
  const int32_t w = next_width;
  const int32_t prev_start = last_start, prev_w = active - last_start;
  const int32_t off = active;
  double* q = column(locked + off);
  std::memcpy(q, next.data(), sizeof(double) * n * w);
  // B_{j+1} from the last step couples this block to the one before it.
  band.m = active + w;
  for (int32_t c = 0; c < prev_w; ++c) {
    for (int32_t r = 0; r < w; ++r) {
      if (off + r - (prev_start + c) <= b) band.at(off + r, prev_start + c) = coupling[r + c * b];
    }
  }
  coupling_prev = coupling;  // B_j, before the QR overwrites it
  last_start = off;
  active += w;

  double* x = work.data();
  std::memcpy(x, q, sizeof(double) * n * w);
  GAB_RETURN_IF_ERROR(chol.solve(x, w, n));
  solves += w;
  double* base = norms.data();
  for (int32_t c = 0; c < w; ++c) base[c] = std::sqrt(dot(n, x + static_cast<int64_t>(c) * n, x + static_cast<int64_t>(c) * n));

  // The three-term recurrence: A_j = Q_j^T W, W -= Q_j A_j + Q_{j-1} B_j^T.
  const BasisKernels& bk = basis_kernels(dense_kernels().level);
  std::vector<double>& a = diag;
  bk.project(n, w, w, q, x, proj.data(), w);
  for (int32_t c = 0; c < w; ++c) {
    for (int32_t r = 0; r < w; ++r) a[r + c * b] = 0.5 * (proj[r + c * w] + proj[c + r * w]);
  }
  bk.subtract(n, w, w, q, a.data(), b, x);
  if (prev_w > 0) {
    // Q_{j-1} B_j^T: the coefficients are B_j transposed.
    for (int32_t c = 0; c < w; ++c) {
      for (int32_t i = 0; i < prev_w; ++i) projt[i + static_cast<int64_t>(c) * prev_w] = coupling_prev[c + i * b];
    }
    bk.subtract(n, prev_w, w, column(locked + prev_start), projt.data(), prev_w, x);
  }

  // The full pass over the basis (its corrections of A_j kept), then QR.
  std::fill(correction.begin(), correction.end(), 0.0);
  orthonormalize(x, w, locked + active, base, locked + off, correction.data());
  for (int32_t c = 0; c < w; ++c) {
    for (int32_t r = c; r < w; ++r) {
      band.at(off + r, off + c) = a[r + c * b] + 0.5 * (correction[r + c * b] + correction[c + r * b]);
    }
  }
  return Status::Ok();
}

double BlockLanczos::residual_estimate(const double* s) const {
  const int32_t w = active - last_start;
  double sum = 0.0;
  for (int32_t r = 0; r < next_width; ++r) {
    double t = 0.0;
    for (int32_t c = 0; c < w; ++c) t += coupling[r + c * b] * s[last_start + c];
    sum += t * t;
  }
  return std::sqrt(sum);
}

}  // namespace eigen_detail
}  // namespace gab
