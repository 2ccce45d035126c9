// The mesh the .gab fuzzer's geometry-only seeds were made from (and that
// tests/codec replays them with): a 10 x 6 torus, built in code (the tests'
// own torus, tests/common/test_meshes.h; make_gab_seeds.sh writes the same).
#pragma once

#include "../common/test_meshes.h"
#include "gab/mesh/mesh.h"

namespace gab_fuzz {

inline gab::Mesh seed_torus() { return gab::testing_util::torus(10, 6); }
// torus-iterative-large's: past 2^14 vertices.
inline gab::Mesh large_seed_torus() { return gab::testing_util::torus(192, 180); }

}  // namespace gab_fuzz
