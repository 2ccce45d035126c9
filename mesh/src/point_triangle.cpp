// Closest point on a triangle by Voronoi-region classification (C. Ericson,
// Real-Time Collision Detection, 2005, section 5.1.5): the sign tests of a
// few dot products tell whether the nearest feature is a vertex, an edge or
// the face, and only that feature's projection is computed. The face case's
// barycentric weights divide by |ab x ac|^2, so zero-area triangles take the
// edge path instead.
#include "gab/mesh/point_triangle.h"

namespace gab {

namespace {

inline double dot(const double u[3], const double v[3]) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
inline void sub(const double u[3], const double v[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = u[i] - v[i];
}
inline double dist2(const double u[3], const double v[3]) {
  double d[3];
  sub(u, v, d);
  return dot(d, d);
}
// q = a + t (b - a)
inline void lerp(const double a[3], const double b[3], double t, double q[3]) {
  for (int i = 0; i < 3; ++i) q[i] = a[i] + t * (b[i] - a[i]);
}

}  // namespace

double closest_point_on_segment(const double p[3], const double a[3], const double b[3], double q[3]) {
  double ab[3], ap[3];
  sub(b, a, ab);
  sub(p, a, ap);
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(ap, ab) / len2 : 0.0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  lerp(a, b, t, q);
  return dist2(p, q);
}

double closest_point_on_triangle(const double p[3], const double a[3], const double b[3], const double c[3],
                                 double q[3]) {
  double ab[3], ac[3], ap[3];
  sub(b, a, ab);
  sub(c, a, ac);
  sub(p, a, ap);
  const double ab2 = dot(ab, ab), ac2 = dot(ac, ac), abac = dot(ab, ac);
  // |ab x ac|^2 = |ab|^2 |ac|^2 - (ab.ac)^2 (Lagrange); relative test so that
  // slivers whose cross product is lost to rounding count as degenerate.
  const double area2 = ab2 * ac2 - abac * abac;
  if (!(area2 > 1e-24 * ab2 * ac2)) {
    double best = closest_point_on_segment(p, a, b, q), r[3];
    const double d2 = closest_point_on_segment(p, b, c, r);
    if (d2 < best) {
      best = d2;
      for (int i = 0; i < 3; ++i) q[i] = r[i];
    }
    const double d3 = closest_point_on_segment(p, c, a, r);
    if (d3 < best) {
      best = d3;
      for (int i = 0; i < 3; ++i) q[i] = r[i];
    }
    return best;
  }
  // Vertex region of a.
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) {
    for (int i = 0; i < 3; ++i) q[i] = a[i];
    return dist2(p, q);
  }
  // Vertex region of b.
  double bp[3];
  sub(p, b, bp);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) {
    for (int i = 0; i < 3; ++i) q[i] = b[i];
    return dist2(p, q);
  }
  // Edge region of ab: vc is the (scaled) barycentric weight of c.
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    lerp(a, b, d1 / (d1 - d3), q);
    return dist2(p, q);
  }
  // Vertex region of c.
  double cp[3];
  sub(p, c, cp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) {
    for (int i = 0; i < 3; ++i) q[i] = c[i];
    return dist2(p, q);
  }
  // Edge region of ac.
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    lerp(a, c, d2 / (d2 - d6), q);
    return dist2(p, q);
  }
  // Edge region of bc.
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    lerp(b, c, (d4 - d3) / ((d4 - d3) + (d5 - d6)), q);
    return dist2(p, q);
  }
  // Face region: barycentric (u, v, w) = (va, vb, vc) / (va + vb + vc).
  const double inv = 1.0 / (va + vb + vc);
  const double v = vb * inv, w = vc * inv;
  for (int i = 0; i < 3; ++i) q[i] = a[i] + ab[i] * v + ac[i] * w;
  return dist2(p, q);
}

}  // namespace gab
