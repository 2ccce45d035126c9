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
//   pP-hH    patches with local solves: graph-Voronoi regions grown (by hops,
//            ties to the lower seed) from n / P farthest-point seeds (the
//            first vertex 0), each solved as the relaxed least squares of
//            the subgraph of its vertices and H rings around them (the
//            anchors there included; factored with AMD), its own vertices
//            kept. Independent, so parallel and deterministic; also the RMS
//            distance to the global shape on the patches' boundary vertices
//            (a neighbour in another patch) and on the rest: the seams.
// Prints per candidate the vertex RMS against the original over the box
// diagonal, its ratio to the global's, the RMS distance to the global shape,
// and seconds (one thread).
//
//   bench/reconstruction_candidates MESH [--spread H] [--weight W] [--iterations I,I,...]
//                                   [--patches P,P,...] [--halos H,H,...]
//   (defaults: 2, 100, 0,10,20,40,80,160,320, none, 4,8,12)
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

// Each vertex's patch: multi-source breadth-first regions from `count`
// seeds, the seeds chosen farthest-first in hops (the first vertex 0; ties
// to the lower index), a vertex joining the region that reaches it first
// (ties to the lower seed). Vertices out of the seeds' components get their
// own patches by the same rule, a seed each.
std::vector<int32_t> voronoi_patches(const gab::EdgeGraph& g, int32_t count, int32_t* num_patches) {
  const int32_t n = g.num_vertices();
  std::vector<int32_t> hops(n, INT32_MAX), seeds;
  auto lower = [&](int32_t from) {  // breadth-first from `from`, keeping the minimum hops
    std::vector<int32_t> queue = {from};
    hops[from] = 0;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int32_t u = queue[head];
      for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
        const int32_t w = g.neighbors[p];
        if (hops[w] <= hops[u] + 1) continue;
        hops[w] = hops[u] + 1;
        queue.push_back(w);
      }
    }
  };
  int32_t next = 0;
  while (static_cast<int32_t>(seeds.size()) < std::max(count, 1) && next >= 0) {
    seeds.push_back(next);
    lower(next);
    next = -1;
    int32_t far = 0;
    for (int32_t v = 0; v < n; ++v) {
      if (hops[v] == INT32_MAX) { next = v; break; }  // another component
      if (hops[v] > far) { far = hops[v]; next = v; }
    }
    if (far == 0 && next >= 0 && hops[next] != INT32_MAX) next = -1;
  }
  std::vector<int32_t> patch(n, -1), queue;
  for (int32_t i = 0; i < static_cast<int32_t>(seeds.size()); ++i) {
    patch[seeds[i]] = i;
    queue.push_back(seeds[i]);
  }
  for (size_t head = 0; head < queue.size(); ++head) {
    const int32_t u = queue[head];
    for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
      const int32_t w = g.neighbors[p];
      if (patch[w] >= 0) continue;
      patch[w] = patch[u];
      queue.push_back(w);
    }
  }
  int32_t patches = static_cast<int32_t>(seeds.size());
  for (int32_t v = 0; v < n; ++v) {  // isolated vertices
    if (patch[v] < 0) patch[v] = patches++;
  }
  *num_patches = patches;
  return patch;
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
  std::vector<int> patch_sizes, halos = {4, 8, 12};
  auto parse_list = [](const char* s) {
    std::vector<int> out;
    while (*s) {
      char* end = nullptr;
      out.push_back(static_cast<int>(std::strtol(s, &end, 10)));
      s = *end == ',' ? end + 1 : end;
    }
    return out;
  };
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--spread")) spread = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--weight")) weight = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--iterations")) iterations = parse_list(argv[i + 1]);
    if (!std::strcmp(argv[i], "--patches")) patch_sizes = parse_list(argv[i + 1]);
    if (!std::strcmp(argv[i], "--halos")) halos = parse_list(argv[i + 1]);
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
  std::vector<int32_t> anchor_index(n, -1);
  for (size_t i = 0; i < anchors.size(); ++i) anchor_index[anchors[i]] = static_cast<int32_t>(i);
  for (int size : patch_sizes) {
    int32_t num_patches = 0;
    const std::vector<int32_t> patch = voronoi_patches(g, std::max<int32_t>(1, n / std::max(size, 1)), &num_patches);
    std::vector<std::vector<int32_t>> members(num_patches);
    for (int32_t v = 0; v < n; ++v) members[patch[v]].push_back(v);
    size_t smallest = n, largest = 0;
    for (const auto& m : members) {
      smallest = std::min(smallest, m.size());
      largest = std::max(largest, m.size());
    }
    std::vector<char> boundary(n, 0);
    for (int32_t v = 0; v < n; ++v) {
      for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) boundary[v] |= patch[g.neighbors[p]] != patch[v];
    }
    for (int halo : halos) {
      std::vector<double> x(3 * static_cast<size_t>(n), 0.0);
      std::vector<int32_t> local(n, -1), region, queue;
      int64_t region_vertices = 0;
      t = now();
      for (int32_t k = 0; k < num_patches; ++k) {
        // The patch and `halo` rings around it, in breadth-first order.
        region = members[k];
        for (size_t i = 0; i < region.size(); ++i) local[region[i]] = static_cast<int32_t>(i);
        size_t ring_begin = 0;
        for (int h = 0; h < halo; ++h) {
          const size_t ring_end = region.size();
          for (size_t i = ring_begin; i < ring_end; ++i) {
            const int32_t u = region[i];
            for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
              const int32_t w = g.neighbors[p];
              if (local[w] >= 0) continue;
              local[w] = static_cast<int32_t>(region.size());
              region.push_back(w);
            }
          }
          ring_begin = ring_end;
        }
        region_vertices += static_cast<int64_t>(region.size());
        gab::EdgeGraph sub;
        sub.offsets.assign(1, 0);
        std::vector<int32_t> sub_anchors;
        std::vector<double> sub_coefficients;
        for (size_t i = 0; i < region.size(); ++i) {
          const int32_t u = region[i];
          for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
            if (local[g.neighbors[p]] >= 0) sub.neighbors.push_back(local[g.neighbors[p]]);
          }
          std::sort(sub.neighbors.begin() + sub.offsets.back(), sub.neighbors.end());
          sub.offsets.push_back(static_cast<int32_t>(sub.neighbors.size()));
          if (anchor_index[u] >= 0) {
            sub_anchors.push_back(static_cast<int32_t>(i));
            for (int c = 0; c < 3; ++c) sub_coefficients.push_back(coefficients[3 * anchor_index[u] + c]);
          }
        }
        gab::RelaxedReconstruction part;
        part.set_ordering(gab::Ordering::kAmd);
        std::vector<double> shape;
        s = part.init(sub, weight, sub_anchors, sub_coefficients);
        if (s.ok()) s = part.reconstruct(&shape);
        if (!s.ok()) {
          std::fprintf(stderr, "patch %d: %s\n", k, s.message().c_str());
          return 1;
        }
        for (size_t i = 0; i < members[k].size(); ++i) {
          for (int c = 0; c < 3; ++c) x[3 * members[k][i] + c] = shape[3 * i + c];
        }
        for (int32_t u : region) local[u] = -1;
      }
      const double seconds = now() - t;
      double seam[2] = {0, 0};
      int64_t seam_count[2] = {0, 0};
      for (int32_t v = 0; v < n; ++v) {
        for (int c = 0; c < 3; ++c) seam[boundary[v] ? 1 : 0] += (x[3 * v + c] - global[3 * v + c]) * (x[3 * v + c] - global[3 * v + c]);
        ++seam_count[boundary[v] ? 1 : 0];
      }
      const double rms = rms_between(x, mesh.positions) / diagonal;
      char name[32];
      std::snprintf(name, sizeof name, "p%d-h%d", size, halo);
      std::printf("%-10s rms %.3e (%.3fx)  from global %.3e  %.3f s  (%d patches of %zu-%zu, regions %.2fn; "
                  "from global on seams %.3e, elsewhere %.3e)\n",
                  name, rms, rms / global_rms, rms_between(x, global) / diagonal, seconds, num_patches, smallest,
                  largest, static_cast<double>(region_vertices) / n,
                  std::sqrt(seam[1] / std::max<int64_t>(seam_count[1], 1)) / diagonal,
                  std::sqrt(seam[0] / std::max<int64_t>(seam_count[0], 1)) / diagonal);
    }
  }
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
