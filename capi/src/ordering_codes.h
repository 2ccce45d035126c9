// The C API's GAB_ORDERING_* codes against the engine's Ordering.
#pragma once

#include <cstdint>

#include "gab/sparse/ordering.h"

namespace gab {
namespace capi {

// The Ordering a GAB_ORDERING_* code stands for; false for any other value.
bool ordering_of_code(int32_t code, Ordering* ordering);

}  // namespace capi
}  // namespace gab
