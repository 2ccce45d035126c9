// gab subdivide (its options: commands.cpp): levels of 1:4 midpoint
// subdivision written to a mesh file, the input of scale studies: bunny00
// after three levels is issue 19's 2.4M-vertex mesh, which `gab study
// --subdivide` builds in memory only.
#include <cstdio>
#include <string>

#include "cli.h"
#include "commands.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/subdivide.h"

namespace gab {
namespace cli {

int run_subdivide(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {"-o", "--levels"}, {})) return usage_error("subdivide", args.error());
  if (args.positionals().size() != 1) return usage_error("subdivide", "expected one input mesh");
  if (!args.has("-o")) return usage_error("subdivide", "need -o OUT");
  int64_t levels = 1;
  // Each level multiplies the size by 4: 6 levels take a 40k-vertex mesh to 160M vertices.
  if (!args.get_int("--levels", 0, 6, &levels)) return usage_error("subdivide", args.error());
  const std::string in = args.positionals()[0], out = args.get("-o");
  if (const int refused = check_output("subdivide", out, {in})) return refused;
  Mesh mesh;
  Status status = read_mesh_warning(in, &mesh);
  if (!status.ok()) return fail(status.message());
  // The subdivision makes positions and triangles only: what else the input
  // carries is named, not lost silently.
  if (!mesh.attributes.empty()) {
    std::string names;
    for (const MeshAttribute& a : mesh.attributes) names += (names.empty() ? "" : ", ") + attribute_label(a);
    std::fprintf(stderr, "gab subdivide: warning: %s: not subdivided, left out of %s: %s\n", in.c_str(), out.c_str(),
                 names.c_str());
  }
  const Mesh fine = subdivide_midpoint(mesh, static_cast<int>(levels));
  status = write_mesh(out, fine);
  if (!status.ok()) return fail(status.message());
  std::printf("%s -> %s: %d vertices, %d triangles after %d levels\n", in.c_str(), out.c_str(), fine.num_vertices(),
              fine.num_triangles(), static_cast<int>(levels));
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
