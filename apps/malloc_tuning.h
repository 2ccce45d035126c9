// The CLI's malloc settings, made at the start of main, in this process:
// no restart (debuggers and tracers see the program they started) and no
// environment variable left to child processes.
#pragma once

namespace gab {
namespace cli {

// With glibc:
//
// M_MMAP_THRESHOLD 32 MiB (glibc's largest): blocks below it come from the
// heap, whose freed memory the next block reuses, instead of pages of their
// own that go back to the system when freed and are faulted in afresh next
// time. The nested dissection allocates and frees graphs and coarsenings of
// a few MB to tens of MB at every level; glibc's own threshold only rises
// to a block's size once such a block has been freed.
//
// The engine's heap release after a large ordering (heap_release.h): the
// tool owns its process, and at millions of vertices the freed graphs would
// otherwise add to the peak.
//
// Elsewhere only the second applies. The user's GLIBC_TUNABLES still
// override the first (a tunable set there is left alone).
void tune_malloc();

}  // namespace cli
}  // namespace gab
