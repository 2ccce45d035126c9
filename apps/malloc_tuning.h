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
// default and 6,200 with this (each fault 3-9 us on this virtual machine).
//
// The heap's next 64 MiB advised as transparent huge pages (madvise, so
// only where the system allows them): reserved as address space, touched
// in 2 MiB pages. A decode of igea took 6,200 page faults of 4 KiB with the
// settings above and 360 with this, about 10% of its time (a fault costs
// 3-4 us per 4 KiB here, 0.7 us per 4 KiB of a huge page); the peak RSS is
// the same.
//
// The engine's heap release after a large ordering (heap_release.h): the
// tool owns its process, and at millions of vertices the freed graphs would
// otherwise add to the peak.
//
// Elsewhere only the last applies. The user's GLIBC_TUNABLES still
// override the first three (a tunable set there is left alone: hugetlb or
// top_pad for the third).
void tune_malloc();

}  // namespace cli
}  // namespace gab
