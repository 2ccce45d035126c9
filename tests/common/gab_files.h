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

// Vertex RMS distance over a's bounding-box diagonal.
inline double relative_rms(const Mesh& a, const Mesh& b) {
  VertexDistance d;
  EXPECT_TRUE(vertex_distance(a, b, &d).ok());
  return d.rms / bounding_box_diagonal(a);
}

}  // namespace testing_util
}  // namespace gab
