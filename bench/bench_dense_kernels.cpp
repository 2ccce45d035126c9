// Dense kernels at the shapes a supernodal Cholesky of a mesh normal matrix
// meets: per supernode of k columns and m rows, POTRF on k x k, TRSM on
// (m-k) x k, SYRK of the (m-k) x (m-k) update with inner dimension k (most of
// the flops: k = 16..300, m-k = 50..1500), and a great many tiny calls
// (k, m <= 8) where call overhead is the cost. Every SIMD level this CPU
// supports is timed; GFLOPS counters are rates over CPU time.
//
// With -DGAB_HAVE_OPENBLAS (and -lopenblas, OPENBLAS_NUM_THREADS=1) the same
// shapes are timed with OpenBLAS's dsyrk/dgemm/dtrsm/dpotrf for comparison,
// e.g. configure with
//   -DGAB_BUILD_BENCH=ON -DCMAKE_CXX_FLAGS=-DGAB_HAVE_OPENBLAS
//   -DCMAKE_EXE_LINKER_FLAGS=-lopenblas
// The project itself never needs OpenBLAS.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "gab/sparse/dense_kernels.h"

#ifdef GAB_HAVE_OPENBLAS
#include <cblas.h>
extern "C" void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info);
#endif

namespace {

using gab::DenseKernels;
using gab::SimdLevel;

// One implementation under test: a gab level or OpenBLAS behind the same
// function-pointer shape.
struct Impl {
  std::string name;
  DenseKernels k;
};

#ifdef GAB_HAVE_OPENBLAS
int32_t blas_potrf(int32_t n, double* a, int32_t lda) {
  int info = 0;
  dpotrf_("L", &n, a, &lda, &info);
  return info == 0 ? -1 : info - 1;
}
void blas_trsm(int32_t m, int32_t n, const double* l, int32_t ldl, double* b, int32_t ldb) {
  cblas_dtrsm(CblasColMajor, CblasRight, CblasLower, CblasTrans, CblasNonUnit, m, n, 1.0, l, ldl, b,
              ldb);
}
void blas_syrk(int32_t n, int32_t k, const double* a, int32_t lda, double* c, int32_t ldc) {
  cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, n, k, -1.0, a, lda, 1.0, c, ldc);
}
void blas_gemm(int32_t m, int32_t n, int32_t k, const double* a, int32_t lda, const double* b,
               int32_t ldb, double* c, int32_t ldc) {
  cblas_dgemm(CblasColMajor, CblasNoTrans, CblasTrans, m, n, k, -1.0, a, lda, b, ldb, 1.0, c, ldc);
}
#endif

std::vector<Impl> implementations() {
  std::vector<Impl> out;
  for (SimdLevel level : {SimdLevel::kScalar, SimdLevel::kAvx2, SimdLevel::kAvx512}) {
    const DenseKernels& k = gab::dense_kernels(level);
    if (k.level == level) out.push_back({gab::simd_level_name(level), k});
  }
#ifdef GAB_HAVE_OPENBLAS
  out.push_back(
      {"openblas", {SimdLevel::kScalar, &blas_potrf, &blas_trsm, &blas_syrk, &blas_gemm}});
#endif
  return out;
}

std::vector<double> random_values(size_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(count);
  for (double& x : v) x = u(rng);
  return v;
}

// C -= A A^T with A the (m-k) x k panel below a supernode's diagonal block,
// so lda = m as in the factorization. Repeated updates only drift C.
void syrk(benchmark::State& state, DenseKernels k, int32_t n, int32_t kk) {
  const int32_t lda = n + kk;
  const std::vector<double> a = random_values(static_cast<size_t>(lda) * kk, 1);
  std::vector<double> c = random_values(static_cast<size_t>(n) * n, 2);
  for (auto _ : state) {
    k.syrk_lower_sub(n, kk, a.data() + kk, lda, c.data(), n);
    benchmark::ClobberMemory();
  }
  state.counters["GFLOPS"] =
      benchmark::Counter(1e-9 * n * (n + 1.0) * kk, benchmark::Counter::kIsIterationInvariantRate);
}

void gemm(benchmark::State& state, DenseKernels k, int32_t m, int32_t n, int32_t kk) {
  const int32_t lda = m + 3;
  const int32_t ldb = n + 5;
  const std::vector<double> a = random_values(static_cast<size_t>(lda) * kk, 3);
  const std::vector<double> b = random_values(static_cast<size_t>(ldb) * kk, 4);
  std::vector<double> c = random_values(static_cast<size_t>(m) * n, 5);
  for (auto _ : state) {
    k.gemm_nt_sub(m, n, kk, a.data(), lda, b.data(), ldb, c.data(), m);
    benchmark::ClobberMemory();
  }
  state.counters["GFLOPS"] =
      benchmark::Counter(2e-9 * m * n * kk, benchmark::Counter::kIsIterationInvariantRate);
}

// Copies of the input needed so one timed batch is long enough for the
// pause/resume around the restore (about a microsecond) not to matter.
int32_t batch_for(size_t doubles_per_call) {
  return static_cast<int32_t>(std::max<size_t>(1, (size_t{1} << 16) / doubles_per_call));
}

// potrf of B B^T + n I; a batch of copies is factored per timed iteration
// and restored outside the timed region.
void potrf(benchmark::State& state, DenseKernels k, int32_t n) {
  const size_t nn = static_cast<size_t>(n) * n;
  const std::vector<double> b = random_values(nn, 6);
  std::vector<double> a(nn, 0.0);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = j; i < n; ++i) {
      double s = i == j ? n : 0.0;
      for (int32_t p = 0; p < n; ++p)
        s += b[i + static_cast<size_t>(p) * n] * b[j + static_cast<size_t>(p) * n];
      a[i + static_cast<size_t>(j) * n] = s;
    }
  }
  const int32_t batch = batch_for(nn);
  std::vector<double> work(nn * batch);
  for (auto _ : state) {
    state.PauseTiming();
    for (int32_t t = 0; t < batch; ++t) std::memcpy(&work[nn * t], a.data(), nn * sizeof(double));
    state.ResumeTiming();
    for (int32_t t = 0; t < batch; ++t) benchmark::DoNotOptimize(k.potrf(n, &work[nn * t], n));
    benchmark::ClobberMemory();
  }
  state.counters["GFLOPS"] = benchmark::Counter(1e-9 * batch * n * n * (n / 3.0),
                                                benchmark::Counter::kIsIterationInvariantRate);
  state.counters["per_call"] = benchmark::Counter(
      batch, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// B := B L^{-T} with a well-conditioned L, batched like potrf.
void trsm(benchmark::State& state, DenseKernels k, int32_t m, int32_t n) {
  std::vector<double> l = random_values(static_cast<size_t>(n) * n, 7);
  for (int32_t j = 0; j < n; ++j) {
    l[j + static_cast<size_t>(j) * n] = 2.0 + l[j + static_cast<size_t>(j) * n];
    for (int32_t i = j + 1; i < n; ++i) l[i + static_cast<size_t>(j) * n] /= n;
  }
  const size_t mn = static_cast<size_t>(m) * n;
  const std::vector<double> b = random_values(mn, 8);
  const int32_t batch = batch_for(mn);
  std::vector<double> work(mn * batch);
  for (auto _ : state) {
    state.PauseTiming();
    for (int32_t t = 0; t < batch; ++t) std::memcpy(&work[mn * t], b.data(), mn * sizeof(double));
    state.ResumeTiming();
    for (int32_t t = 0; t < batch; ++t)
      k.trsm_right_lower_trans(m, n, l.data(), n, &work[mn * t], m);
    benchmark::ClobberMemory();
  }
  state.counters["GFLOPS"] =
      benchmark::Counter(1e-9 * batch * m * n * n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["per_call"] = benchmark::Counter(
      batch, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Tiny calls, timed per call without pausing (pausing costs more than the
// call). POTRF and TRSM run on the identity, which they map to itself, so
// every call sees the same input and does the full work: none of the kernels
// branch on values except on a failing pivot.
void tiny(benchmark::State& state, DenseKernels k, int32_t n) {
  constexpr int32_t kLd = 8;
  std::vector<double> eye(kLd * kLd, 0.0);
  for (int32_t j = 0; j < n; ++j) eye[j + j * kLd] = 1.0;
  std::vector<double> ident = eye;
  const std::vector<double> a = random_values(kLd * kLd, 9);
  std::vector<double> b = random_values(kLd * kLd, 10);
  std::vector<double> c = random_values(kLd * kLd, 11);
  for (auto _ : state) {
    benchmark::DoNotOptimize(k.potrf(n, ident.data(), kLd));
    k.trsm_right_lower_trans(kLd, n, eye.data(), kLd, b.data(), kLd);
    k.syrk_lower_sub(n, n, a.data(), kLd, c.data(), kLd);
    k.gemm_nt_sub(n, n, n, a.data(), kLd, a.data(), kLd, c.data(), kLd);
    benchmark::ClobberMemory();
  }
}

// One kernel at a time, for per-kernel nanoseconds of the tiny calls.
void tiny_potrf(benchmark::State& state, DenseKernels k, int32_t n) {
  std::vector<double> ident(64, 0.0);
  for (int32_t j = 0; j < n; ++j) ident[j + j * 8] = 1.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(k.potrf(n, ident.data(), 8));
    benchmark::ClobberMemory();
  }
}
void tiny_trsm(benchmark::State& state, DenseKernels k, int32_t n) {
  std::vector<double> eye(64, 0.0);
  for (int32_t j = 0; j < n; ++j) eye[j + j * 8] = 1.0;
  std::vector<double> b = random_values(64, 12);
  for (auto _ : state) {
    k.trsm_right_lower_trans(8, n, eye.data(), 8, b.data(), 8);
    benchmark::ClobberMemory();
  }
}
void tiny_syrk(benchmark::State& state, DenseKernels k, int32_t n) {
  const std::vector<double> a = random_values(64, 13);
  std::vector<double> c = random_values(64, 14);
  for (auto _ : state) {
    k.syrk_lower_sub(n, n, a.data(), 8, c.data(), 8);
    benchmark::ClobberMemory();
  }
}
void tiny_gemm(benchmark::State& state, DenseKernels k, int32_t n) {
  const std::vector<double> a = random_values(64, 15);
  std::vector<double> c = random_values(64, 16);
  for (auto _ : state) {
    k.gemm_nt_sub(n, n, n, a.data(), 8, a.data(), 8, c.data(), 8);
    benchmark::ClobberMemory();
  }
}

void register_all() {
  for (const Impl& impl : implementations()) {
    const DenseKernels k = impl.k;
    const std::string& name = impl.name;
    for (const auto& nk : std::vector<std::pair<int32_t, int32_t>>{{64, 16},
                                                                   {256, 64},
                                                                   {512, 128},
                                                                   {1024, 256},
                                                                   {1500, 300},
                                                                   {100, 32},
                                                                   {200, 100},
                                                                   {800, 200},
                                                                   {1500, 16},
                                                                   {50, 300}}) {
      const std::string label =
          "syrk/" + name + "/n:" + std::to_string(nk.first) + "/k:" + std::to_string(nk.second);
      benchmark::RegisterBenchmark(label.c_str(), syrk, k, nk.first, nk.second);
    }
    for (const auto& s : std::vector<std::vector<int32_t>>{{64, 64, 16},
                                                           {256, 256, 64},
                                                           {512, 512, 128},
                                                           {1024, 1024, 256},
                                                           {1500, 1500, 300},
                                                           {1500, 150, 150},
                                                           {1500, 8, 300}}) {
      const std::string label = "gemm/" + name + "/m:" + std::to_string(s[0]) +
                                "/n:" + std::to_string(s[1]) + "/k:" + std::to_string(s[2]);
      benchmark::RegisterBenchmark(label.c_str(), gemm, k, s[0], s[1], s[2]);
    }
    for (int32_t n : {16, 64, 128, 256, 500}) {
      const std::string label = "potrf/" + name + "/n:" + std::to_string(n);
      benchmark::RegisterBenchmark(label.c_str(), potrf, k, n);
    }
    for (const auto& mn :
         std::vector<std::pair<int32_t, int32_t>>{{64, 16}, {500, 100}, {1500, 64}, {1500, 300}}) {
      const std::string label =
          "trsm/" + name + "/m:" + std::to_string(mn.first) + "/n:" + std::to_string(mn.second);
      benchmark::RegisterBenchmark(label.c_str(), trsm, k, mn.first, mn.second);
    }
    for (int32_t n : {1, 2, 4, 8}) {
      const std::string suffix = name + "/n:" + std::to_string(n);
      benchmark::RegisterBenchmark(("tiny_all4/" + suffix).c_str(), tiny, k, n);
      benchmark::RegisterBenchmark(("tiny_potrf/" + suffix).c_str(), tiny_potrf, k, n);
      benchmark::RegisterBenchmark(("tiny_trsm_m8/" + suffix).c_str(), tiny_trsm, k, n);
      benchmark::RegisterBenchmark(("tiny_syrk_k=n/" + suffix).c_str(), tiny_syrk, k, n);
      benchmark::RegisterBenchmark(("tiny_gemm_k=n/" + suffix).c_str(), tiny_gemm, k, n);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
