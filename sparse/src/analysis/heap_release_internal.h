// The analysis's side of heap_release.h.
#pragma once

#include <cstdint>

namespace gab {

// After the ordering of a matrix with `matrix_entries` lower-triangle
// entries: trims the heap when the host enabled it and the matrix is large.
void release_heap_after_ordering(int64_t matrix_entries);

}  // namespace gab
