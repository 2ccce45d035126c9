// gab_decompress, gab_decompress_ex, gab_decompress_with_attributes,
// gab_decompress_options_init: the decoder (gab/codec/decoder.h) behind the
// C door. The decoder's contract on
// untrusted bytes holds here: errors, never reads outside `data`, memory
// within the options' budget.
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>

#include "attribute_arrays.h"
#include "boundary.h"
#include "gab/codec/decoder.h"
#include "ordering_codes.h"

namespace gab {
namespace capi {

namespace {

// The caller's options (NULL: the defaults) as the decoder's.
Status read_options(const gab_decompress_options* in, DecodeOptions* out) {
  gab_decompress_options o;
  gab_decompress_options_init(&o, sizeof o);
  if (in != nullptr) {
    GAB_RETURN_IF_ERROR(check_options_size(in, in->size, sizeof o, "gab_decompress_options_init"));
#define GAB_TAKE(field) take_field(in, in->size, offsetof(gab_decompress_options, field), &o.field)
    GAB_TAKE(max_memory);
    GAB_TAKE(max_anchors);
    GAB_TAKE(threads);
    GAB_TAKE(ordering);
#undef GAB_TAKE
  }
  GAB_RETURN_IF_ERROR(options_threads(o.threads, &out->threads));
  GAB_RETURN_IF_ERROR(codec_ordering_of_code(o.ordering, &out->ordering));
  out->max_anchors = o.max_anchors < 0 ? -1 : o.max_anchors;
  out->max_memory = o.max_memory < 0 ? -1 : o.max_memory;
  return Status::Ok();
}

// What the file holds that a successful decode did not give back: sections
// a level of detail cannot decode (normals predicted from the whole shape),
// sections of a newer format, sections past a cut. "" when nothing. Costs
// a pass over the file's frames (read_gab_info) only when the decode may
// have left something out: a section skipped, fewer anchors than the file
// has, a cut.
std::string undecoded_sections(const unsigned char* data, size_t size, const Mesh& mesh, const DecodeStats& stats) {
  const bool whole = stats.anchors == stats.anchors_in_file && !stats.truncated;
  if (stats.skipped_sections == 0 && whole) return "";
  GabFileInfo info;
  if (!read_gab_info(data, size, &info).ok()) {  // a chunk this level of detail did not need is damaged
    return stats.skipped_sections == 0 ? ""
                                       : "not decoded: " + std::to_string(stats.skipped_sections) + " sections";
  }
  if (info.sections <= static_cast<int32_t>(mesh.attributes.size())) return "";
  std::multiset<std::string> decoded;
  for (const MeshAttribute& a : mesh.attributes) decoded.insert(attribute_label(a));
  std::string named;
  int32_t unknown = 0;
  for (const GabFileInfo::Section& section : info.section_list) {
    if (section.attribute.empty()) {
      ++unknown;
      continue;
    }
    const auto found = decoded.find(section.attribute);
    if (found != decoded.end()) {
      decoded.erase(found);
      continue;
    }
    named += (named.empty() ? "" : ", ") + section.attribute;
  }
  const bool whole_shape = whole && stats.detail == info.detail && stats.refined == info.refined;
  std::string text;
  auto add = [&text](const std::string& part) { text += (text.empty() ? "not decoded: " : ", ") + part; };
  if (!named.empty()) {
    add(named + (whole_shape ? " (of a predictor gab " GAB_VERSION_STRING " does not decode)"
                             : " (predicted from the whole shape, which this decode does not have: every anchor "
                               "of a complete file)"));
  }
  if (unknown > 0) add(std::to_string(unknown) + " sections of kinds gab " GAB_VERSION_STRING " does not decode");
  const int32_t cut = info.sections - static_cast<int32_t>(info.section_list.size());
  if (cut > 0) add(std::to_string(cut) + " sections past the cut");
  return text;
}

// Every decompress door: the mesh into the caller's arrays, the attributes
// too for a door `with_attributes` (else they are named as not returned).
int decompress(const char* function, const unsigned char* data, size_t size, const DecodeOptions* fixed,
               const gab_decompress_options* options, double** positions, int32_t* n, int32_t** triangles,
               int32_t* t, bool with_attributes, gab_attribute** attributes, int32_t* num_attributes,
               char* message, size_t message_size) {
  DecodeStats stats;
  std::string dropped;  // what a success did not give back, for its message
  const int code = guarded(function, message, message_size, [&]() -> Status {
    GAB_RETURN_IF_ERROR(clear_mesh_outputs(positions, n, triangles, t));
    if (with_attributes) GAB_RETURN_IF_ERROR(clear_attribute_outputs(attributes, num_attributes));
    GAB_RETURN_IF_ERROR(require(data != nullptr || size == 0, "data is NULL"));
    static const unsigned char kEmpty = 0;
    DecodeOptions decode_options;
    if (fixed != nullptr) {
      decode_options = *fixed;
    } else {
      GAB_RETURN_IF_ERROR(read_options(options, &decode_options));
    }
    Mesh mesh;
    GAB_RETURN_IF_ERROR(decode_mesh(data != nullptr ? data : &kEmpty, size, decode_options, &mesh, &stats));
    dropped = undecoded_sections(data, size, mesh, stats);
    if (!with_attributes && !mesh.attributes.empty()) {
      dropped += (dropped.empty() ? "" : "; ") + std::string("not returned: ") + describe_attributes(mesh.attributes) +
                 "; gab_decompress_with_attributes returns them";
    }
    gab_attribute* decoded = nullptr;
    int32_t count = 0;
    if (with_attributes) GAB_RETURN_IF_ERROR(export_attributes(mesh.attributes, &decoded, &count));
    const Status exported = export_mesh(mesh, positions, n, triangles, t);
    if (!exported.ok()) {
      std::free(decoded);
      return exported;
    }
    if (with_attributes) {
      *attributes = decoded;
      *num_attributes = count;
    }
    return Status::Ok();
  });
  if (code != GAB_OK) return code;
  std::string text;
  if (stats.truncated) {
    char cut[160];
    std::snprintf(cut, sizeof cut, "the file is truncated: decoded %d of %d chunks (%d of %d anchors)", stats.chunks,
                  stats.chunks_in_file, stats.anchors, stats.anchors_in_file);
    text = cut;
  }
  if (!dropped.empty()) text += (text.empty() ? "" : "; ") + dropped;
  write_message(function, text.c_str(), message, message_size);
  return stats.truncated ? GAB_W_TRUNCATED : GAB_OK;
}

}  // namespace

}  // namespace capi
}  // namespace gab

extern "C" void gab_decompress_options_init(gab_decompress_options* options, size_t size) {
  gab_decompress_options o;
  std::memset(&o, 0, sizeof o);
  o.max_anchors = -1;
  o.threads = 1;
  o.ordering = GAB_ORDERING_AUTO;
  gab::capi::init_options(o, options, size);
}

extern "C" int gab_decompress(const unsigned char* data, size_t size, int32_t max_anchors, double** positions,
                              int32_t* n, int32_t** triangles, int32_t* t, char* message, size_t message_size) {
  gab::DecodeOptions options;
  options.max_anchors = max_anchors < 0 ? -1 : max_anchors;
  return gab::capi::decompress("gab_decompress", data, size, &options, nullptr, positions, n, triangles, t, false,
                               nullptr, nullptr, message, message_size);
}

extern "C" int gab_decompress_ex(const unsigned char* data, size_t size, const gab_decompress_options* options,
                                 double** positions, int32_t* n, int32_t** triangles, int32_t* t, char* message,
                                 size_t message_size) {
  return gab::capi::decompress("gab_decompress_ex", data, size, nullptr, options, positions, n, triangles, t, false,
                               nullptr, nullptr, message, message_size);
}

extern "C" int gab_decompress_with_attributes(const unsigned char* data, size_t size,
                                              const gab_decompress_options* options, double** positions, int32_t* n,
                                              int32_t** triangles, int32_t* t, gab_attribute** attributes,
                                              int32_t* num_attributes, char* message, size_t message_size) {
  return gab::capi::decompress("gab_decompress_with_attributes", data, size, nullptr, options, positions, n,
                               triangles, t, true, attributes, num_attributes, message, message_size);
}
