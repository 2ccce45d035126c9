// The C API's GAB_ORDERING_* and GAB_SOLVER_* codes against the engine's
// Ordering and the codec's Solver.
#pragma once

#include <cstdint>

#include "gab/codec/gab_format.h"
#include "gab/sparse/ordering.h"
#include "gab/status.h"

namespace gab {
namespace capi {

// The Ordering a GAB_ORDERING_* code stands for; false for any other value.
bool ordering_of_code(int32_t code, Ordering* ordering);
// The ordering of a codec options struct (options->ordering): one the
// codec factors with (GAB_ORDERING_AUTO, _AMD, _ND); kInvalidArgument
// saying so for GAB_ORDERING_NATURAL and for an unknown code.
Status codec_ordering_of_code(int32_t code, Ordering* ordering);
// The Solver a GAB_SOLVER_* code stands for; false for any other value.
bool solver_of_code(int32_t code, Solver* solver);
// The GAB_ORDERING_* code of an ordering the codec takes, the GAB_SOLVER_*
// code of a solver; -1 for one the C door has no code for.
int32_t code_of_ordering(Ordering ordering);
int32_t code_of_solver(Solver solver);

}  // namespace capi
}  // namespace gab
