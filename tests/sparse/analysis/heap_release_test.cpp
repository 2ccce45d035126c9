// The host's heap is the host's: the engine trims it only when asked.
#include <gtest/gtest.h>

#include "gab/sparse/heap_release.h"

namespace gab {
namespace {

TEST(HeapRelease, OffUnlessTheHostTurnsItOn) {
  EXPECT_FALSE(heap_release_after_ordering());  // what a library caller gets
  set_heap_release_after_ordering(true);
  EXPECT_TRUE(heap_release_after_ordering());
  set_heap_release_after_ordering(false);
  EXPECT_FALSE(heap_release_after_ordering());
}

}  // namespace
}  // namespace gab
