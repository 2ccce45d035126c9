// How an attribute's values become the integers its section codes
// (docs/format.md 6.3), and back. Normals: points of the integer lattice
// on the octahedron |x| + |y| + |z| = R (R = 2^(bits-1)), directions only.
// Everything else: a uniform grid per component, origin[c] + q * step with q
// in [0, 2^bits), one step for every component (an integer-typed attribute:
// step 1, exact). Internal to the codec.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh_attribute.h"

namespace gab {

// The most bits of a normal's lattice and of a grid.
constexpr int kMaxNormalBits = 16;
constexpr int kMaxGridBits = 31;

struct AttributeQuantizer {
  AttributeKind kind = AttributeKind::kGeneric;
  int components = 1;
  int bits = 8;
  double origin[4] = {0, 0, 0, 0};
  double step = 0;  // 0: every value is the origin (q = 0)

  bool lattice() const { return kind == AttributeKind::kNormal; }
  int32_t radius() const { return int32_t{1} << (bits - 1); }       // the lattice's R
  int64_t max_index() const { return (int64_t{1} << bits) - 1; }    // the grid's largest q

  // The encoder's: a float-typed attribute on a grid of `bits` over its
  // values' span; an integer-typed one exactly, as few bits as its span
  // needs (a span past 2^31 - 1 on the coarsest power-of-two step that
  // fits); a normal on the lattice of `bits`.
  static AttributeQuantizer fit(const MeshAttribute& attribute, int bits);

  // One element's `components` values to integers (normals: x y z on the
  // lattice; a zero vector goes to +z) and back (normals: unit length).
  void quantize(const double* values, int32_t* q) const;
  void dequantize(const int32_t* q, double* values) const;
};

// The lattice point nearest the direction of the integer vector p (not
// zero) at radius r: each |component| rounded, then the sum moved to r by the
// components whose rounding went furthest. Exact integer arithmetic, so
// encoder and decoder agree on every machine.
void project_to_lattice(const int64_t p[3], int32_t r, int32_t out[3]);

}  // namespace gab
