#include "ply_attributes.h"

#include "attribute_text.h"
#include "text_scanner.h"

namespace gab {
namespace mesh_detail {

namespace {

// A set of property names that make one attribute: the first `required`
// must all be there, the rest are taken when there.
struct NameSet {
  AttributeKind kind;
  std::vector<const char*> names;
  size_t required;
};

const std::vector<NameSet>& name_sets() {
  static const std::vector<NameSet> sets = {
      {AttributeKind::kNormal, {"nx", "ny", "nz"}, 3},
      {AttributeKind::kTexCoord, {"s", "t"}, 2},
      {AttributeKind::kTexCoord, {"u", "v"}, 2},
      {AttributeKind::kTexCoord, {"texture_u", "texture_v", "texture_w"}, 2},
      {AttributeKind::kTexCoord, {"texture_s", "texture_t"}, 2},
      {AttributeKind::kColor, {"red", "green", "blue", "alpha"}, 3},
      {AttributeKind::kColor, {"r", "g", "b", "a"}, 3},
      {AttributeKind::kColor, {"diffuse_red", "diffuse_green", "diffuse_blue", "diffuse_alpha"}, 3},
  };
  return sets;
}

const char* kind_key(AttributeKind kind) {
  switch (kind) {
    case AttributeKind::kNormal: return "normals";
    case AttributeKind::kTexCoord: return "texture_coordinates";
    case AttributeKind::kColor: return "vertex_colors";
    case AttributeKind::kGeneric: break;
  }
  return "";
}

const char* kind_words(AttributeKind kind) {
  switch (kind) {
    case AttributeKind::kNormal: return "normals";
    case AttributeKind::kTexCoord: return "texture coordinates";
    case AttributeKind::kColor: return "vertex colours";
    case AttributeKind::kGeneric: break;
  }
  return "";
}

// The properties of `e` that make `set` (its required names, then its
// optional ones present with the same type), or none.
std::vector<int> match(const PlyElement& e, const NameSet& set, const std::vector<PlySlot>& slots) {
  std::vector<int> found;
  for (size_t i = 0; i < set.names.size(); ++i) {
    const int p = e.find(set.names[i]);
    const bool usable = p >= 0 && !e.properties[p].is_list && slots[p].plan == -1 &&
                        (found.empty() || e.properties[p].type == e.properties[found[0]].type);
    if (usable) {
      found.push_back(p);
    } else if (i < set.required) {
      return {};
    }
  }
  return found;
}

void add_plan(PlyAttributes* out, PlyAttributePlan plan, const std::vector<int>& properties, std::vector<PlySlot>* slots) {
  const int index = static_cast<int>(out->plans.size());
  for (size_t c = 0; c < properties.size(); ++c) (*slots)[properties[c]] = PlySlot{index, static_cast<int>(c)};
  out->plans.push_back(std::move(plan));
}

}  // namespace

ValueType value_type(PlyType type) {
  switch (type) {
    case PlyType::kInt8: return ValueType::kInt8;
    case PlyType::kUint8: return ValueType::kUint8;
    case PlyType::kInt16: return ValueType::kInt16;
    case PlyType::kUint16: return ValueType::kUint16;
    case PlyType::kInt32: return ValueType::kInt32;
    case PlyType::kUint32: return ValueType::kUint32;
    case PlyType::kFloat32: return ValueType::kFloat32;
    case PlyType::kFloat64: break;
  }
  return ValueType::kFloat64;
}

const char* ply_type_name(ValueType type) {
  switch (type) {
    case ValueType::kInt8: return "char";
    case ValueType::kUint8: return "uchar";
    case ValueType::kInt16: return "short";
    case ValueType::kUint16: return "ushort";
    case ValueType::kInt32: return "int";
    case ValueType::kUint32: return "uint";
    case ValueType::kFloat32: return "float";
    case ValueType::kFloat64: break;
  }
  return "double";
}

PlyAttributes plan_ply_attributes(const PlyHeader& h, int vertex, const int xyz[3], int face, bool strips) {
  PlyAttributes out;
  const PlyElement& v = h.elements[vertex];
  out.vertex.assign(v.properties.size(), PlySlot());
  for (int c = 0; c < 3; ++c) out.vertex[xyz[c]].plan = -2;  // positions: taken, not an attribute
  if (face >= 0) out.face.assign(h.elements[face].properties.size(), PlySlot());
  const size_t limit = static_cast<size_t>(kMaxMeshAttributes);

  // The common kinds: the first set present of each, in the order normals,
  // texture coordinates (with MeshLab's per-corner ones), colours, as the
  // writer writes them.
  for (AttributeKind kind : {AttributeKind::kNormal, AttributeKind::kTexCoord, AttributeKind::kColor}) {
    for (const NameSet& set : name_sets()) {
      if (set.kind != kind) continue;
      const std::vector<int> found = match(v, set, out.vertex);
      if (found.empty()) continue;
      PlyAttributePlan plan;
      plan.attribute.kind = kind;
      plan.attribute.type = value_type(v.properties[found[0]].type);
      plan.attribute.components = static_cast<int32_t>(found.size());
      plan.key = kind_key(kind);
      plan.label = std::string(kind_words(kind)) + " (";
      for (size_t c = 0; c < found.size(); ++c) plan.label += (c > 0 ? " " : "") + printable(v.properties[found[c]].name);
      add_plan(&out, std::move(plan), found, &out.vertex);
      break;
    }
    // MeshLab's per-corner texture coordinates: a float list on the faces.
    const int p = face >= 0 ? h.elements[face].find("texcoord") : -1;
    if (kind == AttributeKind::kTexCoord && p >= 0 && !strips && h.elements[face].properties[p].is_list &&
        !ply_type_is_integral(h.elements[face].properties[p].type)) {
      PlyAttributePlan plan;
      plan.attribute.kind = AttributeKind::kTexCoord;
      plan.attribute.type = value_type(h.elements[face].properties[p].type);
      plan.attribute.components = 2;
      plan.key = "face.texcoord";
      plan.label = "face property 'texcoord' (";
      add_plan(&out, std::move(plan), {p}, &out.face);
    }
  }
  // Every other vertex property: a generic under its own name.
  for (size_t p = 0; p < v.properties.size() && out.plans.size() < limit; ++p) {
    const PlyProperty& property = v.properties[p];
    if (out.vertex[p].plan != -1 || !generic_name_ok(property.name)) continue;
    PlyAttributePlan plan;
    plan.attribute.kind = AttributeKind::kGeneric;
    plan.attribute.type = value_type(property.type);
    plan.attribute.name = property.name;
    plan.attribute.components = property.is_list ? 0 : 1;
    plan.list = property.is_list;
    plan.key = "vertex." + property.name;
    plan.label = "vertex property '" + property.name + "' (";
    add_plan(&out, std::move(plan), {static_cast<int>(p)}, &out.vertex);
  }
  for (PlySlot& s : out.vertex) s.plan = s.plan == -2 ? -1 : s.plan;
  return out;
}

}  // namespace mesh_detail
}  // namespace gab
