// Error curves of the codec's greedy anchor selection (Sorkine et al. 2005,
// sec. IV; encode_mesh, anchors only) on the shared meshes: the paper's
// one-anchor-per-step rule against batched steps (1-ring local maxima of the
// error, `--batch-fraction` of the anchors so far), w = 100, coefficients on
// a q = 16 grid, from a farthest-point spread set of `--initial` x k
// anchors. Prints, per mesh, the relative vertex RMS and max error at 0.5,
// 1, 2, 5 and 10% of n (one at a time only up to `--single-max` anchors:
// each step is a solve), with the seconds of the whole encode.
//
//   bench/greedy_curves [--batch-fraction F] [--initial R] [--single-max K] [mesh.off ...]
//   (defaults: 0.05, 0.5, 1500, every mesh of ../shared/meshes)
#include <dirent.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gab/codec/encoder.h"
#include "gab/mesh/mesh_io.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Point {
  gab::GreedyStep step;
  double seconds;
};

// One greedy run to exactly k anchors; the last point of its curve.
Point run(const gab::Mesh& mesh, int32_t k, int32_t initial, double batch) {
  gab::EncodeOptions options;
  options.weight = 100;
  options.max_anchors = k;
  options.initial_anchors = std::max(1, initial);
  options.batch_fraction = batch;
  options.bits = 16;
  options.detail = gab::DetailMode::kOff;
  std::vector<uint8_t> file;
  gab::EncodeStats stats;
  const double t = now();
  const gab::Status s = gab::encode_mesh(mesh, options, &file, &stats);
  if (!s.ok()) {
    std::fprintf(stderr, "greedy_curves: %s\n", s.message().c_str());
    std::exit(1);
  }
  return {stats.curve.back(), now() - t};
}

}  // namespace

int main(int argc, char** argv) {
  double batch = 0.05, initial_ratio = 0.5;
  int32_t single_max = 1500;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--batch-fraction") && i + 1 < argc) {
      batch = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--initial") && i + 1 < argc) {
      initial_ratio = std::atof(argv[++i]);
    } else if (!std::strcmp(argv[i], "--single-max") && i + 1 < argc) {
      single_max = std::atoi(argv[++i]);
    } else {
      meshes.push_back(argv[i]);
    }
  }
  if (meshes.empty()) {
    if (DIR* d = opendir(GAB_SHARED_MESHES)) {
      while (dirent* e = readdir(d)) {
        const std::string name = e->d_name;
        if (name.size() > 4 && name.substr(name.size() - 4) == ".off") meshes.push_back(GAB_SHARED_MESHES "/" + name);
      }
      closedir(d);
    }
    std::sort(meshes.begin(), meshes.end());
  }
  std::printf("| mesh | n | k | batched %g%%: rms_rel | linf_rel | s | one at a time: rms_rel | linf_rel | s |\n",
              100 * batch);
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : meshes) {
    gab::Mesh mesh;
    const gab::Status s = gab::read_mesh(path, &mesh);
    if (!s.ok()) {
      std::fprintf(stderr, "greedy_curves: %s\n", s.message().c_str());
      return 1;
    }
    const std::string name = path.substr(path.find_last_of('/') + 1);
    for (double fraction : {0.005, 0.01, 0.02, 0.05, 0.1}) {
      const int32_t k = std::max(2, static_cast<int32_t>(std::lround(fraction * mesh.num_vertices())));
      const int32_t initial = static_cast<int32_t>(initial_ratio * k);
      const Point b = run(mesh, k, initial, batch);
      std::printf("| %s | %d | %d | %.3e | %.3e | %.2f |", name.c_str(), mesh.num_vertices(), k, b.step.rms_rel,
                  b.step.linf_rel, b.seconds);
      if (k <= single_max) {
        const Point one = run(mesh, k, initial, 0.0);
        std::printf(" %.3e | %.3e | %.2f |\n", one.step.rms_rel, one.step.linf_rel, one.seconds);
      } else {
        std::printf(" - | - | - |\n");
      }
      std::fflush(stdout);
    }
  }
  return 0;
}
