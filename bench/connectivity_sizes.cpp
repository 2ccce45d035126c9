// Connectivity bytes and times per mesh: the valence section (what a
// --reorder file holds; the vertex order block is order_sizes'), with a
// check that it decodes to the input's oriented triangles. Times are the
// median of five runs.
//
//   bench/connectivity_sizes [mesh ...]   (default: the shared meshes)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_check.h"
#include "shared_meshes.h"
#include "connectivity/valence_section.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/triangle_set.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Run {
  size_t bytes = 0;
  double encode_s = 0, decode_s = 0;
};

// Codes `mesh` `repeats` times, checks the round trip, and returns the
// bytes and the median times.
Run run(const gab::Mesh& mesh, int repeats, const std::string& path) {
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  std::vector<double> encode_s, decode_s;
  gab::ValenceSection section;
  std::vector<int32_t> decoded;
  for (int r = 0; r < repeats; ++r) {
    double t0 = now();
    section = gab::encode_valence_section(n, mesh.triangles);
    encode_s.push_back(now() - t0);
    t0 = now();
    gab_bench::check(gab::decode_valence_section(section.bytes.data(), section.bytes.size(), n, t, &decoded),
                     path.c_str());
    decode_s.push_back(now() - t0);
  }
  std::vector<int32_t> renamed;
  for (int32_t v : mesh.triangles) renamed.push_back(section.new_index[v]);
  if (gab::oriented_triangle_set(decoded) != gab::oriented_triangle_set(renamed)) {
    std::fprintf(stderr, "%s: the valence section does not round-trip\n", path.c_str());
    std::exit(1);
  }
  return {section.bytes.size(), median(encode_s), median(decode_s)};
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> paths = gab_bench::mesh_paths(argc, argv);
  std::printf("| mesh | n | bytes | bits/vertex | encode s | decode s |\n");
  std::printf("|---|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : paths) {
    gab::Mesh mesh;
    gab_bench::check(gab::read_mesh(path, &mesh), path.c_str());
    const int32_t n = mesh.num_vertices();
    const Run r = run(mesh, 5, path);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("| %s | %d | %zu | %.3f | %.3f | %.3f |\n", name.c_str(), n, r.bytes,
                8.0 * static_cast<double>(r.bytes) / n, r.encode_s, r.decode_s);
  }
  return 0;
}
