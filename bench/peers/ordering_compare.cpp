// Orderings side by side on the mesh matrices of DESIGN.md's benchmark rule
// (L^T L + sum_a e_a e_a^T, k0 = 100): gab's AMD, gab's nested dissection
// and CHOLMOD's METIS ordering (cholmod_metis, METIS_NodeND underneath), each
// timed (median of 3 runs), then analyzed and factored by gab with that
// permutation given, so nnz(L), flops and the entries an anchor update
// touches (mean over the benchmark's 1000 updates) are counted the same way
// for all three, and both gab's updater and cholmod_updown timed on a factor
// in each ordering. Issue 19's quality, ordering-time and update targets. Built
// only with -DGAB_BENCH_CHOLMOD=ON when SuiteSparse (with METIS) is there.
//
//   bench/peers/ordering_compare [mesh ...]   (default: ../shared/meshes' igea, horse, nefertiti, bunny)
//
// `gab subdivide data/meshes/bunny00.off -o b2.off --levels 2` writes the
// 603k-vertex mesh of the issue (3 levels: 2.4M vertices, ~6 GB here).
#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "../bench_check.h"
#include "cholmod_updown.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/sparse/amd.h"
#include "gab/sparse/cholesky.h"
#include "gab/sparse/nested_dissection.h"

namespace {

constexpr int kRepeat = 3;
constexpr int kUpdates = 1000;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// CHOLMOD's METIS permutation of the lower triangle `a`.
std::vector<int32_t> metis_order(const gab::CscMatrix& a, cholmod_common* c) {
  const int32_t n = a.ncols;
  cholmod_sparse* ca = cholmod_allocate_sparse(n, n, a.nnz(), 1, 1, -1, CHOLMOD_PATTERN, c);
  std::copy(a.colptr.begin(), a.colptr.end(), static_cast<int32_t*>(ca->p));
  std::copy(a.rowind.begin(), a.rowind.end(), static_cast<int32_t*>(ca->i));
  std::vector<int32_t> perm(n);
  if (!cholmod_metis(ca, nullptr, 0, 1, perm.data(), c)) {
    std::fprintf(stderr, "ordering_compare: cholmod_metis failed (status %d)\n", c->status);
    std::exit(1);
  }
  cholmod_free_sparse(&ca, c);
  return perm;
}

enum class Peer { kGabAmd, kGabNestedDissection, kGabNestedDissection2, kCholmodMetis };

struct Contender {
  Peer peer;
  const char* name;
};
constexpr Contender kContenders[] = {
    {Peer::kGabAmd, "gab amd"},
    {Peer::kGabNestedDissection, "gab nd"},
    {Peer::kGabNestedDissection2, "gab nd, 2 threads"},
    {Peer::kCholmodMetis, "cholmod metis"}};

std::vector<int32_t> order(const gab::CscMatrix& a, Peer peer, cholmod_common* c) {
  std::vector<int32_t> perm;
  switch (peer) {
    case Peer::kGabAmd:
      gab_bench::check(gab::amd_order(a, &perm), "ordering_compare: amd_order");
      break;
    case Peer::kGabNestedDissection:
      gab_bench::check(gab::nested_dissection_order(a, &perm), "ordering_compare: nested_dissection_order");
      break;
    case Peer::kGabNestedDissection2: {
      gab::NestedDissectionOptions options;
      options.threads = 2;  // the same permutation as on one thread, in less wall time
      gab_bench::check(gab::nested_dissection_order(a, &perm, options), "ordering_compare: nested_dissection_order");
      break;
    }
    case Peer::kCholmodMetis:
      perm = metis_order(a, c);
      break;
  }
  return perm;
}

// The same updates by cholmod_updown on CHOLMOD's factor of `a` ordered by
// perm (converted to the simplicial LDL^T it updates, not timed): seconds in all.
double cholmod_updown_seconds(const gab::CscMatrix& a, const std::vector<int32_t>& perm,
                              const std::vector<int32_t>& seq, cholmod_common* c) {
  const int32_t n = a.ncols;
  const int saved_ordering = c->method[0].ordering, saved_nmethods = c->nmethods, saved_postorder = c->postorder;
  c->nmethods = 1;
  c->method[0].ordering = CHOLMOD_GIVEN;
  c->postorder = 1;
  cholmod_sparse* ca = cholmod_allocate_sparse(n, n, a.nnz(), 1, 1, -1, CHOLMOD_REAL, c);
  std::copy(a.colptr.begin(), a.colptr.end(), static_cast<int32_t*>(ca->p));
  std::copy(a.rowind.begin(), a.rowind.end(), static_cast<int32_t*>(ca->i));
  std::copy(a.values.begin(), a.values.end(), static_cast<double*>(ca->x));
  std::vector<int32_t> given = perm;
  cholmod_factor* f = cholmod_analyze_p(ca, given.data(), nullptr, 0, c);
  cholmod_factorize(ca, f, c);
  cholmod_change_factor(CHOLMOD_REAL, 0, 0, 1, 1, f, c);
  const std::vector<int32_t> inverse = gab_bench::factor_inverse_perm(f);
  double seconds = 0;
  for (const int32_t& v : seq) seconds += gab_bench::timed_updown(f, inverse, &v, 1, c);
  cholmod_free_factor(&f, c);
  cholmod_free_sparse(&ca, c);
  c->nmethods = saved_nmethods;
  c->method[0].ordering = saved_ordering;
  c->postorder = saved_postorder;
  return seconds;
}

void compare(const std::string& path, cholmod_common* c) {
  gab::Mesh mesh;
  if (!gab::read_mesh(path, &mesh).ok()) {
    std::fprintf(stderr, "skip %s\n", path.c_str());
    return;
  }
  const gab::EdgeGraph g = gab::build_edge_graph(mesh);
  const std::vector<int32_t> anchors = gab::benchmark_anchors(g, 100);
  gab::CscMatrix a;
  gab_bench::check(gab::assemble_normal_matrix(g, anchors, 1.0, &a), "ordering_compare: assemble_normal_matrix");
  const int32_t n = a.ncols;
  const std::vector<int32_t> seq = gab::benchmark_update_sequence(n, anchors, kUpdates);
  const std::string name = path.substr(path.find_last_of('/') + 1);
  for (const Contender& ordering : kContenders) {
    std::vector<int32_t> perm;
    std::vector<double> t;
    for (int r = 0; r < kRepeat; ++r) {
      const double t0 = now();
      perm = order(a, ordering.peer, c);
      t.push_back(now() - t0);
    }
    gab::AnalyzeOptions options;
    options.ordering = gab::Ordering::kGiven;
    options.given_perm = perm;
    gab::Cholesky chol;
    gab_bench::check(chol.analyze(a, options), "ordering_compare: analyze");
    gab_bench::check(chol.factorize(a), "ordering_compare: factorize");
    gab_bench::check(chol.prepare_updates(), "ordering_compare: prepare_updates");
    double touched = 0, gab_seconds = 0;
    for (int32_t v : seq) {
      gab::UpdateStats st;
      const double t0 = now();
      gab_bench::check(chol.add_anchor(v, 1.0, &st), "ordering_compare: add_anchor");
      gab_seconds += now() - t0;
      touched += static_cast<double>(st.touched);
    }
    const double updates = static_cast<double>(std::max<size_t>(1, seq.size()));
    touched /= updates;
    const double updown_seconds = cholmod_updown_seconds(a, perm, seq, c);
    std::printf("| %s | %d | %s | %.3f | %.4g | %.4g | %.4g | %.2f | %.3f | %.3f |\n", name.c_str(), n, ordering.name,
                median(t), static_cast<double>(chol.symbolic().nnz_L), chol.symbolic().flops, touched, touched / n,
                gab_seconds / updates * 1e3, updown_seconds / updates * 1e3);
    std::fflush(stdout);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> inputs(argv + 1, argv + argc);
  if (inputs.empty()) {
    for (const char* m : {"igea", "horse", "nefertiti", "bunny"}) {
      inputs.push_back(std::string(GAB_SHARED_MESHES) + "/" + m + ".off");
    }
  }
  cholmod_common c;
  cholmod_start(&c);
  std::printf("| mesh | n | ordering | order s | nnz(L) | flops | touched per update | per n | gab update ms | "
              "cholmod_updown ms |\n");
  std::printf("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::string& path : inputs) compare(path, &c);
  cholmod_finish(&c);
  std::printf("\nnnz(L), flops and touched entries by gab's analysis and updater on each permutation; "
              "order s: the ordering alone, wall time, median of %d, single thread but where said; update ms: the mean of "
              "the %d updates, gab's add_anchor and cholmod_updown (on its simplicial LDL^T) each on a factor in that "
              "ordering, one thread.\n", kRepeat, kUpdates);
  return 0;
}
