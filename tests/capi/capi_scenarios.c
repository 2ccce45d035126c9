/* C99 scenarios over gab.h (capi_scenarios.h): compiled as C, with
   -std=c99 -Wall -Wextra -pedantic -Werror, and nothing but gab.h and the C
   standard library. */
#include "capi/capi_scenarios.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gab/gab.h"

void capi_free_mesh(capi_mesh* mesh) {
  gab_free(mesh->positions);
  gab_free(mesh->triangles);
  mesh->positions = NULL;
  mesh->triangles = NULL;
  mesh->n = mesh->t = 0;
}

int capi_version_and_names(void) {
  static const char* const names[] = {"GAB_OK", "GAB_E_INVALID_ARGUMENT", "GAB_E_IO", "GAB_E_PARSE",
                                      "GAB_E_NOT_POSITIVE_DEFINITE", "GAB_E_OVERFLOW", "GAB_E_OUT_OF_MEMORY",
                                      "GAB_E_RESOURCE_EXHAUSTED", "GAB_E_UNSUPPORTED", "GAB_E_STATE",
                                      "GAB_E_INTERNAL"};
  const int codes[] = {GAB_OK, GAB_E_INVALID_ARGUMENT, GAB_E_IO, GAB_E_PARSE, GAB_E_NOT_POSITIVE_DEFINITE,
                       GAB_E_OVERFLOW, GAB_E_OUT_OF_MEMORY, GAB_E_RESOURCE_EXHAUSTED, GAB_E_UNSUPPORTED,
                       GAB_E_STATE, GAB_E_INTERNAL};
  size_t i;
  if (strcmp(gab_version(), GAB_VERSION_STRING) != 0) return 0;
  for (i = 0; i < sizeof codes / sizeof codes[0]; ++i) {
    if (codes[i] != (int)i || strcmp(gab_error_name(codes[i]), names[i]) != 0) return 0;
  }
  return strcmp(gab_error_name(-1), "GAB_E_UNKNOWN") == 0;
}

/* Vertex RMS distance between two position arrays over a's box diagonal. */
static double relative_rms(const double* a, const double* b, int32_t n) {
  double lo[3], hi[3], sum = 0.0, diagonal2 = 0.0;
  int32_t v;
  int c;
  for (c = 0; c < 3; ++c) lo[c] = hi[c] = a[c];
  for (v = 0; v < n; ++v) {
    for (c = 0; c < 3; ++c) {
      const double x = a[3 * (size_t)v + c], d = x - b[3 * (size_t)v + c];
      lo[c] = x < lo[c] ? x : lo[c];
      hi[c] = x > hi[c] ? x : hi[c];
      sum += d * d;
    }
  }
  for (c = 0; c < 3; ++c) diagonal2 += (hi[c] - lo[c]) * (hi[c] - lo[c]);
  return sqrt(sum / n) / sqrt(diagonal2);
}

void capi_round_trip_run(const double* positions, int32_t n, const int32_t* triangles, int32_t t, double target,
                         int32_t coarse_anchors, capi_round_trip* r) {
  memset(r, 0, sizeof *r);
  r->compress_code = gab_compress(positions, n, triangles, t, target, &r->file, &r->size, r->message,
                                  sizeof r->message);
  if (r->compress_code != GAB_OK) return;
  r->decode_code = gab_decompress(r->file, r->size, -1, &r->decoded.positions, &r->decoded.n,
                                  &r->decoded.triangles, &r->decoded.t, r->message, sizeof r->message);
  if (r->decode_code != GAB_OK) return;
  r->coarse_code = gab_decompress(r->file, r->size, coarse_anchors, &r->coarse.positions, &r->coarse.n,
                                  &r->coarse.triangles, &r->coarse.t, r->message, sizeof r->message);
  if (r->decoded.n == n) r->rms_rel = relative_rms(positions, r->decoded.positions, n);
  if (r->coarse_code == GAB_OK && r->coarse.n == n) r->coarse_rms_rel = relative_rms(positions, r->coarse.positions, n);
}

void capi_round_trip_free(capi_round_trip* r) {
  gab_free(r->file);
  capi_free_mesh(&r->decoded);
  capi_free_mesh(&r->coarse);
  r->file = NULL;
}

int capi_compress_anchors(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                          int32_t anchors, int32_t bits, int32_t threads, unsigned char** file, size_t* size,
                          char* message, size_t message_size) {
  gab_compress_options options;
  gab_compress_options_init(&options, sizeof options);
  options.max_anchors = anchors;
  options.bits = bits;
  options.threads = threads;
  options.detail = GAB_DETAIL_OFF;
  options.reorder = 0; /* the input's numbering: levels compared with it vertex by vertex */
  return gab_compress_ex(positions, n, triangles, t, &options, file, size, message, message_size);
}

int capi_compress_reordered(const double* positions, int32_t n, const int32_t* triangles, int32_t t, double target,
                            double* mapped_rms_rel, double* reported_rms_rel, char* message, size_t message_size) {
  gab_compress_options options;
  gab_compress_report report;
  unsigned char* file = NULL;
  size_t size = 0;
  double* decoded = NULL;
  double* mapped = NULL;
  int32_t* decoded_triangles = NULL;
  int32_t decoded_n = 0, decoded_t = 0, v;
  int c, code;
  gab_compress_options_init(&options, sizeof options);
  options.target_rms_rel = target;
  options.reorder = 1;
  gab_compress_report_init(&report, sizeof report);
  code = gab_compress_with_report(positions, n, triangles, t, &options, &file, &size, &report, message, message_size);
  if (code != GAB_OK) return code;
  *reported_rms_rel = report.rms_rel;
  if (report.size != sizeof report || report.order == NULL || report.bytes != size || report.n != n) {
    code = GAB_E_INTERNAL;
  } else {
    code = gab_decompress(file, size, -1, &decoded, &decoded_n, &decoded_triangles, &decoded_t, message,
                          message_size);
  }
  if (code == GAB_OK && decoded_n == n && (mapped = (double*)malloc(3 * (size_t)n * sizeof *mapped)) != NULL) {
    for (v = 0; v < n; ++v) {
      for (c = 0; c < 3; ++c) mapped[3 * (size_t)v + c] = decoded[3 * (size_t)report.order[v] + c];
    }
    *mapped_rms_rel = relative_rms(positions, mapped, n);
  } else if (code == GAB_OK) {
    code = GAB_E_INTERNAL;
  }
  free(mapped);
  gab_free(decoded);
  gab_free(decoded_triangles);
  gab_free(report.order);
  gab_free(file);
  return code;
}

int capi_read_mesh(const char* path, capi_mesh* mesh, char* message, size_t message_size) {
  return gab_read_mesh(path, &mesh->positions, &mesh->n, &mesh->triangles, &mesh->t, message, message_size);
}

void capi_attribute_round_trip_run(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                                   const double* normals, const double* uv, int32_t uv_count,
                                   const int32_t* uv_corners, const unsigned char* rgba, const double* quality,
                                   int32_t reorder, int32_t normal_bits, capi_attribute_round_trip* r) {
  gab_attribute attributes[4];
  gab_compress_options options;
  double* colours = (double*)malloc(4 * (size_t)n * sizeof *colours);
  size_t i;
  memset(r, 0, sizeof *r);
  memset(attributes, 0, sizeof attributes);
  if (colours == NULL) {
    r->compress_code = GAB_E_OUT_OF_MEMORY;
    return;
  }
  for (i = 0; i < 4 * (size_t)n; ++i) colours[i] = rgba[i];
  attributes[0].kind = GAB_ATTRIBUTE_NORMAL;
  attributes[0].value_type = GAB_VALUE_FLOAT32;
  attributes[0].components = 3;
  attributes[0].elements = n;
  attributes[0].values = normals; /* name and corners NULL: unnamed, per vertex */
  attributes[1].kind = GAB_ATTRIBUTE_TEXCOORD;
  attributes[1].value_type = GAB_VALUE_FLOAT32;
  attributes[1].components = 2;
  attributes[1].elements = uv_count;
  attributes[1].name = "";
  attributes[1].values = uv;
  attributes[1].corners = uv_corners;
  attributes[2].kind = GAB_ATTRIBUTE_COLOR;
  attributes[2].value_type = GAB_VALUE_UINT8;
  attributes[2].components = 4;
  attributes[2].elements = n;
  attributes[2].values = colours;
  attributes[3].kind = GAB_ATTRIBUTE_GENERIC;
  attributes[3].value_type = GAB_VALUE_FLOAT64;
  attributes[3].components = 1;
  attributes[3].elements = n;
  attributes[3].name = "quality";
  attributes[3].values = quality;
  gab_compress_options_init(&options, sizeof options);
  options.reorder = reorder;
  if (normal_bits != 0) options.normal_bits = normal_bits;
  gab_compress_report_init(&r->report, sizeof r->report);
  r->compress_code = gab_compress_with_attributes(positions, n, triangles, t, attributes, 4, &options, &r->file,
                                                  &r->size, &r->report, r->message, sizeof r->message);
  free(colours); /* the library read it during the call only */
  if (r->compress_code != GAB_OK) return;
  r->decode_code = gab_decompress_with_attributes(r->file, r->size, NULL, &r->decoded.positions, &r->decoded.n,
                                                  &r->decoded.triangles, &r->decoded.t, &r->attributes,
                                                  &r->num_attributes, r->message, sizeof r->message);
}

void capi_attribute_round_trip_free(capi_attribute_round_trip* r) {
  gab_free(r->file);
  gab_free(r->report.order);
  gab_free(r->report.attributes); /* one block: the labels inside it */
  capi_free_mesh(&r->decoded);
  gab_free(r->attributes); /* one block: values, corners and names inside it */
  r->file = NULL;
  r->report.order = NULL;
  r->report.attributes = NULL;
  r->attributes = NULL;
}

int capi_read_mesh_with_attributes(const char* path, capi_mesh* mesh, gab_attribute** attributes, int32_t* count,
                                   char* message, size_t message_size) {
  return gab_read_mesh_with_attributes(path, &mesh->positions, &mesh->n, &mesh->triangles, &mesh->t, attributes,
                                       count, message, message_size);
}

void capi_cholesky_run(int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
                       const double* b, int32_t nrhs, int32_t j, double w, double* x, double* x_updated, int code[6]) {
  gab_cholesky* c = NULL;
  const size_t entries = (size_t)n * (size_t)nrhs;
  char message[256];
  memset(code, -1, 6 * sizeof code[0]);
  code[0] = gab_cholesky_create(n, colptr, rowind, NULL, &c, message, sizeof message);
  if (code[0] != GAB_OK) return;
  code[1] = gab_cholesky_factorize(c, values, message, sizeof message);
  memcpy(x, b, entries * sizeof *x);
  code[2] = gab_cholesky_solve(c, x, nrhs);
  code[3] = gab_cholesky_add_anchor(c, j, w);
  memcpy(x_updated, b, entries * sizeof *x_updated);
  code[4] = gab_cholesky_solve(c, x_updated, nrhs);
  code[5] = strcmp(gab_cholesky_message(c), "") == 0 ? GAB_OK : GAB_E_INTERNAL;
  gab_cholesky_destroy(c);
}

int capi_cholesky_ordered(int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
                          int32_t ordering, int32_t threads, const double* b, int32_t nrhs, double* x,
                          int64_t* entries, char* message, size_t message_size) {
  gab_cholesky_options options;
  gab_cholesky* c = NULL;
  int code;
  gab_cholesky_options_init(&options, sizeof options);
  options.ordering = ordering;
  options.threads = threads;
  *entries = -1;
  code = gab_cholesky_create_ex(n, colptr, rowind, values, &options, &c, message, message_size);
  if (code != GAB_OK) return code;
  *entries = gab_cholesky_factor_entries(c);
  memcpy(x, b, (size_t)n * (size_t)nrhs * sizeof *x);
  code = gab_cholesky_solve(c, x, nrhs);
  if (code != GAB_OK) snprintf(message, message_size, "%s", gab_cholesky_message(c));
  gab_cholesky_destroy(c);
  return code;
}

int capi_decompress_ordered(const unsigned char* file, size_t size, int32_t ordering, capi_mesh* mesh,
                            char* message, size_t message_size) {
  gab_decompress_options options;
  gab_decompress_options_init(&options, sizeof options);
  options.ordering = ordering;
  return gab_decompress_ex(file, size, &options, &mesh->positions, &mesh->n, &mesh->triangles, &mesh->t, message,
                           message_size);
}

int capi_error_paths(void) {
  const double positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const int32_t triangles[3] = {0, 1, 7};
  unsigned char* file = (unsigned char*)&file; /* must come back NULL */
  size_t size = 99;
  char small[8];
  int ok = 1;
  /* NULL message buffer: the code alone. */
  ok &= gab_compress(positions, 3, triangles, 1, 1e-3, &file, &size, NULL, 0) == GAB_E_INVALID_ARGUMENT;
  ok &= file == NULL && size == 0;
  /* A small buffer: the message's first 7 bytes and a NUL. */
  memset(small, 'x', sizeof small);
  ok &= gab_compress(positions, 3, triangles, 1, 1e-3, &file, &size, small, sizeof small) == GAB_E_INVALID_ARGUMENT;
  ok &= memcmp(small, "gab_com", 8) == 0;
  /* A zero-size buffer is left alone. */
  small[0] = 'x';
  ok &= gab_compress(positions, 3, triangles, 1, 1e-3, &file, &size, small, 0) == GAB_E_INVALID_ARGUMENT;
  ok &= small[0] == 'x';
  /* NULL handles and NULL frees. */
  ok &= gab_cholesky_solve(NULL, NULL, 1) == GAB_E_INVALID_ARGUMENT;
  ok &= gab_cholesky_add_anchor(NULL, 0, 1.0) == GAB_E_INVALID_ARGUMENT;
  ok &= gab_cholesky_factorize(NULL, NULL, NULL, 0) == GAB_E_INVALID_ARGUMENT;
  ok &= gab_cholesky_factor_entries(NULL) == -1;
  gab_cholesky_destroy(NULL);
  gab_free(NULL);
  return ok;
}
