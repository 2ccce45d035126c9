// Orderings compared on the benchmark matrices of the shared meshes (built as
// bench_phases.cpp's load() does: edge graph, 100 benchmark anchors, weight
// 1): for AMD and nested dissection, the ordering's time (best of 3), the
// factor's nnz(L) and flops from the symbolic analysis, and one numeric
// factorization's time. Usage: bench_ordering [mesh names...] (default: all).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "bench_check.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/off_io.h"
#include "gab/sparse/amd.h"
#include "gab/sparse/cholesky.h"
#include "gab/sparse/nested_dissection.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Best of `runs` timings of order(), which leaves its permutation in *perm.
double time_ordering(const std::function<gab::Status(std::vector<int32_t>*)>& order,
                     std::vector<int32_t>* perm, int runs) {
  double best = 1e30;
  for (int r = 0; r < runs; ++r) {
    const Clock::time_point start = Clock::now();
    gab_bench::check(order(perm), "ordering");
    best = std::min(best, seconds_since(start));
  }
  return best;
}

void report(const char* mesh, const char* method, const gab::CscMatrix& lower,
            const std::vector<int32_t>& perm, double order_seconds) {
  gab::AnalyzeOptions options;
  options.ordering = gab::Ordering::kGiven;
  options.given_perm = perm;
  gab::Cholesky chol;
  gab_bench::check(chol.analyze(lower, options), "analyze");
  const Clock::time_point start = Clock::now();
  gab_bench::check(chol.factorize(lower), "factorize");
  const double factor_seconds = seconds_since(start);
  const gab::SymbolicFactor& f = chol.symbolic();
  std::printf("| %-11s | %-4s | %8.3f | %10.3fM | %9.3e | %8.3f |\n", mesh, method, order_seconds,
              f.nnz_L * 1e-6, f.flops, factor_seconds);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names(argv + 1, argv + argc);
  if (names.empty()) {
    names = {"bunny-small", "camel-head", "max-planck", "bunny", "horse", "feline", "nefertiti", "igea"};
  }
  std::printf("| mesh        | ord  | order s  | nnz(L)      | flops     | factor s |\n");
  std::printf("|-------------|------|----------|-------------|-----------|----------|\n");
  for (const std::string& name : names) {
    const std::string path = std::string(GAB_SHARED_MESHES) + "/" + name + ".off";
    if (!std::ifstream(path)) {
      std::fprintf(stderr, "%s: not found, skipped\n", path.c_str());
      continue;
    }
    gab::Mesh mesh;
    gab_bench::check(gab::read_off(path, &mesh), "read_off");
    const gab::EdgeGraph g = gab::build_edge_graph(mesh);
    const std::vector<int32_t> anchors = gab::benchmark_anchors(g, 100);
    gab::CscMatrix lower;
    gab_bench::check(gab::assemble_normal_matrix(g, anchors, 1.0, &lower), "assemble_normal_matrix");

    std::vector<int32_t> perm;
    double t = time_ordering([&](std::vector<int32_t>* p) { return gab::amd_order(lower, p); }, &perm, 3);
    report(name.c_str(), "AMD", lower, perm, t);
    t = time_ordering([&](std::vector<int32_t>* p) { return gab::nested_dissection_order(lower, p); },
                      &perm, 3);
    report(name.c_str(), "ND", lower, perm, t);
  }
  return 0;
}
