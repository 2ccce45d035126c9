// Connectivity bytes and times per mesh: today's triangle-list coder (the
// .gab connectivity block, order kept) beside the valence coder (issue 17:
// order and numbering not kept, i.e. what --reorder will write), version 1
// and the latest, with a check that each valence section decodes to the
// input's oriented triangles. Times are the latest version's, the median of
// five runs. Draco 1.5.5's connectivity (-cl 10, its -qp 1 file) for
// comparison is in issue 17.
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
#include "connectivity/connectivity_coder.h"
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

// Codes `mesh` with `version` `repeats` times, checks the round trip, and
// returns the bytes and the median times.
Run run_version(const gab::Mesh& mesh, int version, int repeats, const std::string& path) {
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  std::vector<double> encode_s, decode_s;
  gab::ValenceSection section;
  std::vector<int32_t> decoded;
  for (int r = 0; r < repeats; ++r) {
    double t0 = now();
    section = gab::encode_valence_section(n, mesh.triangles, version);
    encode_s.push_back(now() - t0);
    t0 = now();
    gab_bench::check(gab::decode_valence_section(section.bytes.data(), section.bytes.size(), n, t, &decoded, version),
                     path.c_str());
    decode_s.push_back(now() - t0);
  }
  std::vector<int32_t> renamed;
  for (int32_t v : mesh.triangles) renamed.push_back(section.new_index[v]);
  if (gab::oriented_triangle_set(decoded) != gab::oriented_triangle_set(renamed)) {
    std::fprintf(stderr, "%s: the version %d valence section does not round-trip\n", path.c_str(), version);
    std::exit(1);
  }
  return {section.bytes.size(), median(encode_s), median(decode_s)};
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> paths = gab_bench::mesh_paths(argc, argv);
  const int latest = gab::kValenceVersionLatest;
  std::printf("| mesh | n | list coder bytes | valence v1 bytes | valence v%d bytes | v%d bits/vertex | v%d encode s | "
              "v%d decode s |\n",
              latest, latest, latest, latest);
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : paths) {
    gab::Mesh mesh;
    gab_bench::check(gab::read_mesh(path, &mesh), path.c_str());
    const int32_t n = mesh.num_vertices();
    const size_t list_bytes = gab::encode_connectivity(n, mesh.triangles).size();
    const Run v1 = run_version(mesh, 1, 1, path);
    const Run last = run_version(mesh, latest, 5, path);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("| %s | %d | %zu | %zu | %zu | %.3f | %.3f | %.3f |\n", name.c_str(), n, list_bytes, v1.bytes,
                last.bytes, 8.0 * static_cast<double>(last.bytes) / n, last.encode_s, last.decode_s);
  }
  return 0;
}
