// Shared machinery of the dense kernels: the blocking drivers every SIMD
// level instantiates with its own register tile, the packing workspace, and
// the per-level tables that dense_kernels.cpp dispatches between.
//
// The drivers follow Goto & van de Geijn, "Anatomy of high-performance matrix
// multiplication" (TOMS 2008) and the BLIS loop structure (Van Zee & van de
// Geijn, TOMS 2015): the inner dimension is cut into kc-slices, B^T is packed
// into nr-wide micro-panels (one stays in L1 while it is used), A into
// mr-tall micro-panels grouped in mc-row blocks (a block stays in L2), and a
// register tile of mr x nr accumulators does all the arithmetic. POTRF and
// TRSM are the recursive formulations (Gustavson, "Recursion leads to
// automatic variable blocking", IBM J. R&D 1997; Elmroth et al., SIAM Review
// 2004), which spend nearly all their flops in the SYRK/GEMM below them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "gab/sparse/dense_kernels.h"
#include "factor/kernel_team.h"

namespace gab {
namespace dense_detail {

// Per-level kernel tables. avx2_table()/avx512_table() return nullptr when
// the level is not compiled in (non-x86 builds); whether the CPU can run them
// is dense_kernels.cpp's business.
const DenseKernels* scalar_table();
const DenseKernels* avx2_table();
const DenseKernels* avx512_table();

// The calling thread's packing workspace, at least `doubles` long and 64-byte
// aligned, or nullptr if it cannot be had (the caller then takes the unpacked
// path). Callers always ask for their level's fixed maximum, so a thread
// allocates once and the kernels allocate nothing afterwards; it is freed at
// thread exit. One buffer serves all levels: no kernel holds it while
// calling another that packs.
double* packing_workspace(size_t doubles);

// Passed as the tile's diagonal offset when no entry is to be masked.
constexpr int32_t kNoDiagonal = std::numeric_limits<int32_t>::max() / 2;

// A pivot passes iff it is > 0 and finite (NaN fails both comparisons).
inline bool pivot_ok(double d) { return d > 0.0 && d <= std::numeric_limits<double>::max(); }

// Splits n > base for the recursive POTRF/TRSM: the first part is a multiple
// of `align` (the register tile's width) so the GEMM/SYRK below see aligned
// shapes, and about half of n so the recursion stays balanced.
inline int32_t recursive_split(int32_t n, int32_t align) {
  const int32_t half = (n / 2 + align - 1) / align * align;
  return std::min(std::max(half, align), n - 1);
}

// Unblocked right-looking Cholesky (Golub & Van Loan, sec. 4.2), the base
// case of the scalar and AVX2 levels. The trailing update is ordered as in
// LDL^T, a_ic -= a_ij (a_cj / d_j) on the unscaled column, so the chain from
// one pivot to the next is a divide, a multiply and a subtract; the square
// root and the scaling of column j overlap with the following columns.
// Strict upper triangle untouched.
inline int32_t potrf_unblocked(int32_t n, double* a, int32_t lda) {
  for (int32_t j = 0; j < n; ++j) {
    double* aj = a + static_cast<ptrdiff_t>(j) * lda;
    const double d = aj[j];
    if (!pivot_ok(d)) return j;
    const double inv_d = 1.0 / d;
    for (int32_t c = j + 1; c < n; ++c) {
      double* ac = a + static_cast<ptrdiff_t>(c) * lda;
      const double w = aj[c] * inv_d;
      for (int32_t i = c; i < n; ++i) ac[i] -= aj[i] * w;
    }
    const double s = std::sqrt(d);
    aj[j] = s;
    for (int32_t i = j + 1; i < n; ++i) aj[i] /= s;
  }
  return -1;
}

// Unblocked B := B L^{-T}, column by column (X L^T = B read column-wise:
// x_j = (b_j - sum_{p<j} x_p l_jp) / l_jj). Multiplies by the reciprocal of
// the diagonal, like the reference BLAS.
inline void trsm_unblocked(int32_t m, int32_t n, const double* l, int32_t ldl, double* b,
                           int32_t ldb) {
  for (int32_t j = 0; j < n; ++j) {
    const double* lj = l + static_cast<ptrdiff_t>(j) * ldl;
    double* bj = b + static_cast<ptrdiff_t>(j) * ldb;
    const double r = 1.0 / lj[j];
    for (int32_t i = 0; i < m; ++i) bj[i] *= r;
    for (int32_t c = j + 1; c < n; ++c) {
      double* bc = b + static_cast<ptrdiff_t>(c) * ldb;
      const double lcj = lj[c];
      for (int32_t i = 0; i < m; ++i) bc[i] -= bj[i] * lcj;
    }
  }
}

// Copies rows [0, rows) x columns [0, k) of the column-major `a` into
// panels of `height` rows, each panel stored p-major (dst[p*height + r]) so
// the register tile reads it with unit stride; the last panel is zero-padded
// to full height so no tile ever reads garbage (or a denormal).
inline void pack_panels(const double* a, ptrdiff_t lda, int32_t rows, int32_t k, int32_t height,
                        double* dst) {
  for (int32_t i = 0; i < rows; i += height) {
    const int32_t h = std::min(height, rows - i);
    const double* src = a + i;
    for (int32_t p = 0; p < k; ++p) {
      int32_t r = 0;
      for (; r < h; ++r) dst[r] = src[r];
      for (; r < height; ++r) dst[r] = 0.0;
      dst += height;
      src += lda;
    }
  }
}

// Where column j of a lower triangle C lives: a column-major square (ld
// ldc), or packed panels (packed_lower_column, dense_kernels.h). A tile's
// kNr columns start at a multiple of kNr, so they always share one panel
// and one leading dimension.
struct SquareColumns {
  double* c;
  int32_t ldc;
  double* column(int32_t j) const { return c + static_cast<ptrdiff_t>(j) * ldc; }
  int32_t ld(int32_t) const { return ldc; }
};
struct PackedColumns {
  double* c;
  int32_t n;
  double* column(int32_t j) const { return packed_lower_column(c, n, j); }
  int32_t ld(int32_t j) const { return packed_lower_ld(n, j); }
};

// Blocking drivers over a register tile. T provides:
//   kMr, kNr         register tile (rows x columns of C); kNr divides kMr
//   kKc, kMc, kNc    cache blocks: inner-dimension slice, rows of a packed A
//                    block (L2), rows of a packed B^T block (L3); kMr
//                    divides kMc and kNc
//   tile(k, a, as, b, bs, c, ldc, rows, cols, diag):
//     C[0:rows, 0:cols] -= sum_p a[p*as + 0:rows] (b[p*bs + 0:cols])^T,
//     rows <= kMr, cols <= kNr, writing only entries (r, c) with r + diag >= c
//     (diag = row0 - col0 of the tile inside a symmetric C; kNoDiagonal for
//     a plain GEMM tile). a and b may be packed panels (stride kMr) or
//     column-major matrices (stride = leading dimension); the tile never
//     reads a past `rows` or b past `cols`.
//   pack(a, lda, rows, k, dst): pack_panels(a, lda, rows, k, kMr, dst)
//   potrf_small(n, a, lda)   n <= kSmall, same contract as potrf
//   trsm_small(m, n, l, ldl, b, ldb)   n <= kSmall
//   kSmall           largest n of the two base cases
//   direct(m, n, k)  true if the unpacked path is the faster one
//
// Both operands are packed in the same kMr-row panels. The B^T operand of a
// tile is then kNr consecutive rows of a panel read with stride kMr: each
// inner step still touches exactly one 64-byte line of it (kNr doubles at an
// offset that is a multiple of kNr), so it costs the same L1 room as a
// dedicated kNr-wide packing, and SYRK packs its single operand only once.
template <class T>
struct Blocked {
  static_assert(T::kMr % T::kNr == 0 && T::kMc % T::kMr == 0 && T::kNc % T::kMr == 0,
                "tile and cache blocks must nest");
  static_assert(kPackedLowerPanel % T::kNr == 0, "a tile's columns must share a packed panel");

  static void gemm_nt_sub(int32_t m, int32_t n, int32_t k, const double* a, int32_t lda,
                          const double* b, int32_t ldb, double* c, int32_t ldc) {
    if (m <= 0 || n <= 0 || k <= 0) return;
    double* ws = nullptr;
    if (!T::direct(m, n, k)) ws = packing_workspace(workspace_doubles());
    if (ws == nullptr) {
      gemm_direct(m, n, k, a, lda, b, ldb, c, ldc);
      return;
    }
    KernelTeam* team = team_for(m, n, k);
    double* bpack = ws + static_cast<size_t>(T::kMc) * T::kKc;
    for (int32_t pc = 0; pc < k; pc += T::kKc) {
      const int32_t kc = std::min<int32_t>(T::kKc, k - pc);
      const ptrdiff_t off_k = static_cast<ptrdiff_t>(pc);
      for (int32_t jc = 0; jc < n; jc += T::kNc) {
        const int32_t nc = std::min<int32_t>(T::kNc, n - jc);
        T::pack(b + jc + off_k * ldb, ldb, nc, kc, bpack);
        // Row blocks are independent given the packed B^T: a team shares
        // them, each member packing its blocks of A in its own workspace.
        for_each_item(team, (m + T::kMc - 1) / T::kMc, [&](int32_t block) {
          const int32_t ic = block * T::kMc;
          const int32_t mc = std::min<int32_t>(T::kMc, m - ic);
          const RowBlock ablock = pack_rows(a + ic + off_k * lda, lda, mc, kc);
          for (int32_t jr = 0; jr < nc; jr += T::kNr) {
            const int32_t cols = std::min<int32_t>(T::kNr, nc - jr);
            double* cj = c + ic + static_cast<ptrdiff_t>(jc + jr) * ldc;
            const double* bp = panel_rows(bpack, kc, jr);
            for (int32_t ir = 0; ir < mc; ir += T::kMr) {
              T::tile(kc, ablock.rows_from(ir, kc), ablock.stride, bp, T::kMr, cj + ir, ldc,
                      std::min<int32_t>(T::kMr, mc - ir), cols, kNoDiagonal);
            }
          }
        });
      }
    }
  }

  static void syrk_lower_sub(int32_t n, int32_t k, const double* a, int32_t lda, double* c,
                             int32_t ldc) {
    syrk_into(n, k, a, lda, SquareColumns{c, ldc});
  }

  static void syrk_lower_sub_packed(int32_t n, int32_t k, const double* a, int32_t lda, double* c) {
    syrk_into(n, k, a, lda, PackedColumns{c, n});
  }

  // SYRK into the lower triangle of C, its columns placed by `ccols`
  // (SquareColumns or PackedColumns): the same tiles in the same order
  // either way, so both forms give the same bits.
  template <class Columns>
  static void syrk_into(int32_t n, int32_t k, const double* a, int32_t lda, const Columns& ccols) {
    if (n <= 0 || k <= 0) return;
    double* ws = nullptr;
    if (!T::direct(n, n, k)) ws = packing_workspace(workspace_doubles());
    if (ws == nullptr) {
      syrk_direct(n, k, a, lda, ccols);
      return;
    }
    KernelTeam* team = team_for(n, n, k);
    double* bpack = ws + static_cast<size_t>(T::kMc) * T::kKc;
    for (int32_t pc = 0; pc < k; pc += T::kKc) {
      const int32_t kc = std::min<int32_t>(T::kKc, k - pc);
      const double* ak = a + static_cast<ptrdiff_t>(pc) * lda;
      for (int32_t jc = 0; jc < n; jc += T::kNc) {
        const int32_t nc = std::min<int32_t>(T::kNc, n - jc);
        T::pack(ak + jc, lda, nc, kc, bpack);
        // Only row blocks at or below the column block touch the lower
        // triangle; a team shares them (see gemm_nt_sub).
        for_each_item(team, (n - jc + T::kMc - 1) / T::kMc, [&](int32_t block) {
          const int32_t ic = jc + block * T::kMc;
          const int32_t mc = std::min<int32_t>(T::kMc, n - ic);
          // Rows already packed as B^T are reused as A (the usual case:
          // n <= kNc packs A exactly once).
          RowBlock ablock{bpack + static_cast<ptrdiff_t>(ic - jc) * kc, T::kMr, true};
          if (ic + mc > jc + nc) ablock = pack_rows(ak + ic, lda, mc, kc);
          for (int32_t jr = 0; jr < nc; jr += T::kNr) {
            const int32_t j = jc + jr;
            if (j >= ic + mc) break;  // this and later column tiles lie above the block
            const int32_t cols = std::min<int32_t>(T::kNr, nc - jr);
            const double* bp = panel_rows(bpack, kc, jr);
            double* cj = ccols.column(j);
            const int32_t ldc = ccols.ld(j);
            // Start at the diagonal, not at the panel boundary: the first
            // tile reads its panel from an offset, so the only work wasted
            // above the diagonal is inside one kNr x kNr square.
            int32_t i = std::max(ic, j);
            while (i < ic + mc) {
              const int32_t in_block = i - ic;
              const int32_t rows = std::min<int32_t>(T::kMr - in_block % T::kMr, ic + mc - i);
              T::tile(kc, ablock.rows_from(in_block, kc), ablock.stride, bp, T::kMr, cj + i, ldc,
                      rows, cols, i - j);
              i += rows;
            }
          }
        });
      }
    }
  }

  static int32_t potrf(int32_t n, double* a, int32_t lda) {
    if (n <= T::kSmall) return n <= 0 ? -1 : T::potrf_small(n, a, lda);
    // [A11 . ; A21 A22]: L11 = chol(A11), L21 = A21 L11^{-T},
    // L22 = chol(A22 - L21 L21^T).
    const int32_t n1 = recursive_split(n, T::kNr);
    const int32_t n2 = n - n1;
    double* a21 = a + n1;
    const int32_t first = potrf(n1, a, lda);
    if (first >= 0) {
      // Keep the contract that the columns before the failure hold their
      // whole factor: their rows below A11 still need the solve.
      trsm_right_lower_trans(n2, first, a, lda, a21, lda);
      return first;
    }
    double* a22 = a21 + static_cast<ptrdiff_t>(n1) * lda;
    trsm_right_lower_trans(n2, n1, a, lda, a21, lda);
    syrk_lower_sub(n2, n1, a21, lda, a22, lda);
    const int32_t second = potrf(n2, a22, lda);
    return second >= 0 ? n1 + second : -1;
  }

  static void trsm_right_lower_trans(int32_t m, int32_t n, const double* l, int32_t ldl, double* b,
                                     int32_t ldb) {
    if (m <= 0 || n <= 0) return;
    if (n <= T::kSmall) {
      T::trsm_small(m, n, l, ldl, b, ldb);
      return;
    }
    // [X1 X2] [L11^T L21^T; 0 L22^T] = [B1 B2]: X1 = B1 L11^{-T},
    // X2 = (B2 - X1 L21^T) L22^{-T}.
    const int32_t n1 = recursive_split(n, T::kNr);
    const int32_t n2 = n - n1;
    double* b2 = b + static_cast<ptrdiff_t>(n1) * ldb;
    trsm_right_lower_trans(m, n1, l, ldl, b, ldb);
    gemm_nt_sub(m, n2, n1, b, ldb, l + n1, ldl, b2, ldb);
    trsm_right_lower_trans(m, n2, l + n1 + static_cast<ptrdiff_t>(n1) * ldl, ldl, b2, ldb);
  }

  static constexpr DenseKernels table(SimdLevel level) {
    return DenseKernels{level, &potrf, &trsm_right_lower_trans, &syrk_lower_sub, &gemm_nt_sub,
                        &syrk_lower_sub_packed};
  }

 private:
  // Calls from a thread leading a kernel team split their work with it
  // when there is enough: about 2 MFLOP per call or more.
  static KernelTeam* team_for(int32_t m, int32_t n, int32_t k) {
    constexpr int64_t kMinProduct = int64_t{1} << 20;
    return static_cast<int64_t>(m) * n * k >= kMinProduct ? current_team() : nullptr;
  }

  // Rows of A for a run of tiles: packed into the calling thread's
  // workspace (its A part) when it has one, else read in place (a team
  // helper that could not allocate) — the tiles' arithmetic is the same.
  struct RowBlock {
    const double* data;
    ptrdiff_t stride;  // between consecutive k steps
    bool packed;
    // The block's rows from `row` on, in slices of kc (inside a packed
    // panel when row is not a multiple of kMr).
    const double* rows_from(int32_t row, int32_t kc) const {
      if (!packed) return data + row;
      const int32_t offset = row % T::kMr;
      return data + static_cast<ptrdiff_t>(row - offset) * kc + offset;
    }
  };
  static RowBlock pack_rows(const double* a, int32_t lda, int32_t rows, int32_t kc) {
    double* mine = packing_workspace(workspace_doubles());
    if (mine == nullptr) return RowBlock{a, lda, false};
    T::pack(a, lda, rows, kc, mine);
    return RowBlock{mine, T::kMr, true};
  }

  // Packed rows [row, row + kNr) (row a multiple of kNr) of panels packed
  // with inner length kc.
  static const double* panel_rows(const double* packed, int32_t kc, int32_t row) {
    const int32_t offset = row % T::kMr;
    return packed + static_cast<ptrdiff_t>(row - offset) * kc + offset;
  }

  // The whole workspace a packed call may use, requested in full every time
  // so a thread allocates it once, on its first packed call, and never
  // regrows it: kMc x kKc doubles of A, then kNc x kKc of B^T.
  static constexpr size_t workspace_doubles() {
    return static_cast<size_t>(T::kMc + T::kNc) * static_cast<size_t>(T::kKc);
  }

  // Unpacked: tiles read A and B^T straight from the caller's matrices. For
  // small problems packing costs more than it saves.
  // With a team, column strips are shared out.
  static void gemm_direct(int32_t m, int32_t n, int32_t k, const double* a, int32_t lda,
                          const double* b, int32_t ldb, double* c, int32_t ldc) {
    for_each_item(team_for(m, n, k), (n + T::kNr - 1) / T::kNr, [&](int32_t strip) {
      const int32_t j = strip * T::kNr;
      const int32_t cols = std::min<int32_t>(T::kNr, n - j);
      double* cj = c + static_cast<ptrdiff_t>(j) * ldc;
      for (int32_t i = 0; i < m; i += T::kMr) {
        T::tile(k, a + i, lda, b + j, ldb, cj + i, ldc, std::min<int32_t>(T::kMr, m - i), cols,
                kNoDiagonal);
      }
    });
  }

  template <class Columns>
  static void syrk_direct(int32_t n, int32_t k, const double* a, int32_t lda, const Columns& ccols) {
    for_each_item(team_for(n, n, k), (n + T::kNr - 1) / T::kNr, [&](int32_t strip) {
      const int32_t j = strip * T::kNr;
      const int32_t cols = std::min<int32_t>(T::kNr, n - j);
      double* cj = ccols.column(j);
      const int32_t ldc = ccols.ld(j);
      for (int32_t i = j; i < n; i += T::kMr) {
        T::tile(k, a + i, lda, a + j, lda, cj + i, ldc, std::min<int32_t>(T::kMr, n - i), cols,
                i - j);
      }
    });
  }
};

}  // namespace dense_detail
}  // namespace gab
