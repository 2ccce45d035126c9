// Candidates for a reconstruction operator whose cost grows linearly in n
// (the fast-decode design), against the global relaxed least squares
// (Sorkine et al. 2005, eq. 1: (L^T L + w^2 S) x = w^2 S c, L = D - A):
// the same anchors (a hop-spread set: vertices in a fixed pseudo-random
// order, each taken when no anchor lies within `--spread` hops; its
// coefficients the exact positions) reconstructed by
//   global   the engine's factorization (ordering, analysis, factor, solve)
//   cg-I     I iterations of Jacobi-preconditioned conjugate gradients,
//            matrix-free (L applied twice per product), started from each
//            vertex's nearest anchor (breadth-first, ties to the first);
//            dot products summed in vertex order: a fixed amount of work
//            whose result both sides of a codec would compute alike.
// Prints per candidate the vertex RMS against the original over the box
// diagonal, its ratio to the global's, the RMS distance to the global shape,
// and seconds (one thread).
//
//   bench/reconstruction_candidates MESH [--spread H] [--weight W] [--iterations I,I,...]
//   (defaults: 2, 100, 10,20,40,80,160,320)
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

// y = L x for 3 columns interleaved (x0 y0 z0 x1 ...), L = D - A.
void apply_laplacian(const gab::EdgeGraph& g, const std::vector<double>& x, std::vector<double>* y) {
  const int32_t n = g.num_vertices();
  for (int32_t v = 0; v < n; ++v) {
    const int32_t d = g.offsets[v + 1] - g.offsets[v];
    double s[3] = {d * x[3 * v], d * x[3 * v + 1], d * x[3 * v + 2]};
    for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) {
      const int32_t u = g.neighbors[p];
      s[0] -= x[3 * u];
      s[1] -= x[3 * u + 1];
      s[2] -= x[3 * u + 2];
    }
    (*y)[3 * v] = s[0];
    (*y)[3 * v + 1] = s[1];
    (*y)[3 * v + 2] = s[2];
  }
}

struct System {
  const gab::EdgeGraph* g;
  std::vector<double> anchor_diag;  // w^2 on anchors, 0 elsewhere
  std::vector<double> inv_diag;     // 1 / diag(L^T L + w^2 S)
  mutable std::vector<double> tmp;
  // y = (L^T L + w^2 S) x.
  void apply(const std::vector<double>& x, std::vector<double>* y) const {
    apply_laplacian(*g, x, &tmp);
    apply_laplacian(*g, tmp, y);
    for (size_t v = 0; v < anchor_diag.size(); ++v) {
      for (int c = 0; c < 3; ++c) (*y)[3 * v + c] += anchor_diag[v] * x[3 * v + c];
    }
  }
};

// Preconditioned CG, `iterations` steps from x, per coordinate column
// (three independent recurrences sharing the products).
void cg(const System& a, const std::vector<double>& b, int iterations, std::vector<double>* x) {
  const size_t n = b.size() / 3;
  std::vector<double> r(3 * n), z(3 * n), p(3 * n), q(3 * n);
  a.apply(*x, &q);
  for (size_t i = 0; i < 3 * n; ++i) r[i] = b[i] - q[i];
  double rz[3] = {0, 0, 0};
  for (size_t v = 0; v < n; ++v) {
    for (int c = 0; c < 3; ++c) {
      z[3 * v + c] = a.inv_diag[v] * r[3 * v + c];
      p[3 * v + c] = z[3 * v + c];
      rz[c] += r[3 * v + c] * z[3 * v + c];
    }
  }
  for (int it = 0; it < iterations; ++it) {
    a.apply(p, &q);
    double pq[3] = {0, 0, 0};
    for (size_t v = 0; v < n; ++v) {
      for (int c = 0; c < 3; ++c) pq[c] += p[3 * v + c] * q[3 * v + c];
    }
    double alpha[3];
    for (int c = 0; c < 3; ++c) alpha[c] = pq[c] > 0 ? rz[c] / pq[c] : 0;
    double rz_new[3] = {0, 0, 0};
    for (size_t v = 0; v < n; ++v) {
      for (int c = 0; c < 3; ++c) {
        (*x)[3 * v + c] += alpha[c] * p[3 * v + c];
        r[3 * v + c] -= alpha[c] * q[3 * v + c];
        z[3 * v + c] = a.inv_diag[v] * r[3 * v + c];
        rz_new[c] += r[3 * v + c] * z[3 * v + c];
      }
    }
    for (int c = 0; c < 3; ++c) {
      const double beta = rz[c] > 0 ? rz_new[c] / rz[c] : 0;
      rz[c] = rz_new[c];
      for (size_t v = 0; v < n; ++v) p[3 * v + c] = z[3 * v + c] + beta * p[3 * v + c];
    }
  }
}

// Each vertex at its nearest anchor's position (multi-source BFS in anchor order).
std::vector<double> nearest_anchor_guess(const gab::EdgeGraph& g, const std::vector<int32_t>& anchors,
                                         const std::vector<double>& positions) {
  const int32_t n = g.num_vertices();
  std::vector<int32_t> source(n, -1), frontier = anchors, next;
  for (int32_t a : anchors) source[a] = a;
  while (!frontier.empty()) {
    next.clear();
    for (int32_t u : frontier) {
      for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
        const int32_t w = g.neighbors[p];
        if (source[w] >= 0) continue;
        source[w] = source[u];
        next.push_back(w);
      }
    }
    frontier.swap(next);
  }
  std::vector<double> x(3 * static_cast<size_t>(n), 0.0);
  for (int32_t v = 0; v < n; ++v) {
    if (source[v] < 0) continue;
    for (int c = 0; c < 3; ++c) x[3 * v + c] = positions[3 * source[v] + c];
  }
  return x;
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
  std::vector<int> iterations = {10, 20, 40, 80, 160, 320};
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

  System a;
  a.g = &g;
  a.anchor_diag.assign(n, 0.0);
  for (int32_t v : anchors) a.anchor_diag[v] = weight * weight;
  a.inv_diag.resize(n);
  a.tmp.resize(3 * static_cast<size_t>(n));
  for (int32_t v = 0; v < n; ++v) {
    const double d = g.offsets[v + 1] - g.offsets[v];
    a.inv_diag[v] = 1.0 / (d * d + d + a.anchor_diag[v]);
  }
  std::vector<double> b(3 * static_cast<size_t>(n), 0.0);
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int c = 0; c < 3; ++c) b[3 * anchors[i] + c] = weight * weight * coefficients[3 * i + c];
  }
  t = now();
  const std::vector<double> guess = nearest_anchor_guess(g, anchors, mesh.positions);
  const double guess_s = now() - t;
  std::printf("%-10s rms %.3e (%.3fx)  from global %.3e  %.3f s\n", "nearest", rms_between(guess, mesh.positions) / diagonal,
              rms_between(guess, mesh.positions) / diagonal / global_rms, rms_between(guess, global) / diagonal, guess_s);
  for (int iters : iterations) {
    std::vector<double> x = guess;
    t = now();
    cg(a, b, iters, &x);
    const double seconds = now() - t + guess_s;
    const double rms = rms_between(x, mesh.positions) / diagonal;
    char name[32];
    std::snprintf(name, sizeof name, "cg-%d", iters);
    std::printf("%-10s rms %.3e (%.3fx)  from global %.3e  %.3f s\n", name, rms, rms / global_rms,
                rms_between(x, global) / diagonal, seconds);
  }
  return 0;
}
