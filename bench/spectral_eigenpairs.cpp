// The smallest eigenpairs of a mesh's uniform Laplacian L = D - A (the
// spectral baseline's basis, issue 36) by the engine's shift-and-invert
// block Lanczos: seconds (and their parts; the process's CPU seconds, mesh
// reading included, for a shared machine), peak memory, solves, restarts,
// the largest relative residual ||L v - lambda v||_2 / ||L||_1 and the
// largest and k-th eigenvalue.
//
//   bench/spectral_eigenpairs MESH [--count K] [--block B] [--max-basis M]
//                             [--shift S] [--tolerance T] [--orthogonality]
//   (defaults: 1000, the solver's defaults; --orthogonality also prints
//   max |V^T V - I|, O(n K^2))
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/mesh_io.h"
#include "gab/sparse/symmetric_eigensolver.h"
#include "uniform_laplacian.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  gab::SymmetricEigenOptions o;
  o.count = 1000;
  bool orthogonality = false;
  std::string path;
  for (int i = 1; i < argc; ++i) {
    auto value = [&]() { return i + 1 < argc ? argv[++i] : "0"; };
    if (!std::strcmp(argv[i], "--count")) o.count = std::atoi(value());
    else if (!std::strcmp(argv[i], "--block")) o.block_size = std::atoi(value());
    else if (!std::strcmp(argv[i], "--max-basis")) o.max_basis = std::atoi(value());
    else if (!std::strcmp(argv[i], "--shift")) o.shift = std::atof(value());
    else if (!std::strcmp(argv[i], "--tolerance")) o.tolerance = std::atof(value());
    else if (!std::strcmp(argv[i], "--orthogonality")) orthogonality = true;
    else path = argv[i];
  }
  if (path.empty()) path = std::string(GAB_SHARED_MESHES) + "/camel-head.off";
  gab::Mesh mesh;
  gab::Status s = gab::read_mesh(path, &mesh);
  if (!s.ok()) {
    std::fprintf(stderr, "spectral_eigenpairs: %s\n", s.message().c_str());
    return 1;
  }
  const gab::CscMatrix lap = gab_bench::uniform_laplacian_lower(gab::build_edge_graph(mesh));
  const int32_t n = lap.nrows;
  gab::SymmetricEigenResult r;
  const double t0 = now();
  s = gab::smallest_eigenpairs(lap, o, &r);
  const double seconds = now() - t0;
  if (!s.ok()) {
    std::fprintf(stderr, "spectral_eigenpairs: %s\n", s.message().c_str());
    return 1;
  }
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const double worst = *std::max_element(r.residuals.begin(), r.residuals.end());
  std::printf("mesh %s n %d count %d block %d basis %d shift %.3g\n", path.c_str(), n, o.count, o.block_size,
              r.basis_columns, r.shift);
  const double cpu = usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec +
                     usage.ru_stime.tv_usec * 1e-6;
  std::printf("seconds %.2f (factor %.2f, lanczos %.2f, checks %.2f, vectors %.2f) process_cpu_s %.2f peak_rss_mb %.0f\n",
              seconds, r.factor_s, r.lanczos_s, r.check_s, r.vectors_s, cpu, usage.ru_maxrss / 1024.0);
  std::printf("solves %d restarts %d max_residual %.2e lambda_1 %.3e lambda_k %.6f\n", r.solves, r.restarts, worst,
              r.values.front(), r.values.back());
  if (orthogonality) {
    double e = 0.0;
    for (int32_t a = 0; a < o.count; ++a) {
      for (int32_t b = 0; b <= a; ++b) {
        double d = 0.0;
        for (int32_t i = 0; i < n; ++i) d += r.vectors[static_cast<size_t>(a) * n + i] * r.vectors[static_cast<size_t>(b) * n + i];
        e = std::max(e, std::abs(d - (a == b ? 1.0 : 0.0)));
      }
    }
    std::printf("orthogonality %.2e\n", e);
  }
  return 0;
}
