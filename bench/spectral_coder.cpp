// The spectral baseline of issue 36: Karni & Gotsman 2000, "Spectral
// compression of mesh geometry" (SIGGRAPH), as a benchmark, not a format.
//
//   1. L = D - A, the uniform Laplacian of the mesh's edge graph; its K
//      smallest eigenpairs by gab::smallest_eigenpairs (once, K the largest
//      count asked for; a smaller k uses the first k vectors).
//   2. The mean removed, each coordinate function x, y, z projected on the
//      eigenvectors: c_aj = v_j . (x_a - mean_a), j in frequency order.
//   3. For every k and b asked for, a uniform quantizer per axis over the
//      first k coefficients' largest magnitude r_a (K&G quantize to 14
//      bits; here any b): step_a = r_a / (2^(b-1) - 1),
//      q_aj = round(c_aj / step_a).
//   4. The q_aj in frequency order (x, y, z of frequency j, then j + 1)
//      through the codec's adaptive range coder: a signed adaptive
//      Elias-gamma code (SIntCoder) whose context is the octave of a running
//      mean of the same axis's recent |q| (the magnitudes fall with
//      frequency, and the running mean follows them). Decoded back and
//      checked, so the byte count is the real stream's.
//   5. Bytes = the stream + a 29-byte header (k: 4, b: 1, r_a: 3 float32,
//      mean: 3 float32; the decoder uses the float32 values, as here).
//   6. Reconstruction x~_a = mean_a + sum_{j<k} v_j q_aj step_a, against the
//      original: vertex RMS and L-inf (gab/mesh/metrics.h vertex_distance),
//      and Metro RMS / Hausdorff (surface_distance, the samples gab diff uses).
//
// Connectivity is not counted (the decoder is assumed to hold it, and to
// compute the same eigenvectors from it: the paper's setting).
//
//   bench/spectral_coder MESH [--counts K1,K2,...] [--bits B1,B2,...]
//                        [--metro all|front|none] [--threads T] [--block B]
//                        [--max-basis M] [--write K:B:PATH]
//
// Defaults: counts 100,200,500,1000 (capped at n), bits 8..20 step 2,
// metro on the (bytes, vertex RMS) and (bytes, L-inf) Pareto fronts.
// Output: JSON, one object a line: first the eigendecomposition ("eigen":
// seconds and their parts, the process's peak RSS in MB, the vectors' MB,
// the worst relative residual), then one line per (k, b).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "entropy/int_coder.h"
#include "entropy/range_coder.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/metrics.h"
#include "gab/sparse/symmetric_eigensolver.h"
#include "uniform_laplacian.h"

namespace {

constexpr int kHeaderBytes = 4 + 1 + 3 * 4 + 3 * 4;
constexpr int kContexts = 24;

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double peak_rss_mb() {
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// The process's CPU seconds (user + system): on a shared machine, what the
// work cost, whatever else ran beside it.
double process_cpu_s() {
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6 + usage.ru_stime.tv_sec + usage.ru_stime.tv_usec * 1e-6;
}

std::vector<int> parse_list(const char* text) {
  std::vector<int> out;
  for (const char* p = text; *p;) {
    out.push_back(std::atoi(p));
    while (*p && *p != ',') ++p;
    if (*p == ',') ++p;
  }
  return out;
}

int bit_length(uint32_t v) {
  int length = 0;
  while (v) {
    ++length;
    v >>= 1;
  }
  return length;
}

// The context of the next coefficient of one axis: the octave of the running
// mean of the axis's recent magnitudes (fixed point, 4 fractional bits, a
// memory of about 8 coefficients). Encoder and decoder update it alike.
struct MagnitudeContext {
  int64_t mean16 = 0;
  int context() const { return std::min(kContexts - 1, bit_length(static_cast<uint32_t>((mean16 + 8) >> 4))); }
  void update(int32_t q) {
    const int64_t magnitude16 = static_cast<int64_t>(std::abs(static_cast<int64_t>(q))) << 4;
    mean16 += (magnitude16 - mean16) / 8;
  }
};

std::vector<uint8_t> encode_coefficients(const std::vector<int32_t>& q, int32_t k) {
  gab::RangeEncoder encoder;
  gab::SIntCoder coder(kContexts);
  MagnitudeContext axis[3];
  for (int32_t j = 0; j < k; ++j) {
    for (int a = 0; a < 3; ++a) {
      const int32_t value = q[static_cast<size_t>(a) * k + j];
      coder.encode(&encoder, value, axis[a].context());
      axis[a].update(value);
    }
  }
  return encoder.finish();
}

std::vector<int32_t> decode_coefficients(const std::vector<uint8_t>& bytes, int32_t k, bool* complete) {
  gab::RangeDecoder decoder(bytes.data(), bytes.size());
  gab::SIntCoder coder(kContexts);
  MagnitudeContext axis[3];
  std::vector<int32_t> q(static_cast<size_t>(3) * k);
  for (int32_t j = 0; j < k; ++j) {
    for (int a = 0; a < 3; ++a) {
      const int32_t value = coder.decode(&decoder, axis[a].context());
      q[static_cast<size_t>(a) * k + j] = value;
      axis[a].update(value);
    }
  }
  *complete = !decoder.overrun() && decoder.bytes_consumed() == bytes.size();
  return q;
}

// Float32 rounded away from zero, so a range stored as float still covers
// every coefficient.
float float_at_least(double v) {
  float f = static_cast<float>(v);
  if (static_cast<double>(f) < v) f = std::nextafter(f, INFINITY);
  return f;
}

struct Trial {
  int32_t k = 0;
  int bits = 0;
  size_t bytes = 0;
  gab::VertexDistance vertex;
  gab::SurfaceDistance surface;
  bool metro = false;
  double code_s = 0.0;
  double reconstruct_s = 0.0;
};

struct Spectrum {
  int32_t n = 0;
  int32_t count = 0;
  const std::vector<double>* vectors = nullptr;  // n x count, column-major
  std::vector<double> coefficients;               // 3 x count, axis-major
  float mean[3] = {0, 0, 0};
};

// Quantizes, codes and decodes the first k coefficients at `bits`, and
// reconstructs the shape into `shape` (3 per vertex).
bool code_and_reconstruct(const Spectrum& sp, int32_t k, int bits, std::vector<double>* shape, Trial* trial) {
  const double t0 = now();
  const int32_t n = sp.n;
  const double levels = std::ldexp(1.0, bits - 1) - 1.0;
  float range[3];
  double step[3];
  std::vector<int32_t> q(static_cast<size_t>(3) * k);
  for (int a = 0; a < 3; ++a) {
    const double* c = &sp.coefficients[static_cast<size_t>(a) * sp.count];
    double largest = 0.0;
    for (int32_t j = 0; j < k; ++j) largest = std::max(largest, std::abs(c[j]));
    range[a] = float_at_least(largest);
    step[a] = range[a] > 0.0f ? static_cast<double>(range[a]) / levels : 1.0;
    for (int32_t j = 0; j < k; ++j) q[static_cast<size_t>(a) * k + j] = static_cast<int32_t>(std::lround(c[j] / step[a]));
  }
  const std::vector<uint8_t> stream = encode_coefficients(q, k);
  bool complete = false;
  const std::vector<int32_t> decoded = decode_coefficients(stream, k, &complete);
  if (!complete || decoded != q) {
    std::fprintf(stderr, "spectral_coder: k %d bits %d: the stream does not decode to its coefficients\n", k, bits);
    return false;
  }
  trial->k = k;
  trial->bits = bits;
  trial->bytes = stream.size() + kHeaderBytes;
  const double t1 = now();
  trial->code_s = t1 - t0;

  shape->assign(static_cast<size_t>(3) * n, 0.0);
  std::vector<double> axis(static_cast<size_t>(3) * n, 0.0);
  for (int32_t j = 0; j < k; ++j) {
    const double* v = &(*sp.vectors)[static_cast<size_t>(j) * n];
    for (int a = 0; a < 3; ++a) {
      const double w = decoded[static_cast<size_t>(a) * k + j] * step[a];
      if (w == 0.0) continue;
      double* out = &axis[static_cast<size_t>(a) * n];
      for (int32_t i = 0; i < n; ++i) out[i] += w * v[i];
    }
  }
  for (int32_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) (*shape)[3 * static_cast<size_t>(i) + a] = sp.mean[a] + axis[static_cast<size_t>(a) * n + i];
  }
  trial->reconstruct_s = now() - t1;
  return true;
}

// Marks the trials no other trial beats in both bytes and `error`.
void mark_front(const std::vector<Trial>& trials, double (*error)(const Trial&), std::vector<bool>* on_front) {
  for (size_t i = 0; i < trials.size(); ++i) {
    bool dominated = false;
    for (size_t j = 0; j < trials.size() && !dominated; ++j) {
      if (i == j) continue;
      const bool no_worse = trials[j].bytes <= trials[i].bytes && error(trials[j]) <= error(trials[i]);
      const bool better = trials[j].bytes < trials[i].bytes || error(trials[j]) < error(trials[i]);
      dominated = no_worse && better;
    }
    if (!dominated) (*on_front)[i] = true;
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string path;
  std::vector<int> counts = {100, 200, 500, 1000};
  std::vector<int> bit_counts = {8, 10, 12, 14, 16, 18, 20};
  std::string metro = "front";
  gab::SymmetricEigenOptions options;
  int write_k = -1, write_bits = -1;
  std::string write_path;
  for (int i = 1; i < argc; ++i) {
    auto value = [&]() { return i + 1 < argc ? argv[++i] : ""; };
    if (!std::strcmp(argv[i], "--counts")) counts = parse_list(value());
    else if (!std::strcmp(argv[i], "--bits")) bit_counts = parse_list(value());
    else if (!std::strcmp(argv[i], "--metro")) metro = value();
    else if (!std::strcmp(argv[i], "--threads")) options.threads = std::atoi(value());
    else if (!std::strcmp(argv[i], "--block")) options.block_size = std::atoi(value());
    else if (!std::strcmp(argv[i], "--max-basis")) options.max_basis = std::atoi(value());
    else if (!std::strcmp(argv[i], "--write")) {
      const std::string spec = value();
      const size_t c1 = spec.find(':'), c2 = spec.find(':', c1 + 1);
      if (c1 == std::string::npos || c2 == std::string::npos) {
        std::fprintf(stderr, "spectral_coder: --write wants K:B:PATH\n");
        return 1;
      }
      write_k = std::atoi(spec.substr(0, c1).c_str());
      write_bits = std::atoi(spec.substr(c1 + 1, c2 - c1 - 1).c_str());
      write_path = spec.substr(c2 + 1);
    } else path = argv[i];
  }
  if (path.empty() || counts.empty() || bit_counts.empty() ||
      (metro != "all" && metro != "front" && metro != "none")) {
    std::fprintf(stderr,
                 "usage: spectral_coder MESH [--counts K,...] [--bits B,...] [--metro all|front|none] [--threads T]"
                 " [--block B] [--max-basis M] [--write K:B:PATH]\n");
    return 1;
  }
  for (int b : bit_counts) {
    if (b < 2 || b > 30) {
      std::fprintf(stderr, "spectral_coder: bits must be in 2..30\n");
      return 1;
    }
  }

  gab::Mesh mesh;
  gab::Status status = gab::read_mesh(path, &mesh);
  if (!status.ok()) {
    std::fprintf(stderr, "spectral_coder: %s\n", status.message().c_str());
    return 1;
  }
  const int32_t n = mesh.num_vertices();
  for (int& k : counts) k = std::max(1, std::min(k, n));
  std::sort(counts.begin(), counts.end());
  counts.erase(std::unique(counts.begin(), counts.end()), counts.end());

  // 1. The spectrum.
  const gab::CscMatrix lower = gab_bench::uniform_laplacian_lower(gab::build_edge_graph(mesh));
  options.count = counts.back();
  gab::SymmetricEigenResult eig;
  const double rss_before = peak_rss_mb();
  const double cpu0 = process_cpu_s();
  const double t0 = now();
  status = gab::smallest_eigenpairs(lower, options, &eig);
  const double eigen_s = now() - t0;
  const double eigen_cpu_s = process_cpu_s() - cpu0;
  if (!status.ok()) {
    std::printf("{\"eigen\": true, \"n\": %d, \"count\": %d, \"ok\": false, \"seconds\": %.3f, \"cpu_s\": %.3f, \"peak_rss_mb\": %.0f, "
                "\"error\": \"%s\"}\n",
                n, options.count, eigen_s, process_cpu_s() - cpu0, peak_rss_mb(), status.message().c_str());
    return 2;
  }
  const double worst = *std::max_element(eig.residuals.begin(), eig.residuals.end());
  std::printf("{\"eigen\": true, \"n\": %d, \"count\": %d, \"ok\": true, \"seconds\": %.3f, \"cpu_s\": %.3f, \"factor_s\": %.3f, "
              "\"lanczos_s\": %.3f, \"check_s\": %.3f, \"vectors_s\": %.3f, \"solves\": %d, \"restarts\": %d, "
              "\"basis_columns\": %d, \"peak_rss_mb\": %.0f, \"rss_before_mb\": %.0f, \"vectors_mb\": %.1f, "
              "\"max_residual\": %.3e, \"lambda_k\": %.6f}\n",
              n, options.count, eigen_s, eigen_cpu_s, eig.factor_s, eig.lanczos_s, eig.check_s, eig.vectors_s, eig.solves,
              eig.restarts, eig.basis_columns, peak_rss_mb(), rss_before,
              static_cast<double>(n) * options.count * 8.0 / (1024.0 * 1024.0), worst, eig.values.back());
  std::fflush(stdout);

  // 2. Mean and projection (the mean as the decoder has it: float32).
  Spectrum sp;
  sp.n = n;
  sp.count = options.count;
  sp.vectors = &eig.vectors;
  for (int a = 0; a < 3; ++a) {
    double sum = 0.0;
    for (int32_t i = 0; i < n; ++i) sum += mesh.positions[3 * static_cast<size_t>(i) + a];
    sp.mean[a] = static_cast<float>(sum / n);
  }
  sp.coefficients.assign(static_cast<size_t>(3) * sp.count, 0.0);
  for (int32_t j = 0; j < sp.count; ++j) {
    const double* v = &eig.vectors[static_cast<size_t>(j) * n];
    for (int a = 0; a < 3; ++a) {
      double dot = 0.0;
      for (int32_t i = 0; i < n; ++i) dot += v[i] * (mesh.positions[3 * static_cast<size_t>(i) + a] - sp.mean[a]);
      sp.coefficients[static_cast<size_t>(a) * sp.count + j] = dot;
    }
  }

  // 3-6. Every (k, bits).
  std::vector<Trial> trials;
  std::vector<double> shape;
  gab::Mesh approx = mesh;
  for (int32_t k : counts) {
    for (int bits : bit_counts) {
      Trial trial;
      if (!code_and_reconstruct(sp, k, bits, &shape, &trial)) return 1;
      approx.positions = shape;
      status = gab::vertex_distance(mesh, approx, &trial.vertex);
      if (!status.ok()) {
        std::fprintf(stderr, "spectral_coder: %s\n", status.message().c_str());
        return 1;
      }
      if (k == write_k && bits == write_bits) {
        status = gab::write_mesh(write_path, approx);
        if (!status.ok()) {
          std::fprintf(stderr, "spectral_coder: %s\n", status.message().c_str());
          return 1;
        }
      }
      trials.push_back(trial);
    }
  }
  std::vector<bool> measure(trials.size(), metro == "all");
  if (metro == "front") {
    mark_front(trials, [](const Trial& t) { return t.vertex.rms; }, &measure);
    mark_front(trials, [](const Trial& t) { return t.vertex.linf; }, &measure);
  }
  const double diagonal = gab::bounding_box_diagonal(mesh);
  for (size_t i = 0; i < trials.size(); ++i) {
    Trial& t = trials[i];
    if (measure[i]) {
      if (!code_and_reconstruct(sp, t.k, t.bits, &shape, &t)) return 1;
      approx.positions = shape;
      status = gab::surface_distance(mesh, approx, gab::SurfaceDistanceOptions(), &t.surface);
      if (!status.ok()) {
        std::fprintf(stderr, "spectral_coder: %s\n", status.message().c_str());
        return 1;
      }
      t.metro = true;
    }
    std::printf("{\"k\": %d, \"bits\": %d, \"bytes\": %zu, \"bpv\": %.5f, \"rms_rel\": %.6e, \"linf_rel\": %.6e",
                t.k, t.bits, t.bytes, 8.0 * t.bytes / n, t.vertex.rms / diagonal, t.vertex.linf / diagonal);
    if (t.metro) {
      std::printf(", \"metro_rms_rel\": %.6e, \"hausdorff_rel\": %.6e", t.surface.rms / diagonal,
                  t.surface.hausdorff / diagonal);
    }
    std::printf(", \"code_s\": %.4f, \"reconstruct_s\": %.4f}\n", t.code_s, t.reconstruct_s);
  }
  return 0;
}
