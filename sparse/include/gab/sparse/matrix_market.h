// Matrix Market coordinate files (NIST format): read and write.
//
// Reads `%%MatrixMarket matrix coordinate real|integer|pattern
// general|symmetric`. Pattern entries get value 1. Errors name the file and
// line. Header counts are never trusted for allocation beyond what the file
// can actually hold (entries are read before the count is believed).
#pragma once

#include <string>

#include "gab/sparse/csc.h"
#include "gab/sparse/status.h"

namespace gab {

enum class MatrixMarketSymmetry { kGeneral, kSymmetric };

struct MatrixMarketInfo {
  MatrixMarketSymmetry symmetry = MatrixMarketSymmetry::kGeneral;
  bool pattern = false;  // the file had no values
};

// Reads a coordinate Matrix Market file into CSC (duplicates summed). A
// symmetric file yields its lower triangle as stored (upper-triangle entries
// of a symmetric file are mirrored into the lower triangle).
Status read_matrix_market(const std::string& path, CscMatrix* out,
                          MatrixMarketInfo* info = nullptr);

// Same, from the file's text already in memory; `name` is used in messages.
Status parse_matrix_market(const std::string& text, const std::string& name, CscMatrix* out,
                           MatrixMarketInfo* info = nullptr);

// Reads a square matrix meant as symmetric and returns its lower triangle:
// a symmetric file as is; a general file must have symmetric values (checked,
// error names an offending entry).
Status read_symmetric_matrix_market(const std::string& path, CscMatrix* lower);

// Writes a coordinate real file (general, or symmetric when `symmetric` and
// the matrix is a lower triangle), values printed with 17 significant digits.
// The file is written atomically (temporary + rename).
Status write_matrix_market(const std::string& path, const CscMatrix& a, bool symmetric);

}  // namespace gab
