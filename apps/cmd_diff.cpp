// gab diff (its options: commands.cpp)
// Compares two meshes: per-vertex distances (where the numberings
// correspond) and the Metro-style symmetric surface distance, absolute and
// relative to the bounding-box diagonal of A.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli.h"
#include "commands.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/renumber.h"
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace cli {

namespace {

// value / diagonal, or NaN (printed as null) when the diagonal is 0.
double relative(double value, double diagonal) { return diagonal > 0 ? value / diagonal : std::nan(""); }

// A --map file: one index per line (blank lines and surrounding spaces
// allowed), line i the index in B of A's vertex i: a permutation of
// 0..n-1 for n vertices.
Status read_vertex_map(const std::string& path, int32_t n, std::vector<int32_t>* map) {
  std::string text;
  GAB_RETURN_IF_ERROR(read_file(path, &text));
  map->clear();
  std::vector<char> seen(static_cast<size_t>(n), 0);
  size_t line = 0, at = 0;
  while (at < text.size()) {
    const size_t end = std::min(text.find('\n', at), text.size());
    ++line;
    std::string field = text.substr(at, end - at);
    at = end + 1;
    const size_t first = field.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    field = field.substr(first, field.find_last_not_of(" \t\r") - first + 1);
    const std::string where = path + ": line " + std::to_string(line) + ": ";
    char* stop = nullptr;
    const long long value = std::strtoll(field.c_str(), &stop, 10);
    if (*stop != '\0' || field[0] == '+') {
      return Status::Error(StatusCode::kParseError, where + "'" + field + "' is not a vertex index");
    }
    if (static_cast<int64_t>(map->size()) >= n) {
      return Status::Error(StatusCode::kParseError, where + "more indices than A's " + std::to_string(n) + " vertices");
    }
    if (value < 0 || value >= n) {
      return Status::Error(StatusCode::kParseError,
                           where + "index " + field + " is outside 0.." + std::to_string(n - 1));
    }
    if (seen[static_cast<size_t>(value)]) {
      return Status::Error(StatusCode::kParseError, where + "index " + field + " is given twice");
    }
    seen[static_cast<size_t>(value)] = 1;
    map->push_back(static_cast<int32_t>(value));
  }
  if (static_cast<int32_t>(map->size()) != n) {
    return Status::Error(StatusCode::kParseError, path + ": " + std::to_string(map->size()) +
                                                      " indices for A's " + std::to_string(n) + " vertices");
  }
  return Status::Ok();
}

}  // namespace

int run_diff(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {"--samples", "--map"}, {"--json"})) return usage_error("diff", args.error());
  if (args.positionals().size() != 2) return usage_error("diff", "expected two mesh files");
  int64_t samples = -1;
  if (!args.get_int("--samples", 0, 1000000000, &samples)) return usage_error("diff", args.error());
  const bool json = args.has("--json");
  const std::string& path_a = args.positionals()[0];
  const std::string& path_b = args.positionals()[1];

  const double t0 = now_seconds();
  Mesh a, b;
  Status status = read_mesh_warning(path_a, &a);
  if (!status.ok()) return fail(status.message());
  status = read_mesh_warning(path_b, &b);
  if (!status.ok()) return fail(status.message());

  // Per-vertex figures only where vertex i of A is vertex i of B (or
  // map[i], with --map): the same count and the same triangles by index.
  // A renumbered mesh (a decode in traversal order, compress's default;
  // another tool's output) would otherwise pair unrelated vertices.
  std::string why_not;
  Mesh b_in_a_order;
  const Mesh* paired = &b;
  if (a.num_vertices() != b.num_vertices()) {
    why_not = "the vertex counts differ (" + std::to_string(a.num_vertices()) + " and " +
              std::to_string(b.num_vertices()) + ")";
  } else {
    if (args.has("--map")) {
      std::vector<int32_t> map;
      status = read_vertex_map(args.get("--map"), a.num_vertices(), &map);
      if (!status.ok()) return fail(status.message());
      std::vector<int32_t> to_a(map.size());
      for (size_t i = 0; i < map.size(); ++i) to_a[static_cast<size_t>(map[i])] = static_cast<int32_t>(i);
      b_in_a_order = renumber_vertices(b, to_a);
      paired = &b_in_a_order;
    }
    if (oriented_triangle_set(a.triangles) != oriented_triangle_set(paired->triangles)) {
      why_not = args.has("--map") ? "the triangles differ by vertex index under --map " + args.get("--map")
                                  : "the triangles differ by vertex index: the numberings do not correspond (a "
                                    "renumbered mesh, such as a decode in traversal order, gab compress's "
                                    "default; --map FILE pairs them: compress --order-out writes it)";
    }
  }
  const double diagonal = bounding_box_diagonal(a);
  VertexDistance vd;
  const bool per_vertex = why_not.empty() && vertex_distance(a, *paired, &vd).ok();
  // Why not: on stderr beside JSON, in the text's own line otherwise.
  if (!why_not.empty() && json) std::fprintf(stderr, "gab diff: no per-vertex distances: %s\n", why_not.c_str());
  SurfaceDistanceOptions options;
  options.samples = samples;
  SurfaceDistance sd;
  status = surface_distance(a, b, options, &sd);
  if (!status.ok()) return fail(status.message());
  const double seconds = now_seconds() - t0;

  JsonObject out;
  out.add("n", static_cast<int64_t>(a.num_vertices()));
  if (per_vertex) {
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
  if (per_vertex) {
    std::printf("vertex distance: max %.6g (%s of the diagonal), rms %.6g (%s)\n", vd.linf, rel(vd.linf).c_str(),
                vd.rms, rel(vd.rms).c_str());
  } else {
    std::printf("vertex distance: n/a: %s\n", why_not.c_str());
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
