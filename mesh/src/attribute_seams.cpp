// Seam splitting. One pass over the corners finds, for each vertex, the
// distinct combinations ("variants") of the elements its corners refer to,
// in a list per vertex; a second builds the mesh with one vertex per
// variant. Most vertices have one variant, so the lists stay short.
#include "gab/mesh/attribute_seams.h"

#include <cstring>

namespace gab {

namespace {

// The attributes to make per vertex: per corner and selected.
std::vector<size_t> attributes_to_split(const Mesh& mesh, const std::vector<bool>& selected) {
  std::vector<size_t> out;
  for (size_t a = 0; a < mesh.attributes.size(); ++a) {
    const bool chosen = selected.empty() || (a < selected.size() && selected[a]);
    if (chosen && mesh.attributes[a].per_corner()) out.push_back(a);
  }
  return out;
}

// Variants of the vertices: variant i refers to elements key[m i .. m i + m)
// (one per split attribute), becomes vertex out_vertex[i] and copies
// source[i]; next[i] is the next variant of the same input vertex (-1: none).
struct Variants {
  std::vector<int32_t> key, out_vertex, source, next;
  std::vector<int32_t> corner_variant;  // the variant of every corner
  int64_t vertices = 0;                 // vertices of the output
};

Variants find_variants(const Mesh& mesh, const std::vector<size_t>& split) {
  const size_t m = split.size();
  Variants w;
  w.vertices = mesh.num_vertices();
  w.corner_variant.resize(mesh.triangles.size());
  std::vector<int32_t> first(static_cast<size_t>(mesh.num_vertices()), -1);
  std::vector<int32_t> corner_key(m);
  for (size_t c = 0; c < mesh.triangles.size(); ++c) {
    for (size_t j = 0; j < m; ++j) corner_key[j] = mesh.attributes[split[j]].corners[c];
    const int32_t v = mesh.triangles[c];
    int32_t* link = &first[static_cast<size_t>(v)];
    while (*link != -1 && std::memcmp(&w.key[m * static_cast<size_t>(*link)], corner_key.data(), m * sizeof(int32_t)) != 0) {
      link = &w.next[static_cast<size_t>(*link)];
    }
    int32_t variant = *link;
    if (variant == -1) {
      // A new combination: the first of its vertex keeps the vertex's index.
      variant = static_cast<int32_t>(w.next.size());
      const bool first_of_vertex = link == &first[static_cast<size_t>(v)];
      *link = variant;  // before next grows: `link` may point into it
      w.key.insert(w.key.end(), corner_key.begin(), corner_key.end());
      w.out_vertex.push_back(first_of_vertex ? v : static_cast<int32_t>(w.vertices++));
      w.source.push_back(v);
      w.next.push_back(-1);
    }
    w.corner_variant[c] = variant;
  }
  return w;
}

// `from`'s element `e` (k values) copied to element `to` of `values`.
void copy_element(const std::vector<double>& from, size_t e, size_t k, std::vector<double>* values, size_t to) {
  for (size_t i = 0; i < k; ++i) (*values)[k * to + i] = from[k * e + i];
}

}  // namespace

Mesh split_attribute_seams(const Mesh& mesh, const std::vector<bool>& selected, int64_t* added_vertices) {
  const std::vector<size_t> split = attributes_to_split(mesh, selected);
  if (added_vertices != nullptr) *added_vertices = 0;
  if (split.empty()) return mesh;
  const Variants w = find_variants(mesh, split);
  const size_t n = static_cast<size_t>(mesh.num_vertices());
  const size_t total = static_cast<size_t>(w.vertices);
  const size_t variants = w.out_vertex.size();

  Mesh out;
  out.positions = mesh.positions;
  out.positions.resize(3 * total);
  for (size_t i = 0; i < variants; ++i) {
    const size_t to = static_cast<size_t>(w.out_vertex[i]);
    if (to >= n) copy_element(mesh.positions, static_cast<size_t>(w.source[i]), 3, &out.positions, to);
  }
  out.triangles.resize(mesh.triangles.size());
  for (size_t c = 0; c < mesh.triangles.size(); ++c) {
    out.triangles[c] = w.out_vertex[static_cast<size_t>(w.corner_variant[c])];
  }
  out.attributes = mesh.attributes;
  size_t j = 0;  // position in `split`
  for (size_t a = 0; a < out.attributes.size(); ++a) {
    MeshAttribute& attribute = out.attributes[a];
    const std::vector<double>& from = mesh.attributes[a].values;
    const size_t k = static_cast<size_t>(attribute.components);
    if (j < split.size() && split[j] == a) {
      // Made per vertex: each variant's element, zeros where no corner is.
      attribute.values.assign(k * total, 0.0);
      attribute.corners.clear();
      for (size_t i = 0; i < variants; ++i) {
        copy_element(from, static_cast<size_t>(w.key[split.size() * i + j]), k, &attribute.values,
                     static_cast<size_t>(w.out_vertex[i]));
      }
      ++j;
    } else if (!attribute.per_corner()) {
      // Per vertex already: the new vertices copy their source's element.
      attribute.values.resize(k * total);
      for (size_t i = 0; i < variants; ++i) {
        const size_t to = static_cast<size_t>(w.out_vertex[i]);
        if (to >= n) copy_element(from, static_cast<size_t>(w.source[i]), k, &attribute.values, to);
      }
    }
  }
  if (added_vertices != nullptr) *added_vertices = w.vertices - mesh.num_vertices();
  return out;
}

}  // namespace gab
