// The C API's attributes (gab.h: gab_attribute, gab_compress_with_attributes,
// gab_decompress_with_attributes, gab_read_mesh_with_attributes,
// gab_write_mesh, the report's gab_attribute_stats): the C99 scenario's
// results (capi_scenarios.c) checked against the input and the C++ API's,
// the arguments' messages, and what each door names as not returned.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "capi/capi_scenarios.h"
#include "common/gab_files.h"
#include "common/scratch_files.h"
#include "common/test_meshes.h"
#include "gab/gab.h"

namespace {

using gab::Mesh;
using gab::MeshAttribute;

constexpr int kTorusN = 30, kTorusM = 20;

// The attributes the C scenario codes, as arrays over torus(kTorusN,
// kTorusM): area-weighted vertex normals of the surface, texture
// coordinates (i/N, j/M) per corner with seams where the torus closes,
// RGBA bytes and a float "quality" per vertex.
struct TorusAttributes {
  Mesh mesh;
  std::vector<double> normals, uv, quality;
  std::vector<int32_t> uv_corners;
  std::vector<unsigned char> rgba;
  int32_t uv_count = 0;
};

TorusAttributes torus_attributes() {
  TorusAttributes a;
  a.mesh = gab::testing_util::bumpy_torus(kTorusN, kTorusM);
  const int32_t n = a.mesh.num_vertices();
  a.normals.assign(3 * static_cast<size_t>(n), 0.0);
  for (int32_t f = 0; f < a.mesh.num_triangles(); ++f) {
    const double* p[3];
    for (int k = 0; k < 3; ++k) p[k] = &a.mesh.positions[3 * static_cast<size_t>(a.mesh.triangles[3 * f + k])];
    const double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double cross[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) a.normals[3 * static_cast<size_t>(a.mesh.triangles[3 * f + k]) + c] += cross[c];
    }
  }
  for (int32_t v = 0; v < n; ++v) {
    double* x = &a.normals[3 * static_cast<size_t>(v)];
    const double length = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    for (int c = 0; c < 3; ++c) x[c] /= length;
  }
  // torus(): vertex (i, j) is i M + j; the quad (i, j) gives triangles
  // (a, b, c) and (a, c, d), a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1).
  auto element = [](int i, int j) { return i * (kTorusM + 1) + j; };
  for (int i = 0; i <= kTorusN; ++i) {
    for (int j = 0; j <= kTorusM; ++j) a.uv.insert(a.uv.end(), {double(i) / kTorusN, double(j) / kTorusM});
  }
  a.uv_count = (kTorusN + 1) * (kTorusM + 1);
  for (int i = 0; i < kTorusN; ++i) {
    for (int j = 0; j < kTorusM; ++j) {
      a.uv_corners.insert(a.uv_corners.end(), {element(i, j), element(i + 1, j), element(i + 1, j + 1), element(i, j),
                                               element(i + 1, j + 1), element(i, j + 1)});
    }
  }
  for (int32_t v = 0; v < n; ++v) {
    a.rgba.insert(a.rgba.end(), {static_cast<unsigned char>(v * 7 % 256), static_cast<unsigned char>(v % 200),
                                 static_cast<unsigned char>(255 - v % 256), 255});
    a.quality.push_back(std::sin(0.1 * v) * 3.0 + 1.0);
  }
  return a;
}

// The same attributes as the C++ API's, for its file and figures.
Mesh with_cpp_attributes(const TorusAttributes& a) {
  Mesh mesh = a.mesh;
  MeshAttribute normals;
  normals.kind = gab::AttributeKind::kNormal;
  normals.components = 3;
  normals.values = a.normals;
  MeshAttribute uv;
  uv.kind = gab::AttributeKind::kTexCoord;
  uv.components = 2;
  uv.values = a.uv;
  uv.corners = a.uv_corners;
  MeshAttribute colours;
  colours.kind = gab::AttributeKind::kColor;
  colours.type = gab::ValueType::kUint8;
  colours.components = 4;
  colours.values.assign(a.rgba.begin(), a.rgba.end());
  MeshAttribute quality;
  quality.kind = gab::AttributeKind::kGeneric;
  quality.type = gab::ValueType::kFloat64;
  quality.name = "quality";
  quality.values = a.quality;
  mesh.attributes = {normals, uv, colours, quality};
  return mesh;
}

// Every corner's value, keyed by its triangle (the vertices rotated to
// start at the smallest, each through `map` when given) and its vertex:
// what a decode keeps of a per-corner or per-vertex attribute, whatever
// order and first corner the coder chose.
using CornerKey = std::array<int32_t, 4>;
std::map<CornerKey, std::vector<double>> corner_values(const int32_t* triangles, int32_t t, int32_t components,
                                                       const double* values, const int32_t* corners,
                                                       const int32_t* map) {
  std::map<CornerKey, std::vector<double>> out;
  for (int32_t f = 0; f < t; ++f) {
    std::array<int32_t, 3> v;
    for (int k = 0; k < 3; ++k) v[k] = map != nullptr ? map[triangles[3 * f + k]] : triangles[3 * f + k];
    const int first = static_cast<int>(std::min_element(v.begin(), v.end()) - v.begin());
    for (int k = 0; k < 3; ++k) {
      const int32_t element = corners != nullptr ? corners[3 * f + k] : triangles[3 * f + k];
      const double* x = values + static_cast<size_t>(components) * element;
      out[{v[first], v[(first + 1) % 3], v[(first + 2) % 3], v[k]}] = std::vector<double>(x, x + components);
    }
  }
  return out;
}

// The largest difference between the input's and the decode's values at
// the same corners (degrees between directions for normals); -1 when the
// corners do not match.
double largest_error(const std::map<CornerKey, std::vector<double>>& input,
                     const std::map<CornerKey, std::vector<double>>& decoded, bool directions) {
  if (input.size() != decoded.size()) return -1;
  double largest = 0;
  for (const auto& [key, x] : input) {
    const auto found = decoded.find(key);
    if (found == decoded.end()) return -1;
    const std::vector<double>& y = found->second;
    if (directions) {
      double dot = 0, xx = 0, yy = 0;
      for (int c = 0; c < 3; ++c) dot += x[c] * y[c], xx += x[c] * x[c], yy += y[c] * y[c];
      const double cosine = std::max(-1.0, std::min(1.0, dot / std::sqrt(xx * yy)));
      largest = std::max(largest, std::acos(cosine) * 180 / 3.14159265358979323846);
    } else {
      for (size_t c = 0; c < x.size(); ++c) largest = std::max(largest, std::fabs(x[c] - y[c]));
    }
  }
  return largest;
}

// Runs the C scenario, failing the test on a bad code.
struct Scenario {
  TorusAttributes input = torus_attributes();
  capi_attribute_round_trip r;
  Scenario(int32_t reorder, int32_t normal_bits = 0) {
    capi_attribute_round_trip_run(input.mesh.positions.data(), input.mesh.num_vertices(), input.mesh.triangles.data(),
                                  input.mesh.num_triangles(), input.normals.data(), input.uv.data(), input.uv_count,
                                  input.uv_corners.data(), input.rgba.data(), input.quality.data(), reorder,
                                  normal_bits, &r);
  }
  ~Scenario() { capi_attribute_round_trip_free(&r); }
};

TEST(CapiAttributesTest, EveryKindRoundTripsFromCWithinItsQuantization) {
  for (int32_t reorder : {0, 1}) {
    SCOPED_TRACE(reorder ? "reordered" : "numbering kept");
    Scenario s(reorder);
    const capi_attribute_round_trip& r = s.r;
    ASSERT_EQ(r.compress_code, GAB_OK) << r.message;
    ASSERT_EQ(r.decode_code, GAB_OK) << r.message;
    EXPECT_STREQ(r.message, "");  // everything returned: nothing to name
    const Mesh& mesh = s.input.mesh;
    const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
    ASSERT_EQ(r.decoded.n, n);
    ASSERT_EQ(r.decoded.t, t);
    EXPECT_EQ(r.report.reordered, reorder);
    EXPECT_EQ(r.report.merged_vertices, 0);
    const int32_t* map = reorder ? r.report.order : nullptr;
    ASSERT_TRUE(!reorder || map != nullptr);
    // What each decoded attribute is: the input's kind, type, name and shape, in its order.
    ASSERT_EQ(r.num_attributes, 4);
    const gab_attribute* a = r.attributes;
    const int32_t kinds[4] = {GAB_ATTRIBUTE_NORMAL, GAB_ATTRIBUTE_TEXCOORD, GAB_ATTRIBUTE_COLOR,
                              GAB_ATTRIBUTE_GENERIC};
    const int32_t types[4] = {GAB_VALUE_FLOAT32, GAB_VALUE_FLOAT32, GAB_VALUE_UINT8, GAB_VALUE_FLOAT64};
    const int32_t components[4] = {3, 2, 4, 1};
    const char* names[4] = {"", "", "", "quality"};
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(a[i].kind, kinds[i]) << i;
      EXPECT_EQ(a[i].value_type, types[i]) << i;
      EXPECT_EQ(a[i].components, components[i]) << i;
      ASSERT_NE(a[i].name, nullptr);
      EXPECT_STREQ(a[i].name, names[i]);
      EXPECT_EQ(a[i].corners != nullptr, i == 1) << i;  // per corner as given, per vertex as given
      if (a[i].corners == nullptr) {
        EXPECT_EQ(a[i].elements, n) << i;
      }
    }
    for (int32_t c = 0; c < 3 * t; ++c) ASSERT_TRUE(a[1].corners[c] >= 0 && a[1].corners[c] < a[1].elements);
    // The values, corner by corner, within each kind's quantization.
    const int32_t* f = mesh.triangles.data();
    const std::vector<double> colours(s.input.rgba.begin(), s.input.rgba.end());
    const double normal_error =
        largest_error(corner_values(f, t, 3, s.input.normals.data(), nullptr, map),
                      corner_values(r.decoded.triangles, t, 3, a[0].values, a[0].corners, nullptr), true);
    const double uv_error =
        largest_error(corner_values(f, t, 2, s.input.uv.data(), s.input.uv_corners.data(), map),
                      corner_values(r.decoded.triangles, t, 2, a[1].values, a[1].corners, nullptr), false);
    const double colour_error =
        largest_error(corner_values(f, t, 4, colours.data(), nullptr, map),
                      corner_values(r.decoded.triangles, t, 4, a[2].values, a[2].corners, nullptr), false);
    const double quality_error =
        largest_error(corner_values(f, t, 1, s.input.quality.data(), nullptr, map),
                      corner_values(r.decoded.triangles, t, 1, a[3].values, a[3].corners, nullptr), false);
    const auto [low, high] = std::minmax_element(s.input.quality.begin(), s.input.quality.end());
    EXPECT_GE(normal_error, 0);
    EXPECT_LE(normal_error, 0.6);  // 8 bits: a lattice of about 4^8 directions
    EXPECT_GE(uv_error, 0);
    EXPECT_LE(uv_error, 0.5 / 1023 * (1 + 1e-9));  // half a step of the 2^10 - 1 steps over the span 1
    EXPECT_EQ(colour_error, 0);                    // uint8: exact
    EXPECT_GE(quality_error, 0);
    EXPECT_LE(quality_error, 0.5 * (*high - *low) / 65535 * (1 + 1e-9));  // half a step, 16 bits
    // The report: what was coded, as the encoder says it (the errors it measured are the ones seen here).
    const gab_compress_report& rep = r.report;
    ASSERT_EQ(rep.num_attributes, 4);
    ASSERT_NE(rep.attributes, nullptr);
    const char* labels[4] = {"normals", "texture_coordinates", "vertex_colors", "generic:quality"};
    size_t section_bytes = 0;
    for (int i = 0; i < 4; ++i) {
      EXPECT_STREQ(rep.attributes[i].label, labels[i]);
      EXPECT_EQ(rep.attributes[i].kind, kinds[i]);
      EXPECT_EQ(rep.attributes[i].per_corner, i == 1 ? 1 : 0);
      EXPECT_GT(rep.attributes[i].bytes, 0u);
      section_bytes += rep.attributes[i].bytes;
    }
    EXPECT_EQ(rep.attributes[0].bits, 8);
    EXPECT_EQ(rep.attributes[1].bits, 10);
    EXPECT_EQ(rep.attributes[3].bits, 16);
    EXPECT_EQ(rep.attributes[0].elements, n);
    EXPECT_EQ(rep.attributes[1].elements, a[1].elements);
    EXPECT_NEAR(rep.attributes[0].max_error, normal_error, 1e-6);
    EXPECT_NEAR(rep.attributes[1].max_error, uv_error, 1e-12);
    EXPECT_EQ(rep.attributes[2].max_error, 0.0);
    EXPECT_NEAR(rep.attributes[3].max_error, quality_error, 1e-12);
    EXPECT_EQ(rep.attribute_bytes, section_bytes);
    EXPECT_EQ(rep.bytes, r.size);
    EXPECT_EQ(rep.bytes, rep.geometry_bytes + rep.connectivity_bytes + rep.order_bytes + rep.attribute_bytes);

    // The C++ API: the same file and figures, the same decoded attributes.
    gab::EncodeOptions options;
    options.target_rms_rel = 1e-3;
    options.reorder = reorder != 0;
    gab::EncodeStats stats;
    const Mesh cpp_mesh = with_cpp_attributes(s.input);
    const std::vector<uint8_t> file = gab::testing_util::encode_or_die(cpp_mesh, options, &stats);
    ASSERT_EQ(file, std::vector<uint8_t>(r.file, r.file + r.size));
    ASSERT_EQ(stats.attributes.size(), 4u);
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(rep.attributes[i].label, stats.attributes[i].label);
      EXPECT_EQ(rep.attributes[i].bits, stats.attributes[i].bits);
      EXPECT_EQ(rep.attributes[i].from_surface != 0, stats.attributes[i].from_surface);
      EXPECT_EQ(rep.attributes[i].elements, stats.attributes[i].elements);
      EXPECT_EQ(rep.attributes[i].bytes, stats.attributes[i].bytes);
      EXPECT_EQ(rep.attributes[i].max_error, stats.attributes[i].max_error);
    }
    gab::DecodeStats decoded_stats;
    const Mesh decoded = gab::testing_util::decode_or_die(file, gab::DecodeOptions(), &decoded_stats);
    ASSERT_EQ(decoded.attributes.size(), 4u);
    for (int i = 0; i < 4; ++i) {
      const MeshAttribute& d = decoded.attributes[i];
      EXPECT_EQ(std::vector<double>(a[i].values, a[i].values + d.values.size()), d.values) << i;
      EXPECT_EQ(a[i].corners == nullptr ? std::vector<int32_t>()
                                        : std::vector<int32_t>(a[i].corners, a[i].corners + d.corners.size()),
                d.corners)
          << i;
    }
  }
}

// A mesh with several copies of a vertex (a triangle soup, as a file split
// along seams): the traversal order merges them, the report says how many
// and its map covers every input vertex; their per-vertex values come back
// per corner.
TEST(CapiAttributesTest, MergedCopiesAreReportedAndTheMapCoversTheInput) {
  const Mesh grid = gab::testing_util::grid(6, 5);
  std::vector<double> positions;
  std::vector<int32_t> triangles;
  std::vector<double> shade;
  for (int32_t v : grid.triangles) {
    const double* p = &grid.positions[3 * static_cast<size_t>(v)];
    positions.insert(positions.end(), {p[0], p[1], 0.1 * std::sin(p[0] + 2 * p[1])});
    triangles.push_back(static_cast<int32_t>(triangles.size()));
    shade.push_back(static_cast<double>(shade.size() % 7));  // copies of a vertex differ: per corner
  }
  const int32_t n = static_cast<int32_t>(positions.size() / 3), t = static_cast<int32_t>(triangles.size() / 3);
  gab_attribute shade_attribute;
  std::memset(&shade_attribute, 0, sizeof shade_attribute);
  shade_attribute.kind = GAB_ATTRIBUTE_GENERIC;
  shade_attribute.value_type = GAB_VALUE_UINT8;
  shade_attribute.components = 1;
  shade_attribute.elements = n;
  shade_attribute.name = "shade";
  shade_attribute.values = shade.data();
  gab_compress_options o;
  gab_compress_options_init(&o, sizeof o);
  gab_compress_report r;
  gab_compress_report_init(&r, sizeof r);
  unsigned char* file = nullptr;
  size_t size = 0;
  char message[256];
  ASSERT_EQ(gab_compress_with_attributes(positions.data(), n, triangles.data(), t, &shade_attribute, 1, &o, &file,
                                         &size, &r, message, sizeof message),
            GAB_OK)
      << message;
  EXPECT_EQ(r.n, grid.num_vertices());  // the coded mesh: one vertex per position
  EXPECT_EQ(r.n + r.merged_vertices, n);
  ASSERT_NE(r.order, nullptr);
  for (int32_t v = 0; v < n; ++v) ASSERT_TRUE(r.order[v] >= 0 && r.order[v] < r.n) << v;
  ASSERT_EQ(r.num_attributes, 1);
  EXPECT_EQ(r.attributes[0].per_corner, 1);
  EXPECT_EQ(r.attributes[0].max_error, 0.0);
  double* decoded = nullptr;
  int32_t* decoded_triangles = nullptr;
  int32_t dn = 0, dt = 0, count = 0;
  gab_attribute* attributes = nullptr;
  ASSERT_EQ(gab_decompress_with_attributes(file, size, nullptr, &decoded, &dn, &decoded_triangles, &dt, &attributes,
                                           &count, message, sizeof message),
            GAB_OK)
      << message;
  EXPECT_EQ(dn, r.n);
  ASSERT_EQ(count, 1);
  EXPECT_NE(attributes[0].corners, nullptr);
  EXPECT_EQ(largest_error(corner_values(triangles.data(), t, 1, shade.data(), nullptr, r.order),
                          corner_values(decoded_triangles, dt, 1, attributes[0].values, attributes[0].corners, nullptr),
                          false),
            0.0);
  gab_free(attributes);
  gab_free(decoded);
  gab_free(decoded_triangles);
  gab_free(file);
  gab_free(r.order);
  gab_free(r.attributes);
}

// The attributes' bits are options appended to gab_compress_options under
// its size rule: the init gives the C++ defaults, an older struct without
// them gets them too, and the encoder checks their ranges.
TEST(CapiAttributesTest, AttributeBitsComeThroughTheOptionsStruct) {
  gab_compress_options o;
  gab_compress_options_init(&o, sizeof o);
  const gab::EncodeOptions defaults;
  EXPECT_EQ(o.normal_bits, defaults.normal_bits);
  EXPECT_EQ(o.texcoord_bits, defaults.texcoord_bits);
  EXPECT_EQ(o.color_bits, defaults.color_bits);
  EXPECT_EQ(o.generic_bits, defaults.generic_bits);
  EXPECT_EQ(o.normal_bits, 8);
  Scenario coarse(1), fine(1, 12);
  ASSERT_EQ(coarse.r.compress_code, GAB_OK) << coarse.r.message;
  ASSERT_EQ(fine.r.compress_code, GAB_OK) << fine.r.message;
  EXPECT_EQ(fine.r.report.attributes[0].bits, 12);
  EXPECT_LT(fine.r.report.attributes[0].max_error, coarse.r.report.attributes[0].max_error / 4);
  EXPECT_GT(fine.r.report.attributes[0].bytes, coarse.r.report.attributes[0].bytes);
  EXPECT_EQ(fine.r.report.attributes[1].bytes, coarse.r.report.attributes[1].bytes);  // the others' bits as before

  const TorusAttributes input = torus_attributes();
  const Mesh& mesh = input.mesh;
  gab_attribute normals;
  std::memset(&normals, 0, sizeof normals);
  normals.kind = GAB_ATTRIBUTE_NORMAL;
  normals.value_type = GAB_VALUE_FLOAT32;
  normals.components = 3;
  normals.elements = mesh.num_vertices();
  normals.values = input.normals.data();
  char message[256];
  auto compress = [&](const gab_compress_options* options, std::vector<uint8_t>* bytes) {
    unsigned char* file = nullptr;
    size_t size = 0;
    const int code = gab_compress_with_attributes(mesh.positions.data(), mesh.num_vertices(), mesh.triangles.data(),
                                                  mesh.num_triangles(), &normals, 1, options, &file, &size, nullptr,
                                                  message, sizeof message);
    if (bytes != nullptr) bytes->assign(file, file + size);
    gab_free(file);
    return code;
  };
  std::vector<uint8_t> by_default, older_file, twelve;
  ASSERT_EQ(compress(nullptr, &by_default), GAB_OK) << message;
  // A caller compiled before the bits existed: its struct ends at `solver`.
  struct {
    gab_compress_options o;
    unsigned char guard[8];
  } older;
  std::memset(&older, 0xAB, sizeof older);
  gab_compress_options_init(&older.o, offsetof(gab_compress_options, normal_bits));
  EXPECT_EQ(older.o.size, offsetof(gab_compress_options, normal_bits));
  EXPECT_EQ(reinterpret_cast<unsigned char*>(&older.o)[offsetof(gab_compress_options, normal_bits)], 0xAB);
  ASSERT_EQ(compress(&older.o, &older_file), GAB_OK) << message;
  EXPECT_EQ(older_file, by_default);
  o.normal_bits = 12;
  ASSERT_EQ(compress(&o, &twelve), GAB_OK) << message;
  EXPECT_NE(twelve, by_default);
  o.normal_bits = 17;
  EXPECT_EQ(compress(&o, nullptr), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_compress_with_attributes: normal bits must be in 2..16");
  gab_compress_options_init(&o, sizeof o);
  o.texcoord_bits = 0;
  EXPECT_EQ(compress(&o, nullptr), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_compress_with_attributes: texture coordinate, colour and generic bits must be in 1..31");
}

// Every attribute field is checked before any work, the message naming it.
TEST(CapiAttributesTest, BadAttributeArgumentsAreNamedExactly) {
  const Mesh mesh = gab::testing_util::bumpy_torus(8, 6);
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  const std::vector<double> values(4 * static_cast<size_t>(n), 0.5);
  const std::vector<int32_t> corners(3 * static_cast<size_t>(t), 0);
  auto base = [&]() {
    gab_attribute a;
    std::memset(&a, 0, sizeof a);
    a.kind = GAB_ATTRIBUTE_TEXCOORD;
    a.value_type = GAB_VALUE_FLOAT32;
    a.components = 2;
    a.elements = n;
    a.values = values.data();
    return a;
  };
  auto outcome = [&](const gab_attribute* attributes, int32_t count) {
    char message[256];
    unsigned char* file = reinterpret_cast<unsigned char*>(message);  // must come back NULL
    size_t size = 7;
    gab_compress_report r;
    gab_compress_report_init(&r, sizeof r);
    const int code = gab_compress_with_attributes(mesh.positions.data(), n, mesh.triangles.data(), t, attributes,
                                                  count, nullptr, &file, &size, &r, message, sizeof message);
    EXPECT_EQ(code, GAB_E_INVALID_ARGUMENT) << message;
    EXPECT_TRUE(file == nullptr && size == 0 && r.attributes == nullptr && r.num_attributes == 0);
    return std::string(message);
  };
  const std::string at = "gab_compress_with_attributes: ";
  gab_attribute good[2] = {base(), base()};
  EXPECT_EQ(outcome(nullptr, 1), at + "attributes is NULL and num_attributes is 1");
  EXPECT_EQ(outcome(good, -1), at + "num_attributes is -1: must be in 0..64 (GAB_MAX_ATTRIBUTES)");
  EXPECT_EQ(outcome(good, 65), at + "num_attributes is 65: must be in 0..64 (GAB_MAX_ATTRIBUTES)");
  gab_attribute a[2] = {base(), base()};
  a[1].kind = 4;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].kind is 4: must be GAB_ATTRIBUTE_NORMAL, GAB_ATTRIBUTE_TEXCOORD, "
                                "GAB_ATTRIBUTE_COLOR or GAB_ATTRIBUTE_GENERIC");
  a[1] = base();
  a[1].kind = -1;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].kind is -1: must be GAB_ATTRIBUTE_NORMAL, GAB_ATTRIBUTE_TEXCOORD, "
                                "GAB_ATTRIBUTE_COLOR or GAB_ATTRIBUTE_GENERIC");
  a[1] = base();
  a[1].value_type = 8;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].value_type is 8: must be one of GAB_VALUE_INT8 .. GAB_VALUE_FLOAT64 "
                                "(0..7)");
  a[1] = base();
  a[1].kind = GAB_ATTRIBUTE_NORMAL;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].components is 2: GAB_ATTRIBUTE_NORMAL has 3");
  a[1].kind = GAB_ATTRIBUTE_COLOR;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].components is 2: GAB_ATTRIBUTE_COLOR has 3 or 4");
  a[1].kind = GAB_ATTRIBUTE_TEXCOORD;
  a[1].components = 4;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].components is 4: GAB_ATTRIBUTE_TEXCOORD has 2 or 3");
  a[1].kind = GAB_ATTRIBUTE_GENERIC;
  a[1].components = 0;
  a[1].name = "x";
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].components is 0: GAB_ATTRIBUTE_GENERIC has 1 to 4");
  a[1] = base();
  a[1].kind = GAB_ATTRIBUTE_GENERIC;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].name is NULL: a generic attribute is named");
  a[1].name = "";
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].name is \"\": a generic attribute is named");
  a[1].name = "two words";
  EXPECT_EQ(outcome(a, 2), at + "attributes[1]: generic:two words: a generic attribute's name is 1 to 255 letters, "
                                "digits, '_', '-' or '.'");
  a[1] = base();
  a[1].name = "uv";
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].name is \"uv\": only a generic attribute has a name (NULL or \"\")");
  a[1] = base();
  a[1].elements = n - 1;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].elements is " + std::to_string(n - 1) +
                               ": per vertex (corners NULL) it is n = " + std::to_string(n));
  a[1] = base();
  a[1].values = nullptr;
  EXPECT_EQ(outcome(a, 2), at + "attributes[1].values is NULL");
  a[0].corners = corners.data();
  a[0].elements = 0;
  EXPECT_EQ(outcome(a, 1), at + "attributes[0].elements is 0: a per-corner attribute has at least one element");
  std::vector<int32_t> bad_corners = corners;
  bad_corners[7] = 12;
  a[0] = base();
  a[0].elements = 4;
  a[0].corners = bad_corners.data();
  EXPECT_EQ(outcome(a, 1), at + "attributes[0].corners[7] is 12: out of range [0, 4)");
  bad_corners[7] = -1;
  EXPECT_EQ(outcome(a, 1), at + "attributes[0].corners[7] is -1: out of range [0, 4)");
  // The values: the mesh layer's checks, named by the attribute.
  std::vector<double> not_finite = values;
  not_finite[5] = std::nan("");
  a[0] = base();
  a[0].values = not_finite.data();
  EXPECT_EQ(outcome(a, 1), at + "attributes[0]: texture_coordinates: element 2: value is not finite");
  a[0].kind = GAB_ATTRIBUTE_COLOR;
  a[0].components = 3;
  a[0].value_type = GAB_VALUE_UINT8;
  a[0].values = values.data();
  EXPECT_EQ(outcome(a, 1), at + "attributes[0]: vertex_colors: element 0: 0.500000 is not a value of its integer type");
  // The mesh is checked first, as every compress door does.
  char message[128];
  unsigned char* file = nullptr;
  size_t size = 0;
  EXPECT_EQ(gab_compress_with_attributes(nullptr, n, mesh.triangles.data(), t, good, 1, nullptr, &file, &size,
                                         nullptr, message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_compress_with_attributes: positions is NULL");
  // No attributes: the same file as gab_compress_with_report's.
  unsigned char* plain = nullptr;
  size_t plain_size = 0;
  ASSERT_EQ(gab_compress_with_attributes(mesh.positions.data(), n, mesh.triangles.data(), t, nullptr, 0, nullptr,
                                         &file, &size, nullptr, message, sizeof message),
            GAB_OK);
  ASSERT_EQ(gab_compress_ex(mesh.positions.data(), n, mesh.triangles.data(), t, nullptr, &plain, &plain_size, message,
                            sizeof message),
            GAB_OK);
  EXPECT_EQ(std::vector<uint8_t>(file, file + size), std::vector<uint8_t>(plain, plain + plain_size));
  gab_free(file);
  gab_free(plain);
}

// The report's attribute fields follow its size rule: a caller compiled
// before them gets neither the fields nor the array (nothing to free); a
// mesh without attributes reports none.
TEST(CapiAttributesTest, ReportWithoutRoomForTheAttributesGetsNoArray) {
  const TorusAttributes input = torus_attributes();
  const Mesh& mesh = input.mesh;
  gab_attribute normals;
  std::memset(&normals, 0, sizeof normals);
  normals.kind = GAB_ATTRIBUTE_NORMAL;
  normals.value_type = GAB_VALUE_FLOAT32;
  normals.components = 3;
  normals.elements = mesh.num_vertices();
  normals.values = input.normals.data();
  char message[256];
  struct {
    gab_compress_report r;
    unsigned char guard[8];
  } older;
  std::memset(&older, 0xAB, sizeof older);
  const size_t older_size = offsetof(gab_compress_report, merged_vertices);
  gab_compress_report_init(&older.r, older_size);
  unsigned char* file = nullptr;
  size_t size = 0;
  ASSERT_EQ(gab_compress_with_attributes(mesh.positions.data(), mesh.num_vertices(), mesh.triangles.data(),
                                         mesh.num_triangles(), &normals, 1, nullptr, &file, &size, &older.r, message,
                                         sizeof message),
            GAB_OK)
      << message;
  EXPECT_EQ(older.r.size, older_size);
  EXPECT_EQ(older.r.bytes, size);  // the whole file, its attribute section inside
  EXPECT_EQ(reinterpret_cast<unsigned char*>(&older.r)[older_size], 0xAB);  // not written
  EXPECT_EQ(older.guard[0], 0xAB);
  gab_free(older.r.order);
  gab_free(file);
  gab_compress_report r;
  gab_compress_report_init(&r, sizeof r);
  ASSERT_EQ(gab_compress_with_report(mesh.positions.data(), mesh.num_vertices(), mesh.triangles.data(),
                                     mesh.num_triangles(), nullptr, &file, &size, &r, message, sizeof message),
            GAB_OK);
  EXPECT_EQ(r.num_attributes, 0);
  EXPECT_EQ(r.attributes, nullptr);
  EXPECT_EQ(r.attribute_bytes, 0u);
  EXPECT_EQ(r.merged_vertices, 0);
  gab_free(r.order);
  gab_free(file);
}

// What a decode does not give back is named in the message of a success:
// the doors without attribute outputs name the attributes; a level of
// detail names the normals predicted from the whole shape; a cut names the
// sections past it.
TEST(CapiAttributesTest, DecompressNamesWhatItDoesNotReturn) {
  Scenario s(1);
  ASSERT_EQ(s.r.compress_code, GAB_OK) << s.r.message;
  ASSERT_EQ(s.r.decode_code, GAB_OK) << s.r.message;
  const unsigned char* file = s.r.file;
  const size_t size = s.r.size;
  const int32_t n = s.input.mesh.num_vertices();
  const std::string listed = std::to_string(n) + " normals (per vertex), " + std::to_string(s.r.attributes[1].elements) +
                             " texture_coordinates (per corner), " + std::to_string(n) + " vertex_colors (per vertex), " +
                             std::to_string(n) + " generic:quality (per vertex)";
  char message[512];
  double* positions = nullptr;
  int32_t* triangles = nullptr;
  int32_t dn = 0, dt = 0;
  ASSERT_EQ(gab_decompress(file, size, -1, &positions, &dn, &triangles, &dt, message, sizeof message), GAB_OK);
  EXPECT_EQ(std::string(message),
            "gab_decompress: not returned: " + listed + "; gab_decompress_with_attributes returns them");
  gab_free(positions);
  gab_free(triangles);
  ASSERT_EQ(gab_decompress_ex(file, size, nullptr, &positions, &dn, &triangles, &dt, message, sizeof message), GAB_OK);
  EXPECT_EQ(std::string(message),
            "gab_decompress_ex: not returned: " + listed + "; gab_decompress_with_attributes returns them");
  gab_free(positions);
  gab_free(triangles);

  // A level of detail: the normals, predicted from the surface, need the whole shape.
  ASSERT_EQ(s.r.report.attributes[0].from_surface, 1) << "area-weighted normals should be predicted from the surface";
  gab_decompress_options o;
  gab_decompress_options_init(&o, sizeof o);
  o.max_anchors = 10;
  gab_attribute* attributes = nullptr;
  int32_t count = 0;
  ASSERT_EQ(gab_decompress_with_attributes(file, size, &o, &positions, &dn, &triangles, &dt, &attributes, &count,
                                           message, sizeof message),
            GAB_OK);
  EXPECT_EQ(std::string(message),
            "gab_decompress_with_attributes: not decoded: normals (predicted from the whole shape, which this decode "
            "does not have: every anchor of a complete file)");
  ASSERT_EQ(count, 3);  // the others decode at any level
  EXPECT_EQ(attributes[0].kind, GAB_ATTRIBUTE_TEXCOORD);
  EXPECT_EQ(std::vector<double>(attributes[0].values, attributes[0].values + 2 * attributes[0].elements),
            std::vector<double>(s.r.attributes[1].values, s.r.attributes[1].values + 2 * s.r.attributes[1].elements));
  gab_free(attributes);
  gab_free(positions);
  gab_free(triangles);

  // A cut inside the last section: the file's shape and its first three attributes, the fourth named.
  const size_t cut = size - s.r.report.attributes[3].bytes / 2;
  ASSERT_EQ(gab_decompress_with_attributes(file, cut, nullptr, &positions, &dn, &triangles, &dt, &attributes, &count,
                                           message, sizeof message),
            GAB_W_TRUNCATED);
  const std::string chunks = std::to_string(s.r.report.chunks), anchors = std::to_string(s.r.report.anchors);
  EXPECT_EQ(std::string(message), "gab_decompress_with_attributes: the file is truncated: decoded " + chunks + " of " +
                                      chunks + " chunks (" + anchors + " of " + anchors +
                                      " anchors); not decoded: 1 sections past the cut");
  EXPECT_EQ(count, 3);
  EXPECT_EQ(dn, n);
  gab_free(attributes);
  gab_free(positions);
  gab_free(triangles);

  // NULL attribute outputs are refused, every output cleared.
  positions = reinterpret_cast<double*>(message);
  EXPECT_EQ(gab_decompress_with_attributes(file, size, nullptr, &positions, &dn, &triangles, &dt, nullptr, &count,
                                           message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_decompress_with_attributes: attributes is NULL");
  EXPECT_TRUE(positions == nullptr && dn == 0 && count == 0);
  EXPECT_EQ(gab_decompress_with_attributes(file, size, nullptr, &positions, &dn, &triangles, &dt, &attributes,
                                           nullptr, message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_decompress_with_attributes: num_attributes is NULL");
  EXPECT_EQ(attributes, nullptr);
  // A file without attributes: none, no message.
  unsigned char* plain = nullptr;
  size_t plain_size = 0;
  ASSERT_EQ(gab_compress(s.input.mesh.positions.data(), n, s.input.mesh.triangles.data(),
                         s.input.mesh.num_triangles(), 1e-3, &plain, &plain_size, message, sizeof message),
            GAB_OK);
  count = 5;
  ASSERT_EQ(gab_decompress_with_attributes(plain, plain_size, nullptr, &positions, &dn, &triangles, &dt, &attributes,
                                           &count, message, sizeof message),
            GAB_OK);
  EXPECT_STREQ(message, "");
  EXPECT_EQ(count, 0);
  EXPECT_EQ(attributes, nullptr);
  gab_free(positions);
  gab_free(triangles);
  gab_free(plain);
}

// Hostile bytes through the attribute door: every cut and random flips of
// a file with every kind give a code and a message, never a crash (ASan
// checks the reads and that every returned block is freed); a failure
// clears every output.
TEST(CapiAttributesTest, DecompressWithAttributesReportsHostileBytes) {
  Scenario s(1);
  ASSERT_EQ(s.r.compress_code, GAB_OK) << s.r.message;
  const std::vector<uint8_t> file(s.r.file, s.r.file + s.r.size);
  auto decode = [](const std::vector<uint8_t>& bytes, size_t size, int32_t anchors) {
    gab_decompress_options o;
    gab_decompress_options_init(&o, sizeof o);
    o.max_anchors = anchors;
    char message[512];
    double* positions = nullptr;
    int32_t* triangles = nullptr;
    int32_t n = -1, t = -1, count = -1;
    gab_attribute* attributes = reinterpret_cast<gab_attribute*>(message);  // must come back NULL on failure
    const int code = gab_decompress_with_attributes(bytes.data(), size, &o, &positions, &n, &triangles, &t,
                                                    &attributes, &count, message, sizeof message);
    const bool returned = code == GAB_OK || code == GAB_W_TRUNCATED;
    EXPECT_NE(code, GAB_E_INTERNAL) << message;
    EXPECT_TRUE(returned || (positions == nullptr && triangles == nullptr && attributes == nullptr && count == 0 &&
                             message[0] != '\0'))
        << code << ": " << message;
    for (int32_t i = 0; returned && i < count; ++i) {
      EXPECT_TRUE(attributes[i].values != nullptr && attributes[i].name != nullptr);
      if (attributes[i].corners == nullptr) {
        EXPECT_EQ(attributes[i].elements, n);
      } else {
        int32_t outside = 0;
        for (int32_t c = 0; c < 3 * t; ++c) {
          outside += attributes[i].corners[c] < 0 || attributes[i].corners[c] >= attributes[i].elements;
        }
        EXPECT_EQ(outside, 0) << i;
      }
    }
    gab_free(attributes == reinterpret_cast<gab_attribute*>(message) ? nullptr : attributes);
    gab_free(positions);
    gab_free(triangles);
    return code;
  };
  int warned = 0;
  for (size_t cut = 0; cut < file.size(); cut += 1 + file.size() / 151) warned += decode(file, cut, -1) == GAB_W_TRUNCATED;
  EXPECT_GT(warned, 10);  // the cuts past the header decode what came before them
  EXPECT_EQ(decode(file, file.size(), -1), GAB_OK);
  std::mt19937 rng(34);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<uint8_t> damaged = file;
    damaged[rng() % damaged.size()] ^= static_cast<uint8_t>(1 + rng() % 255);
    decode(damaged, damaged.size(), trial % 3 == 0 ? 10 : -1);
  }
}

// gab_read_mesh_with_attributes returns what the readers keep and names
// only what gab does not carry; gab_read_mesh names both.
TEST(CapiAttributesTest, ReadMeshWithAttributesReturnsWhatGabCarries) {
  const std::string obj = gab_test::write_scratch_file(
      "attributes.obj",
      "g part\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
      "f 1/1/1 2/2/1 3/3/1\nf 2/2/1 4/4/1 3/3/1\n");
  capi_mesh mesh{};
  gab_attribute* attributes = nullptr;
  int32_t count = 0;
  char message[512];
  ASSERT_EQ(capi_read_mesh_with_attributes(obj.c_str(), &mesh, &attributes, &count, message, sizeof message), GAB_OK)
      << message;
  EXPECT_EQ(std::string(message), "gab_read_mesh_with_attributes: " + obj + ": not carried: 1 groups (g)");
  EXPECT_EQ(mesh.n, 4);
  EXPECT_EQ(mesh.t, 2);
  ASSERT_EQ(count, 2);
  // The OBJ reader's order: normals, then texture coordinates, each per corner.
  const gab_attribute* normal = &attributes[0];
  const gab_attribute* uv = &attributes[1];
  EXPECT_EQ(normal->kind, GAB_ATTRIBUTE_NORMAL);
  EXPECT_EQ(uv->kind, GAB_ATTRIBUTE_TEXCOORD);
  EXPECT_EQ(normal->value_type, GAB_VALUE_FLOAT32);
  EXPECT_EQ(normal->elements, 1);
  ASSERT_NE(normal->corners, nullptr);
  EXPECT_EQ(std::vector<int32_t>(normal->corners, normal->corners + 6), std::vector<int32_t>(6, 0));
  EXPECT_EQ(std::vector<double>(normal->values, normal->values + 3), (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(uv->elements, 4);
  EXPECT_EQ(uv->components, 2);
  ASSERT_NE(uv->corners, nullptr);
  EXPECT_EQ(std::vector<int32_t>(uv->corners, uv->corners + 6), (std::vector<int32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(std::vector<double>(uv->values, uv->values + 8), (std::vector<double>{0, 0, 1, 0, 0, 1, 1, 1}));
  EXPECT_STREQ(uv->name, "");
  gab_free(attributes);
  capi_free_mesh(&mesh);
  ASSERT_EQ(capi_read_mesh(obj.c_str(), &mesh, message, sizeof message), GAB_OK) << message;
  EXPECT_EQ(std::string(message), "gab_read_mesh: " + obj +
                                      ": not carried: 1 groups (g); not returned: 1 normals (per corner), 4 "
                                      "texture_coordinates (per corner); gab_read_mesh_with_attributes returns them");
  capi_free_mesh(&mesh);
  // A plain file: no attributes, no message; failures clear the outputs.
  const std::string plain = gab_test::write_scratch_file("plain3.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::strcpy(message, "stale");
  count = 3;
  ASSERT_EQ(capi_read_mesh_with_attributes(plain.c_str(), &mesh, &attributes, &count, message, sizeof message),
            GAB_OK);
  EXPECT_STREQ(message, "");
  EXPECT_EQ(count, 0);
  EXPECT_EQ(attributes, nullptr);
  capi_free_mesh(&mesh);
  count = 3;
  EXPECT_EQ(capi_read_mesh_with_attributes(gab_test::scratch_path("missing.obj").c_str(), &mesh, &attributes, &count,
                                           message, sizeof message),
            GAB_E_IO);
  EXPECT_TRUE(count == 0 && attributes == nullptr && mesh.positions == nullptr);
  EXPECT_EQ(capi_read_mesh_with_attributes(plain.c_str(), &mesh, nullptr, &count, message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_read_mesh_with_attributes: attributes is NULL");
  EXPECT_EQ(mesh.positions, nullptr);
}

// gab_write_mesh writes what the format holds, names what it cannot, and
// what it reads back is what was written.
TEST(CapiAttributesTest, WriteMeshWritesTheAttributesAndNamesWhatTheFormatCannotHold) {
  const TorusAttributes input = torus_attributes();
  const Mesh& mesh = input.mesh;
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  const std::vector<double> colours(input.rgba.begin(), input.rgba.end());
  gab_attribute a[4];
  std::memset(a, 0, sizeof a);
  a[0].kind = GAB_ATTRIBUTE_NORMAL;
  a[0].value_type = GAB_VALUE_FLOAT32;
  a[0].components = 3;
  a[0].elements = n;
  a[0].values = input.normals.data();
  a[1].kind = GAB_ATTRIBUTE_TEXCOORD;
  a[1].value_type = GAB_VALUE_FLOAT32;
  a[1].components = 2;
  a[1].elements = input.uv_count;
  a[1].values = input.uv.data();
  a[1].corners = input.uv_corners.data();
  a[2].kind = GAB_ATTRIBUTE_COLOR;
  a[2].value_type = GAB_VALUE_UINT8;
  a[2].components = 4;
  a[2].elements = n;
  a[2].values = colours.data();
  a[3].kind = GAB_ATTRIBUTE_GENERIC;
  a[3].value_type = GAB_VALUE_FLOAT64;
  a[3].components = 1;
  a[3].elements = n;
  a[3].name = "quality";
  a[3].values = input.quality.data();
  char message[512];
  // OBJ: per-corner texture coordinates as they are; no place for the generic.
  const std::string obj = gab_test::scratch_path("written.obj");
  ASSERT_EQ(gab_write_mesh(obj.c_str(), mesh.positions.data(), n, mesh.triangles.data(), t, a, 4, message,
                           sizeof message),
            GAB_OK)
      << message;
  EXPECT_EQ(std::string(message).rfind("gab_write_mesh: " + obj + ": not written: ", 0), 0u) << message;
  EXPECT_NE(std::string(message).find("quality"), std::string::npos) << message;
  // PLY: every attribute, the seams split into more vertices.
  const std::string ply = gab_test::scratch_path("written.ply");
  ASSERT_EQ(gab_write_mesh(ply.c_str(), mesh.positions.data(), n, mesh.triangles.data(), t, a, 4, message,
                           sizeof message),
            GAB_OK)
      << message;
  const int32_t split = (kTorusN + 1) * (kTorusM + 1) - n;  // the seam's copies
  EXPECT_EQ(std::string(message), "gab_write_mesh: " + ply + ": " + std::to_string(split) +
                                      " vertices added where per-corner attributes have seams (the format holds "
                                      "them per vertex)");
  capi_mesh back{};
  gab_attribute* read = nullptr;
  int32_t count = 0;
  ASSERT_EQ(capi_read_mesh_with_attributes(ply.c_str(), &back, &read, &count, message, sizeof message), GAB_OK)
      << message;
  EXPECT_STREQ(message, "");
  EXPECT_EQ(back.n, n + split);
  EXPECT_EQ(back.t, t);
  ASSERT_EQ(count, 4);
  const int32_t kinds[4] = {GAB_ATTRIBUTE_NORMAL, GAB_ATTRIBUTE_TEXCOORD, GAB_ATTRIBUTE_COLOR, GAB_ATTRIBUTE_GENERIC};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(read[i].kind, kinds[i]) << i;
    EXPECT_EQ(read[i].value_type, a[i].value_type) << i;
    EXPECT_EQ(read[i].corners, nullptr) << i;  // PLY: per vertex
  }
  EXPECT_STREQ(read[3].name, "quality");
  // Corner by corner the same values (normals and uv as float32, the rest
  // exact), each vertex read mapped to the input's at its position.
  std::map<std::array<double, 3>, int32_t> at_position;
  for (int32_t v = 0; v < n; ++v) {
    const double* p = &mesh.positions[3 * static_cast<size_t>(v)];
    at_position[{p[0], p[1], p[2]}] = v;
  }
  std::vector<int32_t> to_input(static_cast<size_t>(back.n), -1);
  for (int32_t v = 0; v < back.n; ++v) {
    const double* p = &back.positions[3 * static_cast<size_t>(v)];
    const auto found = at_position.find({p[0], p[1], p[2]});
    ASSERT_NE(found, at_position.end()) << v;
    to_input[v] = found->second;
  }
  const int32_t* f = mesh.triangles.data();
  const double* given[4] = {input.normals.data(), input.uv.data(), colours.data(), input.quality.data()};
  const double bounds[4] = {1e-4, 1e-7, 0, 0};
  for (int i = 0; i < 4; ++i) {
    const double error =
        largest_error(corner_values(f, t, a[i].components, given[i], a[i].corners, nullptr),
                      corner_values(back.triangles, t, read[i].components, read[i].values, nullptr, to_input.data()),
                      i == 0);
    EXPECT_GE(error, 0) << i;
    EXPECT_LE(error, bounds[i]) << i;
  }
  gab_free(read);
  capi_free_mesh(&back);
  // Checked as compress checks them.
  a[2].value_type = 9;
  EXPECT_EQ(gab_write_mesh(ply.c_str(), mesh.positions.data(), n, mesh.triangles.data(), t, a, 4, message,
                           sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_write_mesh: attributes[2].value_type is 9: must be one of GAB_VALUE_INT8 .. "
                        "GAB_VALUE_FLOAT64 (0..7)");
  EXPECT_EQ(gab_write_mesh(nullptr, mesh.positions.data(), n, mesh.triangles.data(), t, nullptr, 0, message,
                           sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_write_mesh: path is NULL");
}

}  // namespace
