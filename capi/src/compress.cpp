// gab_compress, gab_compress_ex, gab_compress_with_report,
// gab_compress_with_attributes and the options' and report's init: the
// encoder (gab/codec/encoder.h) behind the C door.
#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>

#include "attribute_arrays.h"
#include "boundary.h"
#include "gab/codec/encoder.h"
#include "ordering_codes.h"

namespace gab {
namespace capi {

namespace {

constexpr double kDefaultError = 1e-3;  // as the CLI's compress without a stopping rule

// The caller's options (NULL: the defaults) as the encoder's. Fields beyond
// in->size keep their defaults; bytes beyond what this library knows must
// be zero. The encoder checks the values it owns (targets, bits, weight).
Status read_options(const gab_compress_options* in, EncodeOptions* out) {
  gab_compress_options o;
  gab_compress_options_init(&o, sizeof o);
  if (in != nullptr) {
    GAB_RETURN_IF_ERROR(check_options_size(in, in->size, sizeof o, "gab_compress_options_init"));
#define GAB_TAKE(field) take_field(in, in->size, offsetof(gab_compress_options, field), &o.field)
    GAB_TAKE(target_rms_rel);
    GAB_TAKE(target_linf_rel);
    GAB_TAKE(weight);
    GAB_TAKE(max_anchors);
    GAB_TAKE(bits);
    GAB_TAKE(reorder);
    GAB_TAKE(threads);
    GAB_TAKE(detail);
    GAB_TAKE(refine);
    GAB_TAKE(ordering);
    GAB_TAKE(solver);
    GAB_TAKE(normal_bits);
    GAB_TAKE(texcoord_bits);
    GAB_TAKE(color_bits);
    GAB_TAKE(generic_bits);
#undef GAB_TAKE
  }
  GAB_RETURN_IF_ERROR(options_threads(o.threads, &out->threads));
  GAB_RETURN_IF_ERROR(require(o.detail == GAB_DETAIL_AUTO || o.detail == GAB_DETAIL_ON || o.detail == GAB_DETAIL_OFF,
                              "options->detail is " + std::to_string(o.detail) +
                                  ": must be GAB_DETAIL_AUTO, GAB_DETAIL_ON or GAB_DETAIL_OFF"));
  GAB_RETURN_IF_ERROR(codec_ordering_of_code(o.ordering, &out->ordering));
  GAB_RETURN_IF_ERROR(require(solver_of_code(o.solver, &out->solver),
                              "options->solver is " + std::to_string(o.solver) +
                                  ": must be GAB_SOLVER_AUTO, GAB_SOLVER_GLOBAL or GAB_SOLVER_ITERATIVE"));
  const bool no_rule = o.max_anchors == 0 && o.target_rms_rel == 0 && o.target_linf_rel == 0;
  out->max_anchors = o.max_anchors;
  out->target_rms_rel = no_rule ? kDefaultError : o.target_rms_rel;
  out->target_linf_rel = o.target_linf_rel;
  out->bits = o.bits;
  out->weight = o.weight;
  out->normal_bits = o.normal_bits;  // the attributes' bits: the encoder checks their ranges
  out->texcoord_bits = o.texcoord_bits;
  out->color_bits = o.color_bits;
  out->generic_bits = o.generic_bits;
  out->reorder = o.reorder != 0;
  out->refine = o.refine != 0;
  out->detail = o.detail == GAB_DETAIL_ON    ? DetailMode::kOn
                : o.detail == GAB_DETAIL_OFF ? DetailMode::kOff
                                             : DetailMode::kAuto;
  return Status::Ok();
}

// The report of an encode, as gab.h describes it; `order` and `attributes` still to set.
gab_compress_report report_of(const EncodeStats& stats, double weight) {
  gab_compress_report r;
  std::memset(&r, 0, sizeof r);
  r.size = sizeof r;
  r.n = stats.num_vertices;
  r.faces = stats.num_triangles;
  r.anchors = stats.anchors;
  r.chunks = stats.chunks;
  r.bits = stats.bits;
  r.solver = code_of_solver(stats.solver);
  r.ordering = code_of_ordering(stats.ordering);
  r.target_met = stats.target_met;
  r.reordered = stats.reordered;
  r.detail = stats.detail;
  r.refined = stats.refined;
  r.levels = stats.levels;
  r.bytes = stats.bytes;
  r.geometry_bytes = stats.geometry_bytes;
  r.connectivity_bytes = stats.connectivity_bytes;
  r.order_bytes = stats.order_bytes;
  r.detail_bytes = stats.detail_bytes;
  r.refinement_bytes = stats.refinement_bytes;
  r.rms_rel = stats.rms_rel;
  r.linf_rel = stats.linf_rel;
  r.anchor_rms_rel = stats.detail ? stats.anchor_rms_rel : stats.rms_rel;
  r.unrefined_rms_rel = stats.unrefined_rms_rel;
  r.detail_step_rel = stats.detail_step_rel;
  r.bpv_geometry = 8.0 * static_cast<double>(stats.geometry_bytes) / stats.num_vertices;
  r.weight = weight;
  r.encode_s = stats.encode_s;
  r.merged_vertices = stats.merged_vertices;
  r.num_attributes = static_cast<int32_t>(stats.attributes.size());
  r.attribute_bytes = stats.attribute_bytes;
  return r;
}

// The bytes of the caller's report this library writes: its size, at most
// what this library knows (gab.h's rule for an out struct).
size_t report_bytes(const gab_compress_report* report) { return std::min(report->size, sizeof(gab_compress_report)); }

// Zeroes what the library writes of the caller's report but its size field.
void clear_report(gab_compress_report* report) {
  if (report == nullptr || report->size < sizeof(size_t)) return;
  std::memset(reinterpret_cast<unsigned char*>(report) + sizeof(size_t), 0, report_bytes(report) - sizeof(size_t));
}

// Whether the caller's report, `written` bytes of it, holds `field`.
#define GAB_REPORT_HOLDS(written, field) \
  (offsetof(gab_compress_report, field) + sizeof(gab_compress_report::field) <= (written))

// Every compress door: the mesh (and `attributes`, `num_attributes` of
// them) checked, the options read (`fixed`: the encoder's, given by a door
// without options), the file and the report made.
int compress(const char* function, const double* positions, int32_t n, const int32_t* triangles, int32_t t,
             const gab_attribute* attributes, int32_t num_attributes, const EncodeOptions* fixed,
             const gab_compress_options* options, unsigned char** out, size_t* out_size,
             gab_compress_report* report, char* message, size_t message_size) {
  clear_report(report);
  return guarded(function, message, message_size, [&]() -> Status {
    if (out != nullptr) *out = nullptr;
    if (out_size != nullptr) *out_size = 0;
    GAB_RETURN_IF_ERROR(require(out != nullptr, "out is NULL"));
    GAB_RETURN_IF_ERROR(require(out_size != nullptr, "out_size is NULL"));
    GAB_RETURN_IF_ERROR(require(report == nullptr || report->size >= sizeof(size_t),
                                "report->size is " + std::to_string(report != nullptr ? report->size : 0) +
                                    ": set it with gab_compress_report_init"));
    Mesh mesh;
    GAB_RETURN_IF_ERROR(import_mesh(positions, n, triangles, t, &mesh));
    GAB_RETURN_IF_ERROR(import_attributes(attributes, num_attributes, &mesh));
    EncodeOptions encode_options;
    if (fixed != nullptr) {
      encode_options = *fixed;
    } else {
      GAB_RETURN_IF_ERROR(read_options(options, &encode_options));
    }
    std::vector<AttributeKind> kinds;  // the report's; the encoder takes the mesh
    for (const MeshAttribute& a : mesh.attributes) kinds.push_back(a.kind);
    std::vector<uint8_t> file;
    EncodeStats stats;
    GAB_RETURN_IF_ERROR(encode_mesh(std::move(mesh), encode_options, &file, &stats));
    if (report == nullptr) return export_bytes(file, out, out_size);
    // The arrays the caller's report has room for, then the file: on any
    // failure the caller gets none of them.
    gab_compress_report r = report_of(stats, encode_options.weight);
    const size_t written = report_bytes(report);
    struct Owned {
      gab_compress_report* r;
      bool kept = false;
      ~Owned() {
        if (kept) return;
        std::free(r->order);
        std::free(r->attributes);
      }
    } owned{&r};
    if (stats.reordered && GAB_REPORT_HOLDS(written, order)) GAB_RETURN_IF_ERROR(export_indices(stats.new_index, &r.order));
    if (GAB_REPORT_HOLDS(written, attributes)) {
      GAB_RETURN_IF_ERROR(export_attribute_stats(stats.attributes, kinds, &r.attributes));
    }
    GAB_RETURN_IF_ERROR(export_bytes(file, out, out_size));
    owned.kept = true;
    r.size = written;
    std::memcpy(static_cast<void*>(report), &r, written);
    return Status::Ok();
  });
}

#undef GAB_REPORT_HOLDS

}  // namespace

}  // namespace capi
}  // namespace gab

extern "C" void gab_compress_options_init(gab_compress_options* options, size_t size) {
  gab_compress_options o;
  std::memset(&o, 0, sizeof o);
  o.weight = gab::EncodeOptions().weight;
  o.reorder = 1;  // the encoder's default (issue 34): a zero here, set by the caller, keeps the numbering
  o.threads = 1;
  o.detail = GAB_DETAIL_AUTO;
  const gab::EncodeOptions defaults;
  o.normal_bits = defaults.normal_bits;
  o.texcoord_bits = defaults.texcoord_bits;
  o.color_bits = defaults.color_bits;
  o.generic_bits = defaults.generic_bits;
  gab::capi::init_options(o, options, size);
}

extern "C" void gab_compress_report_init(gab_compress_report* report, size_t size) {
  gab_compress_report r;
  std::memset(&r, 0, sizeof r);
  gab::capi::init_options(r, report, size);
}

extern "C" int gab_compress_ex(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                               const gab_compress_options* options, unsigned char** out, size_t* out_size,
                               char* message, size_t message_size) {
  return gab::capi::compress("gab_compress_ex", positions, n, triangles, t, nullptr, 0, nullptr, options, out,
                             out_size, nullptr, message, message_size);
}

extern "C" int gab_compress_with_report(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                                        const gab_compress_options* options, unsigned char** out, size_t* out_size,
                                        gab_compress_report* report, char* message, size_t message_size) {
  return gab::capi::compress("gab_compress_with_report", positions, n, triangles, t, nullptr, 0, nullptr, options,
                             out, out_size, report, message, message_size);
}

extern "C" int gab_compress_with_attributes(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                                            const gab_attribute* attributes, int32_t num_attributes,
                                            const gab_compress_options* options, unsigned char** out,
                                            size_t* out_size, gab_compress_report* report, char* message,
                                            size_t message_size) {
  return gab::capi::compress("gab_compress_with_attributes", positions, n, triangles, t, attributes, num_attributes,
                             nullptr, options, out, out_size, report, message, message_size);
}

extern "C" int gab_compress(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                            double target_rms_rel, unsigned char** out, size_t* out_size, char* message,
                            size_t message_size) {
  // The target as given: 0 is not "the default" here but a missing rule (the encoder says so).
  gab::EncodeOptions options;
  options.target_rms_rel = target_rms_rel;
  options.reorder = false;  // gab.h's contract: the decoded mesh keeps the numbering (the encoder's default drops it)
  return gab::capi::compress("gab_compress", positions, n, triangles, t, nullptr, 0, &options, nullptr, out, out_size,
                             nullptr, message, message_size);
}
