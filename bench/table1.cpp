// The paper's Table I on our meshes: factorization, one-rhs solve, average
// anchor update over ranges of anchor counts, worst update (the benchmark
// rule of docs/cli.md, "gab factor" and "gab study": k0 = 100 spread anchors, updates by
// v_t = t * 2654435761 mod n). Prints a markdown table beside the paper's
// Igea figures (2.4 GHz Pentium 4, TAUCS).
//
//   bench/table1 [--updates U] [mesh.off ...]   (default: ../shared/meshes, U = 2000)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench_check.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/off_io.h"
#include "gab/sparse/cholesky.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void row(const std::string& path, int updates) {
  gab::Mesh mesh;
  if (!gab::read_off(path, &mesh).ok()) return;
  const gab::EdgeGraph g = gab::build_edge_graph(mesh);
  const std::vector<int32_t> anchors = gab::benchmark_anchors(g, 100);
  gab::CscMatrix a;
  gab_bench::check(gab::assemble_normal_matrix(g, anchors, 1.0, &a), "table1: assembly");
  const int32_t n = a.ncols;
  gab::Cholesky chol;
  gab_bench::check(chol.analyze(a), "table1: analyze");
  std::vector<double> tf, ts;
  for (int r = 0; r < 3; ++r) {
    double t0 = now();
    gab_bench::check(chol.factorize(a), "table1: factorize");
    tf.push_back(now() - t0);
  }
  std::vector<double> b = gab::anchor_right_hand_sides(mesh, anchors, 1.0);
  for (int r = 0; r < 5; ++r) {
    std::vector<double> x(b.begin(), b.begin() + n);
    double t0 = now();
    gab_bench::check(chol.solve(x.data(), 1, n), "table1: solve");
    ts.push_back(now() - t0);
  }
  std::vector<char> anchored(n, 0);
  for (int32_t v : anchors) anchored[v] = 1;
  gab_bench::check(chol.prepare_updates(), "table1: prepare_updates");  // not inside the first update's time
  std::vector<double> tu;
  for (uint64_t t = 1; static_cast<int>(tu.size()) < updates && static_cast<int>(tu.size()) < n - 200; ++t) {
    const int32_t v = static_cast<int32_t>((t * 2654435761ull) % static_cast<uint64_t>(n));
    if (anchored[v]) continue;
    anchored[v] = 1;
    double t0 = now();
    gab_bench::check(chol.add_anchor(v, 1.0), "table1: add_anchor");
    tu.push_back(now() - t0);
  }
  auto avg = [&](size_t lo, size_t hi) {
    hi = std::min(hi, tu.size());
    double s = 0;
    for (size_t i = lo; i < hi; ++i) s += tu[i];
    return hi > lo ? s / (hi - lo) : 0.0;
  };
  const std::string name = path.substr(path.find_last_of('/') + 1);
  std::printf("| %s | %d | %.4f | %.5f | %.5f | %.5f | %.5f | %.5f | %.3f |\n", name.c_str(), n,
              median(tf), median(ts), avg(0, 200), avg(200, 1000), avg(1000, tu.size()),
              *std::max_element(tu.begin(), tu.end()), avg(0, tu.size()) / median(ts));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  int updates = 2000;
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--updates") && i + 1 < argc) {
      updates = std::atoi(argv[++i]);
    } else {
      inputs.push_back(argv[i]);
    }
  }
  if (inputs.empty()) {
    for (const char* m : {"bunny-small", "camel-head", "max-planck", "bunny", "horse", "feline",
                          "nefertiti", "igea"}) {
      inputs.push_back(std::string(GAB_SHARED_MESHES) + "/" + m + ".off");
    }
  }
  std::printf("| mesh | n | factor s | solve s (1 rhs) | update avg s, anchors 1-200 | 201-1000 | "
              "1001-%d | worst update s | avg update / solve |\n", updates);
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::printf("| Igea, paper (P4 2.4 GHz) | 134345 | 11.826 | 0.444 | 0.0200 (avg) | | | 0.0215 | 0.045 |\n");
  for (const std::string& p : inputs) row(p, updates);
  return 0;
}
