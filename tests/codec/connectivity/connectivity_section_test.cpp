// The connectivity section's version byte: a version this build does not
// know yet is kUnsupported (a newer writer, not a corrupt file), version 0
// and an empty block are corrupt.
#include "connectivity/connectivity_section.h"

#include <gtest/gtest.h>

#include <vector>

#include "common/test_meshes.h"
#include "connectivity/valence_section.h"

namespace gab {
namespace {

TEST(ConnectivitySectionTest, TheVersionByteIsChecked) {
  const Mesh torus = testing_util::torus(9, 7);
  CodedConnectivity coded;
  ASSERT_TRUE(code_connectivity(torus.num_vertices(), torus.triangles, true, &coded).ok());
  ASSERT_EQ(coded.valence[0], kValenceVersionLatest);
  GabHeader header;
  header.flags = kGabFlagVersionedValence | kGabFlagReordered;
  header.num_vertices = torus.num_vertices();
  header.num_triangles = torus.num_triangles();
  std::vector<uint8_t> block = coded.valence;
  ConnectivitySection section;
  section.block = block.data();
  section.size = block.size();
  std::vector<int32_t> triangles;
  ASSERT_TRUE(decode_connectivity_section(section, header, nullptr, &triangles).ok());
  EXPECT_EQ(triangles, coded.triangles);

  block[0] = kValenceVersionLatest + 1;
  Status s = decode_connectivity_section(section, header, nullptr, &triangles);
  EXPECT_EQ(s.code(), StatusCode::kUnsupported);
  EXPECT_EQ(s.message(), "connectivity block: valence coder version 3 is newer than this build reads");
  block[0] = 0;
  s = decode_connectivity_section(section, header, nullptr, &triangles);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), "connectivity block: valence coder version 0");
  section.size = 0;
  EXPECT_EQ(decode_connectivity_section(section, header, nullptr, &triangles).message(), "connectivity block: empty");
}

}  // namespace
}  // namespace gab
