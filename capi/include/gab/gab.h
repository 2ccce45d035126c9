/* gab's C API: mesh compression with geometry-aware bases and the sparse
   Cholesky engine behind it, for C99 and anything that calls C.

   Contract, for every function below:
   - It returns GAB_OK (0) or one of the GAB_E_* codes, or where a function
     says so a GAB_W_* warning: done, its outputs set, with something the
     caller must know; the codes keep their values across versions.
     Functions taking `message, message_size` write a one-line message there
     on failure or warning, and on a success what it did not give back (the
     next rule; "" when nothing), truncated to fit and always
     NUL-terminated; message may be NULL (then message_size is ignored).
   - Nothing is thrown across it and nothing aborts: bad arguments (NULL
     pointers, negative counts, indices out of range) are reported, and so is
     memory that cannot be had.
   - Memory the library returns (*out, *positions, *triangles, a report's
     order and attributes, an attribute array) is malloc'd and released with
     gab_free, one call per pointer returned (an attribute array is one
     block: its values, corners and names inside it); on failure the out
     pointers are set to NULL / 0.
   - Nothing is dropped silently: a call that succeeds without returning
     something the input held (a file's materials, attributes a function
     without attribute outputs does not return, sections a level of detail
     cannot decode) says what in its message, the code staying GAB_OK.
   - Calls on different handles and different buffers may run in several
     threads at once; one handle is used by one thread at a time.
   - Indices are 0-based int32 (counts below 2^31); coordinates are doubles,
     3 per vertex (x0 y0 z0 x1 ...); triangles 3 int32 vertex indices each.
   - Decoding is safe on untrusted bytes: a malformed, corrupted or forged
     file is an error (GAB_E_PARSE, GAB_E_UNSUPPORTED, GAB_E_RESOURCE_EXHAUSTED),
     never a read outside `data`.
   The C++ API (gab/codec/encoder.h, gab/sparse/cholesky.h, ...) is what this
   wraps; see docs/library.md, "C". */
#ifndef GAB_GAB_H
#define GAB_GAB_H

#include <stddef.h>
#include <stdint.h>

#include "gab/version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Error codes ---------------------------------------------------------- */

#define GAB_OK 0
#define GAB_E_INVALID_ARGUMENT 1      /* an argument breaks the function's contract */
#define GAB_E_IO 2                    /* a file could not be opened or read */
#define GAB_E_PARSE 3                 /* malformed, corrupted or forged bytes */
#define GAB_E_NOT_POSITIVE_DEFINITE 4 /* Cholesky met a non-positive pivot (message names the column) */
#define GAB_E_OVERFLOW 5              /* a count exceeds the int32 index limit */
#define GAB_E_OUT_OF_MEMORY 6         /* memory could not be had */
#define GAB_E_RESOURCE_EXHAUSTED 7    /* the work would exceed a limit of the decoder */
#define GAB_E_UNSUPPORTED 8           /* well-formed input of a newer format, or options this library does not know */
#define GAB_E_STATE 9                 /* a call out of order (a solve before a factorization) */
#define GAB_E_INTERNAL 10             /* a failure that is a bug in gab: please report the message */

/* Warnings: nonzero, so `if (code != GAB_OK)` stops on them too; a caller
   that can use the outputs anyway tests for the warning by name. */
#define GAB_W_TRUNCATED 100 /* gab_decompress*: the file ends inside a chunk (a transfer cut short): the mesh
                               is the shape of its complete chunks, the message says how many of how many */

/* The name of a code ("GAB_E_PARSE", "GAB_W_TRUNCATED"), "GAB_OK", or "GAB_E_UNKNOWN". */
const char* gab_error_name(int code);

/* ---- Library ------------------------------------------------------------- */

/* The library's version, "MAJOR.MINOR.PATCH" (GAB_VERSION_STRING of the build). */
const char* gab_version(void);
/* Releases memory the library returned; NULL is fine. */
void gab_free(void* p);

/* ---- Meshes ---------------------------------------------------------------- */

/* What an attribute describes (gab_attribute.kind): each kind is predicted
   and quantized its own way. */
#define GAB_ATTRIBUTE_NORMAL 0   /* 3 components, any length (the codec codes the direction) */
#define GAB_ATTRIBUTE_TEXCOORD 1 /* 2 components (u v) or 3 (u v w) */
#define GAB_ATTRIBUTE_COLOR 2    /* 3 (r g b) or 4 (r g b a): 0..255 when integer-typed, else as given (0..1) */
#define GAB_ATTRIBUTE_GENERIC 3  /* 1 to 4 components under a name (a PLY property: "quality") */

/* How the source stored the values (gab_attribute.value_type): a PLY
   property's type; OBJ and OFF text is GAB_VALUE_FLOAT32. Integer-typed
   values are coded exactly (each must be an integer of its type's range),
   the others quantized (gab_compress_options' *_bits). */
#define GAB_VALUE_INT8 0
#define GAB_VALUE_UINT8 1
#define GAB_VALUE_INT16 2
#define GAB_VALUE_UINT16 3
#define GAB_VALUE_INT32 4
#define GAB_VALUE_UINT32 5
#define GAB_VALUE_FLOAT32 6
#define GAB_VALUE_FLOAT64 7

/* The most attributes a mesh carries. */
#define GAB_MAX_ATTRIBUTES 64

/* One attribute of a mesh of n vertices and t triangles: `elements` values
   of `components` doubles each (element e's are values[components * e ...]),
   per vertex (corners NULL: elements == n, in vertex order) or per corner
   (corners: 3 t element indices, corner k of triangle f at corners[3 f + k],
   following the triangles: where a vertex has several texture coordinates
   or normals, a seam). Its layout is fixed (an array of them crosses the
   ABI); what a later version needs beyond it comes as another struct.
   Given to gab_compress_with_attributes, the caller's memory, read during
   the call only. Returned (gab_read_mesh_with_attributes,
   gab_decompress_with_attributes), an array in one malloc'd block holding
   its values, corners and names: release it with one gab_free. */
typedef struct gab_attribute {
  int32_t kind;           /* GAB_ATTRIBUTE_* */
  int32_t value_type;     /* GAB_VALUE_* */
  int32_t components;     /* per element: as the kind says */
  int32_t elements;       /* values / components */
  const char* name;       /* a generic's: 1 to 255 letters, digits, '_', '-' or '.'; the other kinds: NULL or ""
                             given, "" returned */
  const double* values;   /* components * elements, finite */
  const int32_t* corners; /* NULL: per vertex; else 3 t indices in [0, elements) */
} gab_attribute;

/* Reads an .obj, .off or .ply file (format by extension, content checked):
   *positions gets 3 n doubles, *triangles 3 t int32 (polygons fan-triangulated).
   Positions and triangles only: on success the message is "" unless the
   file held more; then it names it and the code stays GAB_OK: what gab
   does not carry (materials, groups, polygons' arity, ...: "not carried",
   as the CLI's warning), and the attributes gab reads that this function
   does not return ("not returned"), e.g. "gab_read_mesh: a.obj: not
   returned: 6 normals (per corner), 4 texture_coordinates (per corner);
   gab_read_mesh_with_attributes returns them". O(file size). */
int gab_read_mesh(const char* path, double** positions, int32_t* n, int32_t** triangles, int32_t* t,
                  char* message, size_t message_size);

/* gab_read_mesh with the file's attributes (OBJ vn/vt per corner and v
   colours, PLY normals, texture coordinates, colours and every other vertex
   property as a named generic, OFF's N/C/ST forms; docs/cli.md): *attributes
   gets *num_attributes of them in the file's order, one block (gab_free;
   NULL when there are none). On success the message names only what gab
   does not carry ("gab_read_mesh_with_attributes: a.obj: not carried: 19
   groups (g)"), the code staying GAB_OK. O(file size). */
int gab_read_mesh_with_attributes(const char* path, double** positions, int32_t* n, int32_t** triangles,
                                  int32_t* t, gab_attribute** attributes, int32_t* num_attributes, char* message,
                                  size_t message_size);

/* Writes a mesh atomically (a temporary file, then a rename) in the format
   of the path's extension (.obj, .off or .ply: binary little-endian,
   double coordinates), with its attributes (NULL / 0: none) in the
   format's spelling and the values' types. PLY and OFF hold one value per
   vertex: vertices where per-corner attributes have seams are split. On
   success the message names what the format could not hold (generic
   attributes in OBJ and OFF, ...) and the vertices split, the code staying
   GAB_OK. Arguments are checked as gab_compress_with_attributes checks them.
   O(n + t + attribute values). */
int gab_write_mesh(const char* path, const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                   const gab_attribute* attributes, int32_t num_attributes, char* message, size_t message_size);

/* ---- Compression ------------------------------------------------------------ */

/* The detail layer (gab_compress_options.detail). */
#define GAB_DETAIL_AUTO 0 /* with an error target: the smaller of the files with and without it */
#define GAB_DETAIL_ON 1   /* with an error target: always */
#define GAB_DETAIL_OFF 2  /* never: the anchors alone (a target may be missed) */

/* A factorization's fill-reducing ordering (the .ordering of
   gab_compress_options, gab_decompress_options and gab_cholesky_options):
   a matter of speed and memory only, never of the result. A compress
   records its ordering in the file. */
#define GAB_ORDERING_AUTO 0    /* "auto": nested dissection from 100,000 vertices (columns), AMD below */
#define GAB_ORDERING_AMD 1     /* "amd": approximate minimum degree */
#define GAB_ORDERING_ND 2      /* "nd": nested dissection: less fill for large meshes, dearer to compute */
#define GAB_ORDERING_NATURAL 3 /* "natural": the matrix's own order (its elimination tree postordered); for a
                                  matrix already ordered well; gab_cholesky_options only (the codec refuses it) */

/* The GAB_ORDERING_* value a name stands for ("auto", "amd", "nd" or
   "natural", as the CLI's --ordering reads them); -1 for any other text or
   NULL. O(1). */
int gab_ordering_from_name(const char* name);

/* The reconstruction operator (gab_compress_options.solver), recorded in
   the file: the shape the anchors make. */
#define GAB_SOLVER_AUTO 0      /* "auto": iterative, or global when refine is set (the refinement needs it) */
#define GAB_SOLVER_GLOBAL 1    /* "global": the paper's factored least squares; files 2-17% smaller at 1e-3
                                  (2% at 1e-4), decodes an order of magnitude slower in several times the
                                  memory */
#define GAB_SOLVER_ITERATIVE 2 /* "iterative": fixed conjugate-gradient steps, decode cost linear in n */

/* The GAB_SOLVER_* value a name stands for ("auto", "global" or
   "iterative", as the CLI's --solver reads them); -1 for any other text or
   NULL. O(1). */
int gab_solver_from_name(const char* name);

/* Options of gab_compress_ex. ABI-stable: `size` says how much of the struct
   the caller knows; later versions only append fields, and a field beyond
   `size` takes its default. Fill it with gab_compress_options_init, then set
   fields. Stopping rules (any combination; with none of them, target_rms_rel
   = 1e-3): max_anchors, target_rms_rel, target_linf_rel.
   The numbering: reorder is 1 by default, the smallest file, the decoded
   mesh numbered in the coder's traversal order (gab_compress_with_report's
   `order` maps it); a caller that keys data by vertex index outside the file
   sets reorder = 0, read the same way by every version. This default is a
   contract change (the init used to set 0; gab_compress still keeps the
   numbering): the layout is unchanged, so a program built against an older
   gab.h gets the new default from the init unless it sets reorder = 0.
   The attributes' quantization (normal_bits ... generic_bits) was appended
   under the same rule: a program built against a gab.h without them gets
   their defaults. */
typedef struct gab_compress_options {
  size_t size;            /* sizeof(gab_compress_options) as the caller compiled it */
  double target_rms_rel;  /* relative vertex RMS over the bounding-box diagonal (CLI --error); 0: none */
  double target_linf_rel; /* relative max vertex error (--linf); 0: none */
  double weight;          /* anchor weight w of the relaxed basis, in (0, 1e100] (default 100) */
  int32_t max_anchors;    /* anchors in the file (--anchors); 0: no count limit */
  int32_t bits;           /* q, bits per coordinate, 2..24 (--bits); 0: chosen from the target */
  int32_t reorder;        /* nonzero (default): number the decoded mesh in the coder's traversal order, the
                             smallest file; 0: keep the input's numbering, priced by the order block
                             (--keep-order) */
  int32_t threads;        /* threads for the factorizations (default 1; 0: every core); same file for any count */
  int32_t detail;         /* GAB_DETAIL_AUTO (default), GAB_DETAIL_ON or GAB_DETAIL_OFF */
  int32_t refine;         /* nonzero: append the least-squares refinement chunk (--refine) */
  int32_t ordering;       /* GAB_ORDERING_AUTO (default), GAB_ORDERING_AMD or GAB_ORDERING_ND (--ordering) */
  int32_t solver;         /* GAB_SOLVER_AUTO (default), GAB_SOLVER_GLOBAL or GAB_SOLVER_ITERATIVE (--solver) */
  /* The attributes' quantization (gab_compress_with_attributes; each attribute in its own section after the
     geometry). Integer-typed values are coded exactly whatever these say. */
  int32_t normal_bits;    /* normals: directions on a lattice of about 4^bits points, 2..16 (default 8: at most
                             0.6 degrees off; --normal-bits) */
  int32_t texcoord_bits;  /* texture coordinates: a grid of 2^bits - 1 steps over their span, 1..31 (default 10;
                             --uv-bits) */
  int32_t color_bits;     /* float colours, the same grid, 1..31 (default 8; --color-bits) */
  int32_t generic_bits;   /* float generic attributes, the same grid, 1..31 (default 16; --generic-bits) */
} gab_compress_options;

/* Sets the defaults: options->size = min(size, sizeof(gab_compress_options)),
   every known field within `size` to its default, the rest of `size` bytes
   to zero. Call as gab_compress_options_init(&o, sizeof o). */
void gab_compress_options_init(gab_compress_options* options, size_t size);

/* positions: 3n doubles (x0 y0 z0 x1 ...), triangles: 3t int32. target_rms_rel:
   relative vertex RMS target (as --error); *out receives a malloc'd .gab image.
   The decoded mesh keeps the vertex numbering, as gab_compress_ex's with
   reorder = 0 (`gab compress --keep-order`; their default is the coder's
   order, the smaller file); the triangles come back as the same set of
   oriented triangles, in the coder's order. Cost: about the CLI's `gab
   compress` (factorizations and greedy updates). */
int gab_compress(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                 double target_rms_rel, unsigned char** out, size_t* out_size,
                 char* message, size_t message_size);
/* gab_compress with options (NULL: the defaults). An options struct larger
   than this library knows is accepted when its unknown bytes are zero, else
   GAB_E_UNSUPPORTED. */
int gab_compress_ex(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                    const gab_compress_options* options, unsigned char** out, size_t* out_size,
                    char* message, size_t message_size);

/* What a compress made (gab_compress_with_report): the figures of the CLI's
   `gab compress --json`, under its key names and in its units (docs/cli.md),
   and the map of a renumbered decode. ABI-stable as the options, for an out
   struct: fill it with gab_compress_report_init, then pass it; the library
   writes the fields it knows within `size` and sets `size` to the bytes it
   wrote, so a caller compiled against a newer gab.h reads a newer field only
   when its offset is below `size`. Errors are relative to the input's
   bounding-box diagonal; byte counts include each part's framing, and
   bytes = geometry_bytes + connectivity_bytes + order_bytes +
   attribute_bytes. The fields from merged_vertices on were appended under
   that rule. */

/* One attribute as coded (gab_compress_report.attributes). Its layout is
   fixed, as gab_attribute's; a later version's further figures come in a
   field appended to the report. */
typedef struct gab_attribute_stats {
  const char* label;    /* "normals", "texture_coordinates", "vertex_colors" or "generic:NAME" (the CLI's names) */
  int32_t kind;         /* GAB_ATTRIBUTE_* */
  int32_t bits;         /* its quantization's (integer-typed: the span's, exact) */
  int32_t per_corner;   /* nonzero: coded per corner, with seams; 0: one value per vertex */
  int32_t from_surface; /* nonzero: normals predicted from the decoded surface (a level of detail, or a decode
                           of a file whose detail or refinement chunk is cut off, skips them) */
  int64_t elements;     /* values coded: vertices, or per corner the wedges of corners sharing one */
  size_t bytes;         /* its section with its framing */
  double max_error;     /* the largest error of a decoded value: degrees for normals, value units otherwise */
} gab_attribute_stats;

typedef struct gab_compress_report {
  size_t size;                /* sizeof(gab_compress_report) as the caller compiled it; after a call: bytes written */
  int32_t n;                  /* vertices */
  int32_t faces;              /* triangles */
  int32_t anchors;            /* anchors in the file */
  int32_t chunks;             /* chunks in the file, a refinement or detail chunk included */
  int32_t bits;               /* q, the anchors' bits per coordinate */
  int32_t solver;             /* the file's reconstruction operator: GAB_SOLVER_GLOBAL or GAB_SOLVER_ITERATIVE */
  int32_t ordering;           /* the factorizations' ordering: GAB_ORDERING_AMD or GAB_ORDERING_ND */
  int32_t target_met;         /* nonzero: every error target was met (else out of reach at these bits) */
  int32_t reordered;          /* nonzero: the decoded mesh is numbered in the coder's order; `order` maps it */
  int32_t detail;             /* nonzero: the file ends with a detail chunk */
  int32_t refined;            /* nonzero: the file ends with a least-squares refinement chunk */
  int32_t levels;             /* nonzero: the file is in the level layout */
  size_t bytes;               /* the whole file */
  size_t geometry_bytes;      /* header and chunks (the detail and refinement chunks among them) */
  size_t connectivity_bytes;  /* the triangles */
  size_t order_bytes;         /* the vertex order block (0 when reordered, the default) */
  size_t detail_bytes;        /* the detail chunk (0 without one) */
  size_t refinement_bytes;    /* the refinement chunk (0 without one) */
  double rms_rel;             /* vertex RMS of the decoded shape against the input */
  double linf_rel;            /* max vertex distance of the decoded shape */
  double anchor_rms_rel;      /* the anchors' shape alone (a decode stopping before the detail chunk); else rms_rel */
  double unrefined_rms_rel;   /* the shape before the refinement chunk (0 without one) */
  double detail_step_rel;     /* the detail layer's quantization step (0 without one) */
  double bpv_geometry;        /* geometry bits per vertex: 8 geometry_bytes / n */
  double weight;              /* the anchor weight w used */
  double encode_s;            /* the compress's time, seconds */
  int32_t* order;             /* reordered: n + merged_vertices entries (the input's vertices), order[i] the
                                 decoded mesh's index of input vertex i (what `gab compress --order-out`
                                 writes, line i), malloc'd: release with gab_free; otherwise NULL */
  int32_t merged_vertices;    /* reordered: input vertices merged into a copy at the same position (a mesh split
                                 along seams, a triangle soup), their attributes kept per corner: the input had
                                 n + merged_vertices vertices, the decoded mesh has n */
  int32_t num_attributes;     /* entries of attributes: the attributes given, in their order */
  size_t attribute_bytes;     /* the attribute sections with their framing */
  gab_attribute_stats* attributes; /* num_attributes entries, one malloc'd block (their labels inside it): release
                                      with gab_free; NULL when there are none */
} gab_compress_report;

/* Sets report->size = min(size, sizeof(gab_compress_report)) and the rest of
   `size` bytes to zero. Call as gab_compress_report_init(&r, sizeof r). */
void gab_compress_report_init(gab_compress_report* report, size_t size);

/* gab_compress_ex that also fills *report (NULL: none), on success only; on
   failure the report's fields are zero and its order NULL. The same file as
   gab_compress_ex with the same options; the map costs n int32 more. */
int gab_compress_with_report(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                             const gab_compress_options* options, unsigned char** out, size_t* out_size,
                             gab_compress_report* report, char* message, size_t message_size);

/* gab_compress_with_report with the mesh's attributes (NULL / 0: none, the
   same file as gab_compress_with_report): each coded in its own section
   after the geometry, at the options' *_bits, so a decode of any prefix
   still has the shape. Per-corner attributes follow the triangles into the
   coder's order; with reorder (the default) the decoded mesh carries them
   in its numbering, and copies of a vertex at the same position are merged
   into one (report->merged_vertices), their values kept per corner.
   Arguments are checked before any work, with messages naming the field
   ("attributes[1].corners[7] is 12: out of range [0, 4)"). Cost: the
   compress's, plus O(attribute values + t) a section (normals: one decode
   of the geometry, to predict from the surface the decoder will have). */
int gab_compress_with_attributes(const double* positions, int32_t n, const int32_t* triangles, int32_t t,
                                 const gab_attribute* attributes, int32_t num_attributes,
                                 const gab_compress_options* options, unsigned char** out, size_t* out_size,
                                 gab_compress_report* report, char* message, size_t message_size);

/* max_anchors < 0: the whole file, else the first max_anchors anchors (a
   coarser level). A file cut short decodes to its complete chunks and
   returns GAB_W_TRUNCATED with the mesh set (unless max_anchors ends within
   them: then the cut is not reached and the code is GAB_OK). The decode's
   memory is bounded as gab_decompress_options' default says. Positions and
   triangles only: the message of a success names the attributes the file
   holds ("not returned: 762 normals (per corner);
   gab_decompress_with_attributes returns them"), the code staying GAB_OK. */
int gab_decompress(const unsigned char* data, size_t size, int32_t max_anchors,
                   double** positions, int32_t* n, int32_t** triangles, int32_t* t,
                   char* message, size_t message_size);

/* Options of gab_decompress_ex; ABI-stable as gab_compress_options (fill
   with gab_decompress_options_init, then set fields). */
typedef struct gab_decompress_options {
  size_t size;          /* sizeof(gab_decompress_options) as the caller compiled it */
  int64_t max_memory;   /* bytes the decode may take (--max-memory); 0 (default): 32 KiB per byte of the
                           file, at least 64 MiB; negative: no limit. Over it: GAB_E_RESOURCE_EXHAUSTED,
                           the message saying how much the decode needs */
  int32_t max_anchors;  /* < 0 (default -1): the whole file, else its first max_anchors anchors */
  int32_t threads;      /* threads for the factorizations (default 1; 0: every core); same shape for any count */
  int32_t ordering;     /* a global-solver file's factorizations' (--ordering): GAB_ORDERING_AUTO (default)
                           the one the file records, or GAB_ORDERING_AMD or GAB_ORDERING_ND. Speed and memory
                           only: the same anchors and detail positions bit for bit, a shape solved from the
                           anchors the same up to rounding (1e-11 of the diagonal); an iterative-solver file
                           has no factor and ignores it */
} gab_decompress_options;

/* Sets the defaults, as gab_compress_options_init does. */
void gab_decompress_options_init(gab_decompress_options* options, size_t size);

/* gab_decompress with options (NULL: the defaults). */
int gab_decompress_ex(const unsigned char* data, size_t size, const gab_decompress_options* options,
                      double** positions, int32_t* n, int32_t** triangles, int32_t* t,
                      char* message, size_t message_size);

/* gab_decompress_ex with the file's attributes: *attributes gets
   *num_attributes of them, in the order they were given to the compress,
   numbered as the decoded mesh (per-corner ones following *triangles), one
   block (gab_free; NULL when there are none). Any level of detail decodes
   them whole, except normals predicted from the decoded surface
   (gab_attribute_stats.from_surface), which need the whole shape: a decode
   of fewer anchors, or of a file cut short, leaves them out and its message
   says so ("not decoded: normals: predicted from the whole shape, which
   this decode does not have (every anchor of a complete file)"), as it
   names sections of a newer format, the code staying GAB_OK (or
   GAB_W_TRUNCATED, the message then saying both). */
int gab_decompress_with_attributes(const unsigned char* data, size_t size, const gab_decompress_options* options,
                                   double** positions, int32_t* n, int32_t** triangles, int32_t* t,
                                   gab_attribute** attributes, int32_t* num_attributes, char* message,
                                   size_t message_size);

/* ---- Sparse Cholesky -------------------------------------------------------- */

typedef struct gab_cholesky gab_cholesky;

/* pattern of the lower triangle of a symmetric positive definite n x n matrix, CSC, 0-based:
   ordering and symbolic analysis (values may be NULL); factorize then takes the values.
   colptr: n + 1 entries from 0, nondecreasing; rowind: colptr[n] entries, in
   each column strictly increasing, all >= the column (lower triangle), the
   diagonal present. When values is not NULL the matrix is factorized too.
   The pattern is copied: the caller's arrays may go. Cost: AMD ordering and
   symbolic analysis, O(nnz(L)) memory reserved for the factor; one thread. */
int gab_cholesky_create(int32_t n, const int32_t* colptr, const int32_t* rowind,
                        const double* values, gab_cholesky** out, char* message, size_t message_size);

/* Options of gab_cholesky_create_ex; ABI-stable as gab_compress_options
   (fill with gab_cholesky_options_init, then set fields). The defaults are
   gab_cholesky_create's. */
typedef struct gab_cholesky_options {
  size_t size;      /* sizeof(gab_cholesky_options) as the caller compiled it */
  int32_t ordering; /* GAB_ORDERING_AMD (default), GAB_ORDERING_ND, GAB_ORDERING_NATURAL or GAB_ORDERING_AUTO:
                       the fill, hence the factor's memory and the factorization's time; the solutions are
                       the same up to rounding */
  int32_t threads;  /* threads for the factorizations, solves and the nested dissection (default 1; 0: every
                       core); the same factor, bit for bit, for any count */
} gab_cholesky_options;

/* Sets the defaults, as gab_compress_options_init does. */
void gab_cholesky_options_init(gab_cholesky_options* options, size_t size);

/* gab_cholesky_create with options (NULL: the defaults, gab_cholesky_create
   itself). An options struct larger than this library knows is accepted
   when its unknown bytes are zero, else GAB_E_UNSUPPORTED; an unknown
   ordering or a thread count outside 0..64 is GAB_E_INVALID_ARGUMENT. Cost:
   the options' ordering (nested dissection several times AMD's time,
   natural none) and symbolic analysis. */
int gab_cholesky_create_ex(int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
                           const gab_cholesky_options* options, gab_cholesky** out, char* message,
                           size_t message_size);
/* Numeric factorization: values in the pattern's order (colptr[n] finite
   doubles). Discards any earlier updates. */
int gab_cholesky_factorize(gab_cholesky* c, const double* values, char* message, size_t message_size);
/* b: n x nrhs, column-major, in place. Needs a factorization. */
int gab_cholesky_solve(gab_cholesky* c, double* b, int32_t nrhs);
/* A + w^2 e_j e_j^T, in place: Givens rotations along the elimination-tree
   path of j, no change of structure. Needs a factorization. */
int gab_cholesky_add_anchor(gab_cholesky* c, int32_t j, double w);
/* The doubles the factor is stored in, reserved at create (8 bytes each:
   the bulk of the handle's memory): nnz(L) and the explicit zeros of its
   supernodes' dense blocks, what the ordering is chosen to keep small. -1
   when c is NULL. O(1). */
int64_t gab_cholesky_factor_entries(const gab_cholesky* c);
/* The message of the last call on c (solve, add_anchor, factorize): "" when
   it succeeded. Valid until the next call on c. */
const char* gab_cholesky_message(const gab_cholesky* c);
/* Releases c; NULL is fine. */
void gab_cholesky_destroy(gab_cholesky* c);

#ifdef __cplusplus
}
#endif

#endif /* GAB_GAB_H */
