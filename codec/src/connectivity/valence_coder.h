// Valence-driven connectivity coding (Touma & Gotsman, "Triangle Mesh
// Compression", Graphics Interface 1998), the core of issue 17's coder: a
// closed oriented combinatorial manifold is conquered triangle by triangle
// from a seed, growing a region whose boundary is kept as cyclic "active
// lists" of vertex occurrences. The focus vertex's next unconquered triangle
// either brings a new vertex (ADD, coded with its valence), closes the
// focus's last gap (CLOSE, implied by the valences almost always), joins two
// places of the current list (SPLIT, coded with an offset) or two lists
// (MERGE, a handle of the surface, coded with the list and an offset). On
// regular meshes the valences are nearly all 6 and cost a fraction of a bit.
//
// The list holds vertex *occurrences*: a vertex met by a SPLIT or MERGE
// lies on the boundary once per gap (run of unconquered triangles around
// it), and the encoder names the occurrence whose gap holds the triangle.
// So the coder never looks vertices up by pairs and works on any closed
// combinatorial manifold, double edges (a pinched boundary closed by a
// dummy vertex) included.
//
// Open meshes are closed first (close_boundaries): one dummy vertex per
// boundary loop, flagged in the stream, whose triangles the decoder drops.
#pragma once

#include <cstdint>
#include <vector>

#include "entropy/range_coder.h"
#include "gab/mesh/manifold_cut.h"
#include "gab/status.h"

namespace gab {

// A closed oriented combinatorial manifold: every half-edge has an opposite.
struct ClosedMesh {
  int32_t num_vertices = 0;
  std::vector<int32_t> triangles;  // 3 per triangle
  std::vector<int32_t> opposite;   // per half-edge (see manifold_cut.h), all >= 0
  std::vector<uint8_t> dummy;      // per vertex: 1 for a boundary loop's dummy
};

// The cut mesh with each boundary loop closed by a fan of triangles around a
// dummy vertex (numbered after the cut's vertices, in the order of the
// loops' first boundary half-edges). The cut's triangles keep their indices.
// O(T).
ClosedMesh close_boundaries(const ManifoldCut& cut);
// The same, taking the cut's triangles and opposites (left empty; its
// other fields stay) instead of copying them: a closed mesh costs no copy.
ClosedMesh close_boundaries(ManifoldCut* cut);

// Connected components of a closed mesh (through the opposites). O(T).
int32_t count_components(const ClosedMesh& mesh);

// What the decoder rebuilds: the triangles, oriented as in the input, over
// vertices numbered in decoding order (dummies included and flagged).
struct DecodedConnectivity {
  int32_t num_vertices = 0;
  std::vector<int32_t> triangles;
  std::vector<uint8_t> dummy;
};

// Coder versions. 1: Touma & Gotsman's traversal as first shipped (the
// focus moves to a neighbour after each CLOSE, valences in the context of
// two neighbours). 2: Alliez & Desbrun's adaptive traversal (the focus is
// the vertex with the fewest free triangles) and richer valence statistics
// (adaptive_valence_coder.h).
constexpr int kValenceCoderLatest = 2;

// Codes `mesh` with coder `version` (1..kValenceCoderLatest, clamped into
// it); order[k] is the mesh vertex the decoder will number k. Returns the
// list steps walked (active_lists.h), at least the decoder's. O(T) plus
// O(offset) per SPLIT and O(list) per MERGE.
int64_t encode_valences(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order, int version);

// Decodes what encode_valences coded. Untrusted input: at most
// `max_triangles` triangles and `max_vertices` vertices (dummies included)
// are built, every offset and valence is checked against the state, and
// anything inconsistent is a kParseError naming what, an unknown `version`
// included, as is a stream whose splits and merges would walk more than
// walk_budget(max_triangles) list steps. O(T) as the encoder, and never
// more than that budget.
Status decode_valences(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles, DecodedConnectivity* out,
                       int version);

}  // namespace gab
