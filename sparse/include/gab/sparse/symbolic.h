// Symbolic analysis for the supernodal Cholesky factor, run once per nonzero
// pattern (numeric factorizations reuse it). The pipeline, step by step as
// analyze_structure calls it (symbolic.cpp):
//   fill-reducing order -> elimination tree and its postorder -> permutation
//   -> column counts -> fundamental supernodes -> relaxed amalgamation
//   -> supernode tree -> row structures -> block layout -> update stack size
// and then, in analyze, the assembly map.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/amd.h"
#include "gab/sparse/csc.h"
#include "gab/sparse/etree.h"
#include "gab/sparse/ordering.h"
#include "gab/status.h"

namespace gab {

// Threads a factorization, a solve or an ordering uses at most.
constexpr int32_t kMaxFactorThreads = 64;

// Relaxed amalgamation (defaults as CHOLMOD's): merge a child supernode into
// its parent when the merged supernode has at most cols[0] columns, or at
// most cols[i] columns and a fraction of explicit zeros below zeros[i-1]
// (i = 1, 2), or any size and zeros below zeros[2]. Only a child whose
// columns end right before its parent's can merge (see supernodes.h).
struct RelaxOptions {
  bool enabled = true;  // false: fundamental supernodes (no explicit zeros)
  int32_t cols[3] = {4, 16, 48};
  double zeros[3] = {0.8, 0.1, 0.05};
};

struct AnalyzeOptions {
  Ordering ordering = Ordering::kAmd;  // ordering.h; kAuto chooses by n
  AmdOptions amd;                   // used when ordering is (or resolves to) kAmd
  std::vector<int32_t> given_perm;  // used when ordering == kGiven
  RelaxOptions relax;
  // Threads (1..kMaxFactorThreads) for numeric factorizations (Cholesky):
  // independent subtrees run concurrently; and for the nested-dissection
  // ordering, whose sides of a separator are dissected concurrently. The
  // permutation and the factor are bit-identical for every count; 1 runs
  // everything on the caller's thread.
  int32_t threads = 1;
  // Cholesky::analyze refuses (kResourceExhausted, "the factor would exceed N
  // entries") a factor storing more entries than this, before it reserves
  // or touches any of its storage: for callers facing untrusted input.
  int64_t max_factor_entries = INT64_MAX;
  // A supernode of more than panel_cols columns is stored as a chain of
  // panels: ceil(k / panel_cols) of them, at most max_panels, of near-equal
  // widths, each a supernode of its own (the next panel its parent) whose
  // block is its columns' rows only. A k-column block stores k (k - 1) / 2
  // unused entries above its diagonal; a chain of P panels about 1 / P of
  // them. The numeric factorization factors a chain as one front (no update
  // matrix between its panels). 0: no chains.
  int32_t panel_cols = 64;
  int32_t max_panels = 4;
};

// The analysis of one pattern. Columns are numbered in pivot order
// (permuted); supernode s holds columns [first_col[s], first_col[s+1]) and a
// dense column-major block of rows(s) x ncols(s) values in the factor, its
// rows being its own columns first, then the rows below in increasing order.
struct SymbolicFactor {
  int32_t n = 0;
  std::vector<int32_t> perm;          // perm[k]: original index of pivot k
  std::vector<int32_t> inverse_perm;  // inverse_perm[perm[k]] = k
  EliminationTree etree;              // of the permuted matrix (identity postorder)
  std::vector<int32_t> column_counts; // nnz of L(:, k) incl. diagonal, permuted numbering

  int32_t num_supernodes = 0;
  std::vector<int32_t> first_col;        // num_supernodes + 1
  std::vector<int32_t> supernode_of;     // n: supernode holding column k
  std::vector<int32_t> supernode_parent; // num_supernodes, -1 for roots
  std::vector<int64_t> row_ptr;          // num_supernodes + 1, into row_ind
  std::vector<int32_t> row_ind;          // rows of each supernode (permuted numbering)
  std::vector<int64_t> value_ptr;        // num_supernodes + 1, into the factor's values

  // Numeric assembly map: the entries of A's lower triangle (original
  // numbering) that land in supernode s are a_order[a_ptr[s] .. a_ptr[s+1]),
  // indices into A's values; the one at position q lands at offset a_dest[q]
  // within s's block (values + value_ptr[s]). 32 bits: analyze refuses a
  // block of 2^31 entries or more.
  std::vector<int64_t> a_ptr;
  std::vector<int32_t> a_order;  // indices into A's values
  std::vector<int32_t> a_dest;   // by position in a_order

  int64_t nnz_A = 0;          // lower triangle incl. diagonal
  int64_t nnz_L = 0;          // true nonzeros of L incl. diagonal (sum of column counts)
  int64_t stored_L = 0;       // entries stored in supernode blocks (incl. explicit zeros)
  double flops = 0.0;         // sum over columns of column_count^2 (true nonzeros)
  int64_t stack_peak = 0;     // doubles of multifrontal update stacks needed
  int32_t max_front_rows = 0; // largest rows(s)
  // continued[s] != 0: supernode s is a panel whose chain goes on in s + 1,
  // its parent, whose rows are s's rows below its columns
  // (AnalyzeOptions::panel_cols). Empty: no chains.
  std::vector<uint8_t> continued;

  int32_t rows(int32_t s) const { return static_cast<int32_t>(row_ptr[s + 1] - row_ptr[s]); }
  int32_t cols(int32_t s) const { return first_col[s + 1] - first_col[s]; }
  bool continues(int32_t s) const { return !continued.empty() && continued[s] != 0; }
  // The first and last panels of s's chain (s itself when it is in none).
  int32_t chain_first(int32_t s) const {
    while (s > 0 && continues(s - 1)) --s;
    return s;
  }
  int32_t chain_last(int32_t s) const {
    while (continues(s)) ++s;
    return s;
  }
};

// Analyzes the symmetric matrix whose lower triangle is `lower` (pattern
// only; entries above the diagonal are an error). Time O(nnz(A) + ordering
// + sum of supernode row counts * log), memory O(nnz(A) + n).
Status analyze(const CscMatrix& lower, const AnalyzeOptions& options, SymbolicFactor* out);

// analyze() in two steps, for a caller that acts on the factor's sizes
// (value_ptr, stack_peak) before the assembly map is built: Cholesky faults
// in the factor's storage meanwhile. analyze_structure leaves a_ptr, a_order
// and a_dest empty; map_assembly fills them (O(nnz(A)) with random access).
Status analyze_structure(const CscMatrix& lower, const AnalyzeOptions& options, SymbolicFactor* out);
void map_assembly(const CscMatrix& lower, SymbolicFactor* f);

}  // namespace gab
