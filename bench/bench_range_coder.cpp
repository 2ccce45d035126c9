// Throughput of the codec's entropy-coding layer: adaptive bits through the
// range coder (one model at P(1) = 0.1), and the connectivity coder on igea
// (268,686 triangles; skipped when the shared meshes are absent).
#include <benchmark/benchmark.h>

#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "connectivity/valence_section.h"
#include "entropy/range_coder.h"
#include "gab/mesh/mesh_io.h"

namespace {

std::vector<int> skewed_bits(size_t count) {
  std::mt19937 rng(1);
  std::vector<int> bits(count);
  for (int& b : bits) b = rng() % 10 == 0;
  return bits;
}

void BM_RangeEncodeBits(benchmark::State& state) {
  const std::vector<int> bits = skewed_bits(1 << 20);
  for (auto _ : state) {
    gab::RangeEncoder enc;
    gab::BitModel model;
    for (int b : bits) enc.encode(&model, b);
    benchmark::DoNotOptimize(enc.finish().data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(bits.size()));
}
BENCHMARK(BM_RangeEncodeBits)->Unit(benchmark::kMillisecond);

void BM_RangeDecodeBits(benchmark::State& state) {
  const std::vector<int> bits = skewed_bits(1 << 20);
  gab::RangeEncoder enc;
  gab::BitModel model;
  for (int b : bits) enc.encode(&model, b);
  const std::vector<uint8_t> bytes = enc.finish();
  for (auto _ : state) {
    gab::RangeDecoder dec(bytes.data(), bytes.size());
    gab::BitModel m;
    int sum = 0;
    for (size_t i = 0; i < bits.size(); ++i) sum += dec.decode(&m);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(bits.size()));
}
BENCHMARK(BM_RangeDecodeBits)->Unit(benchmark::kMillisecond);

bool load_igea(gab::Mesh* mesh, benchmark::State& state) {
  const std::string path = std::string(GAB_SHARED_MESHES) + "/igea.off";
  if (!std::ifstream(path) || !gab::read_mesh(path, mesh).ok()) {
    state.SkipWithError("igea.off not present");
    return false;
  }
  return true;
}

void BM_ConnectivityEncodeIgea(benchmark::State& state) {
  gab::Mesh mesh;
  if (!load_igea(&mesh, state)) return;
  size_t bytes = 0;
  for (auto _ : state) {
    const gab::ValenceSection out = gab::encode_valence_section(mesh.num_vertices(), mesh.triangles);
    bytes = out.bytes.size();
    benchmark::DoNotOptimize(out.bytes.data());
  }
  state.counters["bits/triangle"] = 8.0 * bytes / mesh.num_triangles();
  state.SetItemsProcessed(state.iterations() * mesh.num_triangles());
}
BENCHMARK(BM_ConnectivityEncodeIgea)->Unit(benchmark::kMillisecond);

void BM_ConnectivityDecodeIgea(benchmark::State& state) {
  gab::Mesh mesh;
  if (!load_igea(&mesh, state)) return;
  const std::vector<uint8_t> bytes = gab::encode_valence_section(mesh.num_vertices(), mesh.triangles).bytes;
  for (auto _ : state) {
    std::vector<int32_t> triangles;
    if (!gab::decode_valence_section(bytes.data(), bytes.size(), mesh.num_vertices(), mesh.num_triangles(),
                                     &triangles)
             .ok()) {
      state.SkipWithError("decode failed");
    }
    benchmark::DoNotOptimize(triangles.data());
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_triangles());
}
BENCHMARK(BM_ConnectivityDecodeIgea)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
