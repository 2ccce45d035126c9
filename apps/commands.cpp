#include "commands.h"

#include <cstring>

namespace gab {
namespace cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> table = {
      {"compress", run_compress,
       {"-i IN -o OUT.gab [--anchors K | --error E | --linf E] [--bits Q] [--weight W]",
        "[--keep-order] [--geometry-only] [--detail auto|on|off] [--solver auto|global|iterative]",
        "[--refine] [--order-out FILE] [--threads T] [--json] [--quiet] [--strict]",
        "[--normal-bits 8] [--uv-bits 10] [--color-bits 8] [--generic-bits 16]",
        "(tuning: --batch-fraction F --chunk-growth G --initial K --layout smaller|levels|selection",
        "         --ordering auto|amd|nd)"},
       "compress a mesh's geometry with geometry-aware anchors (default --error 0.001: relative\n"
       "vertex RMS over the bounding-box diagonal; q picked from the target, 12 for --anchors);\n"
       "the connectivity is kept, triangles as a set (their order is the coder's), and the decoded\n"
       "mesh is numbered in the coder's traversal order, the smallest file (--reorder, the default,\n"
       "spelled out): --order-out FILE writes the decoded index of each input vertex, a line each,\n"
       "for per-vertex data kept outside the file. --keep-order keeps the input's numbering (the old\n"
       "default) at the price of the vertex order block; --geometry-only keeps it too.\n"
       "Below about 3e-4 the anchors stop early and a detail layer codes every vertex's residual;\n"
       "--detail auto keeps the smaller file, on/off force it (off may miss a target). --solver:\n"
       "the shape the anchors make, recorded in the file: iterative (linear-cost steps; the default)\n"
       "or global (the paper's factored least squares: files about 10% smaller at 1e-3, decoding an\n"
       "order of magnitude slower in several times the memory; auto picks it for --refine, which needs it).\n"
       "--ordering: the global solver's factorizations' (speed only; recorded in the file; auto:\n"
       "nested dissection from 100k vertices). Normals, texture coordinates, colours and other\n"
       "per-vertex properties travel in the file, each quantized by its --*-bits (normals: a lattice\n"
       "of about 4^bits directions; the rest a grid of 2^bits steps over the values' span; integer\n"
       "values such as byte colours exactly); copies of a vertex at one position are merged, their\n"
       "data kept per corner (not with --keep-order). --strict: fail, before any work, when the\n"
       "input holds data gab does not carry (materials, groups, lines, polygons' arity, ...;\n"
       "otherwise a warning names them)"},
      {"decompress", run_decompress,
       {"-i IN.gab -o OUT [--anchors K] [--connectivity MESH] [--threads T] [--ordering auto|amd|nd]",
        "[--max-memory SIZE] [--json] [--quiet]"},
       "decode a .gab file (its first K anchors only: a coarser level of detail); --ordering auto\n"
       "uses the file's; --max-memory bounds the decode's memory (bytes, or with K, M, G; 'none';\n"
       "default: 32 KiB per byte of the file, at least 64 MiB)"},
      {"info", run_info, {"IN.gab [--json]"}, "what a .gab file holds (checksums verified, nothing decoded)"},
      {"demo", run_demo, {""}, "compress a real mesh at several anchor counts, print a table, write the meshes"},
      {"factor", run_factor, {"IN [--ordering amd|nd|natural] [--anchors K] [--repeat R] [--threads T] [--json]"},
       "order, analyze, factor and solve the least-squares matrix of a mesh (.obj .off .ply)\n"
       "or a Matrix Market file (.mtx); report sizes and median phase times"},
      {"study", run_study,
       {"IN... [--ordering amd|nd|natural[,...]] [--updates U] [--batch B] [--anchors K]",
        "[--subdivide K] [--threads T] [--csv F] [--svg F] [--json]"},
       "add U anchors to the factor one (or B) at a time by Givens rotations along the\n"
       "elimination tree; report path lengths, entries touched, times, drift. A comma list\n"
       "of orderings studies each input under each; the growth of the touched entries with n\n"
       "is fitted per ordering (printed, and plotted log-log by --svg); nd also reports the\n"
       "separator bound on each update (JSON separator_bound_avg, null for the others)"},
      {"diff", run_diff, {"A B [--map FILE] [--samples N] [--json]"},
       "distances between two meshes (.obj .off .ply): per vertex where the numberings\n"
       "correspond (the same vertex count and triangles by index; --map FILE: line i the index in\n"
       "B of A's vertex i, as compress --order-out writes), and the symmetric surface distance\n"
       "(mean, RMS, Hausdorff) from N samples"},
      {"subdivide", run_subdivide, {"IN -o OUT [--levels K]"},
       "K levels (default 1) of 1:4 midpoint subdivision of a mesh, written to OUT (.obj .off .ply):\n"
       "the same shape at 4^K times the triangles, for scale studies"},
      {"version", run_version, {""}, "print the version (also gab --version): the library's gab_version()"},
  };
  return table;
}

const Command* find_command(const std::string& name) {
  for (const Command& c : commands()) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

std::string usage_text(const Command& command) {
  const std::string head = std::string("gab ") + command.name + " ";
  std::string text;
  for (size_t i = 0; i < command.synopsis.size(); ++i) {
    if (i > 0) text += "\n" + std::string(head.size(), ' ');
    text += command.synopsis[i];
  }
  text = head + text;
  while (!text.empty() && text.back() == ' ') text.pop_back();  // "gab demo"
  return text;
}

}  // namespace cli
}  // namespace gab
