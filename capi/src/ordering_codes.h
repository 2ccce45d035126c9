// The C API's GAB_ORDERING_* and GAB_SOLVER_* codes against the engine's
// Ordering and the codec's Solver.
#pragma once

#include <cstdint>

#include "gab/codec/gab_format.h"
#include "gab/sparse/ordering.h"

namespace gab {
namespace capi {

// The Ordering a GAB_ORDERING_* code stands for; false for any other value.
bool ordering_of_code(int32_t code, Ordering* ordering);
// The Solver a GAB_SOLVER_* code stands for; false for any other value.
bool solver_of_code(int32_t code, Solver* solver);

}  // namespace capi
}  // namespace gab
