// gab compress (options: commands.cpp): greedy geometry-aware anchors,
// quantized and range coded. Without a stopping rule: --error 0.001.
#include <cstdio>
#include <string>
#include <utility>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "commands.h"
#include "progress_line.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/mesh_io.h"

namespace gab {
namespace cli {

namespace {

constexpr double kDefaultError = 1e-3;

}  // namespace

int run_compress(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {"-i", "-o", "--anchors", "--error", "--linf", "--bits", "--weight", "--batch-fraction", "--batch", "--chunk-growth",
                   "--initial", "--threads", "--layout", "--detail", "--ordering", "--solver", "--order-out",
                   "--normal-bits", "--uv-bits", "--color-bits", "--generic-bits"},
                  {"--json", "--geometry-only", "--refine", "--reorder", "--keep-order", "--quiet", "--strict"})) {
    return usage_error("compress", args.error());
  }
  if (!args.positionals().empty()) return usage_error("compress", "unexpected argument " + args.positionals()[0]);
  if (!args.has("-i") || !args.has("-o")) return usage_error("compress", "need -i IN and -o OUT.gab");
  const int rules = args.has("--anchors") + args.has("--error") + args.has("--linf");
  if (rules > 1) return usage_error("compress", "give at most one of --anchors, --error, --linf");
  EncodeOptions options;
  int64_t anchors = 0, bits = options.bits, initial = 0;
  int64_t normal_bits = options.normal_bits, uv_bits = options.texcoord_bits, color_bits = options.color_bits,
          generic_bits = options.generic_bits;
  double error = rules == 0 ? kDefaultError : 0.0, linf = 0.0;
  if (!args.get_int("--anchors", 1, 0x7FFFFFFF, &anchors) || !args.get_double("--error", 1e-12, 1.0, &error) ||
      !args.get_double("--linf", 1e-12, 1.0, &linf) || !args.get_int("--bits", kGabMinBits, kGabMaxBits, &bits) ||
      !args.get_double("--weight", 1e-6, 1e6, &options.weight) ||
      !args.get_double("--batch-fraction", 0.0, 1.0, &options.batch_fraction) ||
      !args.get_double("--chunk-growth", 1.01, 1e9, &options.chunk_growth) ||
      !args.get_int("--initial", 1, 0x7FFFFFFF, &initial) || !args.get_threads(&options.threads) ||
      !args.get_ordering(kCodecOrderings, Ordering::kAuto, &options.ordering) ||
      !args.get_int("--normal-bits", 2, 16, &normal_bits) || !args.get_int("--uv-bits", 1, 31, &uv_bits) ||
      !args.get_int("--color-bits", 1, 31, &color_bits) || !args.get_int("--generic-bits", 1, 31, &generic_bits)) {
    return usage_error("compress", args.error());
  }
  options.normal_bits = static_cast<int>(normal_bits);
  options.texcoord_bits = static_cast<int>(uv_bits);
  options.color_bits = static_cast<int>(color_bits);
  options.generic_bits = static_cast<int>(generic_bits);
  // --batch was this fraction's first spelling; study's --batch is a count.
  if (args.has("--batch")) {
    if (args.has("--batch-fraction")) return usage_error("compress", "give --batch-fraction only (--batch is its old name)");
    if (!args.get_double("--batch", 0.0, 1.0, &options.batch_fraction)) return usage_error("compress", args.error());
    std::fprintf(stderr, "gab compress: note: --batch is now --batch-fraction\n");
  }
  options.max_anchors = static_cast<int32_t>(anchors);
  options.initial_anchors = static_cast<int32_t>(initial);
  options.target_rms_rel = error;
  options.target_linf_rel = linf;
  options.bits = static_cast<int>(bits);
  options.geometry_only = args.has("--geometry-only");
  options.refine = args.has("--refine");
  // The numbering: the traversal's by default (the smallest file; --reorder
  // spells it out), the input's with --keep-order (priced: the order block)
  // or --geometry-only (no connectivity to traverse).
  if (args.has("--reorder") && args.has("--keep-order")) {
    return usage_error("compress", "give --reorder (the default) or --keep-order, not both");
  }
  if (args.has("--reorder") && options.geometry_only) {
    return usage_error("compress", "--reorder codes the connectivity: it cannot go with --geometry-only");
  }
  options.reorder = !args.has("--keep-order") && !options.geometry_only;
  if (args.has("--order-out") && !options.reorder) {
    return usage_error("compress", std::string("--order-out writes the map onto the traversal's numbering: ") +
                                       (options.geometry_only ? "--geometry-only" : "--keep-order") +
                                       " keeps the input's numbering");
  }
  // The chunk layout (encoder.h FileLayout); "selection" files are readable by older builds.
  const std::string layout = args.get("--layout", "smaller");
  if (layout == "levels") {
    options.layout = FileLayout::kLevels;
  } else if (layout == "selection") {
    options.layout = FileLayout::kSelectionOrder;
  } else if (layout != "smaller") {
    return usage_error("compress", "--layout must be smaller, levels or selection, got '" + layout + "'");
  }
  // The reconstruction operator (gab_format.h Solver).
  const std::string solver = args.get("--solver", "auto");
  if (!parse_solver(solver, &options.solver)) {
    return usage_error("compress", "--solver must be auto, global or iterative, got '" + solver + "'");
  }
  if (options.solver == Solver::kIterative && options.refine) {
    return usage_error("compress", "--refine needs the global solver (--solver global or auto)");
  }
  // The detail layer (encoder.h DetailMode).
  const std::string detail = args.get("--detail", "auto");
  if (detail == "on") {
    options.detail = DetailMode::kOn;
  } else if (detail == "off") {
    options.detail = DetailMode::kOff;
  } else if (detail != "auto") {
    return usage_error("compress", "--detail must be auto, on or off, got '" + detail + "'");
  }
  if (options.detail == DetailMode::kOn && rules > 0 && args.has("--anchors")) {
    return usage_error("compress", "--detail on needs an error target (--error or --linf), not --anchors");
  }
  const bool json = args.has("--json");
  const std::string in = args.get("-i"), out = args.get("-o");
  if (const int refused = check_output("compress", out, {in})) return refused;
  const std::string order_out = args.get("--order-out", "");
  if (!order_out.empty()) {
    if (order_out == out) return usage_error("compress", "--order-out and -o name the same file");
    if (const int refused = check_output("compress", order_out, {in, out})) return refused;
  }

  Mesh mesh;
  MeshReadNotes read_notes;
  Status status = read_mesh_warning(in, &mesh, &read_notes);
  if (!status.ok()) return fail(status.message());
  // --strict: data the file held and gab does not carry stops the compress
  // before any work (the warning above named it; this is the failure).
  if (args.has("--strict") && !read_notes.dropped.empty()) {
    return fail(in + ": --strict: not carried: " + read_notes.dropped_summary());
  }
  std::vector<uint8_t> file;
  EncodeStats stats;
  {
    ProgressLine progress(args.has("--quiet"));
    if (progress.on()) {
      options.progress = [&progress](int32_t k, double rms) {
        char text[96];
        std::snprintf(text, sizeof text, "gab compress: %d anchors, rms %.3g of the diagonal", k, rms);
        progress.show(text);
      };
    }
    status = encode_mesh(std::move(mesh), options, &file, &stats);  // not read again here
    options.progress = nullptr;  // it refers to `progress`, which ends here
  }
  if (!status.ok()) return fail(in + ": " + status.message());
  status = write_output_file(out, std::string_view(reinterpret_cast<const char*>(file.data()), file.size()));
  if (!status.ok()) return fail(status.message());
  if (!order_out.empty()) {
    // Again now that -o exists: another spelling of it is caught only now.
    if (const int refused = check_output("compress", order_out, {in, out})) return refused;
    // Line i: the decoded index of input vertex i (gab diff --map reads it).
    std::string lines;
    lines.reserve(8 * stats.new_index.size());
    for (int32_t v : stats.new_index) lines += std::to_string(v) + "\n";
    status = write_output_file(order_out, lines);
    if (!status.ok()) return fail(status.message());
  }
  if (!stats.target_met && stats.detail) {
    std::fprintf(stderr,
                 "gab compress: warning: the error target is out of reach: the detail layer's finest step leaves "
                 "rms %.3g, max %.3g of the diagonal\n",
                 stats.rms_rel, stats.linf_rel);
  } else if (!stats.target_met) {
    std::fprintf(stderr,
                 "gab compress: warning: the error target is out of reach: every vertex is an anchor and the "
                 "error is rms %.3g, max %.3g of the diagonal at q = %d, w = %g; use more --bits (or a larger "
                 "--weight), or leave the detail layer on\n",
                 stats.rms_rel, stats.linf_rel, stats.bits, options.weight);
  }
  const double bpv = 8.0 * static_cast<double>(stats.geometry_bytes) / stats.num_vertices;
  if (json) {
    JsonObject o;
    o.add("n", static_cast<int64_t>(stats.num_vertices));
    o.add("faces", static_cast<int64_t>(stats.num_triangles));
    o.add("anchors", static_cast<int64_t>(stats.anchors));
    o.add("bits", static_cast<int64_t>(stats.bits));
    o.add("bytes", static_cast<int64_t>(stats.bytes));
    o.add("geometry_bytes", static_cast<int64_t>(stats.geometry_bytes));
    o.add("connectivity_bytes", static_cast<int64_t>(stats.connectivity_bytes));
    o.add("bpv_geometry", bpv);
    o.add("linf_rel", stats.linf_rel);
    o.add("rms_rel", stats.rms_rel);
    o.add("encode_s", stats.encode_s);
    o.add("chunks", static_cast<int64_t>(stats.chunks));
    o.add("weight", options.weight);
    o.add_bool("target_met", stats.target_met);
    o.add_bool("refined", stats.refined);
    o.add("refinement_bytes", static_cast<int64_t>(stats.refinement_bytes));
    o.add("unrefined_rms_rel", stats.unrefined_rms_rel);
    o.add_bool("levels", stats.levels);
    o.add_bool("reordered", stats.reordered);
    o.add("order_bytes", static_cast<int64_t>(stats.order_bytes));
    o.add_bool("detail", stats.detail);
    o.add("detail_bytes", static_cast<int64_t>(stats.detail_bytes));
    o.add("detail_step_rel", stats.detail_step_rel);
    o.add("anchor_rms_rel", stats.detail ? stats.anchor_rms_rel : stats.rms_rel);
    o.add("ordering", std::string(ordering_name(stats.ordering)));
    o.add("solver", std::string(solver_name(stats.solver)));
    std::vector<JsonObject> candidates;
    for (const EncodeStats::Candidate& c : stats.candidates) {
      JsonObject j;
      j.add("name", c.name);
      j.add("bits", static_cast<int64_t>(c.bits));
      j.add("anchors", static_cast<int64_t>(c.anchors));
      j.add("estimate_bytes", static_cast<int64_t>(c.estimate_bytes));
      j.add("bytes", static_cast<int64_t>(c.bytes));
      j.add_bool("target_met", c.target_met);
      j.add("seconds", c.seconds);
      j.add_bool("kept", c.kept);
      candidates.push_back(std::move(j));
    }
    o.add("candidates", candidates);
    o.add("attribute_bytes", static_cast<int64_t>(stats.attribute_bytes));
    o.add("merged_vertices", static_cast<int64_t>(stats.merged_vertices));
    std::vector<JsonObject> attributes;
    for (const AttributeStats& a : stats.attributes) {
      JsonObject j;
      j.add("label", a.label);
      j.add("bits", static_cast<int64_t>(a.bits));
      j.add_bool("per_corner", a.per_corner);
      j.add("elements", a.elements);
      j.add("bytes", static_cast<int64_t>(a.bytes));
      j.add("max_error", a.max_error);
      j.add_bool("from_surface", a.from_surface);
      attributes.push_back(j);
    }
    o.add("attributes", attributes);
    // What the input held that the file does not carry (docs/cli.md).
    JsonObject dropped;
    for (const DroppedData& d : read_notes.dropped) dropped.add(d.key, d.count);
    o.add("dropped", dropped);
    std::printf("%s\n", o.str().c_str());
    return kExitOk;
  }
  // The summary goes to stderr when the file itself went to stdout (any
  // name of it: /dev/stdout, /dev/fd/1, the file stdout is redirected to).
  struct stat written, standard_out;
  const bool to_stdout = ::stat(out.c_str(), &written) == 0 && ::fstat(STDOUT_FILENO, &standard_out) == 0 &&
                         written.st_dev == standard_out.st_dev && written.st_ino == standard_out.st_ino;
  FILE* summary = to_stdout ? stderr : stdout;
  std::fprintf(summary, "%s -> %s: %d vertices, %d triangles, %d anchors in %d chunks%s, q = %d\n", in.c_str(),
               out.c_str(), stats.num_vertices, stats.num_triangles, stats.anchors, stats.chunks,
               stats.refined  ? " (the last a least-squares refinement)"
               : stats.detail ? " (the last the detail layer)"
                              : "",
               stats.bits);
  std::fprintf(summary,
               "%zu bytes (geometry %zu = %.3f bits/vertex, connectivity %zu, vertex order %zu, attributes %zu); error "
               "rms %.3g, max %.3g of the bounding-box diagonal; %.2f s\n",
               stats.bytes, stats.geometry_bytes, bpv, stats.connectivity_bytes, stats.order_bytes,
               stats.attribute_bytes, stats.rms_rel, stats.linf_rel, stats.encode_s);
  if (stats.merged_vertices > 0) {
    std::fprintf(summary, "  %d vertices merged into copies at the same position (their data kept per corner)\n",
                 stats.merged_vertices);
  }
  for (const AttributeStats& a : stats.attributes) {
    std::fprintf(summary, "  %s: %zu bytes, %lld %s, %d bits, largest error %.3g%s%s\n", a.label.c_str(), a.bytes,
                 static_cast<long long>(a.elements), a.per_corner ? "values shared by corners" : "per vertex", a.bits,
                 a.max_error, a.label == "normals" ? " degrees" : "",
                 a.from_surface ? " (predicted from the decoded surface)" : "");
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
