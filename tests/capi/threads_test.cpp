// gab.h's promise: calls on different handles and buffers may run in several
// threads at once. Each thread compresses, decompresses and solves on its
// own data, half of them with two threads of their own inside the library;
// every result must equal the one computed alone, single-threaded,
// beforehand. Run under ASan too (the sanitizer build), and under TSan by
// scripts/tsan-capi.sh.
#include <gtest/gtest.h>

#include <cstring>
#include <thread>
#include <vector>

#include "capi/capi_test_util.h"
#include "common/test_meshes.h"
#include "gab/gab.h"

namespace {

// One thread's work and what it produced.
struct Job {
  gab::Mesh mesh;
  gab::CscMatrix matrix;
  std::vector<uint8_t> file;
  std::vector<double> decoded, coarse, solution;
  int threads = 1;  // inside the library, for compress and decompress
  int failures = 0;
};

void run(Job* job) {
  const gab::Mesh& m = job->mesh;
  unsigned char* file = nullptr;
  size_t size = 0;
  char message[256];
  gab_compress_options compress;
  gab_compress_options_init(&compress, sizeof compress);
  compress.threads = job->threads;
  job->failures += gab_compress_ex(m.positions.data(), m.num_vertices(), m.triangles.data(), m.num_triangles(),
                                   &compress, &file, &size, message, sizeof message) != GAB_OK;
  job->file.assign(file, file + size);
  for (int32_t anchors : {-1, 12}) {
    double* positions = nullptr;
    int32_t* triangles = nullptr;
    int32_t n = 0, t = 0;
    gab_decompress_options decompress;
    gab_decompress_options_init(&decompress, sizeof decompress);
    decompress.max_anchors = anchors;
    decompress.threads = job->threads;
    job->failures += gab_decompress_ex(file, size, &decompress, &positions, &n, &triangles, &t, message,
                                       sizeof message) != GAB_OK;
    (anchors < 0 ? job->decoded : job->coarse).assign(positions, positions + 3 * static_cast<size_t>(n));
    gab_free(positions);
    gab_free(triangles);
  }
  gab_free(file);
  const gab::CscMatrix& a = job->matrix;
  gab_cholesky* c = nullptr;
  job->failures += gab_cholesky_create(a.nrows, a.colptr.data(), a.rowind.data(), a.values.data(), &c, message,
                                       sizeof message) != GAB_OK;
  job->solution.assign(a.nrows, 1.0);
  job->failures += gab_cholesky_add_anchor(c, a.nrows / 2, 2.0) != GAB_OK;
  job->failures += gab_cholesky_solve(c, job->solution.data(), 1) != GAB_OK;
  gab_cholesky_destroy(c);
}

TEST(ThreadsTest, ConcurrentCallsOnDifferentHandlesGiveTheSingleThreadedResults) {
  constexpr int kThreads = 4;
  std::vector<Job> alone(kThreads), together(kThreads);
  for (int i = 0; i < kThreads; ++i) {
    alone[i].mesh = gab::testing_util::bumpy_torus(16 + 4 * i, 12 + 2 * i);
    alone[i].matrix = gab_test::grid_laplacian(10 + 3 * i, 0.1 * (i + 1));
    together[i].mesh = alone[i].mesh;
    together[i].matrix = alone[i].matrix;
    together[i].threads = 1 + i % 2;
    run(&alone[i]);
    ASSERT_EQ(alone[i].failures, 0) << i;
  }
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i) threads.emplace_back(run, &together[i]);
  for (std::thread& t : threads) t.join();
  for (int i = 0; i < kThreads; ++i) {
    EXPECT_EQ(together[i].failures, 0) << i;
    EXPECT_EQ(together[i].file, alone[i].file) << i;
    EXPECT_EQ(together[i].decoded, alone[i].decoded) << i;
    EXPECT_EQ(together[i].coarse, alone[i].coarse) << i;
    EXPECT_EQ(together[i].solution, alone[i].solution) << i;
    EXPECT_FALSE(together[i].file.empty());
  }
}

}  // namespace
