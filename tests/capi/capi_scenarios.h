/* Scenarios written in C99 against gab.h alone (capi_scenarios.c, compiled
   as C): each drives the C API the way an embedding product would and hands
   back what it got; the C++ tests (capi_test.cpp) check it. */
#ifndef GAB_TESTS_CAPI_SCENARIOS_H
#define GAB_TESTS_CAPI_SCENARIOS_H

#include <stddef.h>
#include <stdint.h>

#include "gab/gab.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A mesh the library returned (free with capi_free_mesh). */
typedef struct capi_mesh {
  double* positions;
  int32_t n;
  int32_t* triangles;
  int32_t t;
} capi_mesh;

void capi_free_mesh(capi_mesh* mesh);

/* gab_version against GAB_VERSION_STRING, and gab_error_name of every code:
   1 when all agree with gab.h. */
int capi_version_and_names(void);

/* gab_compress at `target`, then gab_decompress of the whole file and of its
   first `coarse_anchors` anchors. Codes in *compress_code, *decode_code,
   *coarse_code; the file in *file (gab_free), messages in `message`. */
typedef struct capi_round_trip {
  int compress_code, decode_code, coarse_code;
  unsigned char* file;
  size_t size;
  capi_mesh decoded, coarse;
  double rms_rel, coarse_rms_rel; /* vertex RMS over the input's bounding-box diagonal */
  char message[256];
} capi_round_trip;
void capi_round_trip_run(const double* positions, int32_t n, const int32_t* triangles, int32_t t, double target,
                         int32_t coarse_anchors, capi_round_trip* r);
void capi_round_trip_free(capi_round_trip* r);

/* gab_compress_ex with an anchor count alone (detail off, `bits`, `threads`), the numbering kept. */
int capi_compress_anchors(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                          int32_t anchors, int32_t bits, int32_t threads, unsigned char** file, size_t* size,
                          char* message, size_t message_size);

/* gab_compress_with_report with `reorder` set at `target`, then
   gab_decompress, the decoded mesh read through the report's map (decoded
   vertex order[i] for input vertex i): its vertex RMS over the input's
   diagonal in *mapped_rms_rel, the report's in *reported_rms_rel. The
   first failing call's code (GAB_E_INTERNAL when the report's size or map
   is not as gab.h says). */
int capi_compress_reordered(const double* positions, int32_t n, const int32_t* triangles, int32_t t, double target,
                            double* mapped_rms_rel, double* reported_rms_rel, char* message, size_t message_size);

/* gab_read_mesh of `path`. */
int capi_read_mesh(const char* path, capi_mesh* mesh, char* message, size_t message_size);

/* The Cholesky door in order: create from the pattern alone, factorize,
   solve b (n x nrhs) into x, add_anchor(j, w), solve b again into
   x_updated, destroy. Codes of each call in code[0..5] (create, factorize,
   solve, add_anchor, solve, and the message of the last call being ""). */
void capi_cholesky_run(int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
                       const double* b, int32_t nrhs, int32_t j, double w, double* x, double* x_updated, int code[6]);

/* gab_cholesky_create_ex with `ordering` and `threads` (the options struct
   filled by gab_cholesky_options_init), factorizing `values`, then a solve
   of b (n x nrhs) into x. The first failing call's code (its message in
   `message`); the factor's stored entries in *entries. */
int capi_cholesky_ordered(int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
                          int32_t ordering, int32_t threads, const double* b, int32_t nrhs, double* x,
                          int64_t* entries, char* message, size_t message_size);

/* gab_decompress_ex of the whole file with the factorizations' `ordering`. */
int capi_decompress_ordered(const unsigned char* file, size_t size, int32_t ordering, capi_mesh* mesh,
                            char* message, size_t message_size);

/* Attributes from C: four made in C over a mesh of n vertices and t
   triangles, from the caller's arrays (normals: 3n doubles, per vertex,
   float32; uv: 2 uv_count doubles, per corner through uv_corners (3t);
   rgba: 4n integers 0..255, per vertex, uint8; quality: n doubles, per
   vertex, float64, a generic named "quality"), compressed by
   gab_compress_with_attributes with `reorder` (and `normal_bits`, 0: the
   init's) and a report, then decoded whole by gab_decompress_with_attributes.
   Everything the library returned is kept for the caller to check; free it
   with capi_attribute_round_trip_free. */
typedef struct capi_attribute_round_trip {
  int compress_code, decode_code;
  unsigned char* file;
  size_t size;
  gab_compress_report report; /* its order and attributes released by the free */
  capi_mesh decoded;
  gab_attribute* attributes;  /* what the decode returned */
  int32_t num_attributes;
  char message[512];          /* the last call's */
} capi_attribute_round_trip;
void capi_attribute_round_trip_run(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                                   const double* normals, const double* uv, int32_t uv_count,
                                   const int32_t* uv_corners, const unsigned char* rgba, const double* quality,
                                   int32_t reorder, int32_t normal_bits, capi_attribute_round_trip* r);
void capi_attribute_round_trip_free(capi_attribute_round_trip* r);

/* gab_read_mesh_with_attributes of `path`. */
int capi_read_mesh_with_attributes(const char* path, capi_mesh* mesh, gab_attribute** attributes, int32_t* count,
                                   char* message, size_t message_size);

/* Error paths from C: a NULL message buffer, a message truncated to a
   small buffer, NULL handles. 1 when each behaves as gab.h says. */
int capi_error_paths(void);

#ifdef __cplusplus
}
#endif

#endif /* GAB_TESTS_CAPI_SCENARIOS_H */
