// Eigenvectors of a symmetric band matrix for given eigenvalues, by inverse
// iteration (internal).
#pragma once

#include <cstdint>
#include <vector>

#include "eigensolver/band_tridiagonal.h"

namespace gab {
namespace eigen_detail {

// For each values[t] (t < count, sorted descending, each accurate to about
// eps ||band||), the unit eigenvector in column t of vectors (m x count,
// column-major). Each vector is orthogonalized against those of values
// within cluster_gap of its own, so a multiple eigenvalue gets an
// orthonormal basis of its space. About 2 b^2 m flops (the factorization of
// band - value I) per vector, plus 12 m per close neighbour.
void band_eigenvectors(const SymmetricBand& band, const double* values, int32_t count,
                       double cluster_gap, uint64_t seed, double* vectors);

}  // namespace eigen_detail
}  // namespace gab
