// PLY files (Turk's Polygon File Format): read and write, ASCII and binary.
#pragma once

#include <string>
#include <string_view>

#include "gab/mesh/mesh.h"
#include "gab/mesh/mesh_read_notes.h"
#include "gab/status.h"

namespace gab {

enum class PlyEncoding { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

struct PlyWriteOptions {
  PlyEncoding encoding = PlyEncoding::kBinaryLittleEndian;
  bool float32 = false;  // coordinates as float (smaller, rounded) instead of double (exact)
};

// Reads a PLY file: ASCII or binary of either byte order; x y z of element
// `vertex` (any scalar type), the `vertex_indices` (or `vertex_index`) list of
// element `face` (any list count and index types; polygons fan-triangulated)
// and of element `tristrips` (-1 restarts strips; strips alternate
// orientation; their zero-area stitching triangles are dropped). Other
// properties and elements are skipped, and counted in `notes` when given (on
// success), with the polygons triangulated; header lines end at LF, CRLF or
// CR, and a line with an unknown keyword is skipped with a warning there.
// Errors name the file and the line
// (header, ASCII body) or the element and its index (binary body): counts the
// file cannot hold (checked before anything is allocated), indices out of
// range, NaN or infinite coordinates, truncation, faces with fewer than 3
// vertices, no vertices or no faces. O(file size).
Status read_ply(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Same, from the file's bytes in memory; `name` is used in messages.
Status parse_ply(std::string_view bytes, const std::string& name, Mesh* mesh, MeshReadNotes* notes = nullptr);

// The PLY bytes of a mesh: element vertex (x y z as double or float), element
// face (list uchar int vertex_indices). O(V + T).
std::string format_ply(const Mesh& mesh, const PlyWriteOptions& options = PlyWriteOptions());

// Validates the mesh, then writes format_ply(mesh, options) atomically. O(V + T).
Status write_ply(const std::string& path, const Mesh& mesh, const PlyWriteOptions& options = PlyWriteOptions());

}  // namespace gab
