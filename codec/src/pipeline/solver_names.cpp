#include "gab/codec/gab_format.h"

namespace gab {

const char* solver_name(Solver solver) {
  switch (solver) {
    case Solver::kAuto:
      return "auto";
    case Solver::kGlobal:
      return "global";
    case Solver::kIterative:
      return "iterative";
  }
  return "unknown";
}

Solver solver_of_header(int reconstruction) {
  return reconstruction == kGabReconstructionGlobal ? Solver::kGlobal : Solver::kIterative;
}

bool parse_solver(const std::string& name, Solver* solver) {
  for (Solver s : {Solver::kAuto, Solver::kGlobal, Solver::kIterative}) {
    if (name == solver_name(s)) {
      *solver = s;
      return true;
    }
  }
  return false;
}

}  // namespace gab
