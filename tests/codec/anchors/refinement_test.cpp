// The least-squares refinement chunk: the encoder's refined shape is what
// the decoder rebuilds; it applies to the whole anchor set only; a file cut
// inside it decodes unrefined; a corrupt one is an error naming it.
#include <gtest/gtest.h>

#include <string>

#include "common/gab_files.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::encode_or_die;
using testing_util::in_decoded_numbering;
using testing_util::relative_rms;

Status decode(const std::vector<uint8_t>& file, const DecodeOptions& options, Mesh* out, DecodeStats* stats) {
  return decode_mesh(file.data(), file.size(), options, out, stats);
}

struct Refined {
  Mesh mesh;
  EncodeStats stats;
  std::vector<uint8_t> file;
};

Refined refined_torus(int32_t anchors) {
  Refined r;
  r.mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.max_anchors = anchors;
  options.refine = true;
  r.file = encode_or_die(r.mesh, options, &r.stats);
  return r;
}

TEST(Refinement, DecodesToTheEncodersRefinedShape) {
  const Refined r = refined_torus(80);
  ASSERT_TRUE(r.stats.refined);
  EXPECT_LT(r.stats.rms_rel, 0.95 * r.stats.unrefined_rms_rel);  // what least squares buys
  EXPECT_EQ(r.stats.chunks, static_cast<int32_t>(r.stats.chunk_anchors.size()) + 1);
  Mesh out;
  DecodeStats ds;
  ASSERT_TRUE(decode(r.file, DecodeOptions(), &out, &ds).ok());
  EXPECT_TRUE(ds.refined);
  EXPECT_FALSE(ds.truncated);
  EXPECT_EQ(ds.chunks, r.stats.chunks);
  EXPECT_NEAR(relative_rms(in_decoded_numbering(r.mesh, r.stats), out), r.stats.rms_rel, 1e-12);
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(r.file.data(), r.file.size(), &info).ok());
  EXPECT_TRUE(info.refined);
  EXPECT_EQ(info.refinement_bytes, r.stats.refinement_bytes);
  EXPECT_EQ(info.chunk_anchors, r.stats.chunk_anchors);
  EXPECT_EQ(info.chunks_present, r.stats.chunks);
}

TEST(Refinement, OnlyTheWholeAnchorSetIsRefined) {
  const Refined r = refined_torus(80);
  Mesh out;
  DecodeStats ds;
  DecodeOptions all;
  all.max_anchors = 80;
  ASSERT_TRUE(decode(r.file, all, &out, &ds).ok());
  EXPECT_TRUE(ds.refined);
  DecodeOptions fewer;
  fewer.max_anchors = 79;
  ASSERT_TRUE(decode(r.file, fewer, &out, &ds).ok());
  EXPECT_FALSE(ds.refined);
  EXPECT_EQ(ds.anchors, 79);
}

TEST(Refinement, FileCutInsideItDecodesUnrefined) {
  const Refined r = refined_torus(80);
  for (size_t cut : {size_t{1}, size_t{5}, r.stats.refinement_bytes - 1}) {
    const std::vector<uint8_t> cut_file(r.file.begin(), r.file.end() - static_cast<std::ptrdiff_t>(cut));
    Mesh out;
    DecodeStats ds;
    ASSERT_TRUE(decode(cut_file, DecodeOptions(), &out, &ds).ok()) << cut;
    EXPECT_TRUE(ds.truncated);
    EXPECT_FALSE(ds.refined);
    EXPECT_EQ(ds.anchors, 80);
    EXPECT_NEAR(relative_rms(in_decoded_numbering(r.mesh, r.stats), out), r.stats.unrefined_rms_rel, 1e-12);
  }
}

TEST(Refinement, CorruptRefinementIsAnErrorNamingIt) {
  Refined r = refined_torus(80);
  r.file.back() ^= 0x10;
  Mesh out;
  DecodeStats ds;
  const Status s = decode(r.file, DecodeOptions(), &out, &ds);
  ASSERT_FALSE(s.ok());
  const std::string chunk = std::to_string(r.stats.chunk_anchors.size());
  EXPECT_EQ(s.message(), "refinement (chunk " + chunk + ") is corrupt (checksum mismatch)");
}

TEST(Refinement, RmsTargetStopsWhenTheRefinedShapeMeetsIt) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.target_rms_rel = 4e-3;
  options.bits = 14;  // fine enough that the grid leaves the refinement its gain
  EncodeStats plain;
  encode_or_die(mesh, options, &plain);
  options.refine = true;
  EncodeStats refined;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &refined);
  ASSERT_TRUE(plain.target_met);
  ASSERT_TRUE(refined.target_met);
  ASSERT_TRUE(refined.refined);
  EXPECT_LE(refined.rms_rel, 4e-3);
  EXPECT_GT(refined.unrefined_rms_rel, 4e-3);  // the anchors alone fall short
  EXPECT_LT(refined.anchors, plain.anchors);
  Mesh out;
  DecodeStats ds;
  ASSERT_TRUE(decode(file, DecodeOptions(), &out, &ds).ok());
  EXPECT_NEAR(relative_rms(in_decoded_numbering(mesh, refined), out), refined.rms_rel, 1e-12);
}

TEST(Refinement, UnrefinedFilesAreUnchanged) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.max_anchors = 80;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  EXPECT_FALSE(es.refined);
  EXPECT_EQ(es.refinement_bytes, 0u);
  EXPECT_EQ(es.rms_rel, es.unrefined_rms_rel);
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  EXPECT_FALSE(info.refined);
  EXPECT_EQ(file[9] & 2, 0);  // the flags byte: what the first writers wrote
}

TEST(Refinement, IterationCountMustBePositive) {
  EncodeOptions options;
  options.max_anchors = 10;
  options.refine = true;
  options.refine_iterations = 0;
  std::vector<uint8_t> file;
  EncodeStats es;
  const Status s = encode_mesh(bumpy_torus(10, 6), options, &file, &es);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "refinement iterations must be positive");
}

}  // namespace
}  // namespace gab
