// What keeping the input's vertex numbering costs (issue 17): per mesh, the
// order block's bytes (connectivity/order_coder.h) beside log2(n!)/8, the
// price of an arbitrary numbering, and the same for a random renumbering of
// the mesh, with encode and decode times and a round-trip check.
//
//   bench/order_sizes [mesh ...]   (default: the shared meshes)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "bench_check.h"
#include "shared_meshes.h"
#include "connectivity/order_coder.h"
#include "connectivity/valence_section.h"
#include "gab/mesh/mesh_io.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Cost {
  size_t bytes;
  double encode_s, decode_s;
};

// The order block of `triangles` over n vertices as the codec writes it.
Cost order_cost(int32_t n, const std::vector<int32_t>& triangles) {
  const gab::ValenceSection section = gab::encode_valence_section(n, triangles);
  std::vector<int32_t> decoded;
  gab_bench::check(gab::decode_valence_section(section.bytes.data(), section.bytes.size(), n,
                                               static_cast<int32_t>(triangles.size() / 3), &decoded),
                   "valence section");
  std::vector<int32_t> original(static_cast<size_t>(n));
  for (int32_t v = 0; v < n; ++v) original[section.new_index[v]] = v;
  const double t0 = now();
  const std::vector<uint8_t> block = gab::encode_vertex_order(n, decoded, original);
  const double t1 = now();
  std::vector<int32_t> back;
  gab_bench::check(gab::decode_vertex_order(block.data(), block.size(), n, decoded, &back), "order block");
  const double t2 = now();
  if (back != original) {
    std::fprintf(stderr, "order block does not round-trip\n");
    std::exit(1);
  }
  return {block.size(), t1 - t0, t2 - t1};
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> paths = gab_bench::mesh_paths(argc, argv);
  std::printf("| mesh | n | log2(n!)/8 | order bytes | share of bound | encode s | decode s | randomly renumbered: bytes | share |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : paths) {
    gab::Mesh mesh;
    gab_bench::check(gab::read_mesh(path, &mesh), path.c_str());
    const int32_t n = mesh.num_vertices();
    const double bound = std::lgamma(static_cast<double>(n) + 1.0) / std::log(2.0) / 8.0;
    const Cost own = order_cost(n, mesh.triangles);
    std::vector<int32_t> shuffle(static_cast<size_t>(n));
    std::iota(shuffle.begin(), shuffle.end(), 0);
    std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937(12345));
    std::vector<int32_t> shuffled(mesh.triangles.size());
    for (size_t i = 0; i < shuffled.size(); ++i) shuffled[i] = shuffle[mesh.triangles[i]];
    const Cost random = order_cost(n, shuffled);
    const size_t slash = path.find_last_of('/');
    std::printf("| %s | %d | %.0f | %zu | %.4f | %.4f | %.4f | %zu | %.4f |\n",
                path.substr(slash == std::string::npos ? 0 : slash + 1).c_str(), n, bound, own.bytes,
                own.bytes / bound, own.encode_s, own.decode_s, random.bytes, random.bytes / bound);
  }
  return 0;
}
