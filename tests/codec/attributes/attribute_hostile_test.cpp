// Forged attribute sections: every byte of a section changed (its frame's
// checksum made right again, so the decoder itself meets the damage) and
// every cut decode to an error naming the section, or to valid attributes,
// never to a crash or an invalid mesh; a section whose predictor or kind
// this build does not know is skipped unless it says it is required.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "attributes/attribute_section.h"
#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "container/crc32.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::encode_or_die;

// A small torus with a per-vertex colour and per-corner texture coordinates.
std::vector<uint8_t> attributed_file(EncodeStats* stats) {
  Mesh m = bumpy_torus(12, 8);
  MeshAttribute colors;
  colors.kind = AttributeKind::kColor;
  colors.type = ValueType::kUint8;
  colors.components = 3;
  for (int32_t v = 0; v < m.num_vertices(); ++v) colors.values.insert(colors.values.end(), {double(v % 256), 7, 200});
  MeshAttribute uvs;
  uvs.kind = AttributeKind::kTexCoord;
  uvs.components = 2;
  for (int32_t t = 0; t < m.num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      uvs.corners.push_back(static_cast<int32_t>(uvs.values.size() / 2));
      uvs.values.insert(uvs.values.end(), {0.01 * t, 0.3 * k});
    }
  }
  m.attributes = {colors, uvs};
  EncodeOptions o;
  o.max_anchors = 12;
  return encode_or_die(m, o, stats);
}

// The offset of section i's frame in `file` (the sections end the file).
size_t section_offset(const std::vector<uint8_t>& file, const EncodeStats& stats, size_t i) {
  size_t offset = file.size() - stats.attribute_bytes;
  for (size_t j = 0; j < i; ++j) offset += stats.attributes[j].bytes;
  return offset;
}

// Rewrites the CRC of the frame at `offset` to match its payload.
void reseal(std::vector<uint8_t>* file, size_t offset) {
  uint32_t length = 0;
  std::memcpy(&length, file->data() + offset, 4);
  const uint32_t crc = crc32(file->data() + offset + 8, length);
  std::memcpy(file->data() + offset + 4, &crc, 4);
}

TEST(AttributeHostile, EveryChangedByteIsRefusedOrDecodesToValidAttributes) {
  EncodeStats stats;
  const std::vector<uint8_t> file = attributed_file(&stats);
  ASSERT_EQ(stats.attributes.size(), 2u);
  int refused = 0, decoded = 0;
  for (size_t s = 0; s < 2; ++s) {
    const size_t frame = section_offset(file, stats, s);
    for (size_t at = frame + 8; at < frame + stats.attributes[s].bytes; ++at) {
      for (uint8_t x : {uint8_t{0x01}, uint8_t{0x80}, uint8_t{0xFF}}) {
        std::vector<uint8_t> bad = file;
        bad[at] ^= x;
        reseal(&bad, frame);
        Mesh out;
        DecodeStats ds;
        const Status st = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
        if (st.ok()) {
          ++decoded;
          EXPECT_TRUE(validate_mesh(out, "decoded").ok());
          EXPECT_EQ(out.attributes.size() + static_cast<size_t>(ds.skipped_sections), 2u);
        } else {
          ++refused;
          EXPECT_TRUE(st.code() == StatusCode::kParseError) << st.message();
          EXPECT_EQ(st.message().rfind("section " + std::to_string(s) + ": attribute section: ", 0), 0u)
              << st.message();
        }
      }
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(decoded, 0);  // a changed value in the stream may still be a valid one
}

TEST(AttributeHostile, EveryCutKeepsTheCompleteSectionsBeforeIt) {
  EncodeStats stats;
  const std::vector<uint8_t> file = attributed_file(&stats);
  const size_t second = section_offset(file, stats, 1);
  for (size_t cut = section_offset(file, stats, 0); cut < file.size(); ++cut) {
    Mesh out;
    DecodeStats ds;
    ASSERT_TRUE(decode_mesh(file.data(), cut, DecodeOptions(), &out, &ds).ok()) << cut;
    EXPECT_TRUE(ds.truncated);
    EXPECT_EQ(out.attributes.size(), cut >= second ? 1u : 0u) << cut;
  }
}

TEST(AttributeHostile, AnUnknownPredictorIsSkippedUnlessRequired) {
  EncodeStats stats;
  std::vector<uint8_t> file = attributed_file(&stats);
  const size_t frame = section_offset(file, stats, 0);
  file[frame + 8 + 6] = 7;  // predictor byte
  reseal(&file, frame);
  Mesh out;
  DecodeStats ds;
  ASSERT_TRUE(decode_mesh(file.data(), file.size(), DecodeOptions(), &out, &ds).ok());
  EXPECT_EQ(ds.skipped_sections, 1);
  ASSERT_EQ(out.attributes.size(), 1u);
  EXPECT_EQ(out.attributes[0].kind, AttributeKind::kTexCoord);
  file[frame + 8 + 1] = kGabSectionRequired;
  reseal(&file, frame);
  const Status s = decode_mesh(file.data(), file.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.code(), StatusCode::kUnsupported);
  EXPECT_EQ(s.message(), "section 0 is of kind 1, which this build does not know and the file requires");
}

}  // namespace
}  // namespace gab
