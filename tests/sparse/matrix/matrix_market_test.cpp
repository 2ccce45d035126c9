// Matrix Market reader and writer: round trips (bit-exact values), the
// accepted dialect (comments, case, CRLF, pattern, integer, duplicates,
// symmetric mirroring), one test per malformed input (code + line), and the
// atomic writer's failure paths.
#include "gab/sparse/matrix_market.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "common/scratch_files.h"

namespace gab {
namespace {

namespace fs = std::filesystem;

const char kGeneral[] = "%%MatrixMarket matrix coordinate real general\n";
const char kSymmetric[] = "%%MatrixMarket matrix coordinate real symmetric\n";
const char kPattern[] = "%%MatrixMarket matrix coordinate pattern general\n";
const char kInteger[] = "%%MatrixMarket matrix coordinate integer general\n";

Status parse(const std::string& text, CscMatrix* a, MatrixMarketInfo* info = nullptr) {
  return parse_matrix_market(text, "t.mtx", a, info);
}

uint64_t bits(double v) {
  uint64_t u;
  std::memcpy(&u, &v, sizeof(u));
  return u;
}

// Same shape, same structure, and values equal bit for bit (so -0.0 and
// 0.0 differ, which is what a round trip must preserve).
void expect_identical(const CscMatrix& expected, const CscMatrix& actual) {
  ASSERT_EQ(expected.nrows, actual.nrows);
  ASSERT_EQ(expected.ncols, actual.ncols);
  ASSERT_EQ(expected.colptr, actual.colptr);
  ASSERT_EQ(expected.rowind, actual.rowind);
  ASSERT_EQ(expected.values.size(), actual.values.size());
  for (size_t k = 0; k < expected.values.size(); ++k) {
    EXPECT_EQ(bits(expected.values[k]), bits(actual.values[k]))
        << "value " << k << ": " << expected.values[k] << " vs " << actual.values[k];
  }
}

// Values that stress printing: all magnitudes, signed zero, subnormals, the
// extremes, and plain random fractions.
double awkward_value(std::mt19937_64& rng, size_t k) {
  static const double kSpecial[] = {-0.0,
                                    0.0,
                                    0.1,
                                    1.0 / 3.0,
                                    std::numeric_limits<double>::max(),
                                    -std::numeric_limits<double>::max(),
                                    std::numeric_limits<double>::min(),
                                    std::numeric_limits<double>::denorm_min(),
                                    -std::numeric_limits<double>::denorm_min(),
                                    9007199254740993.0,
                                    123456789.0};
  constexpr size_t kSpecialCount = sizeof(kSpecial) / sizeof(kSpecial[0]);
  if (k < kSpecialCount) return kSpecial[k];
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-1000, 1000);
  return std::ldexp(unit(rng), exponent(rng));
}

// A random m x n matrix (lower triangle only when `lower`), every position
// at most once.
CscMatrix random_matrix(int32_t m, int32_t n, double density, bool lower, uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coin(0.0, 1.0);
  std::vector<Triplet> triplets;
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = lower ? j : 0; i < m; ++i) {
      if (coin(rng) < density) triplets.push_back({i, j, 0.0});
    }
  }
  for (size_t k = 0; k < triplets.size(); ++k) triplets[k].value = awkward_value(rng, k);
  CscMatrix a;
  EXPECT_TRUE(csc_from_triplets(m, n, triplets, &a).ok());
  return a;
}

// A fresh directory per test, removed afterwards.
class ScratchDir {
 public:
  ScratchDir() {
    const auto* test = testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::path(gab_test::scratch_dir()) / (std::string(test->test_suite_name()) + "_" + test->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path_)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

 private:
  fs::path path_;
};


// ---------------------------------------------------------------------------
// Reading: the accepted dialect.

TEST(MatrixMarketRead, GeneralRealEntries) {
  CscMatrix a;
  MatrixMarketInfo info;
  ASSERT_TRUE(parse(std::string(kGeneral) + "3 2 3\n3 1 -2.5\n1 1 1e3\n2 2 .25\n", &a, &info).ok());
  EXPECT_EQ(info.symmetry, MatrixMarketSymmetry::kGeneral);
  EXPECT_FALSE(info.pattern);
  EXPECT_EQ(a.nrows, 3);
  EXPECT_EQ(a.ncols, 2);
  EXPECT_EQ(a.colptr, (std::vector<int32_t>{0, 2, 3}));
  EXPECT_EQ(a.rowind, (std::vector<int32_t>{0, 2, 1}));
  EXPECT_EQ(a.values, (std::vector<double>{1000.0, -2.5, 0.25}));
  EXPECT_TRUE(check_csc(a).ok());
}

TEST(MatrixMarketRead, BannerWordsAreCaseInsensitive) {
  CscMatrix a;
  MatrixMarketInfo info;
  ASSERT_TRUE(
      parse("%%matrixmarket MATRIX Coordinate REAL Symmetric\n2 2 1\n2 1 4\n", &a, &info).ok());
  EXPECT_EQ(info.symmetry, MatrixMarketSymmetry::kSymmetric);
  EXPECT_EQ(a.values, (std::vector<double>{4.0}));
}

TEST(MatrixMarketRead, CommentsAndBlankLinesAnywhereAfterBanner) {
  const std::string text = std::string(kGeneral) +
                           "% a comment\n"
                           "\n"
                           "   % an indented comment\n"
                           "2 2 2\n"
                           "\n"
                           "%%  more\n"
                           "  1   1   \t 5  \n"
                           "\t\n"
                           "2 2 6\n"
                           "% trailing comment\n"
                           "\n";
  CscMatrix a;
  ASSERT_TRUE(parse(text, &a).ok());
  EXPECT_EQ(a.rowind, (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(a.values, (std::vector<double>{5.0, 6.0}));
}

TEST(MatrixMarketRead, CrLfLineEndingsAndNoFinalNewline) {
  CscMatrix a;
  ASSERT_TRUE(
      parse("%%MatrixMarket matrix coordinate real general\r\n2 2 2\r\n1 1 1\r\n2 2 +2", &a).ok());
  EXPECT_EQ(a.values, (std::vector<double>{1.0, 2.0}));
}

TEST(MatrixMarketRead, PatternEntriesGetValueOne) {
  CscMatrix a;
  MatrixMarketInfo info;
  ASSERT_TRUE(parse(std::string(kPattern) + "3 3 3\n1 1\n3 1\n2 3\n", &a, &info).ok());
  EXPECT_TRUE(info.pattern);
  EXPECT_EQ(a.colptr, (std::vector<int32_t>{0, 2, 2, 3}));
  EXPECT_EQ(a.rowind, (std::vector<int32_t>{0, 2, 1}));
  EXPECT_EQ(a.values, (std::vector<double>{1.0, 1.0, 1.0}));
}

TEST(MatrixMarketRead, IntegerField) {
  CscMatrix a;
  MatrixMarketInfo info;
  ASSERT_TRUE(parse(std::string(kInteger) + "2 2 3\n1 1 7\n2 1 -3\n2 2 +12\n", &a, &info).ok());
  EXPECT_FALSE(info.pattern);
  EXPECT_EQ(a.values, (std::vector<double>{7.0, -3.0, 12.0}));
}

TEST(MatrixMarketRead, DuplicatesAreSummed) {
  CscMatrix a;
  ASSERT_TRUE(
      parse(std::string(kGeneral) + "2 2 4\n2 1 1.5\n1 1 1\n2 1 2.25\n2 1 -0.5\n", &a).ok());
  EXPECT_EQ(a.rowind, (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(a.values, (std::vector<double>{1.0, 3.25}));
}

TEST(MatrixMarketRead, SymmetricUpperEntriesAreMirroredIntoLowerTriangle) {
  CscMatrix a;
  MatrixMarketInfo info;
  // (1,3) and (2,3) are upper-triangle entries; (3,1) duplicates (1,3).
  ASSERT_TRUE(
      parse(std::string(kSymmetric) + "3 3 5\n1 1 4\n1 3 1\n2 3 2\n3 1 0.5\n3 3 9\n", &a, &info)
          .ok());
  EXPECT_EQ(info.symmetry, MatrixMarketSymmetry::kSymmetric);
  EXPECT_EQ(a.colptr, (std::vector<int32_t>{0, 2, 3, 4}));
  EXPECT_EQ(a.rowind, (std::vector<int32_t>{0, 2, 2, 2}));
  EXPECT_EQ(a.values, (std::vector<double>{4.0, 1.5, 2.0, 9.0}));
}

TEST(MatrixMarketRead, EmptyMatrices) {
  CscMatrix a;
  ASSERT_TRUE(parse(std::string(kGeneral) + "0 0 0\n", &a).ok());
  EXPECT_EQ(a.nrows, 0);
  EXPECT_EQ(a.nnz(), 0);
  ASSERT_TRUE(parse(std::string(kSymmetric) + "4 4 0\n", &a).ok());
  EXPECT_EQ(a.ncols, 4);
  EXPECT_EQ(a.nnz(), 0);
  EXPECT_TRUE(check_csc(a).ok());
}

TEST(MatrixMarketRead, UnderflowReadsAsSignedZeroAndSubnormalsSurvive) {
  CscMatrix a;
  ASSERT_TRUE(
      parse(std::string(kGeneral) + "3 1 3\n1 1 1e-400\n2 1 -1e-400\n3 1 4.9e-324\n", &a).ok());
  EXPECT_EQ(bits(a.values[0]), bits(0.0));
  EXPECT_EQ(bits(a.values[1]), bits(-0.0));
  EXPECT_EQ(a.values[2], std::numeric_limits<double>::denorm_min());
}

TEST(MatrixMarketRead, OutputUntouchedOnError) {
  CscMatrix a;
  ASSERT_TRUE(parse(std::string(kGeneral) + "1 1 1\n1 1 7\n", &a).ok());
  MatrixMarketInfo info;
  info.pattern = true;
  EXPECT_FALSE(parse(std::string(kSymmetric) + "1 1 2\n1 1 1\n", &a, &info).ok());
  EXPECT_EQ(a.values, (std::vector<double>{7.0}));
  EXPECT_TRUE(info.pattern);
}

// A header claiming two billion entries on a three-line file must fail at
// once: nothing may be allocated from the claim. Reserving for it would ask
// for 32 GB, which heuristic overcommit refuses on any machine with less
// memory (this one has 23 GB), so a regression fails here loudly.
TEST(MatrixMarketRead, HugeEntryCountOnTinyFileFailsFast) {
  const auto start = std::chrono::steady_clock::now();
  CscMatrix a;
  const Status s = parse(std::string(kGeneral) + "3 3 2000000000\n1 1 1\n", &a);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), "t.mtx:3: truncated: found 1 of 2000000000 declared entries");
  EXPECT_LT(seconds, 0.5);
}

TEST(MatrixMarketRead, HugeDimensionsOnTinyFileAreRefused) {
  CscMatrix a;
  const Status s = parse(std::string(kGeneral) + "2000000000 2000000000 1\n1 1 1\n", &a);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(),
            "t.mtx:2: size line declares 2000000000 x 2000000000, implausibly large for a "
            "76-byte file (refusing to allocate for it)");
  // Up to 2^24 the dimensions are believed whatever the file size; just
  // above, a tiny file is not enough evidence.
  EXPECT_EQ(parse(std::string(kGeneral) + "16777217 1 0\n", &a).code(), StatusCode::kParseError);
  EXPECT_TRUE(parse(std::string(kGeneral) + "1048576 2 1\n1048576 2 1\n", &a).ok());
  EXPECT_EQ(a.nrows, 1048576);
}

// ---------------------------------------------------------------------------
// Malformed input: one case per way a file can be wrong; each must give the
// exact code and a message "t.mtx:LINE: ..." mentioning what is wrong.

struct MalformedCase {
  const char* label;
  std::string text;
  StatusCode code;
  int line;
  const char* fragment;
};

std::ostream& operator<<(std::ostream& os, const MalformedCase& c) { return os << c.label; }

std::string g(const std::string& rest) { return kGeneral + rest; }

const MalformedCase kMalformed[] = {
    {"EmptyFile", "", StatusCode::kParseError, 1, "empty file"},
    {"MissingBanner", "3 3 1\n1 1 1\n", StatusCode::kParseError, 1,
     "missing '%%MatrixMarket' banner"},
    {"BannerNotFirst", "% comment\n" + g("1 1 0\n"), StatusCode::kParseError, 1,
     "missing '%%MatrixMarket' banner"},
    {"GarbledBanner", "%%MatrixMarkt matrix coordinate real general\n1 1 0\n",
     StatusCode::kParseError, 1, "garbled banner '%%MatrixMarkt'"},
    {"IncompleteBanner", "%%MatrixMarket matrix coordinate real\n1 1 0\n", StatusCode::kParseError,
     1, "incomplete banner"},
    {"BannerTrailingWord", "%%MatrixMarket matrix coordinate real general extra\n1 1 0\n",
     StatusCode::kParseError, 1, "unexpected text 'extra'"},
    {"UnknownField", "%%MatrixMarket matrix coordinate float general\n1 1 0\n",
     StatusCode::kParseError, 1, "unknown field 'float'"},
    {"UnknownSymmetry", "%%MatrixMarket matrix coordinate real diagonal\n1 1 0\n",
     StatusCode::kParseError, 1, "unknown symmetry 'diagonal'"},
    {"UnknownFormat", "%%MatrixMarket matrix sparse real general\n1 1 0\n", StatusCode::kParseError,
     1, "unknown format 'sparse'"},
    {"ArrayUnsupported", "%%MatrixMarket matrix array real general\n2 1\n1\n2\n",
     StatusCode::kParseError, 1, "unsupported format 'array'"},
    {"ComplexUnsupported", "%%MatrixMarket matrix coordinate complex general\n1 1 1\n1 1 1 0\n",
     StatusCode::kParseError, 1, "unsupported field 'complex'"},
    {"HermitianUnsupported", "%%MatrixMarket matrix coordinate real hermitian\n1 1 0\n",
     StatusCode::kParseError, 1, "unsupported symmetry 'hermitian'"},
    {"SkewSymmetricUnsupported", "%%MatrixMarket matrix coordinate real skew-symmetric\n1 1 0\n",
     StatusCode::kParseError, 1, "unsupported symmetry 'skew-symmetric'"},
    {"VectorUnsupported", "%%MatrixMarket vector coordinate real general\n3 1\n1 1\n",
     StatusCode::kParseError, 1, "unsupported object 'vector'"},
    {"MissingSizeLine", g("% nothing but comments\n\n"), StatusCode::kParseError, 3,
     "missing size line"},
    {"SizeLineTwoFields", g("3 3\n1 1 1\n"), StatusCode::kParseError, 2,
     "expected 3 fields (rows cols entries) in the size line, got 2"},
    {"SizeLineTrailingGarbage", g("3 3 1 9\n1 1 1\n"), StatusCode::kParseError, 2,
     "in the size line, got 4"},
    {"SizeLineNotInteger", g("% c\n3 x 1\n1 1 1\n"), StatusCode::kParseError, 3,
     "column count 'x' is not an integer"},
    {"SizeLineFloatCount", g("3 3 1.0\n1 1 1\n"), StatusCode::kParseError, 2,
     "entry count '1.0' is not an integer"},
    {"SizeLineNegative", g("-3 3 1\n1 1 1\n"), StatusCode::kParseError, 2,
     "row count '-3' is negative"},
    {"RowsOverInt32", g("2147483648 1 1\n1 1 1\n"), StatusCode::kOverflow, 2,
     "row count '2147483648' exceeds the int32 index limit 2147483647"},
    {"EntriesOverInt32", g("3 3 2147483648\n1 1 1\n"), StatusCode::kOverflow, 2,
     "entry count '2147483648' exceeds the int32 index limit"},
    {"DimensionBeyondInt64", g("3 99999999999999999999 1\n1 1 1\n"), StatusCode::kOverflow, 2,
     "column count '99999999999999999999' exceeds"},
    {"ZeroRowsWithEntries", g("0 3 1\n1 1 1\n"), StatusCode::kParseError, 2,
     "a 0 x 3 matrix cannot hold the 1 entries declared"},
    {"SymmetricNotSquare", std::string(kSymmetric) + "3 4 1\n1 1 1\n", StatusCode::kParseError, 2,
     "a symmetric matrix must be square, the size line says 3 x 4"},
    {"EntryTooFewFields", g("3 3 2\n1 1 1\n2 2\n"), StatusCode::kParseError, 4,
     "expected 3 fields (row col value), got 2"},
    {"EntryTrailingGarbage", g("3 3 1\n1 1 1 junk\n"), StatusCode::kParseError, 3,
     "expected 3 fields (row col value), got 4"},
    {"PatternEntryWithValue", std::string(kPattern) + "3 3 1\n1 1 1\n", StatusCode::kParseError, 3,
     "expected 2 fields (row col), got 3"},
    {"RowIndexZero", g("3 3 1\n0 1 1\n"), StatusCode::kParseError, 3,
     "row index '0' is out of range [1, 3]"},
    {"ColumnIndexTooLarge", g("3 4 1\n1 5 1\n"), StatusCode::kParseError, 3,
     "column index '5' is out of range [1, 4]"},
    {"RowIndexNegative", g("3 3 1\n-1 1 1\n"), StatusCode::kParseError, 3,
     "row index '-1' is out of range [1, 3]"},
    {"RowIndexBeyondInt64", g("3 3 1\n99999999999999999999999 1 1\n"), StatusCode::kParseError, 3,
     "row index '99999999999999999999999' is out of range"},
    {"RowIndexNotInteger", g("3 3 1\n1.0 1 1\n"), StatusCode::kParseError, 3,
     "row index '1.0' is not an integer"},
    {"ColumnIndexNotNumeric", g("3 3 1\n1 a 1\n"), StatusCode::kParseError, 3,
     "column index 'a' is not an integer"},
    {"ValueNotNumeric", g("3 3 1\n1 1 abc\n"), StatusCode::kParseError, 3,
     "value 'abc' is not a number"},
    {"ValueTrailingGarbage", g("3 3 1\n1 1 1.5x\n"), StatusCode::kParseError, 3,
     "value '1.5x' is not a number"},
    {"ValueDecimalComma", g("3 3 1\n1 1 1,5\n"), StatusCode::kParseError, 3,
     "value '1,5' is not a number"},
    {"ValueFortranExponent", g("3 3 1\n1 1 1.0D+00\n"), StatusCode::kParseError, 3,
     "value '1.0D+00' is not a number"},
    {"ValueDoubleSign", g("3 3 1\n1 1 +-1\n"), StatusCode::kParseError, 3,
     "value '+-1' is not a number"},
    {"ValueNul", g("3 3 1\n1 1 1") + std::string(1, '\0') + "\n", StatusCode::kParseError, 3,
     "value '1?' is not a number"},
    {"ValueNaN", g("3 3 1\n1 1 nan\n"), StatusCode::kParseError, 3, "value 'nan' is not finite"},
    {"ValueInfinity", g("3 3 2\n1 1 1\n2 2 -inf\n"), StatusCode::kParseError, 4,
     "value '-inf' is not finite"},
    {"ValueOverflows", g("3 3 1\n1 1 1e400\n"), StatusCode::kParseError, 3,
     "value '1e400' is not finite"},
    {"IntegerFieldFraction", std::string(kInteger) + "3 3 1\n1 1 1.5\n", StatusCode::kParseError, 3,
     "value '1.5' is not an integer (the banner says 'integer')"},
    {"Truncated", g("3 3 5\n1 1 1\n% trailing comment\n"), StatusCode::kParseError, 4,
     "truncated: found 1 of 5 declared entries"},
    {"TruncatedNoEntries", g("3 3 2\n"), StatusCode::kParseError, 2,
     "truncated: found 0 of 2 declared entries"},
    {"MoreEntriesThanDeclared", g("3 3 1\n1 1 1\n\n2 2 2\n"), StatusCode::kParseError, 5,
     "more entries than the 1 declared in the size line (line 2)"},
};

class MatrixMarketMalformed : public testing::TestWithParam<MalformedCase> {};

TEST_P(MatrixMarketMalformed, FailsWithCodeAndLine) {
  const MalformedCase& c = GetParam();
  CscMatrix a;
  const Status s = parse(c.text, &a);
  EXPECT_EQ(s.code(), c.code) << s.message();
  const std::string prefix = "t.mtx:" + std::to_string(c.line) + ": ";
  EXPECT_EQ(s.message().rfind(prefix, 0), 0u) << "message: " << s.message();
  EXPECT_NE(s.message().find(c.fragment), std::string::npos) << "message: " << s.message();
  EXPECT_EQ(s.message().find('\n'), std::string::npos) << "one line: " << s.message();
}

INSTANTIATE_TEST_SUITE_P(MatrixMarket, MatrixMarketMalformed, testing::ValuesIn(kMalformed),
                         [](const testing::TestParamInfo<MalformedCase>& info) {
                           return std::string(info.param.label);
                         });

TEST(MatrixMarketMalformedMessages, ExactText) {
  CscMatrix a;
  EXPECT_EQ(parse(g("3 3 2\n1 1 1\n% c\n2 2\n"), &a).message(),
            "t.mtx:5: expected 3 fields (row col value), got 2");
  EXPECT_EQ(parse(g("3 3 1\n0 1 1\n"), &a).message(),
            "t.mtx:3: row index '0' is out of range [1, 3]");
  EXPECT_EQ(parse(g("3 3 5\n1 1 1\n"), &a).message(),
            "t.mtx:3: truncated: found 1 of 5 declared entries");
  EXPECT_EQ(parse("%%MatrixMarket matrix array real general\n1 1\n1\n", &a).message(),
            "t.mtx:1: unsupported format 'array' (dense); only 'coordinate' files are read");
  EXPECT_EQ(parse(g("2 2 1\n1 1 1\n1 2 3\n"), &a).message(),
            "t.mtx:4: more entries than the 1 declared in the size line (line 2)");
  EXPECT_EQ(parse(g("3 3 1\n1 1 " + std::string(60, '7') + "x\n"), &a).message(),
            "t.mtx:3: value '" + std::string(40, '7') + "...' is not a number");
  EXPECT_EQ(parse_matrix_market(g("4000000000 1 0\n"), "dir/m.mtx", &a).message(),
            "dir/m.mtx:2: size line: row count '4000000000' exceeds the int32 index limit "
            "2147483647");
}

// ---------------------------------------------------------------------------
// Files: reading from disk, round trips, read_symmetric_matrix_market.

TEST(MatrixMarketFile, MissingFileIsIoErrorNamingPath) {
  ScratchDir dir;
  const std::string path = dir.file("absent.mtx");
  CscMatrix a;
  const Status s = read_matrix_market(path, &a);
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_NE(s.message().find(path), std::string::npos) << s.message();
  EXPECT_EQ(read_symmetric_matrix_market(path, &a).code(), StatusCode::kIoError);
}

TEST(MatrixMarketFile, DirectoryIsIoError) {
  ScratchDir dir;
  CscMatrix a;
  EXPECT_EQ(read_matrix_market(dir.file(""), &a).code(), StatusCode::kIoError);
}

TEST(MatrixMarketFile, ParseErrorsNameThePath) {
  ScratchDir dir;
  const std::string path = dir.file("bad.mtx");
  gab_test::write_file(path, g("3 3 2\n1 1 1\n2 2\n"));
  CscMatrix a;
  const Status s = read_matrix_market(path, &a);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), path + ":4: expected 3 fields (row col value), got 2");
}

// Files are read through a 1 MiB window: lines cross block boundaries, a
// line can be longer than the window, and line numbers must stay exact.
std::string many_entries_text(int count) {
  std::string text = kGeneral;
  text += "1000 1000 " + std::to_string(count) + "\n";
  std::mt19937 rng(5);
  for (int k = 0; k < count; ++k) {
    text += std::to_string(1 + rng() % 1000) + " " + std::to_string(1 + rng() % 1000) + " " +
            std::to_string(static_cast<int>(rng() % 2000) - 1000) + ".0625\n";
  }
  return text;
}

TEST(MatrixMarketFile, LargeFileMatchesInMemoryParse) {
  ScratchDir dir;
  const std::string path = dir.file("large.mtx");
  const std::string text = many_entries_text(150000);  // about 3 MB
  gab_test::write_file(path, text);
  CscMatrix from_file, from_memory;
  ASSERT_TRUE(read_matrix_market(path, &from_file).ok());
  ASSERT_TRUE(parse(text, &from_memory).ok());
  expect_identical(from_memory, from_file);
  EXPECT_GT(from_file.nnz(), 130000);       // some positions repeat (summed)
  EXPECT_GT(text.size(), size_t{2} << 20);  // spans several read windows
}

TEST(MatrixMarketFile, LineNumbersStayExactAcrossBlocks) {
  ScratchDir dir;
  const std::string path = dir.file("late_error.mtx");
  std::string text = many_entries_text(150000);
  text += "1 1 oops\n";  // line 150003, one entry more than declared
  gab_test::write_file(path, text);
  CscMatrix a;
  const Status s = read_matrix_market(path, &a);
  EXPECT_EQ(s.message(), path +
                             ":150003: more entries than the 150000 declared in the size line "
                             "(line 2)");
}

TEST(MatrixMarketFile, LineLongerThanTheReadWindow) {
  ScratchDir dir;
  const std::string path = dir.file("long_comment.mtx");
  gab_test::write_file(path, std::string(kGeneral) + "%" + std::string(3 << 20, 'c') + "\n2 2 1\n2 1 3\n");
  CscMatrix a;
  ASSERT_TRUE(read_matrix_market(path, &a).ok());
  EXPECT_EQ(a.values, (std::vector<double>{3.0}));
  gab_test::write_file(path, std::string(kGeneral) + "2 2 1\n2 1 3" + std::string(3 << 20, ' ') + "x\n");
  EXPECT_EQ(read_matrix_market(path, &a).message(),
            path + ":3: expected 3 fields (row col value), got 4");
}

// A pipe cannot report its size: it is read whole, then parsed as usual.
TEST(MatrixMarketFile, ReadsFromAPipe) {
  ScratchDir dir;
  const std::string path = dir.file("fifo.mtx");
  ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
  const std::string text = many_entries_text(100000);
  std::thread writer([&] { gab_test::write_file(path, text); });
  CscMatrix from_pipe, from_memory;
  const Status s = read_matrix_market(path, &from_pipe);
  writer.join();
  ASSERT_TRUE(s.ok()) << s.message();
  ASSERT_TRUE(parse(text, &from_memory).ok());
  expect_identical(from_memory, from_pipe);
}

TEST(MatrixMarketFile, RoundTripGeneralIsBitExact) {
  ScratchDir dir;
  const std::string path = dir.file("general.mtx");
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    const CscMatrix a = random_matrix(37 + seed, 23, 0.2, /*lower=*/false, seed);
    ASSERT_TRUE(write_matrix_market(path, a, /*symmetric=*/false).ok());
    CscMatrix b;
    MatrixMarketInfo info;
    ASSERT_TRUE(read_matrix_market(path, &b, &info).ok());
    EXPECT_EQ(info.symmetry, MatrixMarketSymmetry::kGeneral);
    EXPECT_FALSE(info.pattern);
    expect_identical(a, b);
  }
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"general.mtx"});
}

TEST(MatrixMarketFile, RoundTripSymmetricIsBitExact) {
  ScratchDir dir;
  const std::string path = dir.file("symmetric.mtx");
  const CscMatrix lower = random_matrix(41, 41, 0.15, /*lower=*/true, 7);
  ASSERT_TRUE(write_matrix_market(path, lower, /*symmetric=*/true).ok());
  EXPECT_EQ(gab_test::read_file(path).rfind("%%MatrixMarket matrix coordinate real symmetric\n41 41 ", 0),
            0u);
  CscMatrix b;
  MatrixMarketInfo info;
  ASSERT_TRUE(read_matrix_market(path, &b, &info).ok());
  EXPECT_EQ(info.symmetry, MatrixMarketSymmetry::kSymmetric);
  expect_identical(lower, b);
  CscMatrix c;
  ASSERT_TRUE(read_symmetric_matrix_market(path, &c).ok());
  expect_identical(lower, c);
}

TEST(MatrixMarketFile, RoundTripPatternOnlyMatrix) {
  ScratchDir dir;
  const std::string path = dir.file("pattern.mtx");
  CscMatrix a = random_matrix(9, 12, 0.3, /*lower=*/false, 3);
  a.values.clear();
  ASSERT_TRUE(write_matrix_market(path, a, /*symmetric=*/false).ok());
  EXPECT_EQ(gab_test::read_file(path).rfind("%%MatrixMarket matrix coordinate pattern general\n", 0), 0u);
  CscMatrix b;
  MatrixMarketInfo info;
  ASSERT_TRUE(read_matrix_market(path, &b, &info).ok());
  EXPECT_TRUE(info.pattern);
  EXPECT_EQ(a.colptr, b.colptr);
  EXPECT_EQ(a.rowind, b.rowind);
  EXPECT_EQ(b.values, std::vector<double>(b.rowind.size(), 1.0));
}

TEST(MatrixMarketFile, RoundTripIntegerAndPatternFilesThroughWriter) {
  ScratchDir dir;
  const std::string path = dir.file("m.mtx");
  CscMatrix a;
  ASSERT_TRUE(
      parse(std::string(kInteger) + "3 3 3\n1 1 -4\n3 2 9007199254740993\n2 3 0\n", &a).ok());
  ASSERT_TRUE(write_matrix_market(path, a, false).ok());
  CscMatrix b;
  ASSERT_TRUE(read_matrix_market(path, &b).ok());
  expect_identical(a, b);
  ASSERT_TRUE(parse(std::string(kPattern) + "2 3 2\n2 3\n1 1\n", &a).ok());
  ASSERT_TRUE(write_matrix_market(path, a, false).ok());
  ASSERT_TRUE(read_matrix_market(path, &b).ok());
  expect_identical(a, b);
}

TEST(MatrixMarketFile, WrittenTextIsPinned) {
  ScratchDir dir;
  const std::string path = dir.file("pinned.mtx");
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(3, 2, {{0, 0, 1.5}, {2, 0, -2.0}, {1, 1, 0.1}}, &a).ok());
  ASSERT_TRUE(write_matrix_market(path, a, false).ok());
  EXPECT_EQ(gab_test::read_file(path),
            "%%MatrixMarket matrix coordinate real general\n"
            "3 2 3\n"
            "1 1 1.5\n"
            "3 1 -2\n"
            "2 2 0.10000000000000001\n");
}

// The writer promises printf's "%.17g" text exactly (it formats with
// std::to_chars, which the standard defines to match printf).
TEST(MatrixMarketFile, ValuesAreWrittenAsPrintf17g) {
  ScratchDir dir;
  const std::string path = dir.file("g17.mtx");
  const CscMatrix a = random_matrix(30, 30, 0.3, /*lower=*/false, 11);
  ASSERT_TRUE(write_matrix_market(path, a, false).ok());
  std::istringstream in(gab_test::read_file(path));
  std::string line;
  std::getline(in, line);  // banner
  std::getline(in, line);  // size
  size_t k = 0;
  while (std::getline(in, line)) {
    ASSERT_LT(k, a.values.size());
    char expected[64];
    std::snprintf(expected, sizeof(expected), "%.17g", a.values[k]);
    EXPECT_EQ(line.substr(line.rfind(' ') + 1), expected) << "entry " << k;
    ++k;
  }
  EXPECT_EQ(k, a.values.size());
}

TEST(MatrixMarketFile, ReadSymmetricFromSymmetricGeneralFile) {
  ScratchDir dir;
  const std::string path = dir.file("general_symmetric.mtx");
  // Values symmetric after duplicate summation: (2,1) = 1 + 2 = 3 = (1,2).
  gab_test::write_file(path, g("3 3 6\n1 1 4\n2 1 1\n1 2 3\n2 1 2\n3 3 5\n2 2 6\n"));
  CscMatrix lower;
  ASSERT_TRUE(read_symmetric_matrix_market(path, &lower).ok());
  EXPECT_EQ(lower.colptr, (std::vector<int32_t>{0, 2, 3, 4}));
  EXPECT_EQ(lower.rowind, (std::vector<int32_t>{0, 1, 1, 2}));
  EXPECT_EQ(lower.values, (std::vector<double>{4.0, 3.0, 6.0, 5.0}));
}

TEST(MatrixMarketFile, ReadSymmetricRejectsUnequalMirror) {
  ScratchDir dir;
  const std::string path = dir.file("asym.mtx");
  gab_test::write_file(path, g("3 3 4\n1 1 4\n% c\n3 1 2\n1 3 2.5\n2 2 1\n"));
  CscMatrix lower;
  const Status s = read_symmetric_matrix_market(path, &lower);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), path +
                             ":5: entry (3, 1) = 2 but (1, 3) = 2.5; a general file read as "
                             "symmetric must have symmetric values");
}

TEST(MatrixMarketFile, ReadSymmetricRejectsMissingMirror) {
  ScratchDir dir;
  const std::string path = dir.file("one_sided.mtx");
  gab_test::write_file(path, g("2 2 2\n1 1 4\n2 1 -1\n"));
  CscMatrix lower;
  const Status s = read_symmetric_matrix_market(path, &lower);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), path +
                             ":4: entry (2, 1) = -1 but (1, 2) is absent; a general file "
                             "read as symmetric must have symmetric values");
  // An explicit zero without a mirror is symmetric (missing counts as zero).
  gab_test::write_file(path, g("2 2 2\n1 1 4\n1 2 0\n"));
  ASSERT_TRUE(read_symmetric_matrix_market(path, &lower).ok());
  EXPECT_EQ(lower.nnz(), 1);
}

TEST(MatrixMarketFile, ReadSymmetricRejectsNonSquare) {
  ScratchDir dir;
  const std::string path = dir.file("rect.mtx");
  gab_test::write_file(path, g("% c\n3 2 1\n1 1 1\n"));
  CscMatrix lower;
  const Status s = read_symmetric_matrix_market(path, &lower);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), path + ":3: a symmetric matrix must be square, the size line says 3 x 2");
}

TEST(MatrixMarketFile, ReadSymmetricKeepsSymmetricFileAsLower) {
  ScratchDir dir;
  const std::string path = dir.file("sym.mtx");
  gab_test::write_file(path, std::string(kSymmetric) + "2 2 2\n1 2 -1\n2 2 3\n");
  CscMatrix lower;
  ASSERT_TRUE(read_symmetric_matrix_market(path, &lower).ok());
  EXPECT_EQ(lower.rowind, (std::vector<int32_t>{1, 1}));
  EXPECT_EQ(lower.values, (std::vector<double>{-1.0, 3.0}));
}

// ---------------------------------------------------------------------------
// Writing: argument checks and atomicity.

TEST(MatrixMarketWrite, SymmetricNeedsSquareLowerTriangle) {
  ScratchDir dir;
  const std::string path = dir.file("x.mtx");
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(2, 2, {{0, 0, 1.0}, {0, 1, 2.0}}, &a).ok());
  Status s = write_matrix_market(path, a, /*symmetric=*/true);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("entry (1, 2) is above the diagonal"), std::string::npos)
      << s.message();
  ASSERT_TRUE(csc_from_triplets(3, 2, {{2, 0, 1.0}}, &a).ok());
  EXPECT_EQ(write_matrix_market(path, a, true).code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(dir.listing().empty());
}

TEST(MatrixMarketWrite, RejectsInvalidCscAndNonFiniteValues) {
  ScratchDir dir;
  const std::string path = dir.file("x.mtx");
  CscMatrix broken;
  broken.nrows = broken.ncols = 2;
  broken.colptr = {0, 2, 2};
  broken.rowind = {1, 0};
  broken.values = {1.0, 2.0};
  EXPECT_EQ(write_matrix_market(path, broken, false).code(), StatusCode::kInvalidArgument);
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(2, 2, {{1, 1, std::nan("")}}, &a).ok());
  const Status s = write_matrix_market(path, a, false);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("entry (2, 2) is not finite"), std::string::npos) << s.message();
  EXPECT_TRUE(dir.listing().empty());
}

TEST(MatrixMarketWrite, MissingDirectoryIsIoErrorAndLeavesNothing) {
  ScratchDir dir;
  const std::string path = dir.file("no_such_dir/x.mtx");
  const CscMatrix a = random_matrix(5, 5, 0.5, false, 1);
  const Status s = write_matrix_market(path, a, false);
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_NE(s.message().find(path), std::string::npos) << s.message();
  EXPECT_TRUE(dir.listing().empty());
}

TEST(MatrixMarketWrite, RenameFailureRemovesTemporary) {
  ScratchDir dir;
  // The target is a non-empty directory: the temporary is written, the
  // rename fails, and the temporary must be gone afterwards.
  const std::string path = dir.file("target");
  fs::create_directories(path);
  gab_test::write_file(path + "/keep", "x");
  const CscMatrix a = random_matrix(5, 5, 0.5, false, 1);
  const Status s = write_matrix_market(path, a, false);
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_NE(s.message().find(path), std::string::npos) << s.message();
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"target"});
  EXPECT_TRUE(fs::is_directory(path));
}

TEST(MatrixMarketWrite, ReplacesExistingFileWhole) {
  ScratchDir dir;
  const std::string path = dir.file("m.mtx");
  gab_test::write_file(path, std::string(100000, 'x'));
  const CscMatrix a = random_matrix(4, 4, 0.5, false, 2);
  ASSERT_TRUE(write_matrix_market(path, a, false).ok());
  CscMatrix b;
  ASSERT_TRUE(read_matrix_market(path, &b).ok());
  expect_identical(a, b);
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"m.mtx"});
}

TEST(MatrixMarketWrite, FailedWriteKeepsPreviousFile) {
  ScratchDir dir;
  const std::string path = dir.file("m.mtx");
  gab_test::write_file(path, "previous");
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(2, 2, {{0, 1, 1.0}}, &a).ok());
  EXPECT_EQ(write_matrix_market(path, a, /*symmetric=*/true).code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(gab_test::read_file(path), "previous");
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"m.mtx"});
}

}  // namespace
}  // namespace gab
