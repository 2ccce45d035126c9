// Version 2 of the valence coder (valence_coder.h): Alliez & Desbrun's
// adaptive traversal ("Valence-Driven Connectivity Encoding for 3D Meshes",
// Eurographics 2001, section 3) on version 1's active lists and events: the
// focus is always the vertex of the current list with the fewest free
// (unconquered) triangles, which keeps the conquered region's boundary
// convex and makes SPLITs rare (nefertiti: 3,071 -> about 110). Each new
// vertex's valence is coded in the context of the three known valences
// around it, through adaptive statistics that learn fast and settle slowly.
#pragma once

#include <cstdint>
#include <vector>

#include "connectivity/valence_coder.h"
#include "entropy/range_coder.h"
#include "gab/status.h"

namespace gab {

// encode_valences / decode_valences with version 2 (same contracts).
int64_t encode_adaptive_valences(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order);
Status decode_adaptive_valences(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles,
                                DecodedConnectivity* out);

}  // namespace gab
