// Inputs that once broke the connectivity fuzzer (tests/fuzz/regressions/
// connectivity-*), replayed in every ordinary test run: each must decode to
// an error naming the problem. connectivity-negative-list-length: a stream
// of the first valence coder whose CLOSE_NEXT ran the active list below two
// vertices, after which the split offsets' unsigned checks let walks of a
// billion steps through (seconds per input, a fuzzer timeout); read by
// today's coder it is garbage that must still fail cleanly.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fuzz/connectivity_fuzz_input.h"
#include "gab/mesh/file_io.h"

namespace gab {
namespace {

const std::string kRegressions = std::string(GAB_FUZZ_DIR) + "/regressions";

TEST(ConnectivityFuzzRegression, EachIsAnErrorNamingTheProblem) {
  const struct {
    const char* name;
    const char* message;
  } cases[] = {
      {"connectivity-negative-list-length", "connectivity block: connectivity: stitch count out of range"},
  };
  for (const auto& c : cases) {
    std::string bytes;
    ASSERT_TRUE(read_file(kRegressions + "/" + c.name, &bytes).ok()) << c.name;
    const std::vector<uint8_t> data(bytes.begin(), bytes.end());
    GabHeader header;
    ConnectivitySection section;
    ASSERT_TRUE(gab_fuzz::parse_connectivity_input(data.data(), data.size(), &header, &section)) << c.name;
    std::vector<int32_t> triangles;
    const Status s = decode_connectivity_section(section, header, nullptr, &triangles);
    EXPECT_EQ(s.code(), StatusCode::kParseError) << c.name;
    EXPECT_EQ(s.message(), c.message) << c.name;
  }
}

}  // namespace
}  // namespace gab
