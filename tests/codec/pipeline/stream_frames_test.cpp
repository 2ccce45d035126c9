// find_gab_chunk_ends: where a file that is still arriving can be cut, as
// the browser viewer asks after every block of bytes.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "gab/codec/decoder.h"

namespace gab {
namespace {

using testing_util::decode_or_die;
using testing_util::encode_or_die;

std::vector<uint8_t> several_chunk_file() {
  EncodeOptions options;
  options.max_anchors = 120;
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_or_die(testing_util::bumpy_torus(24, 16), options, &stats);
  EXPECT_GE(stats.chunk_anchors.size(), 3u);
  return file;
}

TEST(StreamFrames, EveryPrefixCutsAtTheChunksThatArrivedWhole) {
  const std::vector<uint8_t> file = several_chunk_file();
  GabStreamFrames whole;
  ASSERT_TRUE(find_gab_chunk_ends(file.data(), file.size(), &whole).ok());
  ASSERT_TRUE(whole.head_complete);
  ASSERT_EQ(static_cast<int32_t>(whole.chunk_ends.size()), whole.chunks_in_file);
  EXPECT_EQ(whole.chunk_ends.back(), file.size());
  for (size_t size = 0; size <= file.size(); ++size) {
    GabStreamFrames part;
    ASSERT_TRUE(find_gab_chunk_ends(file.data(), size, &part).ok()) << size;
    // Exactly the whole file's ends that fit in the prefix.
    std::vector<size_t> expected;
    for (size_t end : whole.chunk_ends) {
      if (end <= size) expected.push_back(end);
    }
    EXPECT_EQ(part.chunk_ends, expected) << size;
    if (!part.head_complete) {
      EXPECT_TRUE(part.chunk_ends.empty()) << size;
    }
  }
  // Before the first chunk's end the head may or may not be complete; the
  // first chunk cannot end before it is.
  GabStreamFrames first;
  ASSERT_TRUE(find_gab_chunk_ends(file.data(), whole.chunk_ends[0], &first).ok());
  EXPECT_TRUE(first.head_complete);
}

TEST(StreamFrames, EachCutDecodesToACoarserShape) {
  const std::vector<uint8_t> file = several_chunk_file();
  GabStreamFrames frames;
  ASSERT_TRUE(find_gab_chunk_ends(file.data(), file.size(), &frames).ok());
  int32_t previous = 0;
  for (size_t k = 0; k + 1 < frames.chunk_ends.size(); ++k) {
    const std::vector<uint8_t> prefix(file.begin(), file.begin() + static_cast<std::ptrdiff_t>(frames.chunk_ends[k]));
    DecodeStats stats;
    decode_or_die(prefix, DecodeOptions(), &stats);
    EXPECT_EQ(stats.chunks, static_cast<int32_t>(k) + 1);
    EXPECT_GT(stats.anchors, previous);
    previous = stats.anchors;
  }
}

TEST(StreamFrames, ABadHeaderIsAnError) {
  std::vector<uint8_t> file = several_chunk_file();
  file[0] ^= 0xFF;  // the magic
  GabStreamFrames frames;
  EXPECT_FALSE(find_gab_chunk_ends(file.data(), file.size(), &frames).ok());
}

}  // namespace
}  // namespace gab
