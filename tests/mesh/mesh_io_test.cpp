// The format-dispatching entry points, atomic writes, and the real meshes.
#include "gab/mesh/mesh_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "gab/mesh/file_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

using testing_util::exists;
using testing_util::temp_path;

std::string base_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

TEST(MeshIoTest, WriteThenReadEveryFormatByExtension) {
  const Mesh m = testing_util::torus(9, 6);
  for (const char* ext : {".off", ".OBJ", ".ply", ".Ply"}) {
    const std::string path = temp_path(std::string("torus") + ext);
    ASSERT_TRUE(write_mesh(path, m).ok()) << ext;
    Mesh back;
    const Status s = read_mesh(path, &back);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(back.triangles, m.triangles) << ext;
    ASSERT_EQ(back.positions.size(), m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
      EXPECT_NEAR(back.positions[i], m.positions[i], 1e-15) << ext;  // OBJ: tinyobjloader's rounding
    }
    EXPECT_TRUE(gab_test::scratch_entries(base_name(path) + ".gab-partial").empty()) << "temporary file left behind";
    std::remove(path.c_str());
  }
}

TEST(MeshIoTest, PlyOptionsPassThrough) {
  const Mesh m = testing_util::grid(2, 2);
  PlyWriteOptions o;
  o.encoding = PlyEncoding::kBinaryBigEndian;
  const std::string path = temp_path("grid.ply");
  ASSERT_TRUE(write_mesh(path, m, o).ok());
  std::string bytes;
  ASSERT_TRUE(read_file(path, &bytes).ok());
  EXPECT_NE(bytes.find("format binary_big_endian 1.0\n"), std::string::npos);
  Mesh back;
  ASSERT_TRUE(read_mesh(path, &back).ok());
  EXPECT_EQ(back.positions, m.positions);
  std::remove(path.c_str());
}

TEST(MeshIoTest, AtomicWriteReplacesWholeOrNothing) {
  const std::string path = temp_path("replace.off");
  gab_test::write_file(path, "old contents");
  ASSERT_TRUE(write_mesh(path, testing_util::grid(1, 1)).ok());
  Mesh back;
  ASSERT_TRUE(read_mesh(path, &back).ok());
  EXPECT_EQ(back.num_triangles(), 2);

  // Failures: nothing is created, an existing target is untouched, no
  // temporary is left.
  const std::string missing_dir = gab_test::scratch_path("no_such_dir/a.off");
  Status s = write_mesh(missing_dir, back);
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_EQ(s.message(), missing_dir + ": cannot write: No such file or directory");

  const std::string dir = temp_path("target_is_a_dir.ply");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  s = write_mesh(dir, back);
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_EQ(s.message(), dir + ": cannot write: Is a directory");
  EXPECT_TRUE(gab_test::scratch_entries(base_name(dir) + ".gab-partial").empty());
  ::rmdir(dir.c_str());

  Mesh invalid = back;
  invalid.positions[4] = std::nan("");
  s = write_mesh(path, invalid);
  EXPECT_EQ(s.message(), path + ": vertex 1: coordinate is not finite");
  ASSERT_TRUE(read_mesh(path, &back).ok()) << "the previous file must survive a refused write";
  EXPECT_EQ(back.num_triangles(), 2);
  std::remove(path.c_str());
}

TEST(MeshIoTest, LegalOddMeshesRoundTrip) {
  // Isolated vertex, degenerate and duplicate faces, a non-manifold edge
  // (0-1 shared by three triangles), two components, a boundary.
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 7, 7, 7, 5, 5, 5, 6, 5, 5, 5, 6, 5};
  m.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4, 0, 1, 2, 2, 2, 3, 6, 7, 8};
  for (const char* ext : {".off", ".obj", ".ply"}) {
    const std::string path = temp_path(std::string("odd") + ext);
    ASSERT_TRUE(write_mesh(path, m).ok());
    Mesh back;
    ASSERT_TRUE(read_mesh(path, &back).ok());
    EXPECT_EQ(back.triangles, m.triangles) << ext;
    EXPECT_EQ(back.positions, m.positions) << ext;
    std::remove(path.c_str());
  }
}

// write_mesh passes the format's notes: what it could not hold, and the
// vertices split where per-corner data has seams (PLY and OFF; OBJ keeps
// texture coordinates per corner).
TEST(MeshIoTest, WriteMeshReportsWhatTheFormatCannotHold) {
  Mesh m = testing_util::grid(1, 1);  // triangles (0 1 3) (0 3 2)
  MeshAttribute uv;
  uv.kind = AttributeKind::kTexCoord;
  uv.components = 2;
  uv.values = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
  uv.corners = {0, 1, 2, 4, 2, 3};  // vertex 0 on a seam
  MeshAttribute quality;
  quality.kind = AttributeKind::kGeneric;
  quality.name = "quality";
  quality.values = {1, 2, 3, 4};
  m.attributes = {uv, quality};
  const struct {
    const char* ext;
    const char* not_written;
    int64_t split;
  } cases[] = {{".obj", "4 generic attribute 'quality' (OBJ has no place for it)", 0},
               {".off", "4 generic attribute 'quality' (OFF has no place for it)", 1},
               {".ply", "", 1}};
  for (const auto& c : cases) {
    const std::string path = temp_path(std::string("notes") + c.ext);
    MeshWriteNotes notes;
    notes.split_vertices = 99;  // replaced
    ASSERT_TRUE(write_mesh(path, m, PlyWriteOptions(), &notes).ok()) << c.ext;
    EXPECT_EQ(notes.not_written_summary(), c.not_written) << c.ext;
    EXPECT_EQ(notes.split_vertices, c.split) << c.ext;
    Mesh back;
    ASSERT_TRUE(read_mesh(path, &back).ok()) << c.ext;
    EXPECT_EQ(back.num_vertices(), 4 + c.split) << c.ext;
    ASSERT_FALSE(back.attributes.empty()) << c.ext;
    EXPECT_EQ(back.attributes[0].kind, AttributeKind::kTexCoord) << c.ext;
    std::remove(path.c_str());
  }
}

struct SharedMesh {
  const char* name;
  int32_t vertices;
  int32_t faces;
};

class SharedMeshTest : public ::testing::TestWithParam<SharedMesh> {};

TEST_P(SharedMeshTest, ReadsWithTheCountsOfTheReadme) {
  const SharedMesh& c = GetParam();
  const std::string path = testing_util::shared_mesh(c.name);
  if (!exists(path)) GTEST_SKIP() << path << " not present (shared meshes are outside the repository)";
  Mesh m;
  const Status s = read_mesh(path, &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.num_vertices(), c.vertices);
  EXPECT_EQ(m.num_triangles(), c.faces);
  EXPECT_TRUE(validate_mesh(m, path).ok());
}

INSTANTIATE_TEST_SUITE_P(Readme, SharedMeshTest,
                         ::testing::Values(SharedMesh{"igea.off", 134345, 268686},
                                           SharedMesh{"nefertiti.off", 49971, 99938},
                                           SharedMesh{"feline.off", 49864, 99732},
                                           SharedMesh{"horse.off", 48485, 96966},
                                           SharedMesh{"bunny.off", 34834, 69451},
                                           SharedMesh{"max-planck.off", 25445, 50801},
                                           SharedMesh{"camel-head.off", 11381, 22704},
                                           SharedMesh{"bunny-small.off", 3485, 6966}),
                         [](const ::testing::TestParamInfo<SharedMesh>& info) {
                           std::string n = info.param.name;
                           n = n.substr(0, n.find('.'));
                           for (char& ch : n) ch = ch == '-' ? '_' : ch;
                           return n;
                         });

TEST(MeshIoTest, SharedBunnyThroughEveryFormat) {
  const std::string path = testing_util::shared_mesh("bunny.off");
  if (!exists(path)) GTEST_SKIP() << path << " not present";
  Mesh m;
  ASSERT_TRUE(read_mesh(path, &m).ok());
  PlyWriteOptions ascii;
  ascii.encoding = PlyEncoding::kAscii;
  for (const char* ext : {".obj", ".ply", ".off"}) {
    for (const PlyWriteOptions& o : {PlyWriteOptions(), ascii}) {
      const std::string out = temp_path(std::string("bunny") + ext);
      ASSERT_TRUE(write_mesh(out, m, o).ok());
      Mesh back;
      ASSERT_TRUE(read_mesh(out, &back).ok());
      EXPECT_EQ(back.triangles, m.triangles);
      if (std::string(ext) != ".obj") {
        EXPECT_EQ(back.positions, m.positions);
      }
      std::remove(out.c_str());
    }
  }
}

}  // namespace
}  // namespace gab
