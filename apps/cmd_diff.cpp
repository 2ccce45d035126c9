// gab diff (its options: commands.cpp)
// Compares two meshes: per-vertex distances (when the vertex counts match)
// and the Metro-style symmetric surface distance, absolute and relative to
// the bounding-box diagonal of A.
#include <cmath>
#include <cstdio>
#include <string>

#include "cli.h"
#include "commands.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/metrics.h"

namespace gab {
namespace cli {

namespace {

// value / diagonal, or NaN (printed as null) when the diagonal is 0.
double relative(double value, double diagonal) { return diagonal > 0 ? value / diagonal : std::nan(""); }

}  // namespace

int run_diff(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {"--samples"}, {"--json"})) return usage_error("diff", args.error());
  if (args.positionals().size() != 2) return usage_error("diff", "expected two mesh files");
  int64_t samples = -1;
  if (!args.get_int("--samples", 0, 1000000000, &samples)) return usage_error("diff", args.error());
  const bool json = args.has("--json");
  const std::string& path_a = args.positionals()[0];
  const std::string& path_b = args.positionals()[1];

  const double t0 = now_seconds();
  Mesh a, b;
  Status status = read_mesh(path_a, &a);
  if (!status.ok()) return fail(status.message());
  status = read_mesh(path_b, &b);
  if (!status.ok()) return fail(status.message());

  const double diagonal = bounding_box_diagonal(a);
  VertexDistance vd;
  const bool same_count = vertex_distance(a, b, &vd).ok();
  SurfaceDistanceOptions options;
  options.samples = samples;
  SurfaceDistance sd;
  status = surface_distance(a, b, options, &sd);
  if (!status.ok()) return fail(status.message());
  const double seconds = now_seconds() - t0;

  JsonObject out;
  out.add("n", static_cast<int64_t>(a.num_vertices()));
  if (same_count) {
    out.add("linf", vd.linf);
    out.add("rms", vd.rms);
    out.add("linf_rel", relative(vd.linf, diagonal));
    out.add("rms_rel", relative(vd.rms, diagonal));
  } else {
    for (const char* key : {"linf", "rms", "linf_rel", "rms_rel"}) out.add_null(key);
  }
  // With no area samples (--samples 0, or zero-area surfaces) only the
  // Hausdorff distance (from the vertices) is defined.
  const bool sampled = sd.a_to_b.samples + sd.b_to_a.samples > 0;
  const double no_value = std::nan("");
  out.add("metro_mean_rel", sampled ? relative(sd.mean, diagonal) : no_value);
  out.add("metro_rms_rel", sampled ? relative(sd.rms, diagonal) : no_value);
  out.add("hausdorff_rel", relative(sd.hausdorff, diagonal));
  out.add("n_b", static_cast<int64_t>(b.num_vertices()));
  out.add("faces", static_cast<int64_t>(a.num_triangles()));
  out.add("faces_b", static_cast<int64_t>(b.num_triangles()));
  out.add("diagonal", diagonal);
  out.add("metro_mean", sampled ? sd.mean : no_value);
  out.add("metro_rms", sampled ? sd.rms : no_value);
  out.add("hausdorff", sd.hausdorff);
  out.add("a_to_b_mean_rel", relative(sd.a_to_b.mean, diagonal));
  out.add("a_to_b_max_rel", relative(sd.a_to_b.max, diagonal));
  out.add("b_to_a_mean_rel", relative(sd.b_to_a.mean, diagonal));
  out.add("b_to_a_max_rel", relative(sd.b_to_a.max, diagonal));
  out.add("samples", sd.a_to_b.samples);
  out.add("samples_b", sd.b_to_a.samples);
  out.add("diff_s", seconds);
  if (json) {
    std::printf("%s\n", out.str().c_str());
    return kExitOk;
  }
  // Relative to the diagonal, or "n/a" for a box of no size (one point).
  auto rel = [diagonal](double value) {
    char text[32] = "n/a";
    if (diagonal > 0) std::snprintf(text, sizeof(text), "%.6g", value / diagonal);
    return std::string(text);
  };
  std::printf("A %s: %d vertices, %d triangles, bounding-box diagonal %.6g%s\n", path_a.c_str(), a.num_vertices(),
              a.num_triangles(), diagonal, diagonal > 0 ? "" : " (no size: no relative distances)");
  std::printf("B %s: %d vertices, %d triangles\n", path_b.c_str(), b.num_vertices(), b.num_triangles());
  if (same_count) {
    std::printf("vertex distance: max %.6g (%s of the diagonal), rms %.6g (%s)\n", vd.linf, rel(vd.linf).c_str(),
                vd.rms, rel(vd.rms).c_str());
  } else {
    std::printf("vertex distance: n/a (vertex counts differ)\n");
  }
  std::printf("surface distance (%lld + %lld samples): mean %.6g (%s), rms %.6g (%s), Hausdorff %.6g (%s)\n",
              static_cast<long long>(sd.a_to_b.samples), static_cast<long long>(sd.b_to_a.samples), sd.mean,
              rel(sd.mean).c_str(), sd.rms, rel(sd.rms).c_str(), sd.hausdorff, rel(sd.hausdorff).c_str());
  std::printf("  A to B: mean %.6g, max %.6g; B to A: mean %.6g, max %.6g\n", sd.a_to_b.mean, sd.a_to_b.max,
              sd.b_to_a.mean, sd.b_to_a.max);
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
