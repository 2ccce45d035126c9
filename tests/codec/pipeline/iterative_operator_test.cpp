// Files made with the iterative reconstruction operator (header byte 12 = 1,
// docs/format.md 5.2.1): the decoder computes the encoder's shapes exactly,
// in both layouts, with and without the detail layer, for any prefix; the
// operator is recorded; its option errors.
#include <gtest/gtest.h>

#include <cmath>

#include "common/gab_files.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::decode_or_die;
using testing_util::encode_or_die;
using testing_util::relative_rms;

TEST(IterativeOperator, DecodesToTheEncodersShapeInEveryLayout) {
  const Mesh mesh = bumpy_torus(40, 24);
  for (FileLayout layout : {FileLayout::kLevels, FileLayout::kSelectionOrder}) {
    for (double target : {3e-3, 2e-4}) {
      EncodeOptions options;
      options.target_rms_rel = target;
      options.layout = layout;
      options.reconstruction = kGabReconstructionIterative;
      options.detail = target < 5e-4 ? DetailMode::kOn : DetailMode::kOff;
      EncodeStats es;
      const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
      ASSERT_GT(file.size(), 12u);
      EXPECT_EQ(file[12], kGabReconstructionIterative);
      EXPECT_GT(es.chunks, 1);
      EXPECT_EQ(es.detail, target < 5e-4);
      DecodeStats ds;
      const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
      // The decoded shape is the one the encoder measured, to the last bits.
      EXPECT_NEAR(relative_rms(mesh, out), es.rms_rel, 1e-14 + 1e-12 * es.rms_rel) << target;
      EXPECT_LE(es.rms_rel, target);
      EXPECT_EQ(ds.factor_entries, 0);
      EXPECT_EQ(ds.matrix_entries, 0);
    }
  }
}

TEST(IterativeOperator, APrefixDecodesToTheShapeOfItsAnchors) {
  const Mesh mesh = bumpy_torus(36, 20);
  EncodeOptions options;
  options.target_rms_rel = 1e-3;
  options.detail = DetailMode::kOff;
  options.reconstruction = kGabReconstructionIterative;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  ASSERT_GT(es.chunk_anchors.size(), 1u);
  // The first chunk alone: a coarser shape, the same with any later chunk
  // cut off (the operator depends on the anchors only).
  DecodeOptions first;
  first.max_anchors = es.chunk_anchors[0];
  DecodeStats ds;
  const Mesh coarse = decode_or_die(file, first, &ds);
  const std::vector<uint8_t> cut(file.begin(), file.begin() + static_cast<std::ptrdiff_t>(file.size() - 1));
  DecodeStats cut_stats;
  const Mesh whole = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_GT(relative_rms(mesh, coarse), relative_rms(mesh, whole));
  Mesh truncated;
  ASSERT_TRUE(decode_mesh(cut.data(), cut.size(), first, &truncated, &cut_stats).ok());
  EXPECT_EQ(truncated.positions, coarse.positions);
}

// The decode's memory model for this operator (no matrix, no factor: 160
// bytes per vertex of vectors beside the mesh) is checked before the work.
TEST(IterativeOperator, TheMemoryLimitCountsItsVectors) {
  const Mesh mesh = bumpy_torus(40, 24);  // 960 vertices, 1,920 triangles
  EncodeOptions options;
  options.target_rms_rel = 3e-3;
  options.reconstruction = kGabReconstructionIterative;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  // The mesh alone: 150 * 960 + 12 * 1,920 = 167,040 bytes; with the
  // vectors 320,640.
  DecodeOptions tight;
  tight.max_memory = 200000;
  Mesh out;
  DecodeStats ds;
  const Status refused = decode_mesh(file.data(), file.size(), tight, &out, &ds);
  EXPECT_EQ(refused.code(), StatusCode::kResourceExhausted);
  EXPECT_EQ(refused.message(),
            "decoding needs about 1 MiB (960 vertices, 1920 triangles), over its memory limit of 1 MiB: raise it "
            "(DecodeOptions::max_memory, gab decompress --max-memory)");
  tight.max_memory = 330000;
  EXPECT_TRUE(decode_mesh(file.data(), file.size(), tight, &out, &ds).ok());
}

TEST(IterativeOperator, OptionErrors) {
  const Mesh mesh = bumpy_torus(12, 8);
  EncodeOptions options;
  options.target_rms_rel = 1e-3;
  options.reconstruction = kGabReconstructionIterative;
  options.refine = true;
  std::vector<uint8_t> file;
  EncodeStats es;
  EXPECT_EQ(encode_mesh(mesh, options, &file, &es).message(),
            "the refinement chunk needs the global reconstruction operator");
  options.refine = false;
  options.reconstruction = 2;
  EXPECT_EQ(encode_mesh(mesh, options, &file, &es).message(), "unknown reconstruction operator");
}

}  // namespace
}  // namespace gab
