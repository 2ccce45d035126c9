// Valence-driven connectivity coding: Touma & Gotsman's traversal
// ("Triangle Mesh Compression", Graphics Interface 1998) with Alliez &
// Desbrun's adaptive choice of focus ("Valence-Driven Connectivity Encoding
// for 3D Meshes", Eurographics 2001, section 3). A closed oriented
// combinatorial manifold (closed_mesh.h) is conquered triangle by triangle
// from a seed, growing a region whose boundary is kept as cyclic "active
// lists" of vertex occurrences (active_lists.h). The focus is always the
// vertex of the current list with the fewest free (unconquered) triangles,
// which keeps the region's boundary convex and makes SPLITs rare. The
// focus's next unconquered triangle either brings a new vertex (ADD, coded
// with its valence in the context of the three known valences around it),
// closes the focus's last gap (CLOSE, implied by the valences almost
// always), joins two places of the current list (SPLIT, coded with an
// offset) or two lists (MERGE, a handle of the surface, coded with the list
// and an offset). On regular meshes the valences are nearly all 6 and cost
// a fraction of a bit.
//
// The list holds vertex *occurrences*: a vertex met by a SPLIT or MERGE
// lies on the boundary once per gap (run of unconquered triangles around
// it), and the encoder names the occurrence whose gap holds the triangle.
// So the coder never looks vertices up by pairs and works on any closed
// combinatorial manifold, double edges (a pinched boundary closed by a
// dummy vertex) included.
#pragma once

#include <cstdint>
#include <vector>

#include "connectivity/closed_mesh.h"
#include "entropy/range_coder.h"
#include "gab/status.h"

namespace gab {

// What the decoder rebuilds: the triangles, oriented as in the input, over
// vertices numbered in decoding order (dummies included and flagged).
struct DecodedConnectivity {
  int32_t num_vertices = 0;
  std::vector<int32_t> triangles;
  std::vector<uint8_t> dummy;
};

// Codes `mesh`; order[k] is the mesh vertex the decoder will number k.
// Returns the list steps walked (active_lists.h), at least the decoder's.
// O(T) plus O(offset) per SPLIT and O(list) per MERGE.
int64_t encode_valences(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order);

// Decodes what encode_valences coded. Untrusted input: at most
// `max_triangles` triangles and `max_vertices` vertices (dummies included)
// are built, and memory is reserved for no more than the stream's bytes can
// describe; every offset and valence is checked against the state, and
// anything inconsistent is a kParseError naming what, as is a stream whose
// splits and merges would walk more than walk_budget(max_triangles) list
// steps. O(T) as the encoder, and never more than that budget.
// `expected_triangles` (when >= 0: the triangles the caller expects, its
// mesh's before the cut's dummies) sizes the arrays up front instead of the
// bounds, which a real stream's dummies come nowhere near.
Status decode_valences(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles, DecodedConnectivity* out,
                       int64_t expected_triangles = -1);

}  // namespace gab
