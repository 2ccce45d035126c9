// The mesh layer's targets (issue 3), measured on igea (134,345 vertices):
// reading the 11 MB ASCII OFF (< 0.5 s), reading a binary PLY of it
// (< 0.1 s), and `gab diff`'s surface distance against a perturbed copy at
// the default sample count (< 5 s). Skips when the shared meshes are absent.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "gab/mesh/metrics.h"
#include "gab/mesh/mesh_io.h"

namespace {

const std::string kIgea = std::string(GAB_SHARED_MESHES) + "/igea.off";

bool load(gab::Mesh* mesh, benchmark::State& state) {
  if (!std::ifstream(kIgea) || !gab::read_mesh(kIgea, mesh).ok()) {
    state.SkipWithError("igea.off not present");
    return false;
  }
  return true;
}

void BM_ReadIgeaOff(benchmark::State& state) {
  gab::Mesh mesh;
  if (!load(&mesh, state)) return;
  for (auto _ : state) {
    gab::Mesh m;
    if (!gab::read_mesh(kIgea, &m).ok()) state.SkipWithError("read failed");
    benchmark::DoNotOptimize(m.positions.data());
  }
}
BENCHMARK(BM_ReadIgeaOff)->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_ReadIgeaBinaryPly(benchmark::State& state) {
  gab::Mesh mesh;
  if (!load(&mesh, state)) return;
  gab::PlyWriteOptions options;
  options.float32 = state.range(0) != 0;  // the source scan is float32
  const std::string path = "/tmp/gab_bench_igea_" + std::to_string(getpid()) + ".ply";
  if (!gab::write_mesh(path, mesh, options).ok()) state.SkipWithError("write failed");
  for (auto _ : state) {
    gab::Mesh m;
    if (!gab::read_mesh(path, &m).ok()) state.SkipWithError("read failed");
    benchmark::DoNotOptimize(m.positions.data());
  }
  std::remove(path.c_str());
}
BENCHMARK(BM_ReadIgeaBinaryPly)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_SurfaceDistanceIgeaPerturbed(benchmark::State& state) {
  gab::Mesh a;
  if (!load(&a, state)) return;
  // Every coordinate moved by up to 0.1% of the diagonal (deterministic).
  gab::Mesh b = a;
  const double amplitude = 1e-3 * gab::bounding_box_diagonal(a);
  uint64_t s = 1;
  for (double& x : b.positions) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    x += amplitude * (static_cast<double>(s >> 11) / 9007199254740992.0 - 0.5);
  }
  gab::SurfaceDistance d;
  for (auto _ : state) {
    if (!gab::surface_distance(a, b, gab::SurfaceDistanceOptions(), &d).ok()) state.SkipWithError("failed");
  }
  state.counters["hausdorff_rel"] = d.hausdorff / gab::bounding_box_diagonal(a);
  state.counters["samples"] = static_cast<double>(d.a_to_b.samples);
}
BENCHMARK(BM_SurfaceDistanceIgeaPerturbed)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
