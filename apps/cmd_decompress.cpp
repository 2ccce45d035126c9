// gab decompress (its options: commands.cpp)
// Decodes a .gab file (or its first K anchors: a coarser level of detail)
// and writes the mesh (.obj .off .ply by extension), vertex order kept.
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string>

#include "cli.h"
#include "commands.h"
#include "progress_line.h"
#include "gab/codec/decoder.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/mesh_write_notes.h"

namespace gab {
namespace cli {

namespace {

// --max-memory SIZE: bytes, or a number with K, M, G or T (powers of 1024),
// or "none" (no budget: -1). False for anything else.
bool parse_memory(const std::string& text, int64_t* bytes) {
  if (text == "none") {
    *bytes = -1;
    return true;
  }
  size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') ++digits;
  if (digits == 0 || digits > 15 || text.size() > digits + 1) return false;
  int shift = 0;
  if (text.size() == digits + 1) {
    const std::string units = "KMGT";
    const size_t unit = units.find(static_cast<char>(std::toupper(static_cast<unsigned char>(text.back()))));
    if (unit == std::string::npos) return false;
    shift = 10 * static_cast<int>(unit + 1);
  }
  const int64_t value = std::stoll(text.substr(0, digits));
  if (value < 1 || value > (INT64_MAX >> shift)) return false;
  *bytes = value << shift;
  return true;
}

}  // namespace

int run_decompress(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {"-i", "-o", "--anchors", "--connectivity", "--threads", "--ordering", "--max-memory"},
                  {"--json", "--quiet"})) {
    return usage_error("decompress", args.error());
  }
  if (!args.positionals().empty()) {
    return usage_error("decompress", "unexpected argument " + args.positionals()[0]);
  }
  if (!args.has("-i") || !args.has("-o")) return usage_error("decompress", "need -i IN.gab and -o OUT");
  int64_t anchors = -1;
  int32_t threads = 1;
  Ordering ordering = Ordering::kAuto;
  if (!args.get_int("--anchors", 0, 0x7FFFFFFF, &anchors) || !args.get_threads(&threads) ||
      !args.get_ordering(kCodecOrderings, Ordering::kAuto, &ordering)) {
    return usage_error("decompress", args.error());
  }
  int64_t max_memory = 0;
  if (args.has("--max-memory") && !parse_memory(args.get("--max-memory"), &max_memory)) {
    return usage_error("decompress", "--max-memory must be a size in bytes (e.g. 512M, 4G) or 'none', got '" +
                                         args.get("--max-memory") + "'");
  }
  const std::string in = args.get("-i"), out = args.get("-o");
  const std::string ext = extension(out);
  if (ext != "obj" && ext != "off" && ext != "ply") {
    return usage_error("decompress", "output must be .obj, .off or .ply: " + out);
  }
  std::vector<std::string> inputs = {in};
  if (args.has("--connectivity")) inputs.push_back(args.get("--connectivity"));
  if (const int refused = check_output("decompress", out, inputs)) return refused;

  std::string bytes;
  Status status = read_file(in, &bytes);
  if (!status.ok()) return fail(status.message());
  Mesh connectivity;
  DecodeOptions options;
  options.max_anchors = static_cast<int32_t>(anchors);
  options.threads = threads;
  options.ordering = ordering;
  options.max_memory = max_memory;
  if (args.has("--connectivity")) {
    status = read_mesh(args.get("--connectivity"), &connectivity);
    if (!status.ok()) return fail(status.message());
    options.connectivity = &connectivity;
  }
  Mesh mesh;
  DecodeStats stats;
  {
    ProgressLine progress(args.has("--quiet"));
    if (progress.on()) {
      options.progress = [&progress](int32_t chunk, int32_t chunks) {
        progress.show("gab decompress: chunk " + std::to_string(chunk + 1) + " of " + std::to_string(chunks));
      };
    }
    status = decode_mesh(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), options, &mesh, &stats);
    options.progress = nullptr;  // it refers to `progress`, which ends here
  }
  if (!status.ok()) return fail(in + ": " + status.message());
  MeshWriteNotes written;
  status = write_mesh(out, mesh, PlyWriteOptions(), &written);
  if (!status.ok()) return fail(status.message());
  // What the output's format could not hold as decoded: never silent.
  if (written.split_vertices > 0) {
    std::fprintf(stderr,
                 "gab decompress: warning: %s: %lld vertices added where per-corner data has seams (the format holds "
                 "it per vertex; OBJ keeps the mesh's vertices)\n",
                 out.c_str(), static_cast<long long>(written.split_vertices));
  }
  if (!written.not_written.empty()) {
    std::fprintf(stderr, "gab decompress: warning: %s: not written: %s\n", out.c_str(),
                 written.not_written_summary().c_str());
  }
  if (stats.skipped_sections > 0) {
    std::fprintf(stderr,
                 "gab decompress: warning: %s: %d sections not decoded (attributes predicted from the whole decoded "
                 "shape, which a level of detail does not have, or of a kind this build does not know)\n",
                 in.c_str(), stats.skipped_sections);
  }
  if (options.connectivity != nullptr && !stats.geometry_only) {
    std::fprintf(stderr, "gab decompress: warning: --connectivity ignored: %s carries its own connectivity\n",
                 in.c_str());
  }
  if (stats.truncated) {
    std::fprintf(stderr, "gab decompress: warning: %s is truncated: decoded %d of %d chunks (%d of %d anchors)\n",
                 in.c_str(), stats.chunks, stats.chunks_in_file, stats.anchors, stats.anchors_in_file);
  }
  if (args.has("--json")) {
    JsonObject o;
    o.add("n", static_cast<int64_t>(stats.num_vertices));
    o.add("anchors", static_cast<int64_t>(stats.anchors));
    o.add("decode_s", stats.decode_s);
    o.add("factor_s", stats.factor_s);
    o.add("solve_s", stats.solve_s);
    o.add("update_s", stats.update_s);
    o.add("faces", static_cast<int64_t>(stats.num_triangles));
    o.add("anchors_in_file", static_cast<int64_t>(stats.anchors_in_file));
    o.add("chunks", static_cast<int64_t>(stats.chunks));
    o.add("chunks_in_file", static_cast<int64_t>(stats.chunks_in_file));
    o.add_bool("truncated", stats.truncated);
    o.add("refactorizations", static_cast<int64_t>(stats.refactorizations));
    o.add_bool("refined", stats.refined);
    o.add_bool("reordered", stats.reordered);
    o.add("connectivity_s", stats.connectivity_s);
    o.add("matrix_entries", stats.matrix_entries);
    o.add("factor_entries", stats.factor_entries);
    o.add("memory_limit", stats.memory_limit);
    o.add_bool("detail", stats.detail);
    o.add("detail_s", stats.detail_s);
    o.add("ordering", std::string(ordering_name(stats.ordering)));
    o.add("solver", std::string(solver_name(stats.solver)));
    o.add("attributes", static_cast<int64_t>(mesh.attributes.size()));
    o.add("attributes_s", stats.attributes_s);
    o.add("skipped_sections", static_cast<int64_t>(stats.skipped_sections));
    o.add("split_vertices", written.split_vertices);
    std::printf("%s\n", o.str().c_str());
    return kExitOk;
  }
  std::printf("%s -> %s: %d vertices, %d triangles, %d of %d anchors (%d of %d chunks); %.3f s "
              "(factor %.3f, updates %.3f, solves %.3f)\n",
              in.c_str(), out.c_str(), stats.num_vertices, stats.num_triangles, stats.anchors, stats.anchors_in_file,
              stats.chunks, stats.chunks_in_file, stats.decode_s, stats.factor_s, stats.update_s, stats.solve_s);
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
