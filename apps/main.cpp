// gab: the command-line tool. Dispatches to one function per sub-command
// (DESIGN.md section 6 is the contract: exit 0 ok, 1 failure, 2 usage).
#include <cstdio>
#include <cstring>

#include "cli.h"
#include "commands.h"
#include "huge_page_malloc.h"

namespace {

const char* kHelp =
    "gab: geometry-aware bases for triangle meshes, and a sparse Cholesky engine\n"
    "\n"
    "usage: gab <command> [options]\n"
    "\n"
    "commands:\n"
    "  compress -i IN -o OUT.gab [--anchors K | --error E | --linf E] [--bits Q] [--weight W]\n"
    "           [--geometry-only] [--threads T] [--json]\n"
    "      compress a mesh's geometry with geometry-aware anchors (default --error 0.001: relative\n"
    "      vertex RMS over the bounding-box diagonal; q picked from the target, 12 for --anchors)\n"
    "  decompress -i IN.gab -o OUT [--anchors K] [--connectivity MESH] [--threads T] [--json]\n"
    "      decode a .gab file (its first K anchors only: a coarser level of detail)\n"
    "  info IN.gab [--json]\n"
    "      what a .gab file holds (checksums verified, nothing decoded)\n"
    "  demo\n"
    "      compress a real mesh at several anchor counts, print a table, write the meshes\n"
    "  factor IN [--ordering amd|natural] [--anchors K] [--repeat R] [--threads T] [--json]\n"
    "      order, analyze, factor and solve the least-squares matrix of a mesh (.obj .off .ply)\n"
    "      or a Matrix Market file (.mtx); report sizes and median phase times\n"
    "  study IN... [--ordering amd|natural] [--updates U] [--batch B] [--anchors K]\n"
    "        [--subdivide K] [--csv F] [--svg F] [--json]\n"
    "      add U anchors to the factor one (or B) at a time by Givens rotations along the\n"
    "      elimination tree; report path lengths, entries touched, times, drift\n"
    "  diff A B [--samples N] [--json]\n"
    "      distances between two meshes (.obj .off .ply): per vertex when the vertex counts\n"
    "      match, and the symmetric surface distance (mean, RMS, Hausdorff) from N samples\n"
    "\n"
    "--json prints one JSON object on stdout; messages go to stderr. --threads: threads for the\n"
    "factorizations (compress/decompress default: all cores; factor: 1); results never depend on it.\n";

}  // namespace

int main(int argc, char** argv) {
  gab::cli::use_huge_page_malloc(argv);
  if (argc < 2) {
    std::fputs(kHelp, stderr);
    return gab::cli::kExitUsage;
  }
  const char* command = argv[1];
  if (!std::strcmp(command, "help") || !std::strcmp(command, "--help") || !std::strcmp(command, "-h")) {
    std::fputs(kHelp, stdout);
    return gab::cli::kExitOk;
  }
  if (!std::strcmp(command, "factor")) return gab::cli::run_factor(argc - 2, argv + 2);
  if (!std::strcmp(command, "study")) return gab::cli::run_study(argc - 2, argv + 2);
  if (!std::strcmp(command, "diff")) return gab::cli::run_diff(argc - 2, argv + 2);
  if (!std::strcmp(command, "compress")) return gab::cli::run_compress(argc - 2, argv + 2);
  if (!std::strcmp(command, "decompress")) return gab::cli::run_decompress(argc - 2, argv + 2);
  if (!std::strcmp(command, "info")) return gab::cli::run_info(argc - 2, argv + 2);
  if (!std::strcmp(command, "demo")) return gab::cli::run_demo(argc - 2, argv + 2);
  std::fprintf(stderr, "gab: unknown command '%s' (try 'gab help')\n", command);
  return gab::cli::kExitUsage;
}
