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
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "../bench_check.h"
#include "cholmod_updown.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/off_io.h"
#include "gab/sparse/amd.h"
#include "gab/sparse/cholesky.h"
#include "gab/sparse/update.h"

namespace {

std::vector<std::string> update_rows;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.3g", v);
  return buf;
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

constexpr int kRepeat = 5;
// gab's threads for factor and solves (--threads T; CHOLMOD stays on one).
int32_t g_threads = 1;
constexpr int kUpdates = 1000;

// Single-core copy bandwidth (bytes read + written per second) over a
// buffer much larger than the caches: the ceiling for streaming updates.
double copy_bandwidth() {
  const size_t n = size_t{1} << 26;  // 512 MiB per array
  std::vector<double> a(n, 1.0), b(n, 2.0);
  std::vector<double> t;
  for (int r = 0; r < 5; ++r) {
    double t0 = now();
    for (size_t i = 0; i < n; ++i) b[i] = a[i] * 1.000001;
    t.push_back(now() - t0);
  }
  return 2.0 * n * sizeof(double) / median(t);
}

void compare(const std::string& path) {
  gab::Mesh mesh;
  if (!gab::read_off(path, &mesh).ok()) {
    std::fprintf(stderr, "skip %s\n", path.c_str());
    return;
  }
  const gab::EdgeGraph g = gab::build_edge_graph(mesh);
  const std::vector<int32_t> anchors = gab::benchmark_anchors(g, 100);
  gab::CscMatrix a;
  gab_bench::check(gab::assemble_normal_matrix(g, anchors, 1.0, &a), "cholmod_compare: gab::assemble_normal_matrix");
  const std::vector<double> rhs = gab::anchor_right_hand_sides(mesh, anchors, 1.0);
  const int32_t n = a.ncols;

  // gab: AMD, analysis, factor, solve.
  std::vector<double> t_order, t_factor, t_solve;
  std::vector<int32_t> perm;
  gab::Cholesky chol;
  for (int r = 0; r < kRepeat; ++r) {
    double t0 = now();
    gab_bench::check(gab::amd_order(a, &perm), "cholmod_compare: gab::amd_order");
    t_order.push_back(now() - t0);
  }
  gab::AnalyzeOptions options;
  options.ordering = gab::Ordering::kGiven;
  options.given_perm = perm;
  options.threads = g_threads;
  gab_bench::check(chol.analyze(a, options), "cholmod_compare: chol.analyze");
  std::vector<double> x;
  for (int r = 0; r < kRepeat; ++r) {
    double t0 = now();
    gab_bench::check(chol.factorize(a), "cholmod_compare: chol.factorize");
    double t1 = now();
    x = rhs;
    gab_bench::check(chol.solve(x.data(), 3, n), "cholmod_compare: chol.solve");
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

  // Updates: CHOLMOD must first convert to a simplicial LDL^T (not timed),
  // then cholmod_updown with one column (single) or eight (rank-8 batch).
  // C holds w = 1 at the permuted row of each anchor.
  const std::vector<int32_t> seq = gab::benchmark_update_sequence(n, anchors, kUpdates);
  const std::vector<int32_t> cinv = gab_bench::factor_inverse_perm(lf);
  auto updown = [&](cholmod_factor* f, int32_t first, int32_t width) {
    return gab_bench::timed_updown(f, cinv, seq.data() + first, width, &c);
  };
  cholmod_factor* lsingle = cholmod_copy_factor(lf, &c);
  cholmod_change_factor(CHOLMOD_REAL, 0, 0, 1, 1, lsingle, &c);
  cholmod_factor* lbatch = cholmod_copy_factor(lsingle, &c);
  std::vector<double> cu_single, cu_batch;
  for (int u = 0; u < kUpdates; ++u) cu_single.push_back(updown(lsingle, u, 1));
  for (int u = 0; u + 8 <= kUpdates; u += 8) cu_batch.push_back(updown(lbatch, u, 8) / 8.0);
  cholmod_free_factor(&lsingle, &c);
  cholmod_free_factor(&lbatch, &c);

  gab::Cholesky single, batch;
  gab_bench::check(single.analyze(a, options), "cholmod_compare: single.analyze");
  gab_bench::check(single.factorize(a), "cholmod_compare: single.factorize");
  gab_bench::check(batch.analyze(a, options), "cholmod_compare: batch.analyze");
  gab_bench::check(batch.factorize(a), "cholmod_compare: batch.factorize");
  gab_bench::check(single.prepare_updates(), "cholmod_compare: single.prepare_updates");  // not timed
  gab_bench::check(batch.prepare_updates(), "cholmod_compare: batch.prepare_updates");
  std::vector<double> g_single, g_batch;
  double touched_single = 0.0;
  for (int u = 0; u < kUpdates; ++u) {
    gab::UpdateStats st;
    double t0 = now();
    gab_bench::check(single.add_anchor(seq[u], 1.0, &st), "cholmod_compare: single.add_anchor");
    g_single.push_back(now() - t0);
    touched_single += static_cast<double>(st.touched);
  }
  for (int u = 0; u + 8 <= kUpdates; u += 8) {
    double t0 = now();
    gab_bench::check(batch.add_anchors(seq.data() + u, 8, 1.0), "cholmod_compare: batch.add_anchors");
    g_batch.push_back((now() - t0) / 8.0);
  }
  double sum_cs = 0, sum_gs = 0, sum_cb = 0, sum_gb = 0;
  for (double v : cu_single) sum_cs += v;
  for (double v : g_single) sum_gs += v;
  for (double v : cu_batch) sum_cb += v;
  for (double v : g_batch) sum_gb += v;
  const double avg_cs = sum_cs / cu_single.size(), avg_gs = sum_gs / g_single.size();
  const double avg_cb = sum_cb / cu_batch.size(), avg_gb = sum_gb / g_batch.size();
  update_rows.push_back(
      "| " + path.substr(path.find_last_of('/') + 1) + " | " + fmt(avg_cs * 1e3) + " | " +
      fmt(*std::max_element(cu_single.begin(), cu_single.end()) * 1e3) + " | " + fmt(avg_gs * 1e3) + " | " +
      fmt(*std::max_element(g_single.begin(), g_single.end()) * 1e3) + " | " + fmt(avg_cs / avg_gs) + "x | " +
      fmt(avg_cb * 1e3) + " | " + fmt(avg_gb * 1e3) + " | " + fmt(avg_cs / avg_gb) + "x | " +
      fmt(touched_single * 16.0 / sum_gs * 1e-9) + " |");

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
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--threads" && i + 1 < argc) {
      g_threads = std::atoi(argv[++i]);
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
  std::printf("| mesh | n | nnz(L) gab | nnz(L) SuiteSparse AMD | nnz(L) CHOLMOD (gab perm) | "
              "order gab s | order SS-AMD s | ratio | factor gab s | factor CHOLMOD s | ratio | "
              "solve3 gab s | solve3 CHOLMOD s | ratio | GFLOP/s gab | GFLOP/s CHOLMOD |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : inputs) compare(path);
  std::printf("\ngab factor and solves on %d thread(s); CHOLMOD single-threaded.\n", g_threads);
  std::printf("\nAnchor updates (%d by the benchmark rule, w = 1; CHOLMOD on its simplicial LDL^T, "
              "conversion not timed). Times in ms per anchor.\n\n", kUpdates);
  std::printf("| mesh | updown avg | updown max | gab avg | gab max | ratio | updown rank-8 per anchor | "
              "gab batch-8 per anchor | ratio vs single updown | gab GB/s touched |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& row : update_rows) std::printf("%s\n", row.c_str());
  std::printf("\nsingle-core copy bandwidth: %.1f GB/s (read + write)\n", copy_bandwidth() * 1e-9);
  return 0;
}
