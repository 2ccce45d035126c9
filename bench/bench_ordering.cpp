// Orderings compared on the benchmark matrices of the shared meshes (built as
// bench_phases.cpp's load() does: edge graph, 100 benchmark anchors, weight
// 1): for AMD and nested dissection, the ordering's CPU time (best of 3), the
// factor's nnz(L) and flops from the symbolic analysis, and one numeric
// factorization's time. Usage: bench_ordering [mesh names...] (default: all).
// Environment variables ND_LEAF, ND_IMBALANCE, ND_COARSEST, ND_TRIES, ND_PASSES
// ND_PATIENCE, ND_POLISH_FROM, ND_CANDIDATES, ND_TRIAL_SIZE, ND_LARGE_CANDIDATES and ND_LARGE_SIZE override the nested-dissection options (for tuning);
// ND_SEED the generator's seed; ND_RUNS sets how many runs the best time is taken of (3), ND_ONLY skips AMD,
// ND_NO_FACTOR skips the numeric factorization, ND_HASH prints a hash of the ND permutation to stderr (to check that a
// change keeps the ordering).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "bench_check.h"
#include "bench_grid_mesh.h"
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

// The calling thread's CPU time: the orderings are single-threaded, and on a
// shared machine wall time also counts the other tenants' slices.
double thread_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Best of `runs` times of order(), which leaves its permutation in *perm:
// the calling thread's CPU time, or wall time for an ordering on several
// threads.
double time_ordering(const std::function<gab::Status(std::vector<int32_t>*)>& order,
                     std::vector<int32_t>* perm, int runs, bool wall = false) {
  double best = 1e30;
  for (int r = 0; r < runs; ++r) {
    const Clock::time_point wall_start = Clock::now();
    const double start = thread_seconds();
    gab_bench::check(order(perm), "ordering");
    best = std::min(best, wall ? seconds_since(wall_start) : thread_seconds() - start);
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
  if (!std::getenv("ND_NO_FACTOR")) gab_bench::check(chol.factorize(lower), "factorize");
  const double factor_seconds = seconds_since(start);
  const gab::SymbolicFactor& f = chol.symbolic();
  std::printf("| %-11s | %-4s | %8.3f | %10.3fM | %9.3e | %8.3f |\n", mesh, method, order_seconds,
              f.nnz_L * 1e-6, f.flops, factor_seconds);
  std::fflush(stdout);
}

// The options, with the overrides the environment gives.
gab::NestedDissectionOptions nd_options() {
  gab::NestedDissectionOptions o;
  auto read = [](const char* name, double fallback) {
    const char* text = std::getenv(name);
    return text ? std::atof(text) : fallback;
  };
  o.leaf_size = static_cast<int32_t>(read("ND_LEAF", o.leaf_size));
  o.imbalance = read("ND_IMBALANCE", o.imbalance);
  o.coarsest_size = static_cast<int32_t>(read("ND_COARSEST", o.coarsest_size));
  o.initial_tries = static_cast<int32_t>(read("ND_TRIES", o.initial_tries));
  o.refine_passes = static_cast<int32_t>(read("ND_PASSES", o.refine_passes));
  o.refine_patience = static_cast<int32_t>(read("ND_PATIENCE", o.refine_patience));
  o.candidates = static_cast<int32_t>(read("ND_CANDIDATES", o.candidates));
  o.trial_size = static_cast<int32_t>(read("ND_TRIAL_SIZE", o.trial_size));
  o.large_candidates = static_cast<int32_t>(read("ND_LARGE_CANDIDATES", o.large_candidates));
  o.large_size = static_cast<int32_t>(read("ND_LARGE_SIZE", o.large_size));
  o.candidate_tries = static_cast<int32_t>(read("ND_CANDIDATE_TRIES", o.candidate_tries));
  o.threads = static_cast<int32_t>(read("ND_THREADS", o.threads));
  o.runs = static_cast<int32_t>(read("ND_NRUNS", o.runs));
  o.runs_from = static_cast<int32_t>(read("ND_RUNS_FROM", o.runs_from));
  o.runs_levels = static_cast<int32_t>(read("ND_RUNS_LEVELS", o.runs_levels));
  o.runs_ratio = static_cast<int32_t>(read("ND_RUNS_RATIO", o.runs_ratio));
  o.one_sided_refinement = read("ND_ONE_SIDED", o.one_sided_refinement) != 0;
  o.polish_from = static_cast<int32_t>(read("ND_POLISH_FROM", o.polish_from));
  if (const char* seed = std::getenv("ND_SEED")) o.seed = std::strtoull(seed, nullptr, 0);
  return o;
}

// The separators of the tree's top levels: size (subtree size), per depth.
void print_top_separators(const gab::CscMatrix& lower, const gab::NestedDissectionOptions& options) {
  std::vector<int32_t> perm;
  gab::SeparatorTree tree;
  gab_bench::check(gab::nested_dissection_order(lower, &perm, options, &tree), "nested_dissection_order");
  std::vector<int32_t> level{static_cast<int32_t>(tree.nodes.size()) - 1};
  for (int depth = 0; depth < 4 && !level.empty(); ++depth) {
    std::printf("  depth %d:", depth);
    std::vector<int32_t> next;
    for (int32_t s : level) {
      const gab::SeparatorTree::Node& node = tree.nodes[s];
      std::printf(" %d(%d)", node.size, node.first + node.size - node.subtree_first);
      for (int32_t c = tree.child_ptr[s]; c < tree.child_ptr[s + 1]; ++c) next.push_back(tree.children[c]);
    }
    std::printf("\n");
    level.swap(next);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names(argv + 1, argv + argc);
  if (names.empty()) {
    names = {"bunny-small", "camel-head", "max-planck", "bunny", "horse", "feline", "nefertiti", "igea"};
  }
  std::printf("| mesh        | ord  | order s  | nnz(L)      | flops     | factor s |\n");
  std::printf("|-------------|------|----------|-------------|-----------|----------|\n");
  const gab::NestedDissectionOptions options = nd_options();
  const bool nd_only = std::getenv("ND_ONLY") != nullptr;
  for (const std::string& name : names) {
    gab::Mesh mesh;
    if (name.rfind("grid", 0) == 0) {
      const int32_t side = std::atoi(name.c_str() + 4);
      mesh = gab_bench::grid_mesh(side, side);
    } else {
      // A name with a '/' is a path (the subdivided scale meshes); others are shared meshes.
      const std::string path =
          name.find('/') != std::string::npos ? name : std::string(GAB_SHARED_MESHES) + "/" + name + ".off";
      if (!std::ifstream(path)) {
        std::fprintf(stderr, "%s: not found, skipped\n", path.c_str());
        continue;
      }
      gab_bench::check(gab::read_off(path, &mesh), "read_off");
    }
    const gab::EdgeGraph g = gab::build_edge_graph(mesh);
    const std::vector<int32_t> anchors = gab::benchmark_anchors(g, 100);
    gab::CscMatrix lower;
    gab_bench::check(gab::assemble_normal_matrix(g, anchors, 1.0, &lower), "assemble_normal_matrix");

    std::vector<int32_t> perm;
    double t = 0.0;
    if (!nd_only) {
      t = time_ordering([&](std::vector<int32_t>* p) { return gab::amd_order(lower, p); }, &perm, 3);
      report(name.c_str(), "AMD", lower, perm, t);
    }
    const int runs = std::getenv("ND_RUNS") ? std::max(1, std::atoi(std::getenv("ND_RUNS"))) : 3;
    t = time_ordering(
        [&](std::vector<int32_t>* p) { return gab::nested_dissection_order(lower, p, options); }, &perm, runs,
        options.threads > 1);
    report(name.c_str(), "ND", lower, perm, t);
    if (std::getenv("ND_HASH")) {
      uint64_t hash = 1469598103934665603ull;  // FNV-1a over the permutation
      for (int32_t v : perm) hash = (hash ^ static_cast<uint32_t>(v)) * 1099511628211ull;
      std::fprintf(stderr, "%s ND permutation hash %016llx\n", name.c_str(), static_cast<unsigned long long>(hash));
    }
    if (std::getenv("ND_TREE")) print_top_separators(lower, options);
  }
  return 0;
}
