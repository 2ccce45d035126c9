// Candidates for a reconstruction operator whose cost grows linearly in n
// (the fast-decode design), against the global relaxed least squares
// (Sorkine et al. 2005, eq. 1: (L^T L + w^2 S) x = w^2 S c, L = D - A):
// the same anchors (a hop-spread set: vertices in a fixed pseudo-random
// order, each taken when no anchor lies within `--spread` hops; its
// coefficients the exact positions) reconstructed by
//   global   the engine's factorization (ordering, analysis, factor, solve)
//   cg-I     I steps of IterativeReconstruction (Jacobi-preconditioned
//            conjugate gradients, matrix-free, from each vertex's nearest
//            anchor after kStartSweeps harmonic sweeps; cg-0 is that
//            start): a fixed amount of work whose result both sides of a
//            codec compute alike.
//   hS+cg-I  the same from another start: S Jacobi sweeps of the harmonic
//            interpolation (free vertices to their neighbours' mean) after
//            the nearest-anchor start, instead of the built-in sweeps.
// Prints per candidate the vertex RMS against the original over the box
// diagonal, its ratio to the global's, the RMS distance to the global shape,
// and seconds (one thread).
//
//   bench/reconstruction_candidates MESH [--spread H] [--weight W] [--iterations I,I,...]
//   (defaults: 2, 100, 0,10,20,40,80,160,320)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/iterative_reconstruction.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/relaxed_reconstruction.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Anchors no closer than `spread` + 1 hops, in a fixed pseudo-random order.
std::vector<int32_t> spread_anchors(const gab::EdgeGraph& g, int spread) {
  const int32_t n = g.num_vertices();
  std::vector<int32_t> order(n);
  for (int32_t i = 0; i < n; ++i) order[i] = i;
  uint64_t state = 0x9E3779B97F4A7C15ull;
  for (int32_t i = n - 1; i > 0; --i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(order[i], order[static_cast<int32_t>((state >> 33) % static_cast<uint64_t>(i + 1))]);
  }
  std::vector<int32_t> hops(n, -1), touched, frontier, next;
  std::vector<char> covered(n, 0);
  std::vector<int32_t> anchors;
  for (int32_t v : order) {
    if (covered[v]) continue;
    anchors.push_back(v);
    // Mark everything within `spread` hops as covered.
    frontier.assign(1, v);
    covered[v] = 1;
    touched.assign(1, v);
    hops[v] = 0;
    for (int h = 0; h < spread; ++h) {
      next.clear();
      for (int32_t u : frontier) {
        for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
          const int32_t w = g.neighbors[p];
          if (hops[w] >= 0) continue;
          hops[w] = h + 1;
          covered[w] = 1;
          touched.push_back(w);
          next.push_back(w);
        }
      }
      frontier.swap(next);
    }
    for (int32_t u : touched) hops[u] = -1;
  }
  return anchors;
}

// `sweeps` Jacobi sweeps of the harmonic interpolation (each free vertex to
// its neighbours' mean, anchors fixed) from x.
void harmonic_sweeps(const gab::EdgeGraph& g, const std::vector<char>& anchored, int sweeps, std::vector<double>* x) {
  std::vector<double> next(x->size());
  for (int s = 0; s < sweeps; ++s) {
    for (int32_t v = 0; v < g.num_vertices(); ++v) {
      for (int c = 0; c < 3; ++c) {
        if (anchored[v] || g.degree(v) == 0) {
          next[3 * v + c] = (*x)[3 * v + c];
          continue;
        }
        double sum = 0;
        for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) sum += (*x)[3 * g.neighbors[p] + c];
        next[3 * v + c] = sum / g.degree(v);
      }
    }
    x->swap(next);
  }
}

double rms_between(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(s / static_cast<double>(a.size() / 3));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: reconstruction_candidates MESH [--spread H] [--weight W] [--iterations I,...]\n");
    return 2;
  }
  int spread = 2;
  double weight = 100;
  std::vector<int> iterations = {0, 10, 20, 40, 80, 160, 320};
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--spread")) spread = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--weight")) weight = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--iterations")) {
      iterations.clear();
      for (const char* s = argv[i + 1]; *s;) {
        char* end = nullptr;
        iterations.push_back(static_cast<int>(std::strtol(s, &end, 10)));
        s = *end == ',' ? end + 1 : end;
      }
    }
  }
  gab::Mesh mesh;
  const gab::Status read = gab::read_mesh(argv[1], &mesh);
  if (!read.ok()) {
    std::fprintf(stderr, "%s\n", read.message().c_str());
    return 1;
  }
  const gab::EdgeGraph g = gab::build_edge_graph(mesh);
  const int32_t n = g.num_vertices();
  const double diagonal = gab::bounding_box_diagonal(mesh);
  const std::vector<int32_t> anchors = spread_anchors(g, spread);
  std::vector<double> coefficients;
  for (int32_t a : anchors) {
    for (int c = 0; c < 3; ++c) coefficients.push_back(mesh.positions[3 * a + c]);
  }
  std::printf("%s: n = %d, %zu anchors (spread %d hops, %.1f%% of n), w = %g\n", argv[1], n, anchors.size(), spread,
              100.0 * anchors.size() / n, weight);

  double t = now();
  gab::RelaxedReconstruction rec;
  rec.set_ordering(gab::Ordering::kNestedDissection);
  gab::Status s = rec.init(g, weight, anchors, coefficients);
  std::vector<double> global;
  if (s.ok()) s = rec.reconstruct(&global);
  if (!s.ok()) {
    std::fprintf(stderr, "global: %s\n", s.message().c_str());
    return 1;
  }
  const double global_s = now() - t;
  const double global_rms = rms_between(global, mesh.positions) / diagonal;
  std::printf("%-10s rms %.3e (1.000x)  from global %.3e  %.3f s\n", "global", global_rms, 0.0, global_s);

  for (int steps : iterations) {
    gab::IterativeReconstruction it;
    std::vector<double> x;
    t = now();
    s = it.init(g, weight, anchors, coefficients);
    if (s.ok()) s = it.solve(steps, &x);
    const double seconds = now() - t;
    if (!s.ok()) {
      std::fprintf(stderr, "cg: %s\n", s.message().c_str());
      return 1;
    }
    const double rms = rms_between(x, mesh.positions) / diagonal;
    char name[32];
    std::snprintf(name, sizeof name, "cg-%d", steps);
    std::printf("%-10s rms %.3e (%.3fx)  from global %.3e  %.3f s\n", name, rms, rms / global_rms,
                rms_between(x, global) / diagonal, seconds);
  }
  std::vector<char> anchored(n, 0);
  for (int32_t a : anchors) anchored[a] = 1;
  for (int sweeps : {4, 16}) {
    for (int steps : iterations) {
      gab::IterativeReconstruction it;
      std::vector<double> x;
      t = now();
      s = it.init(g, weight, anchors, coefficients);
      std::vector<double> start = it.nearest_anchor_shape();
      harmonic_sweeps(g, anchored, sweeps, &start);
      if (s.ok()) s = it.set_start(start);
      if (s.ok()) s = it.solve(steps, &x);
      const double seconds = now() - t;
      if (!s.ok()) return 1;
      const double rms = rms_between(x, mesh.positions) / diagonal;
      char name[32];
      std::snprintf(name, sizeof name, "h%d+cg-%d", sweeps, steps);
      std::printf("%-10s rms %.3e (%.3fx)  from global %.3e  %.3f s\n", name, rms, rms / global_rms,
                  rms_between(x, global) / diagonal, seconds);
    }
  }
  return 0;
}
