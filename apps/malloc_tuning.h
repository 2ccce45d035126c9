// The CLI's malloc settings, where glibc offers them.
#pragma once

namespace gab {
namespace cli {

// On Linux with glibc, re-executes this program (same arguments) with
// GLIBC_TUNABLES extended by the settings below that it does not set
// already (by an earlier pass, or by the user, who can override either).
// Returns only when it does not re-execute. The tunables must be set before
// the process starts, hence the re-exec (about a millisecond).
//
// glibc.malloc.hugetlb=1: transparent huge pages for the heap. The codec's
// and mesh layer's arrays (hundreds of MB on a large mesh) come from malloc
// in 4 KiB pages, and where a page fault is expensive (on the virtual
// machines we measure on, 20-40 us) the faults cost more than the
// arithmetic: decompressing igea took 29,400 faults and 0.7-1.2 s of system
// time, 5,500 faults and 0.35-0.5 s with huge pages (the factor's own
// buffers are already advised: large_buffer.h).
//
// glibc.malloc.mmap_threshold=32 MiB (glibc's largest): blocks below it come
// from the heap, whose freed memory the next block reuses, instead of pages
// of their own that go back to the system when freed and are faulted in
// afresh next time. The nested dissection allocates and frees graphs and
// coarsenings of a few MB to tens of MB at every level; glibc's own
// threshold only rises to a block's size once such a block has been freed.
// Decompressing igea (6 alternating runs): 0.97 s against 1.04 s, 8,400
// minor faults against 12,900; the 2.4M-vertex mesh: 23.4 s against 26.3 s
// (one run each), the same peak RSS (the factor and the large graphs are
// above the threshold).
void tune_malloc(char** argv);

}  // namespace cli
}  // namespace gab
