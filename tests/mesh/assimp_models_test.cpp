// Debian's assimp-testmodels (/usr/share/assimp/models), when installed:
// every OBJ, PLY and OFF file there reads as before or with the same error,
// its normals, texture coordinates and colours are carried (and then not
// named as dropped), and they survive a write -> read through each format.
#include <dirent.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/obj_io.h"
#include "gab/mesh/off_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

const std::string kModels = "/usr/share/assimp/models";

bool installed() { return testing_util::exists(kModels + "/OBJ/spider.obj"); }

#define SKIP_UNLESS_INSTALLED()                                                                        \
  if (!installed()) {                                                                                  \
    GTEST_SKIP() << "assimp-testmodels is not installed (" << kModels << "/OBJ/spider.obj)";           \
  }

// The mesh files of the OBJ, PLY and OFF folders, as "FOLDER/NAME".
std::vector<std::string> model_files() {
  std::vector<std::string> out;
  for (const char* folder : {"OBJ", "PLY", "OFF"}) {
    DIR* d = opendir((kModels + "/" + folder).c_str());
    if (d == nullptr) continue;
    while (dirent* e = readdir(d)) {
      std::string name = e->d_name;
      const size_t dot = name.find_last_of('.');
      if (dot == std::string::npos) continue;
      std::string ext = name.substr(dot + 1);
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (ext == "obj" || ext == "ply" || ext == "off") out.push_back(std::string(folder) + "/" + name);
    }
    closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The files gab refused before it read attributes, with the same messages
// (after the path); every other file reads.
const std::map<std::string, std::string>& refused() {
  static const std::map<std::string, std::string> files = {
      {"OBJ/box_UTF16BE.obj", ": not an OBJ file (it looks like binary data)"},
      {"OBJ/number_formats.obj", ":11: vertex 7: bad coordinate '3.1+e2'"},
      {"OBJ/point_cloud.obj", ": mesh has no faces"},
      {"OBJ/testline.obj", ": mesh has no faces"},
      {"OBJ/testpoints.obj", ": mesh has no faces"},
      {"PLY/issue623.ply", ": no 'face' or 'tristrips' element (mesh has no faces)"},
      {"PLY/points.ply", ": no 'face' or 'tristrips' element (mesh has no faces)"},
      {"PLY/pond.0.ply", ": no 'face' or 'tristrips' element (mesh has no faces)"},
      {"OFF/invalid.off", ":3: bad count '0.1' in header"},
  };
  return files;
}

const MeshAttribute* first(const Mesh& m, AttributeKind kind) {
  for (const MeshAttribute& a : m.attributes) {
    if (a.kind == kind) return &a;
  }
  return nullptr;
}

const char* kind_key(AttributeKind kind) {
  return kind == AttributeKind::kNormal ? "normals" : kind == AttributeKind::kTexCoord ? "texture_coordinates" : "vertex_colors";
}

TEST(AssimpModelsTest, EveryFileReadsOrFailsAsBeforeAndCarriedDataIsNotNamed) {
  SKIP_UNLESS_INSTALLED();
  int read = 0;
  for (const std::string& file : model_files()) {
    const std::string path = kModels + "/" + file;
    Mesh m;
    MeshReadNotes notes;
    const Status s = read_mesh(path, &m, &notes);
    const auto it = refused().find(file);
    if (it != refused().end()) {
      EXPECT_EQ(s.message(), path + it->second);
      continue;
    }
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_TRUE(validate_mesh(m, path).ok()) << file;
    // A kind the notes name is one the mesh does not carry.
    for (const DroppedData& d : notes.dropped) {
      for (AttributeKind kind : {AttributeKind::kNormal, AttributeKind::kTexCoord, AttributeKind::kColor}) {
        if (d.key == kind_key(kind)) {
          EXPECT_EQ(first(m, kind), nullptr) << file << " names " << d.label;
        }
      }
    }
    ++read;
  }
  EXPECT_GE(read, 20);
}

TEST(AssimpModelsTest, NamedModelsComeOutWithTheirAttributes) {
  SKIP_UNLESS_INSTALLED();
  struct Expected {
    const char* file;
    int32_t vertices;
    AttributeKind kind;
    bool per_corner;
    int64_t elements;
    int32_t components;
  };
  const Expected cases[] = {
      {"OBJ/spider.obj", 762, AttributeKind::kTexCoord, true, 302, 2},
      {"OBJ/spider.obj", 762, AttributeKind::kNormal, true, 747, 3},
      {"OBJ/WusonOBJ.obj", 2117, AttributeKind::kNormal, true, 2076, 3},
      // 688 vt (u v w), and one element of zeros for the 2,042 faces without vt.
      {"OBJ/regr01.obj", 2108, AttributeKind::kTexCoord, true, 688 + 1, 3},
      {"PLY/Wuson.ply", 11184, AttributeKind::kNormal, false, 11184, 3},
      {"PLY/Wuson.ply", 11184, AttributeKind::kTexCoord, false, 11184, 2},
      {"PLY/float-color.ply", 3, AttributeKind::kColor, false, 3, 4},
      {"OBJ/cube_with_vertexcolors.obj", 8, AttributeKind::kColor, false, 8, 3},
  };
  for (const Expected& c : cases) {
    Mesh m;
    MeshReadNotes notes;
    ASSERT_TRUE(read_mesh(kModels + "/" + c.file, &m, &notes).ok()) << c.file;
    EXPECT_EQ(m.num_vertices(), c.vertices) << c.file;
    const MeshAttribute* a = first(m, c.kind);
    ASSERT_NE(a, nullptr) << c.file << ": no " << kind_key(c.kind);
    EXPECT_EQ(a->per_corner(), c.per_corner) << c.file;
    EXPECT_EQ(a->num_elements(), c.elements) << c.file;
    EXPECT_EQ(a->components, c.components) << c.file;
  }
  Mesh regr01;
  MeshReadNotes notes;
  const std::string regr01_path = kModels + "/OBJ/regr01.obj";
  ASSERT_TRUE(read_mesh(regr01_path, &regr01, &notes).ok());
  ASSERT_EQ(notes.warnings.size(), 1u);
  EXPECT_EQ(notes.warnings[0], regr01_path + ":83: 2042 faces have no vt index; their corners refer to texture "
                                             "coordinate 689 (all zeros), added after the file's 688");
}

// A corner's value of `a` (its first `k` components), as a fraction for
// integer-typed colours (OBJ and OFF write them so).
std::vector<double> corner_value(const Mesh& m, const MeshAttribute& a, size_t corner, size_t k) {
  const size_t e = static_cast<size_t>(a.per_corner() ? a.corners[corner] : m.triangles[corner]);
  std::vector<double> out(a.values.begin() + static_cast<std::ptrdiff_t>(a.components * e),
                          a.values.begin() + static_cast<std::ptrdiff_t>(a.components * e + k));
  if (a.kind == AttributeKind::kColor && is_integer_type(a.type)) {
    for (double& x : out) x /= 255.0;
  }
  return out;
}

// `back`, read from `mesh` written in another format, has the same corners:
// positions, and the values of the normals, texture coordinates (u v) and
// colours (r g b) at each, within float rounding.
void expect_same_corners(const Mesh& mesh, const Mesh& back, const std::string& what) {
  ASSERT_EQ(back.triangles.size(), mesh.triangles.size()) << what;
  for (size_t c = 0; c < mesh.triangles.size(); ++c) {
    for (int i = 0; i < 3; ++i) {
      const double x = mesh.positions[3 * static_cast<size_t>(mesh.triangles[c]) + i];
      ASSERT_NEAR(back.positions[3 * static_cast<size_t>(back.triangles[c]) + i], x, 1e-14 * std::fabs(x)) << what;
    }
  }
  for (AttributeKind kind : {AttributeKind::kNormal, AttributeKind::kTexCoord, AttributeKind::kColor}) {
    const MeshAttribute* a = first(mesh, kind);
    if (a == nullptr) continue;
    const MeshAttribute* b = first(back, kind);
    ASSERT_NE(b, nullptr) << what << ": " << kind_key(kind) << " lost";
    const size_t k = kind == AttributeKind::kNormal ? 3 : kind == AttributeKind::kTexCoord ? 2 : 3;
    for (size_t c = 0; c < mesh.triangles.size(); ++c) {
      const std::vector<double> x = corner_value(mesh, *a, c, k), y = corner_value(back, *b, c, k);
      for (size_t i = 0; i < k; ++i) ASSERT_NEAR(y[i], x[i], 1e-6 * (1 + std::fabs(x[i]))) << what << " corner " << c;
    }
  }
}

TEST(AssimpModelsTest, AttributesSurviveEveryFormat) {
  SKIP_UNLESS_INSTALLED();
  int checked = 0;
  for (const std::string& file : model_files()) {
    if (refused().count(file) != 0) continue;
    Mesh m;
    ASSERT_TRUE(read_mesh(kModels + "/" + file, &m).ok()) << file;
    const std::string ext = file.substr(file.size() - 3);
    for (MeshFormat format : {MeshFormat::kObj, MeshFormat::kPly, MeshFormat::kOff}) {
      std::string bytes;
      MeshWriteNotes notes;
      switch (format) {
        case MeshFormat::kObj: bytes = format_obj(m, &notes); break;
        case MeshFormat::kOff: bytes = format_off(m, &notes); break;
        case MeshFormat::kPly: bytes = format_ply(m, PlyWriteOptions(), &notes); break;
      }
      const std::string what = file + " as " + (format == MeshFormat::kObj ? "OBJ" : format == MeshFormat::kPly ? "PLY" : "OFF");
      // What a format cannot hold is named: regr01's w in OFF, float-color's alpha in OBJ.
      const std::map<std::string, std::string> not_written = {
          {"OBJ/regr01.obj as OFF", "689 texture coordinate w values (OFF holds s t)"},
          {"PLY/float-color.ply as OBJ", "3 colour alpha values (OBJ holds r g b)"}};
      const auto named = not_written.find(what);
      EXPECT_EQ(notes.not_written_summary(), named == not_written.end() ? "" : named->second) << what;
      Mesh back;
      const Status s = parse_mesh(bytes, format, what, &back);
      ASSERT_TRUE(s.ok()) << s.message();
      expect_same_corners(m, back, what);
      // In its own format, every attribute comes back exactly (split at
      // its seams where the format holds one value per vertex).
      const bool same_format = (format == MeshFormat::kObj && (ext == "obj" || ext == "OBJ")) ||
                               (format == MeshFormat::kPly && (ext == "ply" || ext == "PLY")) ||
                               (format == MeshFormat::kOff && (ext == "off" || ext == "OFF"));
      if (same_format) {
        const Mesh expected = format == MeshFormat::kObj ? m : split_attribute_seams(m);
        EXPECT_TRUE(testing_util::same_attributes(back, expected)) << what;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 60);
}

// The vertices PLY and OFF add at spider's seams: one per distinct (v, vt,
// vn) of its corners, less the vertices the faces use.
TEST(AssimpModelsTest, SpidersSeamsAreSplitForPlyAndOff) {
  SKIP_UNLESS_INSTALLED();
  Mesh m;
  ASSERT_TRUE(read_mesh(kModels + "/OBJ/spider.obj", &m).ok());
  ASSERT_EQ(m.attributes.size(), 2u);
  std::set<std::tuple<int32_t, int32_t, int32_t>> combinations;
  std::set<int32_t> used;
  for (size_t c = 0; c < m.triangles.size(); ++c) {
    combinations.insert({m.triangles[c], m.attributes[0].corners[c], m.attributes[1].corners[c]});
    used.insert(m.triangles[c]);
  }
  const int64_t expected = static_cast<int64_t>(combinations.size() - used.size());
  EXPECT_GT(expected, 0);
  MeshWriteNotes ply_notes, off_notes;
  const std::string ply = format_ply(m, PlyWriteOptions(), &ply_notes);
  format_off(m, &off_notes);
  EXPECT_EQ(ply_notes.split_vertices, expected);
  EXPECT_EQ(off_notes.split_vertices, expected);
  Mesh back;
  ASSERT_TRUE(parse_mesh(ply, MeshFormat::kPly, "spider.ply", &back).ok());
  EXPECT_EQ(back.num_vertices(), m.num_vertices() + expected);
}

}  // namespace
}  // namespace gab
