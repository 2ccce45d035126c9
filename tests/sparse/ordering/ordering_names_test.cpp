// One vocabulary for the orderings (ordering.h): every door parses the same
// names into the same enum, and kAuto means one thing everywhere.
#include "gab/sparse/ordering.h"

#include <gtest/gtest.h>

#include "gab/sparse/cholesky.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

TEST(OrderingNames, EveryNamedOrderingRoundTripsAndNothingElseParses) {
  for (Ordering o : {Ordering::kAuto, Ordering::kAmd, Ordering::kNestedDissection, Ordering::kNatural}) {
    Ordering parsed = Ordering::kGiven;
    ASSERT_TRUE(parse_ordering(ordering_name(o), &parsed)) << ordering_name(o);
    EXPECT_EQ(parsed, o);
  }
  Ordering untouched = Ordering::kAmd;
  for (const char* text : {"given", "AMD", "metis", "", "nd,amd"}) {
    EXPECT_FALSE(parse_ordering(text, &untouched)) << text;
  }
  EXPECT_EQ(untouched, Ordering::kAmd);
}

TEST(OrderingNames, AutoIsNestedDissectionFromItsSizeOn) {
  EXPECT_EQ(resolve_ordering(Ordering::kAuto, kNestedDissectionFrom - 1), Ordering::kAmd);
  EXPECT_EQ(resolve_ordering(Ordering::kAuto, kNestedDissectionFrom), Ordering::kNestedDissection);
  EXPECT_EQ(resolve_ordering(Ordering::kNatural, 10 * kNestedDissectionFrom), Ordering::kNatural);
  // The analysis resolves it the same way: below the size, AMD's permutation.
  const CscMatrix a = testing_util::grid_laplacian(20, 20);
  AnalyzeOptions by_auto, by_amd;
  by_auto.ordering = Ordering::kAuto;
  SymbolicFactor auto_factor, amd_factor;
  ASSERT_TRUE(analyze(a, by_auto, &auto_factor).ok());
  ASSERT_TRUE(analyze(a, by_amd, &amd_factor).ok());
  EXPECT_EQ(auto_factor.perm, amd_factor.perm);
}

}  // namespace
}  // namespace gab
