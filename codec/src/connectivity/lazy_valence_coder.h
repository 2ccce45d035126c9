// Version 2 of the valence coder (valence_coder.h): the same traversal
// events as version 1, but a vertex's valence is coded late, when the
// traversal first needs it, as its count of free triangles given the count
// already conquered around it. See lazy_valence_coder.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "connectivity/valence_coder.h"
#include "entropy/range_coder.h"
#include "gab/status.h"

namespace gab {

// As encode_valences / decode_valences with version 2.
void encode_lazy_valences(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order);
Status decode_lazy_valences(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles, DecodedConnectivity* out);

}  // namespace gab
