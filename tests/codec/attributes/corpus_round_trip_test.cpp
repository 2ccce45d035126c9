// Every attribute of every mesh file of Debian's assimp-testmodels (OBJ, PLY
// and OFF folders) that gab reads comes back from compress and decompress
// within its quantization: normals within the lattice's reach of their
// direction, integer-typed values exactly, the rest within half a grid step
// of their span. Skipped, with a message, when the package is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "codec/attributes/attribute_checks.h"
#include "common/gab_files.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/mesh_io.h"

namespace gab {
namespace {

const std::string kModels = "/usr/share/assimp/models";

std::vector<std::string> corpus() {
  std::vector<std::string> files;
  for (const char* folder : {"OBJ", "PLY", "OFF"}) {
    std::error_code e;
    for (const auto& entry : std::filesystem::directory_iterator(kModels + "/" + folder, e)) {
      MeshFormat format;
      if (entry.is_regular_file() && mesh_format_from_path(entry.path().string(), &format).ok()) {
        files.push_back(entry.path().string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Half a grid step of the attribute's largest component span at `bits`.
double half_step(const MeshAttribute& a, int bits) {
  const size_t k = static_cast<size_t>(a.components);
  double span = 0;
  for (size_t c = 0; c < k; ++c) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = c; i < a.values.size(); i += k) {
      lo = std::min(lo, a.values[i]);
      hi = std::max(hi, a.values[i]);
    }
    span = std::max(span, hi - lo);
  }
  return 0.5 * span / (std::ldexp(1.0, bits) - 1);
}

TEST(AttributeCorpus, EveryAttributeOfAssimpsModelsSurvivesWithinItsQuantization) {
  if (!std::filesystem::exists(kModels + "/OBJ/spider.obj")) {
    GTEST_SKIP() << "assimp-testmodels is not installed (" << kModels << "/OBJ/spider.obj)";
  }
  int files = 0, attributes = 0;
  for (const std::string& path : corpus()) {
    SCOPED_TRACE(path);
    Mesh mesh;
    if (!read_mesh(path, &mesh).ok()) continue;  // the readers' own tests pin what they refuse
    ++files;
    EncodeOptions o;
    o.target_rms_rel = 1e-3;
    EncodeStats stats;
    std::vector<uint8_t> file;
    ASSERT_TRUE(encode_mesh(mesh, o, &file, &stats).ok());
    ASSERT_EQ(stats.attributes.size(), mesh.attributes.size());
    Mesh out;
    DecodeStats ds;
    ASSERT_TRUE(decode_mesh(file.data(), file.size(), DecodeOptions(), &out, &ds).ok());
    ASSERT_EQ(out.attributes.size(), mesh.attributes.size());
    for (size_t i = 0; i < mesh.attributes.size(); ++i) {
      const MeshAttribute& a = mesh.attributes[i];
      SCOPED_TRACE(attribute_label(a));
      ++attributes;
      EXPECT_EQ(out.attributes[i].kind, a.kind);
      EXPECT_EQ(out.attributes[i].type, a.type);
      EXPECT_EQ(out.attributes[i].name, a.name);
      const double error = testing_util::largest_attribute_error(mesh, out, stats.new_index, i);
      EXPECT_LE(error, stats.attributes[i].max_error + 1e-9);
      if (a.kind == AttributeKind::kNormal) {
        EXPECT_LE(stats.attributes[i].max_error, 0.65);
      } else if (is_integer_type(a.type)) {
        EXPECT_EQ(error, 0.0);
      } else {
        EXPECT_LE(error, half_step(a, stats.attributes[i].bits) * (1 + 1e-9) + 1e-12);
      }
    }
  }
  EXPECT_GE(files, 20);
  EXPECT_GE(attributes, 10);
}

}  // namespace
}  // namespace gab
