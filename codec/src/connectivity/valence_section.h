// Any triangle list through the valence coder (valence_coder.h): the
// manifold cut and its undoing, the closing of boundaries, the valences, and
// what a traversal cannot carry (vertices the cut copied, degenerate
// triangles, vertices on no triangle), in one range-coded stream.
//
// The decoder numbers vertices in traversal order (then the vertices on no
// proper triangle, in their input order) and lists the triangles in the
// order it conquers them, then the degenerate ones. Orientation is kept;
// triangle order, which corner comes first and the vertex numbering are not.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/status.h"

namespace gab {

struct ValenceSection {
  std::vector<uint8_t> bytes;
  // new_index[v]: the decoder's number for input vertex v (a permutation).
  std::vector<int32_t> new_index;
  // The traversal's list steps (active_lists.h): the section decodes only
  // if this is within walk_budget(4 t).
  int64_t walked = 0;
};

// Codes `triangles` over n vertices (indices in [0, n), n >= 1).
// O(n + T), plus the traversal's splits (see valence_coder.h).
ValenceSection encode_valence_section(int32_t n, const std::vector<int32_t>& triangles);

// Decodes a section coded for n vertices and t triangles. Untrusted input:
// any inconsistency (counts that disagree with n and t, an index out of
// range, a stream cut short or with trailing bytes) is a kParseError naming
// it. A count is checked against what `size` bytes can describe before it
// is looped over: t (a closed region's triangles number at most twice its
// vertices plus four per handle, each vertex and handle a coded decision;
// a degenerate triangle is three coded indices) and the stitches and
// degenerate triangles the stream declares. O(n + T).
Status decode_valence_section(const uint8_t* data, size_t size, int32_t n, int32_t t,
                              std::vector<int32_t>* triangles);

}  // namespace gab
