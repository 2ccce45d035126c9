// gab factor (its options: commands.cpp)
// Orders, analyzes, factors and solves (3 right-hand sides) the benchmark
// matrix of IN, reporting the median time of each phase over R runs.
#include <cmath>
#include <cstdio>

#include "benchmark_system.h"
#include "cli.h"
#include "commands.h"
#include "gab/sparse/amd.h"
#include "gab/sparse/cholesky.h"
#include "gab/sparse/nested_dissection.h"

namespace gab {
namespace cli {

int run_factor(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {"--ordering", "--anchors", "--repeat", "--threads"}, {"--json"})) {
    return usage_error("factor", args.error());
  }
  if (args.positionals().size() != 1) return usage_error("factor", "expected one input file");
  // One thread by default: the factorization figures compare with
  // single-threaded peers.
  int64_t anchors = 100, repeat = 5, threads = 1;
  if (!args.get_int("--anchors", 1, INT32_MAX, &anchors) || !args.get_int("--repeat", 1, 1000, &repeat) ||
      !args.get_int("--threads", 1, kMaxFactorThreads, &threads)) {
    return usage_error("factor", args.error());
  }
  Ordering ordering = Ordering::kAmd;
  if (!args.get_ordering(kBenchmarkOrderings, Ordering::kAmd, &ordering)) return usage_error("factor", args.error());
  const bool json = args.has("--json");
  const std::string& path = args.positionals()[0];

  BenchmarkSystem sys;
  Status status = load_benchmark_system(path, static_cast<int32_t>(anchors), &sys);
  if (!status.ok()) return fail(status.message());
  warn_read_notes(path, sys.read_notes);
  const CscMatrix& a = sys.lower;
  const int32_t n = a.ncols;

  std::vector<double> order_s, symbolic_s, factor_s, solve_s;
  std::vector<int32_t> perm;
  Cholesky chol;
  std::vector<double> x;
  for (int64_t r = 0; r < repeat; ++r) {
    double t0 = now_seconds();
    if (ordering != Ordering::kNatural) {
      NestedDissectionOptions nd;
      nd.threads = static_cast<int32_t>(threads);  // the same permutation for any count
      status = ordering == Ordering::kAmd ? amd_order(a, &perm) : nested_dissection_order(a, &perm, nd);
      if (!status.ok()) return fail(path + ": ordering: " + status.message());
    } else {
      perm.resize(n);
      for (int32_t i = 0; i < n; ++i) perm[i] = i;
    }
    double t1 = now_seconds();
    AnalyzeOptions options;
    options.ordering = Ordering::kGiven;
    options.given_perm = perm;
    options.threads = static_cast<int32_t>(threads);
    status = chol.analyze(a, options);
    if (!status.ok()) return fail(path + ": " + status.message());
    double t2 = now_seconds();
    status = chol.factorize(a);
    if (!status.ok()) return fail(path + ": " + status.message());
    x = sys.rhs;
    double t3 = now_seconds();
    status = chol.solve(x.data(), 3, n);
    if (!status.ok()) return fail(path + ": " + status.message());
    double t4 = now_seconds();
    order_s.push_back(t1 - t0);
    symbolic_s.push_back(t2 - t1);
    factor_s.push_back(t3 - t2);
    solve_s.push_back(t4 - t3);
  }

  // Relative residual ||A x - b|| / ||b|| over the three right-hand sides.
  double num = 0.0, den = 0.0;
  std::vector<double> ax(n);
  for (int c = 0; c < 3; ++c) {
    const double* xc = x.data() + static_cast<size_t>(c) * n;
    const double* bc = sys.rhs.data() + static_cast<size_t>(c) * n;
    symmetric_lower_matvec(a, xc, ax.data());
    for (int32_t i = 0; i < n; ++i) {
      num += (ax[i] - bc[i]) * (ax[i] - bc[i]);
      den += bc[i] * bc[i];
    }
  }
  const double residual = den > 0 ? std::sqrt(num / den) : std::sqrt(num);
  const SymbolicFactor& f = chol.symbolic();
  const double factor_median = median(factor_s);

  JsonObject out;
  out.add("n", static_cast<int64_t>(n));
  out.add("nnz_A", a.nnz());
  out.add("nnz_L", f.nnz_L);
  out.add("flops", f.flops);
  out.add("supernodes", static_cast<int64_t>(f.num_supernodes));
  out.add("etree_height", static_cast<int64_t>(f.etree.height()));
  out.add("order_s", median(order_s));
  out.add("symbolic_s", median(symbolic_s));
  out.add("factor_s", factor_median);
  out.add("solve_s", median(solve_s));
  out.add("gflops", factor_median > 0 ? f.flops / factor_median * 1e-9 : 0.0);
  out.add("residual", residual);
  out.add("ordering", std::string(ordering_name(ordering)));
  out.add("stored_L", f.stored_L);
  out.add("simd", std::string(chol.simd_level()));
  out.add("repeat", repeat);
  out.add("threads", threads);
  if (json) {
    std::printf("%s\n", out.str().c_str());
  } else {
    std::printf("%s: n = %d, nnz(A) = %lld, nnz(L) = %lld (%d supernodes, etree height %d)\n",
                path.c_str(), n, static_cast<long long>(a.nnz()), static_cast<long long>(f.nnz_L),
                f.num_supernodes, f.etree.height());
    std::printf("order %.4f s, symbolic %.4f s, factor %.4f s (%.1f GFLOP/s, %s, %lld thread%s), "
                "solve x3 %.4f s\n",
                median(order_s), median(symbolic_s), factor_median,
                factor_median > 0 ? f.flops / factor_median * 1e-9 : 0.0,
                chol.simd_level(), static_cast<long long>(threads),
                threads == 1 ? "" : "s", median(solve_s));
    std::printf("relative residual %.3g (median of %lld runs)\n", residual, static_cast<long long>(repeat));
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
