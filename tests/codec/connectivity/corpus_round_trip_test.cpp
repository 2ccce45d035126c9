// Every mesh we can find round-trips through the connectivity section: the
// shared meshes (../shared/meshes) and libcgal-demo's data/meshes (unpacked
// by scripts/setup-and-run.sh: open, non-manifold, polygonal, tiny). With
// the order kept the decoded oriented triangles equal the input's on the
// same vertex numbers; reordered, they equal them after the traversal's
// renumbering. Skipped, saying so, when neither folder is there.
#include <dirent.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "connectivity/connectivity_section.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace {

std::vector<std::string> mesh_files(const std::string& folder) {
  std::vector<std::string> files;
  if (DIR* d = opendir(folder.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      for (const char* ext : {".off", ".obj", ".ply"}) {
        if (name.size() > 4 && name.compare(name.size() - 4, 4, ext) == 0) files.push_back(folder + "/" + name);
      }
    }
    closedir(d);
  }
  return files;
}

// Codes the mesh's connectivity and decodes it as a file's decoder would.
std::vector<int32_t> round_trip(const Mesh& mesh, bool reorder, std::vector<int32_t>* new_index) {
  CodedConnectivity coded;
  const Status s = code_connectivity(mesh.num_vertices(), mesh.triangles, reorder, &coded);
  EXPECT_TRUE(s.ok()) << s.message();
  GabHeader header;
  header.flags = reorder ? kGabFlagReordered : 0;
  header.num_vertices = mesh.num_vertices();
  header.num_triangles = mesh.num_triangles();
  ConnectivitySection section;
  section.block = coded.valence.data();
  section.size = coded.valence.size();
  section.order = coded.order.data();
  section.order_size = coded.order.size();
  std::vector<int32_t> triangles;
  const Status d = decode_connectivity_section(section, header, nullptr, &triangles);
  EXPECT_TRUE(d.ok()) << d.message();
  EXPECT_EQ(triangles, coded.triangles);  // what the encoder codes the geometry on
  *new_index = coded.new_index;
  return triangles;
}

TEST(CorpusRoundTrip, EveryMeshKeepsItsTrianglesAndNumbering) {
  std::vector<std::string> files = mesh_files(GAB_DATA_MESHES);
  const std::vector<std::string> shared = mesh_files(GAB_SHARED_MESHES);
  files.insert(files.end(), shared.begin(), shared.end());
  if (files.empty()) GTEST_SKIP() << "no meshes in " << GAB_DATA_MESHES << " or " << GAB_SHARED_MESHES;
  int tested = 0;
  for (const std::string& file : files) {
    Mesh mesh;
    if (!read_mesh(file, &mesh).ok()) continue;  // a few corpus files are not triangle meshes we read
    ++tested;
    std::vector<int32_t> new_index;
    const std::vector<int32_t> kept = round_trip(mesh, false, &new_index);
    EXPECT_EQ(oriented_triangle_set(kept), oriented_triangle_set(mesh.triangles)) << file;
    const std::vector<int32_t> reordered = round_trip(mesh, true, &new_index);
    ASSERT_EQ(new_index.size(), static_cast<size_t>(mesh.num_vertices())) << file;
    std::vector<int32_t> renamed(mesh.triangles.size());
    for (size_t i = 0; i < renamed.size(); ++i) renamed[i] = new_index[mesh.triangles[i]];
    EXPECT_EQ(oriented_triangle_set(reordered), oriented_triangle_set(renamed)) << file;
    if (HasFailure()) return;
  }
  EXPECT_GT(tested, 0);
  std::printf("%d meshes round-tripped\n", tested);
}

}  // namespace
}  // namespace gab
