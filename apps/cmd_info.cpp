// gab info (its options: commands.cpp)
// What a .gab file holds, from its header and chunk frames (checksums
// verified), without decoding it.
#include <cstdio>
#include <string>
#include <vector>

#include "cli.h"
#include "commands.h"
#include "gab/codec/decoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/file_io.h"

namespace gab {
namespace cli {

namespace {

}  // namespace

int run_info(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {}, {"--json"})) return usage_error("info", args.error());
  if (args.positionals().size() != 1) return usage_error("info", "expected one .gab file");
  const std::string in = args.positionals()[0];
  std::string bytes;
  Status status = read_file(in, &bytes);
  if (!status.ok()) return fail(status.message());
  GabFileInfo info;
  status = read_gab_info(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), &info);
  if (!status.ok()) return fail(in + ": " + status.message());
  const double bpv = 8.0 * static_cast<double>(info.geometry_bytes) / info.num_vertices;
  if (args.has("--json")) {
    JsonObject o;
    o.add("version", static_cast<int64_t>(info.version));
    o.add("n", static_cast<int64_t>(info.num_vertices));
    o.add("faces", static_cast<int64_t>(info.num_triangles));
    o.add("anchors", static_cast<int64_t>(info.anchors));
    o.add("chunks", static_cast<int64_t>(info.chunks));
    o.add("chunks_present", static_cast<int64_t>(info.chunks_present));
    o.add_bool("truncated", info.truncated);
    o.add("bits", static_cast<int64_t>(info.bits));
    o.add("weight", info.weight);
    o.add_bool("geometry_only", info.geometry_only);
    o.add("bytes", static_cast<int64_t>(info.bytes));
    o.add("geometry_bytes", static_cast<int64_t>(info.geometry_bytes));
    o.add("connectivity_bytes", static_cast<int64_t>(info.connectivity_bytes));
    o.add("order_bytes", static_cast<int64_t>(info.order_bytes));
    o.add("bpv_geometry", bpv);
    o.add_bool("refined", info.refined);
    o.add("refinement_bytes", static_cast<int64_t>(info.refinement_bytes));
    o.add_bool("detail", info.detail);
    o.add("detail_bytes", static_cast<int64_t>(info.detail_bytes));
    o.add("detail_step", info.detail_step);
    o.add_bool("levels", info.levels);
    o.add_bool("reordered", info.reordered);
    o.add("ordering", std::string(ordering_name(info.ordering)));
    o.add("reconstruction", static_cast<int64_t>(info.reconstruction));
    o.add("solver", std::string(solver_name(solver_of_header(info.reconstruction))));
    o.add("prediction_sweeps", static_cast<int64_t>(info.prediction_sweeps));
    o.add("final_sweeps", static_cast<int64_t>(info.final_sweeps));
    o.add("final_steps16", static_cast<int64_t>(info.final_steps16));
    o.add("final_most_steps", static_cast<int64_t>(info.final_most_steps));
    o.add("sections", static_cast<int64_t>(info.sections));
    o.add("attribute_bytes", static_cast<int64_t>(info.section_bytes));
    std::vector<JsonObject> sections;
    for (const GabFileInfo::Section& section : info.section_list) {
      JsonObject e;
      e.add("kind", static_cast<int64_t>(section.kind));
      e.add("bytes", static_cast<int64_t>(section.bytes));
      if (!section.attribute.empty()) {
        e.add("attribute", section.attribute);
        e.add_bool("per_corner", section.per_corner);
        e.add("elements", section.elements);
        e.add("bits", static_cast<int64_t>(section.bits));
        e.add("predictor", static_cast<int64_t>(section.predictor));
      }
      sections.push_back(e);
    }
    o.add("section_list", sections);
    std::printf("%s\n", o.str().c_str());
    return kExitOk;
  }
  std::printf("%s: .gab version %d, %d vertices, %d triangles%s\n", in.c_str(), info.version, info.num_vertices,
              info.num_triangles, info.geometry_only ? " (geometry only: decode with --connectivity MESH)" : "");
  // The ordering is the global solver's: an iterative file's means nothing.
  const Solver file_solver = solver_of_header(info.reconstruction);
  const std::string solver =
      (file_solver == Solver::kGlobal
           ? std::string("ordered by ") + (info.ordering == Ordering::kNestedDissection ? "nested dissection" : "AMD") +
                 "; "
           : std::string()) +
      solver_name(file_solver) + " reconstruction";
  // An iterative file's decode work (operators 2 and 3; operator 1's is fixed).
  char work[160] = "";
  if (info.final_most_steps > 0 || info.final_sweeps > 0 || info.prediction_sweeps > 0) {
    std::snprintf(work, sizeof work,
                  " (start sweeps %d per prediction, %d final; final steps %g per anchor spacing, at most %d)",
                  info.prediction_sweeps, info.final_sweeps, info.final_steps16 / 16.0, info.final_most_steps);
  }
  std::printf("%d anchors in %d chunks%s%s; q = %d bits, w = %g, %s%s\n", info.anchors, info.chunks,
              info.levels ? " (chunk 0 codes the anchor set, later chunks are the decoder's levels)" : "",
              info.truncated ? (" (truncated: " + std::to_string(info.chunks_present) + " complete)").c_str() : "",
              info.bits, info.weight, solver.c_str(), work);
  std::printf("%zu bytes: geometry %zu (%.3f bits/vertex), connectivity %zu (%s)", info.bytes, info.geometry_bytes,
              bpv, info.connectivity_bytes,
              info.geometry_only ? "a hash" : "valence coded");
  if (info.order_bytes > 0) {
    std::printf(", vertex order %zu", info.order_bytes);
  } else if (info.reordered) {
    std::printf(", vertices in traversal order");
  }
  if (info.section_bytes > 0) std::printf(", attributes %zu", info.section_bytes);
  std::printf("\n");
  int64_t anchors = 0;
  for (size_t c = 0; c < info.chunk_bytes.size(); ++c) {
    anchors += info.chunk_anchors[c];
    std::printf("  chunk %zu: %d anchors (%lld in all), %zu bytes\n", c, info.chunk_anchors[c],
                static_cast<long long>(anchors), info.chunk_bytes[c]);
  }
  if (info.refined) {
    if (info.refinement_bytes > 0) {
      std::printf("  chunk %zu: least-squares refinement of all %d anchors, %zu bytes\n", info.chunk_bytes.size(),
                  info.anchors, info.refinement_bytes);
    } else {
      std::printf("  (the least-squares refinement chunk is missing)\n");
    }
  }
  if (info.detail) {
    if (info.detail_bytes > 0) {
      std::printf("  chunk %d: detail layer, every vertex's residual at step %.4g, %zu bytes\n", info.chunks - 1,
                  info.detail_step, info.detail_bytes);
    } else {
      std::printf("  (the detail chunk is missing)\n");
    }
  }
  for (size_t i = 0; i < info.section_list.size(); ++i) {
    const GabFileInfo::Section& section = info.section_list[i];
    if (section.attribute.empty()) {
      std::printf("  section %zu: of kind %d, which this build does not know, %zu bytes\n", i, section.kind,
                  section.bytes);
    } else {
      static const char* const kPredictors[] = {"", ", predicted from the decoded surface",
                                                ", predicted from the decoded surface and the neighbours",
                                                ", predicted from the decoded surface (faces unweighted)",
                                                ", predicted from the decoded surface (faces by angle)",
                                                ", predicted from the values in its triangles",
                                                ", predicted from the values in its triangles, else the surface"};
      std::printf("  section %zu: %s, %lld %s, %d bits%s, %zu bytes\n", i, section.attribute.c_str(),
                  static_cast<long long>(section.elements), section.per_corner ? "values shared by corners" : "per vertex",
                  section.bits, kPredictors[section.predictor < 7 ? section.predictor : 0], section.bytes);
    }
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
