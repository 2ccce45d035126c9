// gab study (its options: commands.cpp)
// Factors each input's benchmark matrix, then adds U anchors by the
// benchmark update rule (v_t = t * 2654435761 mod n, skipping anchored
// vertices) through the Givens updater, B at a time, and reports what every
// update cost against nnz(L), plus the drift from a fresh factorization.
// --threads (default 1, the figure to set beside single-threaded peers) is
// what the Cholesky gets: the factorization and the solves (the updates run
// on the calling thread). --ordering takes a comma list: each input is
// studied under each ordering, and the growth of the touched entries with n
// is fitted per ordering. With nd, each update is also set beside the
// separator bound computed from the dissection's own separators
// (separator_update_bounds, nested_dissection.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "benchmark_system.h"
#include "cli.h"
#include "commands.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/sparse/cholesky.h"
#include "gab/sparse/nested_dissection.h"
#include "svg_plot.h"

namespace gab {
namespace cli {

namespace {

struct UpdateRecord {
  int64_t first_update;  // 1-based number of the batch's first anchor
  int32_t vertex;        // its vertex
  int32_t count;         // anchors in the batch
  UpdateStats stats;
  double seconds;
  int64_t separator_bound;  // sum of the batch's anchors' separator bounds (-1: no separator tree)
};

struct StudyResult {
  std::string input;
  std::string ordering;
  int32_t n = 0;
  int64_t nnz_L = 0;
  // The same updates measured on the true (simplicial) structure: the
  // elimination-tree path and the nonzeros of L on it, which is what a
  // simplicial updater touches and what the separator bound speaks of.
  double true_path_avg = 0.0, true_touched_avg = 0.0;
  double factor_s = 0.0, solve1_s = 0.0, drift = 0.0;
  // Average over the anchors of separator_update_bounds (nd only): a bound on
  // true_touched_avg.
  bool has_bound = false;
  double separator_bound_avg = 0.0;
  bool diagonal_positive = true;
  std::vector<UpdateRecord> records;
};

// `warn`: print what the reader left out (once per input, not per ordering).
Status study_one(const std::string& path, Ordering ordering, int64_t updates,
                 int64_t batch, int64_t anchors, int64_t subdivide, int64_t threads,
                 bool warn, StudyResult* out) {
  BenchmarkSystem sys;
  GAB_RETURN_IF_ERROR(load_benchmark_system(path, static_cast<int32_t>(anchors), &sys,
                                            static_cast<int>(subdivide)));
  if (warn) warn_read_notes(path, sys.read_notes);
  CscMatrix a = sys.lower;
  const int32_t n = a.ncols;
  AnalyzeOptions options;
  options.ordering = ordering;
  options.threads = static_cast<int32_t>(threads);
  // Nested dissection is run here (as analyze would run it: default options,
  // the factorization's threads, the same permutation for any count) to
  // keep its separator tree for the bound.
  std::vector<int64_t> bound;
  if (ordering == Ordering::kNestedDissection) {
    std::vector<int32_t> perm;
    SeparatorTree tree;
    NestedDissectionOptions nd;
    nd.threads = static_cast<int32_t>(threads);
    GAB_RETURN_IF_ERROR(nested_dissection_order(a, &perm, nd, &tree));
    GAB_RETURN_IF_ERROR(separator_update_bounds(tree, perm, &bound));
    options.ordering = Ordering::kGiven;
    options.given_perm = std::move(perm);
  }
  Cholesky chol;
  GAB_RETURN_IF_ERROR(chol.analyze(a, options));
  double t0 = now_seconds();
  GAB_RETURN_IF_ERROR(chol.factorize(a));
  out->factor_s = now_seconds() - t0;
  {
    // One warm 1-rhs solve: the paper compares an update with it.
    std::vector<double> x(sys.rhs.begin(), sys.rhs.begin() + n);
    GAB_RETURN_IF_ERROR(chol.solve(x.data(), 1, n));
    x.assign(sys.rhs.begin(), sys.rhs.begin() + n);
    t0 = now_seconds();
    GAB_RETURN_IF_ERROR(chol.solve(x.data(), 1, n));
    out->solve1_s = now_seconds() - t0;
  }
  out->input = path;
  out->ordering = ordering_name(ordering);
  out->n = n;
  out->nnz_L = chol.symbolic().nnz_L;

  const std::vector<int32_t> seq = benchmark_update_sequence(n, sys.anchors, updates);
  {
    const SymbolicFactor& f = chol.symbolic();
    for (int32_t v : seq) {
      for (int32_t c = f.inverse_perm[v]; c != -1; c = f.etree.parent[c]) {
        out->true_path_avg += 1.0;
        out->true_touched_avg += f.column_counts[c];
      }
    }
    if (!seq.empty()) {
      out->true_path_avg /= static_cast<double>(seq.size());
      out->true_touched_avg /= static_cast<double>(seq.size());
    }
    out->has_bound = !bound.empty();
    if (out->has_bound && !seq.empty()) {
      for (int32_t v : seq) out->separator_bound_avg += static_cast<double>(bound[v]);
      out->separator_bound_avg /= static_cast<double>(seq.size());
    }
  }
  GAB_RETURN_IF_ERROR(chol.prepare_updates());  // not inside the first update's time
  for (size_t u = 0; u < seq.size(); u += static_cast<size_t>(batch)) {
    const int32_t count = static_cast<int32_t>(std::min<size_t>(batch, seq.size() - u));
    UpdateRecord rec;
    rec.first_update = static_cast<int64_t>(u) + 1;
    rec.vertex = seq[u];
    rec.count = count;
    rec.separator_bound = bound.empty() ? -1 : 0;
    for (int32_t k = 0; k < count && !bound.empty(); ++k) rec.separator_bound += bound[seq[u + k]];
    t0 = now_seconds();
    Status s = count == 1 ? chol.add_anchor(seq[u], 1.0, &rec.stats)
                          : chol.add_anchors(seq.data() + u, count, 1.0, &rec.stats);
    rec.seconds = now_seconds() - t0;
    if (!s.ok()) return s;
    out->records.push_back(rec);
  }

  // Drift: the updated factor's solution against a fresh factorization of
  // the updated matrix, for three smooth solutions.
  for (int32_t v : seq) {
    for (int32_t p = a.colptr[v]; p < a.colptr[v + 1]; ++p) {
      if (a.rowind[p] == v) a.values[p] += 1.0;
    }
  }
  std::vector<double> xt(static_cast<size_t>(n) * 3), b(xt.size());
  for (int r = 0; r < 3; ++r) {
    for (int32_t i = 0; i < n; ++i) xt[i + static_cast<size_t>(r) * n] = std::cos(0.001 * i * (r + 1));
    symmetric_lower_matvec(a, xt.data() + static_cast<size_t>(r) * n, b.data() + static_cast<size_t>(r) * n);
  }
  std::vector<double> xu = b, xf = b;
  GAB_RETURN_IF_ERROR(chol.solve(xu.data(), 3, n));
  Cholesky fresh;
  AnalyzeOptions same;
  same.ordering = Ordering::kGiven;
  same.given_perm = chol.symbolic().perm;
  GAB_RETURN_IF_ERROR(fresh.analyze(a, same));
  GAB_RETURN_IF_ERROR(fresh.factorize(a));
  GAB_RETURN_IF_ERROR(fresh.solve(xf.data(), 3, n));
  double num = 0.0, den = 0.0;
  for (size_t i = 0; i < xu.size(); ++i) {
    num += (xu[i] - xf[i]) * (xu[i] - xf[i]);
    den += xf[i] * xf[i];
  }
  out->drift = den > 0 ? std::sqrt(num / den) : std::sqrt(num);
  const SymbolicFactor& f = chol.symbolic();
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    const double* block = chol.values() + f.value_ptr[s];
    for (int32_t c = 0; c < f.cols(s); ++c) {
      if (!(block[static_cast<int64_t>(c) * f.rows(s) + c] > 0.0)) out->diagonal_positive = false;
    }
  }
  return Status::Ok();
}

JsonObject summary(const StudyResult& r, int64_t batch, int64_t threads) {
  int64_t anchors = 0, path_max = 0, touched_max = 0;
  double path_sum = 0, touched_sum = 0, super_sum = 0, flops_sum = 0, time_sum = 0, time_max = 0;
  std::vector<double> per_anchor;
  for (const UpdateRecord& u : r.records) {
    anchors += u.count;
    path_sum += u.stats.path_columns;
    super_sum += u.stats.path_supernodes;
    touched_sum += static_cast<double>(u.stats.touched);
    flops_sum += u.stats.flops;
    time_sum += u.seconds;
    path_max = std::max<int64_t>(path_max, u.stats.path_columns);
    touched_max = std::max<int64_t>(touched_max, u.stats.touched);
    time_max = std::max(time_max, u.seconds / u.count);
    per_anchor.push_back(u.seconds / u.count);
  }
  const double per = anchors > 0 ? 1.0 / static_cast<double>(anchors) : 0.0;
  const double nb = r.records.empty() ? 0.0 : 1.0 / static_cast<double>(r.records.size());
  JsonObject j;
  j.add("n", static_cast<int64_t>(r.n));
  j.add("nnz_L", r.nnz_L);
  j.add("updates", anchors);
  // Path and touched figures are per update call (per batch when B > 1).
  j.add("path_len_avg", path_sum * nb);
  j.add("path_len_max", path_max);
  j.add("touched_avg", touched_sum * nb);
  j.add("touched_max", touched_max);
  j.add("update_s_avg", time_sum * per);
  j.add("update_s_median", median(per_anchor));
  j.add("update_s_max", time_max);
  j.add("factor_s", r.factor_s);
  j.add("drift", r.drift);
  j.add("input", r.input);
  j.add("batch", batch);
  j.add("threads", threads);
  j.add("ordering", r.ordering);
  // Per anchor, as true_touched_avg (which it bounds); null without a separator tree.
  if (r.has_bound) {
    j.add("separator_bound_avg", r.separator_bound_avg);
  } else {
    j.add_null("separator_bound_avg");
  }
  j.add("path_supernodes_avg", super_sum * nb);
  j.add("flops_avg", flops_sum * nb);
  j.add("solve1_s", r.solve1_s);
  j.add("true_path_len_avg", r.true_path_avg);
  j.add("true_touched_avg", r.true_touched_avg);
  // Factor bytes read and written per second while updating.
  j.add("update_gbytes_per_s", time_sum > 0 ? touched_sum * 16.0 / time_sum * 1e-9 : 0.0);
  j.add_bool("diagonal_positive", r.diagonal_positive);
  return j;
}

std::string path_name(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

std::string csv(const std::vector<StudyResult>& results) {
  // The original columns first, then the ordering and the batch's separator
  // bound (empty without a separator tree).
  std::string out =
      "input,update,vertex,anchors,path_columns,path_supernodes,touched,flops,seconds,ordering,separator_bound\n";
  char buf[640];
  for (const StudyResult& r : results) {
    for (const UpdateRecord& u : r.records) {
      const std::string bound = u.separator_bound < 0 ? "" : std::to_string(u.separator_bound);
      std::snprintf(buf, sizeof(buf), "%s,%lld,%d,%d,%d,%d,%lld,%.0f,%.9f,%s,%s\n", r.input.c_str(),
                    static_cast<long long>(u.first_update), u.vertex, u.count, u.stats.path_columns,
                    u.stats.path_supernodes, static_cast<long long>(u.stats.touched), u.stats.flops,
                    u.seconds, r.ordering.c_str(), bound.c_str());
      out += buf;
    }
  }
  return out;
}

double average_touched(const StudyResult& r) {
  double sum = 0;
  for (const UpdateRecord& u : r.records) sum += static_cast<double>(u.stats.touched);
  return r.records.empty() ? 0.0 : sum / static_cast<double>(r.records.size());
}

// Least-squares fit of log(touched per update) = exponent log(n) + c over one
// ordering's inputs: the growth exponent (the separator bound's is 1 on
// surfaces of bounded genus).
struct Growth {
  std::string ordering;
  std::vector<std::pair<double, double>> points;  // (n, average touched), increasing n
  bool fitted = false;                            // two or more distinct n
  double exponent = 0.0, log_constant = 0.0;
};

std::vector<Growth> growth_by_ordering(const std::vector<StudyResult>& results,
                                       const std::vector<std::string>& orderings) {
  std::vector<Growth> out;
  for (const std::string& ordering : orderings) {
    Growth g;
    g.ordering = ordering;
    for (const StudyResult& r : results) {
      const double touched = average_touched(r);
      if (r.ordering == ordering && r.n > 0 && touched > 0) g.points.emplace_back(r.n, touched);
    }
    std::sort(g.points.begin(), g.points.end());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& p : g.points) {
      const double x = std::log(p.first), y = std::log(p.second);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double m = static_cast<double>(g.points.size());
    const double denominator = m * sxx - sx * sx;
    if (g.points.size() >= 2 && denominator > 1e-12 * m * sxx) {
      g.fitted = true;
      g.exponent = (m * sxy - sx * sy) / denominator;
      g.log_constant = (sy - g.exponent * sx) / m;
    }
    out.push_back(std::move(g));
  }
  return out;
}

std::string svg(const std::vector<StudyResult>& results, const std::vector<Growth>& growth) {
  static const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  Chart touched{"Entries of L touched per update", "update", "touched nonzeros", {}};
  Chart seconds{"Time per update", "update", "microseconds", {}};
  for (size_t i = 0; i < results.size(); ++i) {
    const StudyResult& r = results[i];
    const std::string color = kColors[i % 6];
    const std::string name = r.input.substr(r.input.find_last_of('/') + 1) + " " + r.ordering;
    Series st{name + " (nnz(L) = " + std::to_string(r.nnz_L) + ")", color, {}, {}, false, false};
    Series ss{name, color, {}, {}, false, false};
    Series sb{name + ": separator bound", color, {}, {}, false, true};
    for (const UpdateRecord& u : r.records) {
      st.x.push_back(static_cast<double>(u.first_update));
      st.y.push_back(static_cast<double>(u.stats.touched));
      ss.x.push_back(static_cast<double>(u.first_update));
      ss.y.push_back(u.seconds * 1e6);
      if (u.separator_bound >= 0) {
        sb.x.push_back(static_cast<double>(u.first_update));
        sb.y.push_back(static_cast<double>(u.separator_bound));
      }
    }
    touched.series.push_back(st);
    if (!sb.x.empty()) touched.series.push_back(sb);
    seconds.series.push_back(ss);
  }
  std::vector<Chart> charts = {touched, seconds};
  // Growth against n on log-log axes, each ordering with its fitted exponent,
  // beside the O(n) separator bound (bounded genus) drawn through the
  // smallest input of the first fitted ordering.
  Chart chart{"Average touched entries per update against n", "n", "average touched nonzeros", {}, true};
  for (size_t i = 0; i < growth.size(); ++i) {
    const Growth& g = growth[i];
    if (!g.fitted) continue;
    const std::string color = kColors[i % 6];
    char exponent[64];
    std::snprintf(exponent, sizeof(exponent), ": touched ~ n^%.2f", g.exponent);
    Series measured{g.ordering + exponent, color, {}, {}, true, false};
    Series line{"", color, {}, {}, false, false};
    Series fit{"", color, {}, {}, false, true};
    for (const auto& p : g.points) {
      measured.x.push_back(p.first);
      measured.y.push_back(p.second);
      fit.x.push_back(p.first);
      fit.y.push_back(std::exp(g.log_constant + g.exponent * std::log(p.first)));
    }
    line.x = measured.x;
    line.y = measured.y;
    chart.series.push_back(measured);
    chart.series.push_back(line);
    chart.series.push_back(fit);
    if (chart.series.size() == 3) {
      Series bound{"O(n) through the smallest input", "#888", {}, {}, false, true};
      for (const auto& p : g.points) {
        bound.x.push_back(p.first);
        bound.y.push_back(g.points[0].second * p.first / g.points[0].first);
      }
      chart.series.push_back(bound);
    }
  }
  if (!chart.series.empty()) charts.push_back(chart);
  return render_svg(charts);
}

}  // namespace

int run_study(int argc, char** argv) {
  Args args;
  if (!args.parse(argc, argv, {"--ordering", "--updates", "--batch", "--anchors", "--subdivide", "--threads",
                                    "--csv", "--svg"},
                  {"--json"})) {
    return usage_error("study", args.error());
  }
  if (args.positionals().empty()) return usage_error("study", "expected at least one input file");
  int64_t updates = 1000, batch = 1, anchors = 100, subdivide = 0, threads = 1;
  if (!args.get_int("--updates", 0, INT32_MAX, &updates) || !args.get_int("--batch", 1, 4096, &batch) ||
      !args.get_int("--anchors", 1, INT32_MAX, &anchors) || !args.get_int("--subdivide", 0, 6, &subdivide) ||
      !args.get_int("--threads", 1, kMaxFactorThreads, &threads)) {
    return usage_error("study", args.error());
  }
  std::vector<Ordering> orderings;
  if (!args.get_orderings(kBenchmarkOrderings, Ordering::kAmd, &orderings)) return usage_error("study", args.error());
  const bool json = args.has("--json");
  std::vector<StudyResult> results;
  for (const std::string& path : args.positionals()) {
    for (const Ordering ordering : orderings) {
      StudyResult r;
      const Status s =
          study_one(path, ordering, updates, batch, anchors, subdivide, threads, ordering == orderings.front(), &r);
      if (!s.ok()) return fail(s.message());
      const JsonObject j = summary(r, batch, threads);
      if (json) {
        std::printf("%s\n", j.str().c_str());
      } else {
        double touched = 0, seconds = 0, path = 0;
        int64_t count = 0;
        for (const UpdateRecord& u : r.records) {
          touched += static_cast<double>(u.stats.touched);
          seconds += u.seconds;
          path += u.stats.path_columns;
          count += u.count;
        }
        const double calls = r.records.empty() ? 1.0 : static_cast<double>(r.records.size());
        std::printf("%s (%s): n = %d, nnz(L) = %lld, factor %.4f s, 1-rhs solve %.4f s\n",
                    path_name(r.input).c_str(), r.ordering.c_str(), r.n, static_cast<long long>(r.nnz_L),
                    r.factor_s, r.solve1_s);
        std::printf("  %lld anchors in batches of %lld: path %.0f columns, %.0f entries touched (%.3f%% of nnz(L)) per call;"
                    " %.1f us per anchor; drift %.2g\n",
                    static_cast<long long>(count), static_cast<long long>(batch), path / calls, touched / calls,
                    100.0 * touched / calls / static_cast<double>(r.nnz_L), count ? seconds / count * 1e6 : 0.0,
                    r.drift);
        if (r.has_bound) {
          std::printf("  true path: %.0f entries per anchor; separator bound %.0f\n", r.true_touched_avg,
                      r.separator_bound_avg);
        }
      }
      std::fflush(stdout);
      results.push_back(std::move(r));
    }
  }
  // The growth exponents: with the results on stdout, beside them; with
  // --json on stderr (stdout holds only the JSON objects).
  std::vector<std::string> ordering_names;
  for (const Ordering o : orderings) ordering_names.push_back(ordering_name(o));
  const std::vector<Growth> growth = growth_by_ordering(results, ordering_names);
  for (const Growth& g : growth) {
    if (!g.fitted) continue;
    std::fprintf(json ? stderr : stdout, "%s: touched entries per update grow as n^%.3f (fitted over %zu inputs)\n",
                 g.ordering.c_str(), g.exponent, g.points.size());
  }
  for (const auto& [option, text] : {std::pair<const char*, std::string>("--csv", csv(results)),
                                     std::pair<const char*, std::string>("--svg", svg(results, growth))}) {
    if (!args.has(option)) continue;
    const Status written = write_output_file(args.get(option), text);
    if (!written.ok()) return fail(written.message());
  }
  return kExitOk;
}

}  // namespace cli
}  // namespace gab
