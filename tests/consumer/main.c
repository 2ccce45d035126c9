/* A C99 program written against gab.h alone, as a product embeds gab: it
   builds with find_package(gab) + gab::gab (tests/consumer/CMakeLists.txt,
   and tests/consumer_c from a C-only project), with a plain
   `cc -std=c99 main.c -lgab` and with pkg-config against the installed
   prefix (.ci/run). Round-trips a grid with a bump through the codec, solves a 1-D
   Laplacian and updates it; exits 0 only if all is right. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gab/gab.h>

static int round_trip(void) {
  double positions[3 * 36];
  int32_t triangles[6 * 25], n = 0, t = 0, *decoded_triangles = NULL;
  double *decoded = NULL, worst = 0.0;
  unsigned char* file = NULL;
  size_t size = 0;
  char message[256];
  int i, j, ok;
  for (j = 0; j < 6; ++j) {
    for (i = 0; i < 6; ++i) {
      double* p = &positions[3 * (i + 6 * j)];
      p[0] = i;
      p[1] = j;
      p[2] = (i - 2.5) * (j - 2.5) * 0.1;
    }
  }
  for (j = 0; j < 5; ++j) {
    for (i = 0; i < 5; ++i) {
      const int32_t v = i + 6 * j, quad[6] = {v, v + 1, v + 7, v, v + 7, v + 6};
      memcpy(&triangles[6 * (i + 5 * j)], quad, sizeof quad);
    }
  }
  if (gab_compress(positions, 36, triangles, 50, 1e-3, &file, &size, message, sizeof message) != GAB_OK ||
      gab_decompress(file, size, -1, &decoded, &n, &decoded_triangles, &t, message, sizeof message) != GAB_OK) {
    fprintf(stderr, "consumer (C): %s\n", message);
    gab_free(file);
    return 0;
  }
  for (i = 0; i < 3 * 36; ++i) worst = fmax(worst, fabs(decoded[i] - positions[i]));
  ok = n == 36 && t == 50 && worst < 0.05;
  printf("consumer (C): gab %s, .gab round trip %s, %u bytes, max error %.3g\n", gab_version(),
         ok ? "ok" : "failed", (unsigned)size, worst);
  gab_free(file);
  gab_free(decoded);
  gab_free(decoded_triangles);
  return ok;
}

static int solve_and_update(void) {
  enum { n = 50 };
  int32_t colptr[n + 1], rowind[2 * n - 1];
  double values[2 * n - 1], b[n], x[n], worst = 0.0, residual = 0.0;
  gab_cholesky* c = NULL;
  char message[256];
  int i, k = 0, ok;
  for (i = 0; i < n; ++i) { /* tridiagonal [-1 2 -1], lower triangle */
    colptr[i] = k;
    rowind[k] = i;
    values[k++] = 2.0;
    if (i + 1 < n) {
      rowind[k] = i + 1;
      values[k++] = -1.0;
    }
  }
  colptr[n] = k;
  for (i = 0; i < n; ++i) b[i] = x[i] = (i == 0 || i == n - 1) ? 1.0 : 0.0; /* A * ones */
  if (gab_cholesky_create(n, colptr, rowind, values, &c, message, sizeof message) != GAB_OK) {
    fprintf(stderr, "consumer (C): %s\n", message);
    return 0;
  }
  ok = gab_cholesky_solve(c, x, 1) == GAB_OK;
  for (i = 0; i < n; ++i) worst = fmax(worst, fabs(x[i] - 1.0));
  /* A + 2^2 e_0 e_0^T x = b: the residual of the updated factor's solution. */
  memcpy(x, b, sizeof x);
  ok = ok && gab_cholesky_add_anchor(c, 0, 2.0) == GAB_OK && gab_cholesky_solve(c, x, 1) == GAB_OK;
  for (i = 0; i < n; ++i) {
    const double ax = (2.0 + (i == 0 ? 4.0 : 0.0)) * x[i] - (i > 0 ? x[i - 1] : 0.0) - (i + 1 < n ? x[i + 1] : 0.0);
    residual = fmax(residual, fabs(ax - b[i]));
  }
  ok = ok && worst < 1e-10 && residual < 1e-10 && fabs(x[0] - 1.0) > 0.1;
  printf("consumer (C): Cholesky max error %.3g, after an update residual %.3g: %s\n", worst, residual,
         ok ? "ok" : "failed");
  gab_cholesky_destroy(c);
  return ok;
}

int main(void) {
  const int version_ok = strcmp(gab_version(), GAB_VERSION_STRING) == 0;
  const int coded = round_trip();
  const int solved = solve_and_update();
  return version_ok && coded && solved ? 0 : 1;
}
