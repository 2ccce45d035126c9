// The connectivity section: what the encoder codes is what the section
// decodes (numbered as the input, or in traversal order when reordered),
// and a damaged order block is an error naming it.
#include "connectivity/connectivity_section.h"

#include <gtest/gtest.h>

#include <vector>

#include "common/test_meshes.h"
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace {

Status decode(const CodedConnectivity& coded, const Mesh& mesh, bool reordered, std::vector<int32_t>* triangles) {
  GabHeader header;
  header.flags = reordered ? kGabFlagReordered : 0;
  header.num_vertices = mesh.num_vertices();
  header.num_triangles = mesh.num_triangles();
  ConnectivitySection section;
  section.block = coded.valence.data();
  section.size = coded.valence.size();
  section.order = coded.order.data();
  section.order_size = coded.order.size();
  return decode_connectivity_section(section, header, nullptr, triangles);
}

TEST(ConnectivitySectionTest, DecodesWhatWasCodedInEitherNumbering) {
  const Mesh torus = testing_util::torus(9, 7);
  for (bool reorder : {false, true}) {
    CodedConnectivity coded;
    ASSERT_TRUE(code_connectivity(torus.num_vertices(), torus.triangles, reorder, &coded).ok());
    EXPECT_EQ(coded.order.empty(), reorder);
    std::vector<int32_t> triangles;
    const Status s = decode(coded, torus, reorder, &triangles);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(triangles, coded.triangles);
    if (!reorder) {
      EXPECT_EQ(oriented_triangle_set(triangles), oriented_triangle_set(torus.triangles));
    }
  }
}

TEST(ConnectivitySectionTest, ADamagedBlockIsAnError) {
  const Mesh torus = testing_util::torus(9, 7);
  CodedConnectivity coded;
  ASSERT_TRUE(code_connectivity(torus.num_vertices(), torus.triangles, false, &coded).ok());
  std::vector<int32_t> triangles;
  CodedConnectivity cut = coded;
  cut.order.resize(cut.order.size() / 2);
  Status s = decode(cut, torus, false, &triangles);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  cut = coded;
  cut.valence.clear();
  s = decode(cut, torus, false, &triangles);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message().rfind("connectivity block: ", 0), 0u) << s.message();
}

}  // namespace
}  // namespace gab
