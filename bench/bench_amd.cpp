// Benchmarks of the AMD ordering on the matrices gab factors (the 2-ring pattern of
// L^T L for a mesh Laplacian L) and on regular grids. Counters: n, nnz_A (lower
// triangle incl. diagonal), nnz_L (incl. diagonal, as predicted by the ordering) and
// the predicted Cholesky flops.
//
// Meshes come from GAB_SHARED_MESHES (nefertiti, igea) and, when the environment
// variable GAB_EXTRA_MESHES names a directory, also camel.off and armadillo.off from it
// (e.g. the CGAL demo data: tar xzf /usr/share/doc/libcgal-dev/data.tar.gz data/meshes).
//
// Comparison with SuiteSparse AMD (never needed to build the project): configure with
//   -DCMAKE_CXX_FLAGS=-DGAB_HAVE_SUITESPARSE_AMD -DCMAKE_CXX_STANDARD_LIBRARIES=-lamd
// to add BM_SuiteSparseAmd* twins of every case.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/sparse/amd.h"

#ifdef GAB_HAVE_SUITESPARSE_AMD
#include <suitesparse/amd.h>
#endif

namespace {

using gab::CscMatrix;

// Lower triangle (incl. diagonal) of the 5-point (2D, nz == 1) or 7-point grid graph.
CscMatrix grid_lower(int32_t nx, int32_t ny, int32_t nz) {
  const int32_t n = nx * ny * nz;
  CscMatrix a;
  a.nrows = a.ncols = n;
  a.colptr.assign(static_cast<size_t>(n) + 1, 0);
  for (int32_t z = 0; z < nz; ++z) {
    for (int32_t y = 0; y < ny; ++y) {
      for (int32_t x = 0; x < nx; ++x) {
        const int32_t v = (z * ny + y) * nx + x;
        a.rowind.push_back(v);
        if (x + 1 < nx) a.rowind.push_back(v + 1);
        if (y + 1 < ny) a.rowind.push_back(v + nx);
        if (z + 1 < nz) a.rowind.push_back(v + nx * ny);
        a.colptr[v + 1] = static_cast<int32_t>(a.rowind.size());
      }
    }
  }
  return a;
}

// Matrices are built once per process and shared by the gab and SuiteSparse cases.
const CscMatrix* mesh_matrix(const std::string& name) {
  static std::map<std::string, CscMatrix> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second.ncols > 0 ? &it->second : nullptr;
  std::vector<std::string> dirs = {GAB_SHARED_MESHES};
  if (const char* extra = std::getenv("GAB_EXTRA_MESHES")) dirs.push_back(extra);
  CscMatrix a;
  // The benchmark system (docs/cli.md, "gab factor"), through the mesh layer.
  for (const std::string& dir : dirs) {
    gab::Mesh mesh;
    if (!gab::read_mesh(dir + "/" + name + ".off", &mesh).ok()) continue;
    const gab::EdgeGraph graph = gab::build_edge_graph(mesh);
    if (gab::assemble_normal_matrix(graph, gab::benchmark_anchors(graph, 100), 1.0, &a).ok()) break;
  }
  CscMatrix& slot = cache[name];
  slot = std::move(a);
  return slot.ncols > 0 ? &slot : nullptr;
}

const CscMatrix* grid_matrix(int32_t side, int32_t dims) {
  static std::map<std::pair<int32_t, int32_t>, CscMatrix> cache;
  const auto key = std::make_pair(side, dims);
  auto it = cache.find(key);
  if (it == cache.end()) {
    it = cache.emplace(key, grid_lower(side, side, dims == 3 ? side : 1)).first;
  }
  return &it->second;
}

void report(benchmark::State& state, const CscMatrix& a, int64_t nnz_l, double flops) {
  state.counters["n"] = a.ncols;
  state.counters["nnz_A"] = static_cast<double>(a.nnz());
  state.counters["nnz_L"] = static_cast<double>(nnz_l);
  state.counters["flops"] = flops;
}

void run_gab(benchmark::State& state, const CscMatrix* a) {
  if (a == nullptr) {
    state.SkipWithError("matrix not available");
    return;
  }
  std::vector<int32_t> perm;
  gab::AmdInfo info;
  for (auto _ : state) {
    const gab::Status s = gab::amd_order(*a, &perm, gab::AmdOptions(), &info);
    if (!s.ok()) {
      state.SkipWithError(s.message().c_str());
      return;
    }
    benchmark::DoNotOptimize(perm.data());
  }
  report(state, *a, info.nnz_L_estimate, info.flops_estimate);
  state.counters["dense_rows"] = info.dense_rows;
  state.counters["compressions"] = info.compressions;
}

#ifdef GAB_HAVE_SUITESPARSE_AMD
void run_suitesparse(benchmark::State& state, const CscMatrix* a) {
  if (a == nullptr) {
    state.SkipWithError("matrix not available");
    return;
  }
  std::vector<int32_t> perm(static_cast<size_t>(a->ncols));
  double control[AMD_CONTROL], info[AMD_INFO];
  amd_defaults(control);
  for (auto _ : state) {
    const int status = amd_order(a->ncols, a->colptr.data(), a->rowind.data(), perm.data(),
                                 control, info);
    if (status < AMD_OK) {
      state.SkipWithError("amd_order failed");
      return;
    }
    benchmark::DoNotOptimize(perm.data());
  }
  // AMD_LNZ excludes the diagonal. Its flop counts are for LDL^T; not reported.
  report(state, *a, static_cast<int64_t>(info[AMD_LNZ]) + a->ncols, 0.0);
}
#endif

void BM_AmdMesh(benchmark::State& state, const char* name) { run_gab(state, mesh_matrix(name)); }
void BM_AmdGrid2D(benchmark::State& state) {
  run_gab(state, grid_matrix(static_cast<int32_t>(state.range(0)), 2));
}
void BM_AmdGrid3D(benchmark::State& state) {
  run_gab(state, grid_matrix(static_cast<int32_t>(state.range(0)), 3));
}

BENCHMARK_CAPTURE(BM_AmdMesh, camel, "camel")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AmdMesh, armadillo, "armadillo")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AmdMesh, nefertiti, "nefertiti")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_AmdMesh, igea, "igea")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AmdGrid2D)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AmdGrid3D)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);

#ifdef GAB_HAVE_SUITESPARSE_AMD
void BM_SuiteSparseAmdMesh(benchmark::State& state, const char* name) {
  run_suitesparse(state, mesh_matrix(name));
}
void BM_SuiteSparseAmdGrid2D(benchmark::State& state) {
  run_suitesparse(state, grid_matrix(static_cast<int32_t>(state.range(0)), 2));
}
void BM_SuiteSparseAmdGrid3D(benchmark::State& state) {
  run_suitesparse(state, grid_matrix(static_cast<int32_t>(state.range(0)), 3));
}
BENCHMARK_CAPTURE(BM_SuiteSparseAmdMesh, camel, "camel")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SuiteSparseAmdMesh, armadillo, "armadillo")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SuiteSparseAmdMesh, nefertiti, "nefertiti")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SuiteSparseAmdMesh, igea, "igea")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SuiteSparseAmdGrid2D)->Arg(100)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SuiteSparseAmdGrid3D)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);
#endif

}  // namespace

BENCHMARK_MAIN();
