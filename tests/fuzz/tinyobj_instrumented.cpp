// tinyobjloader compiled with the fuzzers' instrumentation (see CMakeLists).
#define TINYOBJLOADER_USE_DOUBLE
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
