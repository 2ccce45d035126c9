// The smallest eigenpairs of a sparse symmetric positive semi-definite
// matrix (a graph Laplacian L = D - A, singular: one zero eigenvalue per
// connected component), by shift-and-invert block Lanczos on the engine's
// Cholesky.
//
//   gab::SymmetricEigenOptions options;
//   options.count = 100;
//   gab::SymmetricEigenResult eig;
//   GAB_RETURN_IF_ERROR(gab::smallest_eigenpairs(lower, options, &eig));
//   // eig.values[i] ascending, eig.vectors column i (n x count, column-major)
//
// Method: A - sigma I (sigma < 0, so it is positive definite) is factored
// once; Lanczos runs on its inverse, whose largest eigenvalues 1/(lambda -
// sigma) belong to A's smallest. Blocks of block_size vectors, fully
// reorthogonalized (every block against the whole basis, with SIMD
// kernels); the projected band matrix's eigenvalues by band reduction and
// implicit QL, its eigenvectors by inverse iteration. When the basis reaches
// max_basis columns, the converged pairs are locked and the run restarts
// from the best unconverged Ritz vectors (memory stays bounded).
//
// Cost: one factorization; a basis of m columns, m about 2 to 3 count
// (camel-head, count 1,000: 2,264), takes m solves, 2 n m^2 flops of
// reorthogonalization and 2 n m count for the eigenvectors (about 8 s on
// one core for that example: docs/tuning-engine.md). Memory: n (max_basis +
// block_size) doubles for the basis, n count for the vectors, the factor.
//
// One block Krylov space holds at most block_size copies of a multiple
// eigenvalue (a Laplacian has one zero per connected component), so once
// all pairs converged, short runs orthogonal to them look for pairs above
// the found ones and swap them in (SymmetricEigenResult::probes). A missed
// eigenvalue within 1e-9 (relative) of the largest returned one is not
// told apart from it.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

struct SymmetricEigenOptions {
  int32_t count = 6;          // k: how many of the smallest eigenpairs (1..n)
  // Every returned pair has ||A v - lambda v||_2 <= tolerance ||A||_1
  // (v unit, lambda its Rayleigh quotient).
  double tolerance = 1e-10;
  // sigma < 0; 0 chooses -1e-3 ||A||_1 (close enough to 0 that the wanted end of the
  // spectrum is well separated after inversion, far enough that A - sigma I
  // is safely positive definite).
  double shift = 0.0;
  int32_t block_size = 8;     // vectors per Lanczos block (1..64)
  int32_t max_basis = 0;      // basis columns held (>= count + block_size); 0: min(n, 2.5 count + 256)
  int32_t max_restarts = 20;  // runs after the first before giving up
  int32_t threads = 1;        // of the factorization and solves (AnalyzeOptions::threads)
  uint64_t seed = 1;          // of the random start block (results are deterministic)
};

struct SymmetricEigenResult {
  std::vector<double> values;     // count eigenvalues, ascending
  std::vector<double> vectors;    // n x count, column-major, orthonormal
  std::vector<double> residuals;  // per pair, ||A v - lambda v||_2 / ||A||_1
  double norm = 0.0;              // ||A||_1, the residuals' scale
  double shift = 0.0;             // the sigma used
  int32_t solves = 0;             // applications of (A - sigma I)^{-1} (vectors)
  int32_t restarts = 0;           // runs after the first
  int32_t probes = 0;             // final probes that found a missed pair (see below)
  int32_t basis_columns = 0;      // the most basis columns held at once
  // Where the time went (seconds): the factorization (ordering included),
  // the Lanczos steps (solves and orthogonalization), the convergence
  // checks (the band's eigenvalues and vectors), the Ritz vectors and
  // residuals.
  double factor_s = 0.0, lanczos_s = 0.0, check_s = 0.0, vectors_s = 0.0;
};

// The `options.count` smallest eigenpairs of the symmetric positive
// semi-definite A given by its lower triangle (with values; entries above
// the diagonal are ignored). Errors: kInvalidArgument (not square, no
// values, a value not finite, count outside 1..n, bad options), kNotPositiveDefinite (A - sigma I is not: A is not positive
// semi-definite), kResourceExhausted (not converged within max_restarts:
// the message says how many pairs had converged).
Status smallest_eigenpairs(const CscMatrix& lower, const SymmetricEigenOptions& options,
                           SymmetricEigenResult* result);

}  // namespace gab
