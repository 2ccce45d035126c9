// Error metrics between two meshes: per-vertex distances (same vertex order)
// and a Metro-style symmetric surface distance.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {

// Length of the diagonal of the axis-aligned box of all vertices. O(V).
double bounding_box_diagonal(const Mesh& mesh);

struct VertexDistance {
  double linf = 0;  // max_i |a_i - b_i|
  double rms = 0;   // sqrt(mean_i |a_i - b_i|^2)
};

// Distances between corresponding vertices; the meshes must have the same
// vertex count (kInvalidArgument otherwise). O(V).
Status vertex_distance(const Mesh& a, const Mesh& b, VertexDistance* out);

// Squared 3D distance per vertex between `shape` (3 per vertex, like
// Mesh::positions) and the mesh's positions, into error2 (n entries), with
// their RMS and max (not squared). What a greedy anchor loop scans after
// every reconstruction. O(V).
void squared_vertex_errors(const Mesh& mesh, const std::vector<double>& shape, std::vector<double>* error2,
                           VertexDistance* out);

struct DirectedDistance {
  double mean = 0;     // mean over the area samples of the distance to the other surface
  double rms = 0;      // root mean square of the same
  double max = 0;      // max over the area samples and the referenced vertices
  int64_t samples = 0; // area samples used
};

struct SurfaceDistance {
  DirectedDistance a_to_b, b_to_a;
  double mean = 0;       // over the samples of both directions together
  double rms = 0;        // over the samples of both directions together
  double hausdorff = 0;  // max of the two directions' max
};

struct SurfaceDistanceOptions {
  // Area-uniform samples on each surface; negative: default_sample_count().
  int64_t samples = -1;
  uint64_t seed = 0x67616220646966ULL;  // fixed: the same inputs give the same numbers
};

// The default number of samples per surface: two per triangle of the larger
// mesh, at least 100,000. O(1).
int64_t default_sample_count(const Mesh& a, const Mesh& b);

// Metro-style distance (Cignoni, Rocchini and Scopigno 1998): samples spread
// uniformly by area on each surface, exact point-to-surface distance to the
// other through a TriangleBvh; the max also looks at every vertex used by a
// triangle. Inputs must be valid meshes (kInvalidArgument otherwise).
// O((T_a + T_b) log T + (samples + V) * query), a query being O(log T)
// for typical inputs.
Status surface_distance(const Mesh& a, const Mesh& b, const SurfaceDistanceOptions& options, SurfaceDistance* out);

}  // namespace gab
