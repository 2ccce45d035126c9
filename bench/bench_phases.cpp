// Google Benchmark suite of the engine's phases (order, symbolic, factor,
// solve with 3 right-hand sides) on generated grids and on the real meshes
// of ../shared/meshes (skipped when absent). Counters report nnz(L) and
// GFLOP/s so runs can be compared with the peers in bench/peers.
#include <benchmark/benchmark.h>

#include <fstream>
#include <map>
#include <string>

#include "bench_check.h"
#include "bench_grid_mesh.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/off_io.h"
#include "gab/sparse/amd.h"
#include "gab/sparse/cholesky.h"

namespace {

struct System {
  gab::CscMatrix lower;
  std::vector<double> rhs;
};

const System* load(const std::string& name) {
  static std::map<std::string, System> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return &it->second;
  gab::Mesh mesh;
  if (name.rfind("grid", 0) == 0) {
    const int32_t side = std::stoi(name.substr(4));
    mesh = gab_bench::grid_mesh(side, side);
  } else {
    const std::string path = std::string(GAB_SHARED_MESHES) + "/" + name + ".off";
    if (!std::ifstream(path) || !gab::read_off(path, &mesh).ok()) return nullptr;
  }
  const gab::EdgeGraph g = gab::build_edge_graph(mesh);
  const std::vector<int32_t> anchors = gab::benchmark_anchors(g, 100);
  System s;
  if (!gab::assemble_normal_matrix(g, anchors, 1.0, &s.lower).ok()) return nullptr;
  s.rhs = gab::anchor_right_hand_sides(mesh, anchors, 1.0);
  return &cache.emplace(name, std::move(s)).first->second;
}

const char* kInputs[] = {"grid100", "grid300", "bunny-small", "camel-head", "max-planck", "horse",
                         "feline", "nefertiti", "igea"};

void BM_Order(benchmark::State& state, std::string name) {
  const System* s = load(name);
  if (!s) return state.SkipWithError("input not available");
  std::vector<int32_t> perm;
  for (auto _ : state) gab_bench::check(gab::amd_order(s->lower, &perm), "amd_order");
}

void BM_Symbolic(benchmark::State& state, std::string name) {
  const System* s = load(name);
  if (!s) return state.SkipWithError("input not available");
  gab::AnalyzeOptions options;
  options.ordering = gab::Ordering::kGiven;
  gab_bench::check(gab::amd_order(s->lower, &options.given_perm), "amd_order");
  gab::SymbolicFactor f;
  for (auto _ : state) gab_bench::check(gab::analyze(s->lower, options, &f), "analyze");
  state.counters["nnz_L"] = static_cast<double>(f.nnz_L);
  state.counters["supernodes"] = f.num_supernodes;
}

void BM_Factor(benchmark::State& state, std::string name) {
  const System* s = load(name);
  if (!s) return state.SkipWithError("input not available");
  gab::Cholesky chol;
  gab_bench::check(chol.analyze(s->lower), "analyze");
  for (auto _ : state) {
    if (!chol.factorize(s->lower).ok()) return state.SkipWithError("factorization failed");
  }
  state.counters["GFLOP/s"] =
      benchmark::Counter(chol.symbolic().flops * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Solve3(benchmark::State& state, std::string name) {
  const System* s = load(name);
  if (!s) return state.SkipWithError("input not available");
  gab::Cholesky chol;
  gab_bench::check(chol.analyze(s->lower), "analyze");
  gab_bench::check(chol.factorize(s->lower), "factorize");
  std::vector<double> x;
  const int32_t n = s->lower.ncols;
  for (auto _ : state) {
    state.PauseTiming();
    x = s->rhs;
    state.ResumeTiming();
    gab_bench::check(chol.solve(x.data(), 3, n), "solve");
  }
}

const int kRegistered = [] {
  for (const char* name : kInputs) {
    benchmark::RegisterBenchmark((std::string("Order/") + name).c_str(), BM_Order, std::string(name))
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("Symbolic/") + name).c_str(), BM_Symbolic, std::string(name))
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("Factor/") + name).c_str(), BM_Factor, std::string(name))
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("Solve3/") + name).c_str(), BM_Solve3, std::string(name))
        ->Unit(benchmark::kMillisecond);
  }
  return 0;
}();

}  // namespace

BENCHMARK_MAIN();
