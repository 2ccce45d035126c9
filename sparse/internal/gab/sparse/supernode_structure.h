// The steps of the symbolic analysis that turn a partition into supernodes
// (SymbolicFactor::first_col) into the factor's supernodal structure; called
// in this order by analyze_structure (symbolic.cpp).
#pragma once

#include "gab/sparse/csc.h"
#include "gab/sparse/symbolic.h"

namespace gab {

// The supernode tree: num_supernodes, supernode_of and supernode_parent
// (the supernode holding the etree parent of each one's last column; for a
// panel that continues, the next panel), from first_col, continued and
// etree. O(n).
void link_supernodes(SymbolicFactor* f);

// Rows of every supernode (row_ptr, row_ind): its own columns, then the
// union of the rows below them from A's columns and from its children's
// structures, sorted; a chain of panels takes its supernode's rows, each
// panel from its own columns on. `graph` is A's symmetric pattern (both triangles) in
// the original numbering, read through f->perm. O(sum of rows * log).
void supernode_rows(const CscMatrix& graph, SymbolicFactor* f);

// Where each supernode's dense block starts in the factor's values
// (value_ptr), the entries stored (stored_L) and the tallest block
// (max_front_rows). O(ns).
void lay_out_blocks(SymbolicFactor* f);

}  // namespace gab
