// gab_cholesky_*: the engine's Cholesky (gab/sparse/cholesky.h) behind the C
// door. The handle keeps its own copy of the pattern, the values of the last
// factorization, and the message of its last call (solve and add_anchor have
// no message buffer in their signature).
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "boundary.h"
#include "gab/sparse/cholesky.h"
#include "ordering_codes.h"

struct gab_cholesky {
  gab::CscMatrix lower;  // the pattern, and the values of the last factorize
  gab::Cholesky chol;
  char message[1024] = "";  // of the last call: "" when it succeeded (no allocation to fail)
};

namespace gab {
namespace capi {

namespace {

// The caller's pattern, checked: colptr from 0 and nondecreasing (read
// before rowind, whose length it gives), rows in range and strictly
// increasing (check_csc), the first row of every column its diagonal (so
// nothing above it, and the diagonal a positive definite matrix needs).
Status import_pattern(int32_t n, const int32_t* colptr, const int32_t* rowind, CscMatrix* lower) {
  GAB_RETURN_IF_ERROR(require(n > 0, "n = " + std::to_string(n) + ": must be positive"));
  GAB_RETURN_IF_ERROR(require(colptr != nullptr, "colptr is NULL"));
  GAB_RETURN_IF_ERROR(require(colptr[0] == 0, "colptr[0] = " + std::to_string(colptr[0]) + ": must be 0"));
  for (int32_t j = 0; j < n; ++j) {
    if (colptr[j + 1] < colptr[j]) return invalid("colptr decreases at column " + std::to_string(j));
  }
  GAB_RETURN_IF_ERROR(require(rowind != nullptr, "rowind is NULL"));
  lower->nrows = lower->ncols = n;
  lower->colptr.assign(colptr, colptr + n + 1);
  lower->rowind.assign(rowind, rowind + colptr[n]);
  lower->values.clear();
  GAB_RETURN_IF_ERROR(check_csc(*lower));
  for (int32_t j = 0; j < n; ++j) {
    const int32_t first = colptr[j] < colptr[j + 1] ? rowind[colptr[j]] : n;
    if (first < j) {
      return invalid("column " + std::to_string(j) + ": row " + std::to_string(first) +
                     " is above the diagonal (give the lower triangle)");
    }
    if (first > j) return invalid("column " + std::to_string(j) + " has no diagonal entry");
  }
  return Status::Ok();
}

// The caller's options (NULL: the defaults, gab_cholesky_create's) as the
// engine's analysis options. Any named ordering: the engine has them all.
Status read_options(const gab_cholesky_options* in, AnalyzeOptions* out) {
  gab_cholesky_options o;
  gab_cholesky_options_init(&o, sizeof o);
  if (in != nullptr) {
    GAB_RETURN_IF_ERROR(check_options_size(in, in->size, sizeof o, "gab_cholesky_options_init"));
#define GAB_TAKE(field) take_field(in, in->size, offsetof(gab_cholesky_options, field), &o.field)
    GAB_TAKE(ordering);
    GAB_TAKE(threads);
#undef GAB_TAKE
  }
  GAB_RETURN_IF_ERROR(require(ordering_of_code(o.ordering, &out->ordering),
                              "options->ordering is " + std::to_string(o.ordering) +
                                  ": must be GAB_ORDERING_AMD, GAB_ORDERING_ND, GAB_ORDERING_NATURAL or "
                                  "GAB_ORDERING_AUTO"));
  return options_threads(o.threads, &out->threads);
}

Status factorize(gab_cholesky* c, const double* values) {
  GAB_RETURN_IF_ERROR(require(values != nullptr, "values is NULL"));
  const size_t nnz = c->lower.rowind.size();
  for (size_t k = 0; k < nnz; ++k) {
    if (!std::isfinite(values[k])) return invalid("values[" + std::to_string(k) + "] is not finite");
  }
  c->lower.values.assign(values, values + nnz);
  return c->chol.factorize(c->lower);
}

// Runs a call on the handle and keeps its message there (solve and
// add_anchor have no buffer of their own; factorize has both). Solves and
// updates need a factorization: without one, GAB_E_STATE.
template <class Body>
int on_handle(gab_cholesky* c, const char* function, bool needs_factor, char* message, size_t size, Body&& body) {
  if (c == nullptr) {
    write_message(function, "c is NULL", message, size);
    return GAB_E_INVALID_ARGUMENT;
  }
  int code = GAB_E_STATE;
  if (needs_factor && !c->chol.factorized()) {
    std::snprintf(c->message, sizeof c->message,
                  "%s: no factorization: call gab_cholesky_factorize first (or it failed)", function);
  } else {
    code = guarded(function, c->message, sizeof c->message, body);
  }
  if (message != nullptr && size > 0) std::snprintf(message, size, "%s", c->message);
  return code;
}

// gab_cholesky_create and _ex: the options read, the pattern copied and
// checked, ordered and analyzed, then factorized when values are given.
int create(const char* function, int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
           const gab_cholesky_options* options, gab_cholesky** out, char* message, size_t message_size) {
  return guarded(function, message, message_size, [&]() -> Status {
    if (out != nullptr) *out = nullptr;
    GAB_RETURN_IF_ERROR(require(out != nullptr, "out is NULL"));
    AnalyzeOptions analyze_options;
    GAB_RETURN_IF_ERROR(read_options(options, &analyze_options));
    std::unique_ptr<gab_cholesky> c(new gab_cholesky);
    GAB_RETURN_IF_ERROR(import_pattern(n, colptr, rowind, &c->lower));
    GAB_RETURN_IF_ERROR(c->chol.analyze(c->lower, analyze_options));
    if (values != nullptr) GAB_RETURN_IF_ERROR(factorize(c.get(), values));
    *out = c.release();
    return Status::Ok();
  });
}

}  // namespace

}  // namespace capi
}  // namespace gab

extern "C" void gab_cholesky_options_init(gab_cholesky_options* options, size_t size) {
  gab_cholesky_options o;
  std::memset(&o, 0, sizeof o);
  o.ordering = GAB_ORDERING_AMD;  // gab_cholesky_create's
  o.threads = 1;
  gab::capi::init_options(o, options, size);
}

extern "C" int gab_cholesky_create(int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
                                   gab_cholesky** out, char* message, size_t message_size) {
  return gab::capi::create("gab_cholesky_create", n, colptr, rowind, values, nullptr, out, message, message_size);
}

extern "C" int gab_cholesky_create_ex(int32_t n, const int32_t* colptr, const int32_t* rowind, const double* values,
                                      const gab_cholesky_options* options, gab_cholesky** out, char* message,
                                      size_t message_size) {
  return gab::capi::create("gab_cholesky_create_ex", n, colptr, rowind, values, options, out, message,
                           message_size);
}

extern "C" int64_t gab_cholesky_factor_entries(const gab_cholesky* c) {
  if (c == nullptr) return -1;
  const gab::SymbolicFactor& f = c->chol.symbolic();
  return f.value_ptr.empty() ? 0 : f.value_ptr.back();
}

extern "C" int gab_cholesky_factorize(gab_cholesky* c, const double* values, char* message, size_t message_size) {
  return gab::capi::on_handle(c, "gab_cholesky_factorize", false, message, message_size,
                              [&]() { return gab::capi::factorize(c, values); });
}

extern "C" int gab_cholesky_solve(gab_cholesky* c, double* b, int32_t nrhs) {
  return gab::capi::on_handle(c, "gab_cholesky_solve", true, nullptr, 0, [&]() -> gab::Status {
    GAB_RETURN_IF_ERROR(gab::capi::require(nrhs >= 0, "nrhs = " + std::to_string(nrhs) + ": must not be negative"));
    if (nrhs == 0) return gab::Status::Ok();
    GAB_RETURN_IF_ERROR(gab::capi::require(b != nullptr, "b is NULL"));
    return c->chol.solve(b, nrhs, c->lower.nrows);
  });
}

extern "C" int gab_cholesky_add_anchor(gab_cholesky* c, int32_t j, double w) {
  return gab::capi::on_handle(c, "gab_cholesky_add_anchor", true, nullptr, 0, [&]() -> gab::Status {
    const int32_t n = c->lower.nrows;
    GAB_RETURN_IF_ERROR(gab::capi::require(j >= 0 && j < n, "j = " + std::to_string(j) + " is out of range [0, " +
                                                                 std::to_string(n) + ")"));
    GAB_RETURN_IF_ERROR(gab::capi::require(std::isfinite(w), "w is not finite"));
    return c->chol.add_anchor(j, w);
  });
}

extern "C" const char* gab_cholesky_message(const gab_cholesky* c) {
  return c == nullptr ? "gab_cholesky_message: c is NULL" : c->message;
}

extern "C" void gab_cholesky_destroy(gab_cholesky* c) { delete c; }
