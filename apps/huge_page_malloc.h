// Transparent huge pages for the CLI's heap, where glibc offers them.
#pragma once

namespace gab {
namespace cli {

// On Linux with glibc, re-executes this program (same arguments) with
// glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES, unless that tunable is
// already set (by an earlier pass or by the user, who can turn it off with
// glibc.malloc.hugetlb=0). Returns only when it does not re-execute.
//
// Why: the codec's and mesh layer's arrays (hundreds of MB on a large mesh)
// come from malloc in 4 KiB pages, and where a page fault is expensive (on
// the virtual machines we measure on, 20-40 us) the faults cost more than
// the arithmetic: decompressing igea took 29,400 faults and 0.7-1.2 s of
// system time, 5,500 faults and 0.35-0.5 s with huge pages
// (the factor's own buffers are already advised: large_buffer.h). The
// tunable must be set before the process starts, hence the re-exec (about
// a millisecond).
void use_huge_page_malloc(char** argv);

}  // namespace cli
}  // namespace gab
