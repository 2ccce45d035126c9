// Replays the fuzzers' seed corpora (tests/fuzz/corpus/<reader>/) and any
// input that once broke a reader (tests/fuzz/regressions/, file name
// <reader>-<what>) through the readers with the fuzzers' own checks: no
// crash, a message naming the file on failure, a valid mesh on success that
// survives a write -> read round trip, attributes and all.
#include <dirent.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/obj_io.h"
#include "gab/mesh/off_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

const std::string kFuzzDir = GAB_FUZZ_DIR;

std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> out;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      if (e->d_name[0] != '.') out.push_back(dir + "/" + e->d_name);
    }
    closedir(d);
  }
  return out;
}

void replay(const std::string& path, MeshFormat format) {
  std::string bytes;
  ASSERT_TRUE(read_file(path, &bytes).ok()) << path;
  const std::string name = "replay";
  Mesh mesh;
  const Status s = parse_mesh(bytes, format, name, &mesh);
  if (!s.ok()) {
    EXPECT_EQ(s.message().rfind(name, 0), 0u) << path << ": " << s.message();
    return;
  }
  ASSERT_TRUE(validate_mesh(mesh, name).ok()) << path;
  std::string again;
  switch (format) {
    case MeshFormat::kOff: again = format_off(mesh); break;
    case MeshFormat::kObj: again = format_obj(mesh); break;
    case MeshFormat::kPly: again = format_ply(mesh); break;
  }
  Mesh back;
  ASSERT_TRUE(parse_mesh(again, format, name, &back).ok()) << path;
  // PLY and OFF hold attributes per vertex: per-corner ones come back split.
  const Mesh expected = format == MeshFormat::kObj ? mesh : split_attribute_seams(mesh);
  EXPECT_EQ(back.triangles, expected.triangles) << path;
  ASSERT_EQ(back.positions.size(), expected.positions.size());
  for (size_t i = 0; i < expected.positions.size(); ++i) {
    EXPECT_NEAR(back.positions[i], expected.positions[i], 1e-14 * std::fabs(expected.positions[i])) << path;
  }
  EXPECT_TRUE(testing_util::same_attributes(back, expected)) << path;
}

TEST(FuzzRegressionTest, SeedCorporaAndPastFindingsReplayCleanly) {
  int replayed = 0;
  const struct {
    const char* reader;
    MeshFormat format;
  } readers[] = {{"off", MeshFormat::kOff}, {"ply", MeshFormat::kPly}, {"obj", MeshFormat::kObj}};
  for (const auto& r : readers) {
    for (const std::string& path : files_in(kFuzzDir + "/corpus/" + r.reader)) {
      replay(path, r.format);
      ++replayed;
    }
    for (const std::string& path : files_in(kFuzzDir + "/regressions")) {
      if (path.find(std::string("/") + r.reader + "-") == std::string::npos) continue;
      replay(path, r.format);
      ++replayed;
    }
  }
  if (replayed == 0) GTEST_SKIP() << "no corpus under " << kFuzzDir;
  EXPECT_GE(replayed, 10);
}

}  // namespace
}  // namespace gab
