// OFF files (Geomview Object File Format): read and write.
#pragma once

#include <string>

#include "gab/mesh/mesh.h"
#include "gab/sparse/status.h"

namespace gab {

// Reads an OFF / COFF / NOFF / CNOFF file ('#' comments allowed). Polygons
// are fan-triangulated; per-vertex or per-face extras (colours, normals) are
// skipped. Errors name the file and line: bad header, counts the file cannot
// hold (checked before anything is allocated), indices out of range, NaN or
// infinite coordinates, truncated files, faces with fewer than 3 vertices.
Status read_off(const std::string& path, Mesh* mesh);

// Same, from text in memory; `name` is used in messages.
Status parse_off(const std::string& text, const std::string& name, Mesh* mesh);

}  // namespace gab
