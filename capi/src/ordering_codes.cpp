// gab_ordering_from_name, gab_solver_from_name and the GAB_ORDERING_* and
// GAB_SOLVER_* codes: the names are the engine's and the codec's
// (parse_ordering, parse_solver), the codes the C door's.
#include "ordering_codes.h"

#include <string>

#include "boundary.h"
#include "gab/codec/matrix_ordering.h"
#include "gab/gab.h"

namespace gab {
namespace capi {
namespace {

struct OrderingCode {
  int32_t code;
  Ordering ordering;
};

// The named orderings (parse_ordering's), each with its code; the codec
// takes the first three (codec_takes_ordering).
constexpr OrderingCode kCodes[] = {{GAB_ORDERING_AUTO, Ordering::kAuto},
                                   {GAB_ORDERING_AMD, Ordering::kAmd},
                                   {GAB_ORDERING_ND, Ordering::kNestedDissection},
                                   {GAB_ORDERING_NATURAL, Ordering::kNatural}};

// The solvers, each with its code.
struct SolverCode {
  int32_t code;
  Solver solver;
};
constexpr SolverCode kSolverCodes[] = {{GAB_SOLVER_AUTO, Solver::kAuto},
                                       {GAB_SOLVER_GLOBAL, Solver::kGlobal},
                                       {GAB_SOLVER_ITERATIVE, Solver::kIterative}};

}  // namespace

bool solver_of_code(int32_t code, Solver* solver) {
  for (const SolverCode& row : kSolverCodes) {
    if (row.code == code) {
      *solver = row.solver;
      return true;
    }
  }
  return false;
}

bool ordering_of_code(int32_t code, Ordering* ordering) {
  for (const OrderingCode& row : kCodes) {
    if (row.code == code) {
      *ordering = row.ordering;
      return true;
    }
  }
  return false;
}

Status codec_ordering_of_code(int32_t code, Ordering* ordering) {
  const char* const taken = "GAB_ORDERING_AUTO, GAB_ORDERING_AMD or GAB_ORDERING_ND";
  GAB_RETURN_IF_ERROR(require(ordering_of_code(code, ordering),
                              "options->ordering is " + std::to_string(code) + ": must be " + taken));
  return require(codec_takes_ordering(*ordering), std::string("options->ordering is GAB_ORDERING_NATURAL: the ") +
                                                      "codec's factorizations take " + taken +
                                                      " (natural is for gab_cholesky_create_ex)");
}

int32_t code_of_ordering(Ordering ordering) {
  for (const OrderingCode& row : kCodes) {
    if (row.ordering == ordering) return row.code;
  }
  return -1;
}

int32_t code_of_solver(Solver solver) {
  for (const SolverCode& row : kSolverCodes) {
    if (row.solver == solver) return row.code;
  }
  return -1;
}

}  // namespace capi
}  // namespace gab

extern "C" int gab_ordering_from_name(const char* name) {
  gab::Ordering ordering;
  if (name == nullptr || !gab::parse_ordering(name, &ordering)) return -1;
  return gab::capi::code_of_ordering(ordering);
}

extern "C" int gab_solver_from_name(const char* name) {
  gab::Solver solver;
  if (name == nullptr || !gab::parse_solver(name, &solver)) return -1;
  return gab::capi::code_of_solver(solver);
}
