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
      options.solver = Solver::kIterative;
      options.detail = target < 5e-4 ? DetailMode::kOn : DetailMode::kOff;
      EncodeStats es;
      const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
      ASSERT_GT(file.size(), 12u);
      EXPECT_EQ(file[12], kGabReconstructionIterativeLocal);
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
  options.solver = Solver::kIterative;
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
  options.solver = Solver::kIterative;
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
  options.solver = Solver::kIterative;
  options.refine = true;
  std::vector<uint8_t> file;
  EncodeStats es;
  EXPECT_EQ(encode_mesh(mesh, options, &file, &es).message(),
            "the refinement chunk needs the global reconstruction operator");
  options.refine = false;
  options.solver = static_cast<Solver>(7);
  EXPECT_EQ(encode_mesh(mesh, options, &file, &es).message(), "unknown reconstruction operator");
}

// Single precision steps at any magnitude: the residual is scaled by a
// power of two, so a mesh scaled by 2^k (coordinates near 1e90 or 1e-90,
// far outside float's range) codes to the same error, and a weight whose
// square overflows a float (w = 1e30) still decodes to the encoder's shape.
TEST(IterativeOperator, AnyMagnitudeAndWeight) {
  const Mesh mesh = bumpy_torus(24, 16);
  EncodeOptions options;
  options.target_rms_rel = 2e-3;
  options.solver = Solver::kIterative;
  EncodeStats base;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &base);
  for (int exponent : {300, -300}) {
    Mesh scaled = mesh;
    for (double& x : scaled.positions) x = std::ldexp(x, exponent);
    EncodeStats es;
    const std::vector<uint8_t> scaled_file = encode_or_die(scaled, options, &es);
    EXPECT_EQ(es.anchors, base.anchors) << exponent;
    EXPECT_NEAR(es.rms_rel, base.rms_rel, 1e-9 * base.rms_rel) << exponent;
    DecodeStats ds;
    const Mesh out = decode_or_die(scaled_file, DecodeOptions(), &ds);
    EXPECT_NEAR(relative_rms(scaled, out), es.rms_rel, 1e-12 * es.rms_rel) << exponent;
  }
  options.weight = 1e30;
  EncodeStats heavy;
  const std::vector<uint8_t> heavy_file = encode_or_die(mesh, options, &heavy);
  DecodeStats ds;
  const Mesh out = decode_or_die(heavy_file, DecodeOptions(), &ds);
  EXPECT_NEAR(relative_rms(mesh, out), heavy.rms_rel, 1e-12 * heavy.rms_rel);
  EXPECT_LE(heavy.rms_rel, 2e-3);
}

// The default (Solver::kAuto) is the iterative operator, or the global one
// when the refinement chunk is asked for; the file and the stats say which.
TEST(IterativeOperator, IsTheDefaultUnlessTheRefinementNeedsTheGlobalOne) {
  const Mesh mesh = bumpy_torus(16, 10);
  for (bool refine : {false, true}) {
    EncodeOptions options;
    options.target_rms_rel = 1e-3;
    options.refine = refine;
    EncodeStats es;
    const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
    ASSERT_GT(file.size(), 12u);
    EXPECT_EQ(file[12], refine ? kGabReconstructionGlobal : kGabReconstructionIterativeLocal);
    EXPECT_EQ(es.solver, refine ? Solver::kGlobal : Solver::kIterative);
    DecodeStats ds;
    decode_or_die(file, DecodeOptions(), &ds);
    EXPECT_EQ(ds.solver, es.solver);
  }
  EncodeOptions global;
  global.target_rms_rel = 1e-3;
  global.solver = Solver::kGlobal;
  EncodeStats es;
  EXPECT_EQ(encode_or_die(mesh, global, &es)[12], kGabReconstructionGlobal);
  EXPECT_EQ(es.solver, Solver::kGlobal);
}

}  // namespace
}  // namespace gab
