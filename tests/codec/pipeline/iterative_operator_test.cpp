// Files made with the iterative reconstruction operator (header byte 12 = 3,
// docs/format.md 5.2.3): the decoder computes the encoder's shapes exactly,
// in both layouts, with and without the detail layer, for any prefix and
// any of its parameters; the operator is recorded; its option errors.
#include <gtest/gtest.h>

#include <cmath>

#include "common/gab_files.h"
#include "container/crc32.h"
#include "reconstruction/iterative_tuning.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::decode_or_die;
using testing_util::encode_or_die;
using testing_util::in_decoded_numbering;
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
      EXPECT_EQ(file[12], kGabReconstructionIterativeTuned);
      EXPECT_GT(es.chunks, 1);
      EXPECT_EQ(es.detail, target < 5e-4);
      DecodeStats ds;
      const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
      // The decoded shape is the one the encoder measured, to the last bits.
      EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, es), out), es.rms_rel, 1e-14 + 1e-12 * es.rms_rel)
          << target;
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
  const Mesh numbered = in_decoded_numbering(mesh, es);
  EXPECT_GT(relative_rms(numbered, coarse), relative_rms(numbered, whole));
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

// Operator 3's sweeps and final steps travel in the file (chunk 0's head):
// whatever the encoder chose, the decoder computes its shapes exactly, and
// `gab info` reads them back.
TEST(IterativeOperator, TheFileCarriesItsParameters) {
  const Mesh mesh = bumpy_torus(40, 24);  // 960 vertices: the default rule's 4, 8, 32, 64
  struct Tuning {
    int32_t prediction_sweeps, final_sweeps, final_steps16, final_most;
  };
  for (const Tuning& t : {Tuning{-1, -1, -1, -1}, Tuning{0, 0, 0, 0}, Tuning{2, 5, 8, 20}, Tuning{16, 16, 64, 64}}) {
    for (FileLayout layout : {FileLayout::kLevels, FileLayout::kSelectionOrder}) {
      EncodeOptions options;
      options.target_rms_rel = 3e-3;
      options.layout = layout;
      options.detail = DetailMode::kOff;
      options.prediction_sweeps = t.prediction_sweeps;
      options.final_sweeps = t.final_sweeps;
      options.final_steps16 = t.final_steps16;
      options.final_most_steps = t.final_most;
      EncodeStats es;
      const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
      DecodeStats ds;
      const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
      EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, es), out), es.rms_rel, 1e-14 + 1e-12 * es.rms_rel)
          << t.final_steps16;
      EXPECT_LE(es.rms_rel, 3e-3);
      GabFileInfo info;
      ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
      EXPECT_EQ(info.reconstruction, kGabReconstructionIterativeTuned);
      EXPECT_EQ(info.prediction_sweeps, t.prediction_sweeps < 0 ? 4 : t.prediction_sweeps);
      EXPECT_EQ(info.final_sweeps, t.final_sweeps < 0 ? 8 : t.final_sweeps);
      EXPECT_EQ(info.final_steps16, t.final_steps16 < 0 ? 32 : t.final_steps16);
      EXPECT_EQ(info.final_most_steps, t.final_most < 0 ? 64 : t.final_most);
    }
  }
}

// A forged parameter past its range is refused by name, by the decoder and
// by read_gab_info (each bounds a decode's work: at most 16 sweeps a start
// and 64 steps a shape), and so are options past them.
TEST(IterativeOperator, ParametersOutOfRangeAreNamedErrors) {
  const Mesh mesh = bumpy_torus(16, 10);
  EncodeOptions options;
  options.target_rms_rel = 3e-3;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  const size_t frame = info.header_bytes + info.connectivity_bytes + info.order_bytes;  // chunk 0's
  const struct {
    size_t field;
    uint8_t value;
    const char* message;
  } forged[] = {{0, 17, "chunk 0: the operator's prediction sweeps 17 exceeds 16"},
                {1, 200, "chunk 0: the operator's final sweeps 200 exceeds 16"},
                {2, 65, "chunk 0: the operator's final steps per spacing (sixteenths) 65 exceeds 64"},
                {3, 255, "chunk 0: the operator's most final steps 255 exceeds 64"}};
  for (const auto& f : forged) {
    std::vector<uint8_t> bad = file;
    bad[frame + 8 + f.field] = f.value;
    uint32_t length = 0;
    for (int b = 0; b < 4; ++b) length |= static_cast<uint32_t>(bad[frame + b]) << (8 * b);
    const uint32_t crc = crc32(bad.data() + frame + 8, length);
    for (int b = 0; b < 4; ++b) bad[frame + 4 + b] = static_cast<uint8_t>(crc >> (8 * b));
    Mesh out;
    DecodeStats ds;
    const Status s = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
    EXPECT_EQ(s.code(), StatusCode::kParseError);
    EXPECT_EQ(s.message(), f.message);
    EXPECT_EQ(read_gab_info(bad.data(), bad.size(), &info).message(), f.message);
  }
  // A chunk 0 too short to hold them.
  const uint8_t three[] = {4, 8, 16};
  IterativeTuning tuning;
  size_t offset = 0;
  EXPECT_EQ(parse_iterative_tuning(three, sizeof three, &tuning, &offset).message(),
            "the operator's parameters are cut short");
  std::vector<uint8_t> out;
  options.prediction_sweeps = 17;
  EXPECT_EQ(encode_mesh(mesh, options, &out, &es).message(), "sweeps must be in 0..16 (or -1: the encoder's)");
  options.prediction_sweeps = -1;
  options.final_most_steps = 65;
  EXPECT_EQ(encode_mesh(mesh, options, &out, &es).message(),
            "final steps must be in 0..64 (or -1: the encoder's)");
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
    EXPECT_NEAR(relative_rms(in_decoded_numbering(scaled, es), out), es.rms_rel, 1e-12 * es.rms_rel) << exponent;
  }
  options.weight = 1e30;
  EncodeStats heavy;
  const std::vector<uint8_t> heavy_file = encode_or_die(mesh, options, &heavy);
  DecodeStats ds;
  const Mesh out = decode_or_die(heavy_file, DecodeOptions(), &ds);
  EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, heavy), out), heavy.rms_rel, 1e-12 * heavy.rms_rel);
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
    EXPECT_EQ(file[12], refine ? kGabReconstructionGlobal : kGabReconstructionIterativeTuned);
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
