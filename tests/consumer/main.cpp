// Solves a 1-D Laplacian system, reads an OBJ mesh and round-trips a mesh
// through the .gab codec, all through the installed headers; exits 0 only if
// all three are right.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <vector>

#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/mesh_io.h"
#include "gab/sparse/cholesky.h"

// The triangles as a set of oriented triangles: the codec keeps each
// triangle's vertices and orientation, not the list's order or which corner
// comes first.
std::vector<std::array<int32_t, 3>> oriented_set(const std::vector<int32_t>& triangles) {
  std::vector<std::array<int32_t, 3>> set;
  for (size_t f = 0; f + 2 < triangles.size(); f += 3) {
    std::array<int32_t, 3> t = {triangles[f], triangles[f + 1], triangles[f + 2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    set.push_back(t);
  }
  std::sort(set.begin(), set.end());
  return set;
}

int main() {
  const int n = 100;
  std::vector<gab::Triplet> t;
  for (int i = 0; i < n; ++i) {
    t.push_back({i, i, 2.0});
    if (i + 1 < n) t.push_back({i + 1, i, -1.0});
  }
  gab::CscMatrix a;
  gab::Cholesky chol;
  if (!gab::csc_from_triplets(n, n, t, &a).ok() || !chol.analyze(a).ok() || !chol.factorize(a).ok()) {
    std::fprintf(stderr, "consumer: factorization failed\n");
    return 1;
  }
  std::vector<double> x(n, 1.0), b(n), ax(n);
  gab::symmetric_lower_matvec(a, x.data(), b.data());
  std::vector<double> y = b;
  if (!chol.solve(y.data(), 1, n).ok()) {
    std::fprintf(stderr, "consumer: solve failed\n");
    return 1;
  }
  double err = 0.0;
  for (int i = 0; i < n; ++i) err = std::fmax(err, std::fabs(y[i] - 1.0));
  std::printf("consumer: max error %.3g\n", err);
  // The mesh layer too (its OBJ reader links tinyobjloader, a dependency
  // the package config must bring along).
  gab::Mesh mesh;
  const gab::Status read = gab::parse_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", gab::MeshFormat::kObj, "t.obj", &mesh);
  std::printf("consumer: OBJ read %s, %d triangle(s)\n", read.ok() ? "ok" : read.message().c_str(), mesh.num_triangles());
  // The codec: a 6 x 6 grid with a bump, 12 anchors.
  gab::Mesh grid;
  for (int j = 0; j < 6; ++j) {
    for (int i = 0; i < 6; ++i) grid.positions.insert(grid.positions.end(), {double(i), double(j), (i - 2.5) * (j - 2.5) * 0.1});
  }
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) {
      const int v = i + 6 * j;
      grid.triangles.insert(grid.triangles.end(), {v, v + 1, v + 7, v, v + 7, v + 6});
    }
  }
  gab::EncodeOptions options;
  options.max_anchors = 12;
  std::vector<uint8_t> file;
  gab::EncodeStats encoded;
  gab::Mesh decoded;
  gab::DecodeStats stats;
  bool coded = gab::encode_mesh(grid, options, &file, &encoded).ok() &&
               gab::decode_mesh(file.data(), file.size(), gab::DecodeOptions(), &decoded, &stats).ok() &&
               stats.anchors == 12 && encoded.new_index.size() == grid.positions.size() / 3;
  // The decoded mesh is numbered in the coder's traversal order (the
  // default): the same triangles through the encoder's map.
  if (coded) {
    std::vector<int32_t> renamed;
    for (int32_t v : grid.triangles) renamed.push_back(encoded.new_index[v]);
    coded = oriented_set(decoded.triangles) == oriented_set(renamed);
  }
  std::printf("consumer: .gab round trip %s, %zu bytes\n", coded ? "ok" : "failed", file.size());
  return err < 1e-10 && read.ok() && mesh.num_triangles() == 1 && coded ? 0 : 1;
}
