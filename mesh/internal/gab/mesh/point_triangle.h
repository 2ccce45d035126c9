// Exact closest points on segments and triangles in 3D.
#pragma once

namespace gab {

// Closest point q on segment [a, b] to p; returns |p - q|^2. A zero-length
// segment is the point a. O(1).
double closest_point_on_segment(const double p[3], const double a[3], const double b[3], double q[3]);

// Closest point q on triangle (a, b, c) to p; returns |p - q|^2. Degenerate
// (zero-area) triangles are handled as their three edges. O(1).
double closest_point_on_triangle(const double p[3], const double a[3], const double b[3], const double c[3],
                                 double q[3]);

}  // namespace gab
