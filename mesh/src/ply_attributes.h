// Internal to the mesh layer: which PLY properties become which mesh
// attributes, decided from the header alone, before the body is read.
#pragma once

#include <string>
#include <vector>

#include "gab/mesh/mesh.h"
#include "ply_header.h"

namespace gab {
namespace mesh_detail {

// Where one property's values go: component `component` of plan `plan`.
struct PlySlot {
  int plan = -1;  // -1: not an attribute's
  int component = 0;
};

struct PlyAttributePlan {
  MeshAttribute attribute;  // kind, type, name, components (0 for a list, until its first item count)
  // How the notes name it if its values make it unusable (a value that is
  // not finite, a list of varying length): "normals", "normals (nx ny nz".
  std::string key, label;
  bool list = false;  // a vertex list property: one generic of as many components as its items
};

struct PlyAttributes {
  std::vector<PlyAttributePlan> plans;  // in the order the mesh gets them
  std::vector<PlySlot> vertex;          // per property of the vertex element
  std::vector<PlySlot> face;            // per property of the face element
};

// The attributes of element `vertex` (x y z at properties xyz[3]) and
// element `face` (-1: none; `strips`: the mesh also has tristrips, whose
// corners no face list can describe):
// - normals: nx ny nz;
// - texture coordinates: s t, u v, texture_u texture_v [texture_w],
//   texture_s texture_t (the first pair present);
// - colours: red green blue [alpha], r g b [a], diffuse_red diffuse_green
//   diffuse_blue [diffuse_alpha] (the first set present);
// each of one type throughout (else its properties count as others);
// - a face list `texcoord` (u v per corner, MeshLab's): per-corner texture
//   coordinates, after the per-vertex ones;
// - every other vertex property: a generic named as it (a list property:
//   a generic of its items, 1 to 4).
// At most kMaxMeshAttributes in all, in the order normals, texture
// coordinates, colours, generics (the writer's); a property left
// without a slot (past the limit, a name an attribute cannot have) is the
// caller's to note. O(properties).
PlyAttributes plan_ply_attributes(const PlyHeader& header, int vertex, const int xyz[3], int face, bool strips);

// The attribute value type of a PLY type.
ValueType value_type(PlyType type);
// A value type's name in a PLY header: "char", "uchar", ..., "float", "double".
const char* ply_type_name(ValueType type);

}  // namespace mesh_detail
}  // namespace gab
