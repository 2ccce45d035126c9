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
// M_TRIM_THRESHOLD 256 MiB: the free memory at the heap's top stays with
// the process up to that much, instead of going back to the system at
// 128 KiB (glibc's default once the mmap threshold is set) and being
// faulted in again by the next allocation. A decode frees and allocates
// its per-level buffers all along: igea's took 10,400 page faults with the
// default and 6,200 with this (each fault ~9 us on a virtual machine).
//
// The engine's heap release after a large ordering (heap_release.h): the
// tool owns its process, and at millions of vertices the freed graphs would
// otherwise add to the peak.
//
// Elsewhere only the last applies. The user's GLIBC_TUNABLES still
// override the first two (a tunable set there is left alone).
void tune_malloc();

}  // namespace cli
}  // namespace gab
