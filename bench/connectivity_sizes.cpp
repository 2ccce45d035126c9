// Connectivity bytes and times per mesh: today's triangle-list coder (the
// .gab connectivity block, order kept) beside the valence coder (issue 17:
// order and numbering not kept, i.e. what --reorder will write), with a
// check that the valence section decodes to the input's oriented triangles.
// Draco 1.5.5's connectivity (-cl 10, its -qp 1 file) for comparison is in
// issue 17.
//
//   bench/connectivity_sizes [mesh ...]   (default: the shared meshes)
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_check.h"
#include "connectivity/connectivity_coder.h"
#include "connectivity/valence_section.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/triangle_set.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths(argv + 1, argv + argc);
  if (paths.empty()) {
    for (const char* name : {"igea", "nefertiti", "feline", "horse", "max-planck", "bunny", "bunny-small", "camel-head"}) {
      paths.push_back(std::string(GAB_SHARED_MESHES) + "/" + name + ".off");
    }
  }
  std::printf("| mesh | n | list coder bytes | valence bytes | bits/vertex | encode s | decode s |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : paths) {
    gab::Mesh mesh;
    gab_bench::check(gab::read_mesh(path, &mesh), path.c_str());
    const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
    const size_t list_bytes = gab::encode_connectivity(n, mesh.triangles).size();
    double t0 = now();
    const gab::ValenceSection section = gab::encode_valence_section(n, mesh.triangles);
    const double encode_s = now() - t0;
    std::vector<int32_t> decoded;
    t0 = now();
    gab_bench::check(gab::decode_valence_section(section.bytes.data(), section.bytes.size(), n, t, &decoded),
                     path.c_str());
    const double decode_s = now() - t0;
    std::vector<int32_t> renamed;
    for (int32_t v : mesh.triangles) renamed.push_back(section.new_index[v]);
    if (gab::oriented_triangle_set(decoded) != gab::oriented_triangle_set(renamed)) {
      std::fprintf(stderr, "%s: the valence section does not round-trip\n", path.c_str());
      return 1;
    }
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("| %s | %d | %zu | %zu | %.3f | %.3f | %.3f |\n", name.c_str(), n, list_bytes, section.bytes.size(),
                8.0 * static_cast<double>(section.bytes.size()) / n, encode_s, decode_s);
  }
  return 0;
}
