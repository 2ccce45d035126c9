// Anchor updates of a supernodal Cholesky factor, in place: the factor of
// M + w^2 e_j e_j^T (add) or M - w^2 e_j e_j^T (remove) from the factor of
// M, by Givens rotations along the elimination-tree path of pivot
// inverse_perm[j]. The nonzero structure never changes (Sorkine et al.
// 2005: the incremental update of the factorization). Allocation-free: the caller supplies the workspace; cholesky.h
// wraps these in Cholesky::add_anchor / remove_anchor.
#pragma once

#include <cstdint>

#include "gab/sparse/cholesky.h"  // UpdateStats
#include "gab/sparse/dense_kernels.h"
#include "gab/status.h"
#include "gab/sparse/symbolic.h"

namespace gab {

// Workspace the updates need. Before the first update, the first
// update_workspace_zero_prefix() doubles must be zero and the ints all -1;
// every update leaves that prefix zero and the ints' persistent marks -1
// (the rest of both is scratch; update.cpp's Workspace and IntWorkspace).
int64_t update_workspace_doubles(const SymbolicFactor& f);
int64_t update_workspace_zero_prefix(const SymbolicFactor& f);
int64_t update_workspace_ints(const SymbolicFactor& f);

// Factor of M + w^2 e_j e_j^T from the factor of M (j in the original
// numbering, w != 0 finite). Cost: the entries of L on the path (stats).
Status add_anchor_supernodal(const SymbolicFactor& f, double* values, int32_t j, double weight,
                             SimdLevel level, double* work, UpdateStats* stats);

// Batch form: the factor of M + w^2 sum_i e_{j_i} e_{j_i}^T, in sweeps of
// up to 8 anchors over the union of their paths (each block of L is read
// once per sweep instead of once per anchor). Same result as `count` single
// updates up to rounding. *stats sums the sweeps: touched counts each
// sweep's union once.
Status add_anchors_supernodal(const SymbolicFactor& f, double* values, const int32_t* js,
                              int32_t count, double weight, SimdLevel level, double* work,
                              int32_t* iwork, UpdateStats* stats);

// Factor of M - w^2 e_j e_j^T, by the stable method of LINPACK's dchdd
// (Saunders 1972; Golub & Van Loan sec. 6.5.4): solve L p = w e_j along the
// path, then rotations from the top of the path down. If the result would
// not be positive definite (||p|| >= 1, with a small safety margin) the
// factor is left unchanged and kNotPositiveDefinite is returned. About twice
// the cost of an add.
Status remove_anchor_supernodal(const SymbolicFactor& f, double* values, int32_t j,
                                double weight, SimdLevel level, double* work, int32_t* iwork,
                                UpdateStats* stats);

}  // namespace gab
