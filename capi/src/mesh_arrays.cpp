// Meshes and bytes across the C boundary (boundary.h): the caller's arrays
// in, checked; malloc'd arrays out.
#include <cstdlib>
#include <cstring>

#include "boundary.h"

namespace gab {
namespace capi {

namespace {

// A malloc'd copy of `count` elements (at least one byte, so a
// zero-length result is still a pointer gab_free accepts).
template <class T>
Status malloc_copy(const T* data, size_t count, T** out) {
  void* p = std::malloc(count > 0 ? count * sizeof(T) : 1);
  if (p == nullptr) return Status::Error(StatusCode::kOutOfMemory, "cannot allocate the result");
  if (count > 0) std::memcpy(p, data, count * sizeof(T));
  *out = static_cast<T*>(p);
  return Status::Ok();
}

}  // namespace

Status import_mesh(const double* positions, int32_t n, const int32_t* triangles, int32_t t, Mesh* mesh) {
  GAB_RETURN_IF_ERROR(require(n > 0, "n = " + std::to_string(n) + ": a mesh needs at least one vertex"));
  GAB_RETURN_IF_ERROR(require(t > 0, "t = " + std::to_string(t) + ": a mesh needs at least one triangle"));
  GAB_RETURN_IF_ERROR(require(positions != nullptr, "positions is NULL"));
  GAB_RETURN_IF_ERROR(require(triangles != nullptr, "triangles is NULL"));
  mesh->positions.assign(positions, positions + 3 * static_cast<size_t>(n));
  mesh->triangles.assign(triangles, triangles + 3 * static_cast<size_t>(t));
  return validate_mesh(*mesh, "mesh");
}

Status clear_mesh_outputs(double** positions, int32_t* n, int32_t** triangles, int32_t* t) {
  if (positions != nullptr) *positions = nullptr;
  if (triangles != nullptr) *triangles = nullptr;
  if (n != nullptr) *n = 0;
  if (t != nullptr) *t = 0;
  GAB_RETURN_IF_ERROR(require(positions != nullptr, "positions is NULL"));
  GAB_RETURN_IF_ERROR(require(n != nullptr, "n is NULL"));
  GAB_RETURN_IF_ERROR(require(triangles != nullptr, "triangles is NULL"));
  return require(t != nullptr, "t is NULL");
}

Status export_mesh(const Mesh& mesh, double** positions, int32_t* n, int32_t** triangles, int32_t* t) {
  double* p = nullptr;
  int32_t* f = nullptr;
  GAB_RETURN_IF_ERROR(malloc_copy(mesh.positions.data(), mesh.positions.size(), &p));
  const Status copied = malloc_copy(mesh.triangles.data(), mesh.triangles.size(), &f);
  if (!copied.ok()) {
    std::free(p);
    return copied;
  }
  *positions = p;
  *triangles = f;
  *n = mesh.num_vertices();
  *t = mesh.num_triangles();
  return Status::Ok();
}

Status export_bytes(const std::vector<uint8_t>& bytes, unsigned char** out, size_t* out_size) {
  GAB_RETURN_IF_ERROR(malloc_copy(bytes.data(), bytes.size(), out));
  *out_size = bytes.size();
  return Status::Ok();
}

Status export_indices(const std::vector<int32_t>& indices, int32_t** out) {
  return malloc_copy(indices.data(), indices.size(), out);
}

}  // namespace capi
}  // namespace gab
