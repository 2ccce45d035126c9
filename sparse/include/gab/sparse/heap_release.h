// An opt-in for hosts that own their process: the engine hands the C heap's
// free pages back to the system after dissecting a large matrix.
#pragma once

namespace gab {

// When enabled, the symbolic analysis of a matrix of 2^23 lower-triangle
// entries or more (a mesh of about 800k vertices up) ordered by nested
// dissection calls glibc's malloc_trim(0) between the ordering and the
// factor's storage: the dissection frees its graphs (GBs at millions of
// vertices) just before the factor is allocated, and the freed heap would
// otherwise add to the process's peak. The heap belongs to the host, so this
// is off by default (the gab tool turns it on). Process-wide; a no-op where
// the C library has no malloc_trim. Cost of a trim: proportional to the
// heap's size.
void set_heap_release_after_ordering(bool enabled);
bool heap_release_after_ordering();

}  // namespace gab
