// gab demo (its options: commands.cpp)
// The main job of the quick start: a real mesh (libcgal-demo's camel, which
// scripts/setup-and-run.sh unpacks into data/meshes/; else $GAB_DEMO_MESH;
// else a bumpy sphere made in code) compressed at several anchor counts, a
// table in the spirit of the paper's Figure 6 (anchors, bytes, bits per
// vertex, errors), every file decoded again and checked, and the decoded
// meshes written to gab-demo/ for viewing.
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli.h"
#include "commands.h"
#include "demo_mesh.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/renumber.h"

namespace gab {
namespace cli {

namespace {

const char* kOutDir = "gab-demo";

bool exists(const std::string& path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

// The demo's input and a name for it.
Status demo_input(Mesh* mesh, std::string* name) {
  const char* env = std::getenv("GAB_DEMO_MESH");
  for (const std::string& path : {env ? std::string(env) : std::string(), std::string("data/meshes/camel.off")}) {
    if (!path.empty() && exists(path)) {
      *name = path;
      return read_mesh_warning(path, mesh);
    }
  }
  *name = "a bumpy sphere (generated; run scripts/setup-and-run.sh for libcgal-demo's camel)";
  *mesh = bumpy_sphere(5);
  return Status::Ok();
}

}  // namespace

int run_demo(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {}, {}) || !args.positionals().empty()) {
    return usage_error("demo", args.error().empty() ? "takes no arguments" : args.error());
  }
  Mesh mesh;
  std::string name;
  Status status = demo_input(&mesh, &name);
  if (!status.ok()) return fail(status.message());
  if (!exists(kOutDir) && mkdir(kOutDir, 0777) != 0) return fail(std::string("cannot create ") + kOutDir);
  status = write_mesh(std::string(kOutDir) + "/original.off", mesh);
  if (!status.ok()) return fail(status.message());
  const int32_t n = mesh.num_vertices();
  std::printf("gab demo: %s\n%d vertices, %d triangles; q = 12 bits, w = 100\n\n", name.c_str(), n,
              mesh.num_triangles());
  std::printf("%8s %10s %10s %10s %11s %11s %9s %9s\n", "anchors", "bytes", "geo bytes", "geo b/v", "rms_rel",
              "linf_rel", "encode s", "decode s");
  for (double fraction : {0.005, 0.01, 0.02, 0.05, 0.1}) {
    EncodeOptions options;
    options.max_anchors = std::max(1, static_cast<int32_t>(std::lround(fraction * n)));
    options.threads = default_threads();
    std::vector<uint8_t> file;
    EncodeStats es;
    status = encode_mesh(mesh, options, &file, &es);
    if (!status.ok()) return fail(status.message());
    Mesh decoded;
    DecodeStats ds;
    DecodeOptions decode_options;
    decode_options.threads = default_threads();
    status = decode_mesh(file.data(), file.size(), decode_options, &decoded, &ds);
    if (!status.ok()) return fail("decoding the demo's own file: " + status.message());
    // The default file numbers the vertices in traversal order: the input
    // is compared in that numbering (es.new_index), vertex by vertex.
    VertexDistance d;
    status = vertex_distance(es.reordered ? renumber_vertices(mesh, es.new_index) : mesh, decoded, &d);
    if (!status.ok()) return fail(status.message());
    const double diagonal = bounding_box_diagonal(mesh);
    // The decoder must see what the encoder saw (to rounding).
    if (std::fabs(d.rms / diagonal - es.rms_rel) > 1e-9) {
      return fail("decoded shape differs from the encoder's reconstruction");
    }
    const std::string stem = std::string(kOutDir) + "/anchors-" + std::to_string(es.anchors);
    status = write_output_file(stem + ".gab", std::string_view(reinterpret_cast<const char*>(file.data()), file.size()));
    if (status.ok()) status = write_mesh(stem + ".off", decoded);
    if (!status.ok()) return fail(status.message());
    std::printf("%8d %10zu %10zu %10.3f %11.3e %11.3e %9.2f %9.2f\n", es.anchors, es.bytes, es.geometry_bytes,
                8.0 * es.geometry_bytes / n, d.rms / diagonal, d.linf / diagonal, es.encode_s, ds.decode_s);
  }
  std::printf("\nerrors: 3D vertex distance to the original over the bounding-box diagonal.\n"
              "files and decoded meshes: %s/ (anchors-K.gab, anchors-K.off, original.off)\n", kOutDir);
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
