// Matrix Market coordinate files (NIST format): read and write.
//
// Reads `%%MatrixMarket matrix coordinate real|integer|pattern
// general|symmetric` (banner words case-insensitive; '%' comments and blank
// lines allowed anywhere after the banner). Pattern entries get value 1;
// duplicates are summed. Array, complex, hermitian and skew-symmetric files
// are refused as unsupported.
//
// Contract on untrusted input: every malformed file gives kParseError (or
// kOverflow for counts above the int32 index limit) with a one-line message
// "NAME:LINE: what is wrong", LINE 1-based. Header counts are never trusted
// for allocation: entries are reserved only up to what the file's size can
// hold, and dimensions above 2^24 are refused unless the file has at least
// one byte per 16 rows/columns. Cost: O(bytes + nrows + ncols + nnz).
#pragma once

#include <string>

#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

enum class MatrixMarketSymmetry { kGeneral, kSymmetric };

struct MatrixMarketInfo {
  MatrixMarketSymmetry symmetry = MatrixMarketSymmetry::kGeneral;
  bool pattern = false;  // the file had no values
};

// Reads a coordinate Matrix Market file into CSC (duplicates summed). A
// symmetric file yields its lower triangle (upper-triangle entries of a
// symmetric file are mirrored into the lower triangle). A file that cannot
// be opened or read: kIoError naming the path. `out` and `info` are written
// only on success.
Status read_matrix_market(const std::string& path, CscMatrix* out,
                          MatrixMarketInfo* info = nullptr);

// Same, from the file's text already in memory; `name` is used in messages.
Status parse_matrix_market(const std::string& text, const std::string& name, CscMatrix* out,
                           MatrixMarketInfo* info = nullptr);

// Reads a square matrix meant as symmetric and returns its lower triangle:
// a symmetric file as is; a general file must have symmetric values, compared
// exactly after duplicate summation with a missing mirror counting as zero
// (kParseError naming an offending entry, 1-based, and its line). Non-square:
// kParseError at the size line.
Status read_symmetric_matrix_market(const std::string& path, CscMatrix* lower);

// Writes a coordinate real file (general, or symmetric when `symmetric`;
// then the matrix must be a square lower triangle), values printed as
// "%.17g" so they read back bit-exact; a matrix without values is written as
// pattern. Invalid CSC, entries above the diagonal for `symmetric`, or
// non-finite values: kInvalidArgument. The file is written atomically
// (unique temporary beside `path`, then rename): on failure the temporary is
// removed, kIoError is returned and `path` is untouched. O(nnz).
Status write_matrix_market(const std::string& path, const CscMatrix& a, bool symmetric);

}  // namespace gab
