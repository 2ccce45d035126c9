// Any triangle list cut into an oriented combinatorial manifold with
// boundary, the form a traversal-based connectivity coder needs (Rossignac's
// Edgebreaker and Touma & Gotsman's valence coder both walk a corner table),
// with what undoes the cut recorded:
//
// * triangles with a repeated vertex (degenerate) are set aside;
// * an edge is glued (its two half-edges become each other's opposite) only
//   when exactly two triangles use it, in opposite directions; an edge of
//   three or more triangles (non-manifold) or of two triangles that disagree
//   on orientation is cut: each of its half-edges becomes a boundary edge;
// * the corners around a vertex then fall into fans (linked by the glued
//   edges); a vertex with several fans (a pinch, or the ends of a cut) keeps
//   its index for its first fan and gets a copy for each further one.
//
// Mapping each copy back to its original (copy_of) gives back the input's
// oriented triangles exactly. Corner c = 3t + i is triangle t's i-th
// vertex; half-edge c runs from corner c's vertex to corner next(c)'s.
#pragma once

#include <cstdint>
#include <vector>

namespace gab {

struct ManifoldCut {
  // Vertices of the cut mesh: the input's n, then the copies.
  int32_t num_vertices = 0;
  // The non-degenerate triangles, in input order, over the cut vertices.
  std::vector<int32_t> triangles;
  // For each cut triangle, its index in the input.
  std::vector<int32_t> source_triangle;
  // opposite[c]: the half-edge glued to half-edge c (it runs the other way),
  // or -1 on the boundary. An involution.
  std::vector<int32_t> opposite;
  // copy_of[k]: the input vertex that cut vertex n + k copies.
  std::vector<int32_t> copy_of;
  // The degenerate triangles, as in the input (3 indices each), and their
  // input indices.
  std::vector<int32_t> degenerate;
  std::vector<int32_t> degenerate_source;
};

// Cuts `triangles` (3 indices each, all in [0, n)) as above. Deterministic:
// copies are numbered in the order of their fans' first corners.
// O(n + T) time and memory (half-edges are bucketed by their lower vertex).
ManifoldCut cut_to_manifold(int32_t n, const std::vector<int32_t>& triangles);

inline int32_t next_corner(int32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
inline int32_t prev_corner(int32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }

}  // namespace gab
