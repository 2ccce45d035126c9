// What every C entry point does at the boundary (gab.h's contract): map a
// gab::Status to a stable GAB_E_* code, write the caller's message buffer,
// catch every exception, and move arrays between C and gab's types.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "gab/gab.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {
namespace capi {

// The GAB_E_* code of a status code (GAB_OK for kOk).
int error_code(StatusCode code);

// Writes "FUNCTION: text" ("" when text is) into the caller's buffer:
// truncated to size - 1 bytes and NUL-terminated; nothing when message is
// NULL or size is 0. Allocates nothing, so it cannot throw.
void write_message(const char* function, const char* text, char* message, size_t size);

// kInvalidArgument with `what`, and the same unless `ok`: the door's
// argument checks (in loops, test first: `what` is built before the call).
Status invalid(const std::string& what);
Status require(bool ok, const std::string& what);

// Writes "FUNCTION: message" to the caller's buffer ("" when ok) and
// returns the status's GAB_E_* code. Cannot throw.
int report(const char* function, const Status& status, char* message, size_t size);

// Runs `body` (returning a Status) and reports its outcome as gab.h
// promises: the code, and "FUNCTION: message" in the caller's buffer (""
// on success). No exception leaves: std::bad_alloc is GAB_E_OUT_OF_MEMORY,
// anything else GAB_E_INTERNAL naming what was thrown.
template <class Body>
int guarded(const char* function, char* message, size_t size, Body&& body) {
  try {
    return report(function, body(), message, size);
  } catch (const std::bad_alloc&) {
    write_message(function, "out of memory", message, size);
    return GAB_E_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    write_message(function, e.what(), message, size);  // a bug: GAB_E_INTERNAL says so
  } catch (...) {
    write_message(function, "internal error: unknown exception", message, size);
  }
  return GAB_E_INTERNAL;
}

// A mesh from the caller's arrays (3n doubles, 3t indices), checked as
// every mesh reader's output is (validate_mesh): counts, NULL pointers,
// finite coordinates, indices in range. O(n + t).
Status import_mesh(const double* positions, int32_t n, const int32_t* triangles, int32_t t, Mesh* mesh);

// An options struct from the caller (gab.h's ABI rule): its first field,
// `size`, holds at least a size_t, and its bytes beyond the `known` this
// library has are zero (kUnsupported otherwise: a newer caller's field this
// library would ignore). `init` names the function that fills it.
Status check_options_size(const void* options, size_t size, size_t known, const char* init);

// gab.h's *_options_init: writes `defaults` (zeroed, then its known
// defaults set) into the caller's `size` bytes, its size field min(size,
// sizeof), the rest of `size` zeroed; nothing when not even the size field
// fits.
template <class Options>
void init_options(Options defaults, Options* out, size_t size) {
  if (out == nullptr || size < sizeof(size_t)) return;
  defaults.size = size < sizeof defaults ? size : sizeof defaults;
  std::memset(static_cast<void*>(out), 0, size);
  std::memcpy(static_cast<void*>(out), &defaults, defaults.size);
}

// An options struct's `threads`: 1..kMaxFactorThreads as given, 0 every
// core (at most kMaxFactorThreads); kInvalidArgument otherwise.
Status options_threads(int32_t given, int32_t* threads);

// Copies one field of the caller's struct (`size` bytes of it valid) when
// that size covers it; the field keeps its default otherwise.
template <class T>
void take_field(const void* options, size_t size, size_t offset, T* field) {
  if (offset + sizeof(T) <= size) std::memcpy(field, static_cast<const char*>(options) + offset, sizeof(T));
}

// Sets the output arrays of a function returning a mesh to NULL / 0, and
// fails when one of the four pointers is NULL.
Status clear_mesh_outputs(double** positions, int32_t* n, int32_t** triangles, int32_t* t);

// The mesh into malloc'd arrays the caller frees with gab_free.
Status export_mesh(const Mesh& mesh, double** positions, int32_t* n, int32_t** triangles, int32_t* t);

// Bytes into a malloc'd array the caller frees with gab_free.
Status export_bytes(const std::vector<uint8_t>& bytes, unsigned char** out, size_t* out_size);

// Indices into a malloc'd array the caller frees with gab_free.
Status export_indices(const std::vector<int32_t>& indices, int32_t** out);

}  // namespace capi
}  // namespace gab
