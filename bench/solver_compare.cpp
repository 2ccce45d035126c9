// The reconstruction operators side by side through the whole codec: each
// mesh encoded at a relative RMS target (default 1e-3, --reorder, one
// thread) with the global least squares (the paper's, factored) and with
// the iterative operator (IterativeReconstruction's conjugate-gradient
// steps, linear in n), then decoded: whole-file bytes, the decoded shape's
// RMS against the original, encode and decode seconds (median of --repeat
// decodes), and the decode's parts.
//
//   bench/solver_compare [--error E] [--repeat R] [--threads T] [--out DIR] [mesh.off ...]
//   (defaults: 1e-3, 3, 1 (the decode's threads; the encode takes one), every shared mesh;
//   --out writes each file as DIR/MESH-OPERATOR.gab, for `gab decompress` to measure its memory)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/renumber.h"
#include "shared_meshes.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  double error = 1e-3;
  int repeat = 3;
  int threads = 1;
  std::string out_dir;
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--error") && i + 1 < argc) {
      error = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) {
      out_dir = argv[++i];
    } else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc) {
      threads = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else {
      rest.push_back(argv[i]);
    }
  }
  std::printf("%-12s %-9s %9s %10s %8s %8s %8s %8s %8s\n", "mesh", "operator", "bytes", "rms", "enc s", "dec s",
              "conn s", "factor s", "solve s");
  for (const std::string& path : gab_bench::mesh_paths(static_cast<int>(rest.size()), rest.data())) {
    gab::Mesh mesh;
    if (!gab::read_mesh(path, &mesh).ok()) {
      std::fprintf(stderr, "cannot read %s\n", path.c_str());
      return 1;
    }
    std::string name = path.substr(path.find_last_of('/') + 1);
    name = name.substr(0, name.find('.'));
    const double diagonal = gab::bounding_box_diagonal(mesh);
    for (gab::Solver op : {gab::Solver::kGlobal, gab::Solver::kIterative}) {
      gab::EncodeOptions options;
      options.target_rms_rel = error;
      options.reorder = true;
      options.solver = op;
      std::vector<uint8_t> file;
      gab::EncodeStats es;
      double t = now();
      const gab::Status encoded = gab::encode_mesh(mesh, options, &file, &es);
      const double encode_s = now() - t;
      if (!encoded.ok()) {
        std::fprintf(stderr, "%s: %s\n", name.c_str(), encoded.message().c_str());
        return 1;
      }
      const char* op_name = op == gab::Solver::kGlobal ? "global" : "iterative";
      if (!out_dir.empty()) {
        const std::string out = out_dir + "/" + name + "-" + op_name + ".gab";
        const gab::Status written = gab::write_output_file(
            out, std::string_view(reinterpret_cast<const char*>(file.data()), file.size()));
        if (!written.ok()) {
          std::fprintf(stderr, "%s\n", written.message().c_str());
          return 1;
        }
      }
      std::vector<double> seconds;
      gab::Mesh decoded;
      gab::DecodeStats ds;
      gab::DecodeOptions decode;
      decode.threads = threads;
      for (int r = 0; r < repeat; ++r) {
        t = now();
        const gab::Status s = gab::decode_mesh(file.data(), file.size(), decode, &decoded, &ds);
        seconds.push_back(now() - t);
        if (!s.ok()) {
          std::fprintf(stderr, "%s: decode: %s\n", name.c_str(), s.message().c_str());
          return 1;
        }
      }
      std::sort(seconds.begin(), seconds.end());
      // The decoded mesh is numbered in the coder's order: compare in it.
      const gab::Mesh original = gab::renumber_vertices(mesh, es.new_index);
      gab::VertexDistance distance;
      if (!gab::vertex_distance(original, decoded, &distance).ok()) {
        std::fprintf(stderr, "%s: the decoded mesh does not match\n", name.c_str());
        return 1;
      }
      const double rms = distance.rms / diagonal;
      std::printf("%-12s %-9s %9zu %10.3e %8.2f %8.3f %8.3f %8.3f %8.3f\n", name.c_str(), op_name, file.size(), rms,
                  encode_s,
                  seconds[seconds.size() / 2], ds.connectivity_s, ds.factor_s, ds.solve_s);
      std::fflush(stdout);
    }
  }
  return 0;
}
