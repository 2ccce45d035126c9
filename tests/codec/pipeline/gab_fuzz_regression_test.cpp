// Inputs that once broke the .gab fuzzer (tests/fuzz/regressions/gab-*,
// stored as the decoder reads them: the fuzzer's options byte dropped and
// the checksums rewritten by reseal_gab.py), replayed in every ordinary test
// run: each must fail with the message naming the problem.
// gab-grid-past-the-weight: a torus file whose grid origin's z became
// -4.7e307, finite, so w^2 times a coordinate overflowed and the decode
// "succeeded" with non-finite coordinates.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gab/codec/decoder.h"
#include "gab/mesh/file_io.h"

namespace gab {
namespace {

const std::string kRegressions = std::string(GAB_FUZZ_DIR) + "/regressions";

TEST(GabFuzzRegression, EachIsAnErrorNamingTheProblem) {
  const struct {
    const char* name;
    const char* message;
  } cases[] = {
      {"gab-grid-past-the-weight", "bad .gab header: the grid reaches past 2e100"},
  };
  for (const auto& c : cases) {
    std::string bytes;
    ASSERT_TRUE(read_file(kRegressions + "/" + c.name, &bytes).ok()) << c.name;
    const std::vector<uint8_t> data(bytes.begin(), bytes.end());
    Mesh mesh;
    DecodeStats stats;
    const Status s = decode_mesh(data.data(), data.size(), DecodeOptions(), &mesh, &stats);
    EXPECT_EQ(s.code(), StatusCode::kParseError) << c.name;
    EXPECT_EQ(s.message(), c.message) << c.name;
  }
}

}  // namespace
}  // namespace gab
