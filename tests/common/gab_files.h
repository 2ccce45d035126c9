// .gab files for the codec tests: encode and decode or fail the test, and
// the error a decoded shape makes.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "common/test_meshes.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/renumber.h"

namespace gab {
namespace testing_util {

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

// The input mesh numbered as its file decodes it: a reordered file (the
// default, EncodeStats::reordered) numbers the vertices in traversal order,
// input vertex v as es.new_index[v]; a kept numbering is the input's. The
// encoder measured its errors in this numbering, so sums over it match its
// figures to the last bit.
inline Mesh in_decoded_numbering(const Mesh& input, const EncodeStats& es) {
  if (!es.reordered) return input;
  EXPECT_EQ(es.new_index.size(), static_cast<size_t>(input.num_vertices()));
  return renumber_vertices(input, es.new_index);
}

// Vertex RMS distance over a's bounding-box diagonal.
inline double relative_rms(const Mesh& a, const Mesh& b) {
  VertexDistance d;
  EXPECT_TRUE(vertex_distance(a, b, &d).ok());
  return d.rms / bounding_box_diagonal(a);
}

}  // namespace testing_util
}  // namespace gab
