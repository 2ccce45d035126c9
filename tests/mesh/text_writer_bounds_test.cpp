// The writers reserve their output with kMaxRealChars / kMaxIndexChars
// (text_scanner.h); a bound that is too small only costs a regrowth, but one
// that is not a bound at all is a silent lie, so check it on the longest
// numbers there are.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "text_scanner.h"

namespace gab {
namespace {

size_t real_chars(double x) {
  std::string s;
  mesh_detail::append_real(&s, x);
  return s.size();
}

TEST(TextWriterBounds, NoDoubleNeedsMoreThanKMaxRealChars) {
  using limits = std::numeric_limits<double>;
  // 17 significant digits, a sign and a three-digit negative exponent: 24.
  EXPECT_EQ(real_chars(-1.2345678901234567e-300), mesh_detail::kMaxRealChars);
  for (double x : {limits::max(), -limits::max(), limits::min(), -limits::min(), limits::denorm_min(),
                   -limits::denorm_min(), -limits::epsilon(), 0.1, -1.0 / 3.0, 0.0, -0.0}) {
    EXPECT_LE(real_chars(x), mesh_detail::kMaxRealChars) << x;
  }
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1074, 1023);
  size_t longest = 0;
  for (int i = 0; i < 200000; ++i) {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    longest = std::max(longest, real_chars(x));
  }
  EXPECT_LE(longest, mesh_detail::kMaxRealChars);
}

TEST(TextWriterBounds, NoVertexIndexNeedsMoreThanKMaxIndexChars) {
  std::string s;
  mesh_detail::append_int(&s, std::numeric_limits<int32_t>::min());
  EXPECT_EQ(s.size(), mesh_detail::kMaxIndexChars);
  s.clear();
  mesh_detail::append_int(&s, std::numeric_limits<int32_t>::max());
  EXPECT_LE(s.size(), mesh_detail::kMaxIndexChars);
}

}  // namespace
}  // namespace gab
