// Meshes and files for the .gab encoder/decoder tests.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/metrics.h"
#include "mesh/mesh_test_util.h"

namespace gab {
namespace testing_util {

// A torus with a deterministic bumpy radius (no symmetry, so no exact ties
// in the greedy error ranking).
inline Mesh bumpy_torus(int n, int m) {
  Mesh t = torus(n, m);
  for (int32_t v = 0; v < t.num_vertices(); ++v) {
    double* p = &t.positions[3 * static_cast<size_t>(v)];
    const double bump = 1.0 + 0.08 * std::sin(3.1 * p[0] + 1.3) * std::cos(2.3 * p[1] - 0.4) + 0.03 * std::sin(7.0 * p[2]);
    for (int c = 0; c < 3; ++c) p[c] *= bump;
  }
  return t;
}

inline std::vector<uint8_t> encode_or_die(const Mesh& mesh, const EncodeOptions& options, EncodeStats* stats) {
  std::vector<uint8_t> file;
  const Status s = encode_mesh(mesh, options, &file, stats);
  EXPECT_TRUE(s.ok()) << s.message();
  return file;
}

inline Mesh decode_or_die(const std::vector<uint8_t>& file, const DecodeOptions& options, DecodeStats* stats) {
  Mesh out;
  const Status s = decode_mesh(file.data(), file.size(), options, &out, stats);
  EXPECT_TRUE(s.ok()) << s.message();
  return out;
}

// Vertex RMS distance over a's bounding-box diagonal.
inline double relative_rms(const Mesh& a, const Mesh& b) {
  VertexDistance d;
  EXPECT_TRUE(vertex_distance(a, b, &d).ok());
  return d.rms / bounding_box_diagonal(a);
}

}  // namespace testing_util
}  // namespace gab
