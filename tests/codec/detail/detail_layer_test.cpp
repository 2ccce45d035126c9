// The detail layer (gab_format.h flag bit 5, codec/src/detail): the decoded
// shape is the encoder's to the last bit, targets are met, prefixes and
// damage behave as for the other chunks.
#include <gtest/gtest.h>

#include <cmath>

#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/metrics.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::decode_or_die;
using testing_util::encode_or_die;

TEST(DetailLayer, DecodedShapeIsTheEncodersAndMeetsTheTarget) {
  const Mesh mesh = bumpy_torus(60, 30);
  EncodeOptions options;
  options.target_rms_rel = 1e-4;
  options.detail = DetailMode::kOn;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  ASSERT_TRUE(es.detail);
  EXPECT_LE(es.rms_rel, 1e-4);
  EXPECT_GT(es.anchor_rms_rel, 1e-4);  // the anchors alone stop well above the target
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_TRUE(ds.detail);
  VertexDistance d;
  ASSERT_TRUE(vertex_distance(mesh, out, &d).ok());
  EXPECT_DOUBLE_EQ(d.rms / bounding_box_diagonal(mesh), es.rms_rel);
  EXPECT_DOUBLE_EQ(d.linf / bounding_box_diagonal(mesh), es.linf_rel);
}

}  // namespace
}  // namespace gab
