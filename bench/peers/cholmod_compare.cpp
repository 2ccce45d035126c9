// Side-by-side timing of gab against CHOLMOD (supernodal, single thread) on
// the same matrices and the same ordering (gab's AMD permutation is given to
// CHOLMOD), plus SuiteSparse AMD against gab's AMD. Built only with
// -DGAB_BENCH_CHOLMOD=ON when SuiteSparse is installed; run with
// OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1. Prints a markdown table.
//
//   bench/peers/cholmod_compare [mesh.off ...]   (default: ../shared/meshes)
#include <amd.h>
#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/off_io.h"
#include "gab/sparse/amd.h"
#include "gab/sparse/cholesky.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

constexpr int kRepeat = 5;

void compare(const std::string& path) {
  gab::Mesh mesh;
  if (!gab::read_off(path, &mesh).ok()) {
    std::fprintf(stderr, "skip %s\n", path.c_str());
    return;
  }
  const gab::EdgeGraph g = gab::build_edge_graph(mesh);
  const std::vector<int32_t> anchors = gab::benchmark_anchors(g, 100);
  gab::CscMatrix a;
  gab::assemble_normal_matrix(g, anchors, 1.0, &a);
  const std::vector<double> rhs = gab::anchor_right_hand_sides(mesh, anchors, 1.0);
  const int32_t n = a.ncols;

  // gab: AMD, analysis, factor, solve.
  std::vector<double> t_order, t_factor, t_solve;
  std::vector<int32_t> perm;
  gab::Cholesky chol;
  for (int r = 0; r < kRepeat; ++r) {
    double t0 = now();
    gab::amd_order(a, &perm);
    t_order.push_back(now() - t0);
  }
  gab::AnalyzeOptions options;
  options.ordering = gab::Ordering::kGiven;
  options.given_perm = perm;
  chol.analyze(a, options);
  std::vector<double> x;
  for (int r = 0; r < kRepeat; ++r) {
    double t0 = now();
    chol.factorize(a);
    double t1 = now();
    x = rhs;
    chol.solve(x.data(), 3, n);
    double t2 = now();
    t_factor.push_back(t1 - t0);
    t_solve.push_back(t2 - t1);
  }

  // SuiteSparse AMD on the same pattern (full symmetric, no diagonal needed).
  const gab::CscMatrix graph = gab::symmetric_graph(a);
  std::vector<int32_t> ss_perm(n);
  std::vector<double> t_ss_order;
  double control[AMD_CONTROL], info[AMD_INFO];
  amd_defaults(control);
  for (int r = 0; r < kRepeat; ++r) {
    double t0 = now();
    amd_order(n, graph.colptr.data(), graph.rowind.data(), ss_perm.data(), control, info);
    t_ss_order.push_back(now() - t0);
  }
  const double ss_amd_lnz = info[AMD_LNZ] + n;

  // CHOLMOD: lower-triangle symmetric matrix, gab's permutation given.
  cholmod_common c;
  cholmod_start(&c);
  c.nmethods = 1;
  c.method[0].ordering = CHOLMOD_GIVEN;
  c.supernodal = CHOLMOD_SUPERNODAL;
  c.postorder = 1;
  cholmod_sparse* ca = cholmod_allocate_sparse(n, n, a.nnz(), 1, 1, -1, CHOLMOD_REAL, &c);
  std::copy(a.colptr.begin(), a.colptr.end(), static_cast<int32_t*>(ca->p));
  std::copy(a.rowind.begin(), a.rowind.end(), static_cast<int32_t*>(ca->i));
  std::copy(a.values.begin(), a.values.end(), static_cast<double*>(ca->x));
  std::vector<int32_t> given = perm;
  cholmod_factor* lf = cholmod_analyze_p(ca, given.data(), nullptr, 0, &c);
  cholmod_dense* b = cholmod_allocate_dense(n, 3, n, CHOLMOD_REAL, &c);
  std::copy(rhs.begin(), rhs.end(), static_cast<double*>(b->x));
  std::vector<double> c_factor, c_solve;
  for (int r = 0; r < kRepeat; ++r) {
    double t0 = now();
    cholmod_factorize(ca, lf, &c);
    double t1 = now();
    cholmod_dense* xs = cholmod_solve(CHOLMOD_A, lf, b, &c);
    double t2 = now();
    cholmod_free_dense(&xs, &c);
    c_factor.push_back(t1 - t0);
    c_solve.push_back(t2 - t1);
  }
  const double c_lnz = c.lnz;
  const double c_fl = c.fl;

  const std::string name = path.substr(path.find_last_of('/') + 1);
  std::printf("| %s | %d | %lld | %.0f | %.0f | %.4f | %.4f | %.2fx | %.4f | %.4f | %.2fx | %.4f | %.4f | %.2fx | %.1f | %.1f |\n",
              name.c_str(), n, static_cast<long long>(chol.symbolic().nnz_L), ss_amd_lnz, c_lnz,
              median(t_order), median(t_ss_order), median(t_ss_order) / median(t_order),
              median(t_factor), median(c_factor), median(c_factor) / median(t_factor),
              median(t_solve), median(c_solve), median(c_solve) / median(t_solve),
              chol.symbolic().flops / median(t_factor) * 1e-9, c_fl / median(c_factor) * 1e-9);
  std::fflush(stdout);
  cholmod_free_dense(&b, &c);
  cholmod_free_factor(&lf, &c);
  cholmod_free_sparse(&ca, &c);
  cholmod_finish(&c);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) inputs.push_back(argv[i]);
  if (inputs.empty()) {
    for (const char* m : {"bunny-small", "camel-head", "max-planck", "bunny", "horse", "feline",
                          "nefertiti", "igea"}) {
      inputs.push_back(std::string(GAB_SHARED_MESHES) + "/" + m + ".off");
    }
  }
  std::printf("| mesh | n | nnz(L) gab | nnz(L) SuiteSparse AMD | nnz(L) CHOLMOD (gab perm) | "
              "order gab s | order SS-AMD s | ratio | factor gab s | factor CHOLMOD s | ratio | "
              "solve3 gab s | solve3 CHOLMOD s | ratio | GFLOP/s gab | GFLOP/s CHOLMOD |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : inputs) compare(path);
  return 0;
}
