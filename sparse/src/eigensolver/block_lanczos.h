// The block Lanczos process on a symmetric operator, fully reorthogonalized
// (internal to the eigensolver).
#pragma once

#include <cstdint>
#include <vector>

#include "eigensolver/band_tridiagonal.h"
#include "gab/sparse/cholesky.h"
#include "gab/status.h"

namespace gab {
namespace eigen_detail {

// The basis V (n x capacity, column-major) holds the locked vectors
// (columns [0, locked): converged eigenvectors, kept orthogonal to every
// later vector) and the current run's Lanczos blocks (columns [locked,
// locked + active)). The run's projected matrix V^T Op V is block
// tridiagonal, kept as a band of half-bandwidth b:
//   Op Q_j = Q_{j-1} B_j^T + Q_j A_j + Q_{j+1} B_{j+1}.
// `next` holds Q_{j+1} (orthonormal, next_width columns; fewer than b when
// directions deflated) and `coupling` its B_{j+1} (next_width x width of
// Q_j, column-major, leading dimension b, upper trapezoidal).
struct BlockLanczos {
  int32_t n = 0, b = 0, capacity = 0;
  std::vector<double> v;
  int32_t locked = 0, active = 0;
  int32_t last_start = 0;  // the last block's first column in the run (active - its width)
  SymmetricBand band;      // the run's projected matrix (band.m == active)
  std::vector<double> next, coupling;
  int32_t next_width = 0;
  int64_t solves = 0;
  // Per-step workspace, sized by reserve(): the operator's block (n x b),
  // projections (capacity x b), b x b blocks, norms.
  std::vector<double> work, proj, projt, diag, correction, coupling_prev, norms;

  // Sizes everything; n x capacity doubles for V, 2 n b more.
  void reserve(int32_t n_, int32_t b_, int32_t capacity_);
  double* column(int32_t j) { return v.data() + static_cast<int64_t>(j) * n; }
  // Empties the run; `start` (n x width) becomes Q_0 after orthonormalizing
  // against the locked columns and itself (a random block when nullptr).
  void start_run(const double* start, int32_t width, uint64_t seed);
  // Whether the next block fits in the basis.
  bool room() const { return next_width > 0 && locked + active + next_width <= capacity; }
  // Appends Q_{j+1}, applies the operator to it (solves with the factor of
  // A - sigma I) and makes the next block. Requires room().
  Status extend(Cholesky& chol);
  // ||B_{j+1} s_last|| for a Ritz vector s (active entries) of the band:
  // the norm of Op y - theta y for y = V s.
  double residual_estimate(const double* s) const;

 private:
  // Orthonormalizes `count` columns of x (ld n) against V[:, 0:cols] (block
  // classical Gram-Schmidt, a second pass when a column lost more than half
  // its norm) and then among themselves into `next`; R entries (the
  // coefficients on the new columns) into coupling. proj_out, when given,
  // receives V^T x for the columns in [diag_first, diag_first + count) (the
  // corrections of A_j). base[c] is the column's norm before any projection
  // (the deflation scale).
  void orthonormalize(double* x, int32_t count, int32_t cols, const double* base,
                      int32_t diag_first, double* diag_correction);
};

}  // namespace eigen_detail
}  // namespace gab
