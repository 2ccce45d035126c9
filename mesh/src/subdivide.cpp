// 1:4 midpoint subdivision (Loop's topology without its smoothing weights).
#include "gab/mesh/subdivide.h"

#include <algorithm>
#include <unordered_map>

namespace gab {

namespace {

Mesh subdivide_once(const Mesh& in) {
  Mesh out;
  out.positions = in.positions;
  const int32_t nt = in.num_triangles();
  out.triangles.reserve(static_cast<size_t>(nt) * 12);
  // Edge (lo, hi) -> its midpoint vertex, created on first sight.
  std::unordered_map<uint64_t, int32_t> midpoint;
  midpoint.reserve(static_cast<size_t>(nt) * 2);
  auto mid = [&](int32_t a, int32_t b) {
    const uint64_t key = (static_cast<uint64_t>(std::min(a, b)) << 32) | static_cast<uint32_t>(std::max(a, b));
    auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    const int32_t v = static_cast<int32_t>(out.positions.size() / 3);
    for (int c = 0; c < 3; ++c) {
      out.positions.push_back(0.5 * (in.positions[3 * static_cast<size_t>(a) + c] +
                                     in.positions[3 * static_cast<size_t>(b) + c]));
    }
    midpoint.emplace(key, v);
    return v;
  };
  for (int32_t t = 0; t < nt; ++t) {
    const int32_t a = in.triangles[3 * t], b = in.triangles[3 * t + 1], c = in.triangles[3 * t + 2];
    const int32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
    out.triangles.insert(out.triangles.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  return out;
}

}  // namespace

Mesh subdivide_midpoint(const Mesh& mesh, int levels) {
  Mesh m = mesh;
  for (int i = 0; i < levels; ++i) m = subdivide_once(m);
  return m;
}

}  // namespace gab
