// The detail layer (gab_format.h flag bit 5, codec/src/detail): the decoded
// shape is the encoder's to the last bit, targets are met (also on meshes
// the anchors alone cannot reach), the encoder keeps the smaller file, and
// levels of detail, truncation and damage behave as for the other chunks.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "container/crc32.h"
#include "container/framing.h"
#include "detail/detail_chunk.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/metrics.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::decode_or_die;
using testing_util::encode_or_die;
using testing_util::in_decoded_numbering;

VertexDistance distance(const Mesh& a, const Mesh& b) {
  VertexDistance d;
  EXPECT_TRUE(vertex_distance(a, b, &d).ok());
  return d;
}

// The unit cube: 8 vertices, 12 triangles, outward.
Mesh cube() {
  Mesh m;
  for (int v = 0; v < 8; ++v) {
    m.positions.insert(m.positions.end(), {double(v & 1), double(v >> 1 & 1), double(v >> 2)});
  }
  m.triangles = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return m;
}

// The detail chunk's frame: where it starts in the file and its payload length.
void detail_frame(const std::vector<uint8_t>& file, size_t* at, size_t* length) {
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  ASSERT_TRUE(info.detail);
  *at = file.size() - info.detail_bytes;
  *length = info.detail_bytes - kGabFrameBytes;
}

void fix_crc(std::vector<uint8_t>* file, size_t at, size_t length) {
  const uint32_t crc = crc32(file->data() + at + kGabFrameBytes, length);
  for (int b = 0; b < 4; ++b) (*file)[at + 4 + b] = static_cast<uint8_t>(crc >> (8 * b));
}

EncodeOptions detail_options(double rms) {
  EncodeOptions options;
  options.target_rms_rel = rms;
  options.detail = DetailMode::kOn;
  return options;
}

TEST(DetailLayer, DecodedShapeIsTheEncodersAndMeetsTheTarget) {
  const Mesh mesh = bumpy_torus(60, 30);
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, detail_options(1e-4), &es);
  ASSERT_TRUE(es.detail);
  EXPECT_LE(es.rms_rel, 1e-4);
  EXPECT_GT(es.rms_rel, 0.7e-4);       // the step is as coarse as the target allows
  EXPECT_GT(es.anchor_rms_rel, 1e-3);  // the anchors alone stop well above the target
  EXPECT_GT(es.detail_bytes, es.bytes / 2);
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_TRUE(ds.detail);
  EXPECT_EQ(ds.chunks, es.chunks);
  const VertexDistance d = distance(in_decoded_numbering(mesh, es), out);
  EXPECT_DOUBLE_EQ(d.rms / bounding_box_diagonal(mesh), es.rms_rel);
  EXPECT_DOUBLE_EQ(d.linf / bounding_box_diagonal(mesh), es.linf_rel);
  // A uniform quantizer of step s: at most s sqrt(3) / 2 per vertex.
  EXPECT_LE(es.linf_rel, es.detail_step_rel * std::sqrt(3.0) / 2 * (1 + 1e-9));
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  EXPECT_TRUE(info.detail);
  EXPECT_EQ(info.detail_bytes, es.detail_bytes);
  EXPECT_DOUBLE_EQ(info.detail_step / bounding_box_diagonal(mesh), es.detail_step_rel);
  EXPECT_EQ(info.chunks_present, es.chunks);
  EXPECT_EQ(info.chunk_bytes.size() + 1, static_cast<size_t>(es.chunks));  // the detail is not an anchor chunk
}

TEST(DetailLayer, LinfTargetIsMetOnEveryVertex) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeOptions options;
  options.target_linf_rel = 2e-4;
  options.detail = DetailMode::kOn;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  ASSERT_TRUE(es.detail);
  EXPECT_TRUE(es.target_met);
  DecodeStats ds;
  const VertexDistance d = distance(in_decoded_numbering(mesh, es), decode_or_die(file, DecodeOptions(), &ds));
  EXPECT_LE(d.linf / bounding_box_diagonal(mesh), 2e-4);
}

TEST(DetailLayer, TinyMeshesMeetTheTargetTheAnchorsAloneMiss) {
  // Every cube vertex an anchor still errs by the relaxed basis (w = 20:
  // about 2% of the diagonal), whatever q: the anchors alone miss 1e-3;
  // auto adds the detail layer.
  const Mesh mesh = cube();
  EncodeOptions options;
  options.target_rms_rel = 1e-3;
  options.weight = 20;
  options.detail = DetailMode::kOff;
  EncodeStats off;
  encode_or_die(mesh, options, &off);
  EXPECT_FALSE(off.target_met);
  options.detail = DetailMode::kAuto;
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, options, &es);
  EXPECT_TRUE(es.target_met);
  EXPECT_TRUE(es.detail);
  DecodeStats ds;
  const VertexDistance d = distance(in_decoded_numbering(mesh, es), decode_or_die(file, DecodeOptions(), &ds));
  EXPECT_LE(d.rms / bounding_box_diagonal(mesh), 1e-3);
}

TEST(DetailLayer, AutoKeepsTheSmallerFile) {
  // At 3e-4 the encoder codes both candidates: auto is the smaller of on and off.
  const Mesh mesh = bumpy_torus(50, 25);
  EncodeOptions options;
  options.target_rms_rel = 3e-4;
  size_t sizes[3];
  bool detail[3];
  int i = 0;
  for (DetailMode mode : {DetailMode::kOff, DetailMode::kOn, DetailMode::kAuto}) {
    options.detail = mode;
    EncodeStats es;
    sizes[i] = encode_or_die(mesh, options, &es).size();
    detail[i] = es.detail;
    EXPECT_TRUE(es.target_met);
    ++i;
  }
  EXPECT_FALSE(detail[0]);
  EXPECT_TRUE(detail[1]);
  EXPECT_EQ(sizes[2], std::min(sizes[0], sizes[1]));
  EXPECT_EQ(detail[2], sizes[1] < sizes[0]);
  // An anchor count alone never uses it.
  EncodeOptions count;
  count.max_anchors = 40;
  EncodeStats es;
  encode_or_die(mesh, count, &es);
  EXPECT_FALSE(es.detail);
}

TEST(DetailLayer, LevelsOfDetailAndTruncationShowTheAnchorsShape) {
  const Mesh mesh = bumpy_torus(40, 20);
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, detail_options(1e-4), &es);
  ASSERT_TRUE(es.detail);
  const double diagonal = bounding_box_diagonal(mesh);
  // Without the detail: the anchors' shape, whose error the encoder reported.
  DecodeOptions no_detail;
  no_detail.detail = false;
  DecodeStats ds;
  Mesh out = decode_or_die(file, no_detail, &ds);
  EXPECT_FALSE(ds.detail);
  EXPECT_NEAR(distance(in_decoded_numbering(mesh, es), out).rms / diagonal, es.anchor_rms_rel, 1e-12);
  // Fewer anchors: a coarser level, no detail.
  DecodeOptions coarser;
  coarser.max_anchors = es.anchors - 1;
  out = decode_or_die(file, coarser, &ds);
  EXPECT_FALSE(ds.detail);
  EXPECT_GT(distance(in_decoded_numbering(mesh, es), out).rms / diagonal, es.anchor_rms_rel * 0.999);
  // Cut inside the detail chunk: truncated, the anchors' shape.
  size_t at = 0, length = 0;
  detail_frame(file, &at, &length);
  for (size_t cut : {at, at + 4, at + kGabFrameBytes + length / 2, file.size() - 1}) {
    const std::vector<uint8_t> part(file.begin(), file.begin() + cut);
    out = decode_or_die(part, DecodeOptions(), &ds);
    EXPECT_TRUE(ds.truncated) << cut;
    EXPECT_FALSE(ds.detail) << cut;
    EXPECT_EQ(ds.chunks, es.chunks - 1) << cut;
    EXPECT_NEAR(distance(in_decoded_numbering(mesh, es), out).rms / diagonal, es.anchor_rms_rel, 1e-12) << cut;
  }
}

TEST(DetailLayer, DamagedOrNewerChunksAreNamedErrors) {
  const Mesh mesh = bumpy_torus(30, 15);
  EncodeStats es;
  const std::vector<uint8_t> file = encode_or_die(mesh, detail_options(1e-4), &es);
  size_t at = 0, length = 0;
  detail_frame(file, &at, &length);
  const std::string chunk = "detail (chunk " + std::to_string(es.chunks - 1) + ")";
  Mesh out;
  DecodeStats ds;
  std::vector<uint8_t> bad = file;
  bad[at + kGabFrameBytes + length / 2] ^= 0x10;
  Status s = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), chunk + " is corrupt (checksum mismatch)");
  // A newer version of the chunk, framed correctly: this build cannot read it.
  bad = file;
  bad[at + kGabFrameBytes] = static_cast<uint8_t>(kDetailVersion + 1);
  fix_crc(&bad, at, length);
  s = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.code(), StatusCode::kUnsupported);
  EXPECT_EQ(s.message(), "detail version 2 is newer than this decoder's (1)");
  GabFileInfo info;
  EXPECT_EQ(read_gab_info(bad.data(), bad.size(), &info).code(), StatusCode::kUnsupported);
  // A step out of range (here zero).
  bad = file;
  for (int b = 1; b <= 8; ++b) bad[at + kGabFrameBytes + b] = 0;
  fix_crc(&bad, at, length);
  s = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.message(), chunk + ": detail step out of range");
  EXPECT_EQ(read_gab_info(bad.data(), bad.size(), &info).message(), chunk + ": detail step out of range");
  // Residuals cut short: the stream's last bytes gone, the frame made whole.
  bad = file;
  const size_t shorter = length - 6;
  bad.resize(bad.size() - 6);
  for (int b = 0; b < 4; ++b) bad[at + b] = static_cast<uint8_t>(shorter >> (8 * b));
  fix_crc(&bad, at, shorter);
  s = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.message(), chunk + ": detail residuals are cut short");
  // Bytes after the detail chunk.
  bad = file;
  bad.push_back(0);
  EXPECT_EQ(decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds).message(),
            "trailing bytes after the last chunk");
}

TEST(DetailLayer, FilesDoNotDependOnTheThreadCount) {
  const Mesh mesh = bumpy_torus(90, 45);
  EncodeOptions options = detail_options(1e-4);
  EncodeStats one, two;
  options.threads = 1;
  const std::vector<uint8_t> a = encode_or_die(mesh, options, &one);
  options.threads = 2;
  const std::vector<uint8_t> b = encode_or_die(mesh, options, &two);
  EXPECT_EQ(a, b);
  DecodeOptions decode;
  decode.threads = 2;
  DecodeStats ds;
  const Mesh out = decode_or_die(a, decode, &ds);
  EXPECT_DOUBLE_EQ(distance(in_decoded_numbering(mesh, one), out).rms / bounding_box_diagonal(mesh), one.rms_rel);
}

}  // namespace
}  // namespace gab
