#include "gab/mesh/iterative_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>

#include "anchor_checks.h"

namespace gab {

namespace {

// The threads of one solve: run(job) calls job(begin, end, b) for every
// block b of kBlock vertices (vertices [begin, end)), each member of the team
// taking a fixed range of blocks, and returns when all are done. Helpers the
// system refuses (an address-space cap maps each stack) leave a smaller
// team: the blocks split among fewer members, the same results.
class StepTeam {
 public:
  using Job = std::function<void(int32_t, int32_t, int32_t)>;

  StepTeam(int32_t threads, int32_t vertices)
      : blocks_((vertices + IterativeReconstruction::kBlock - 1) / IterativeReconstruction::kBlock),
        vertices_(vertices) {
    const int32_t wanted = std::max(1, std::min(threads, blocks_));
    for (int32_t member = 1; member < wanted; ++member) {
#if defined(__cpp_exceptions)
      try {
        helpers_.emplace_back([this, member] { serve(member); });
      } catch (const std::system_error&) {
        break;
      }
#else
      helpers_.emplace_back([this, member] { serve(member); });  // built without exceptions: a refusal ends the process
#endif
    }
    size_ = 1 + static_cast<int32_t>(helpers_.size());
  }
  ~StepTeam() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    start_.notify_all();
    for (std::thread& t : helpers_) t.join();
  }
  StepTeam(const StepTeam&) = delete;
  StepTeam& operator=(const StepTeam&) = delete;

  void run(const Job& job) {
    if (size_ == 1) {
      work(job, 0);
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &job;
      pending_ = size_ - 1;
      ++generation_;
    }
    start_.notify_all();
    work(job, 0);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
  }

 private:
  void work(const Job& job, int32_t member) const {
    const int32_t first = static_cast<int32_t>(static_cast<int64_t>(blocks_) * member / size_);
    const int32_t last = static_cast<int32_t>(static_cast<int64_t>(blocks_) * (member + 1) / size_);
    for (int32_t b = first; b < last; ++b) job(b * IterativeReconstruction::kBlock, end_of(b), b);
  }
  int32_t end_of(int32_t b) const { return std::min(vertices_, (b + 1) * IterativeReconstruction::kBlock); }
  void serve(int32_t member) {
    uint64_t seen = 0;
    for (;;) {
      const Job* job = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        job = job_;
      }
      work(*job, member);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        --pending_;
      }
      done_.notify_one();
    }
  }

  const int32_t blocks_, vertices_;
  int32_t size_ = 1;
  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const Job* job_ = nullptr;
  uint64_t generation_ = 0;
  int32_t pending_ = 0;
  bool stopping_ = false;
};

}  // namespace

Status IterativeReconstruction::check_new(const std::vector<int32_t>& anchors,
                                          const std::vector<double>& coefficients) {
  return check_new_anchors<int32_t>(anchors, coefficients, &anchor_of_, -1, -2);
}

void IterativeReconstruction::record(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients) {
  for (size_t i = 0; i < anchors.size(); ++i) {
    anchor_of_[anchors[i]] = static_cast<int32_t>(anchors_.size());
    anchors_.push_back(anchors[i]);
    coefficients_.insert(coefficients_.end(), &coefficients[3 * i], &coefficients[3 * i] + 3);
  }
}

Status IterativeReconstruction::init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
                                     const std::vector<double>& coefficients) {
  if (!(weight > 0.0) || !std::isfinite(weight)) {
    return Status::Error(StatusCode::kInvalidArgument, "anchor weight must be positive and finite");
  }
  graph_ = &graph;
  n_ = graph.num_vertices();
  weight_ = weight;
  anchors_.clear();
  coefficients_.clear();
  shape_.clear();
  anchor_of_.assign(n_, -1);
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  GAB_RETURN_IF_ERROR(check_components_anchored(graph, anchors));
  record(anchors, coefficients);
  return Status::Ok();
}

Status IterativeReconstruction::add_anchors(const std::vector<int32_t>& anchors,
                                            const std::vector<double>& coefficients) {
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  record(anchors, coefficients);
  return Status::Ok();
}

Status IterativeReconstruction::set_coefficients(int32_t first, const std::vector<double>& coefficients) {
  if (first < 0 || coefficients.size() % 3 != 0 ||
      static_cast<size_t>(first) + coefficients.size() / 3 > anchors_.size()) {
    return Status::Error(StatusCode::kInvalidArgument, "coefficients past the last anchor");
  }
  GAB_RETURN_IF_ERROR(check_anchor_coefficients(coefficients.size() / 3, coefficients));
  std::copy(coefficients.begin(), coefficients.end(), coefficients_.begin() + 3 * static_cast<size_t>(first));
  return Status::Ok();
}

Status IterativeReconstruction::set_start(const std::vector<double>& positions) {
  if (positions.size() != 3 * static_cast<size_t>(n_)) {
    return Status::Error(StatusCode::kInvalidArgument, "a start needs 3 coordinates per vertex");
  }
  for (double x : positions) {
    if (!std::isfinite(x)) return Status::Error(StatusCode::kInvalidArgument, "a start coordinate is not finite");
  }
  shape_ = positions;
  return Status::Ok();
}

std::vector<double> IterativeReconstruction::nearest_anchor_shape() {
  nearest_anchor_start();
  return shape_;
}

void IterativeReconstruction::nearest_anchor_start() {
  const EdgeGraph& g = *graph_;
  std::vector<int32_t> source(n_, -1), frontier = anchors_, next;
  std::sort(frontier.begin(), frontier.end());
  for (int32_t a : frontier) source[a] = anchor_of_[a];
  while (!frontier.empty()) {
    next.clear();
    for (int32_t u : frontier) {
      for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
        const int32_t w = g.neighbors[p];
        if (source[w] >= 0) continue;
        source[w] = source[u];
        next.push_back(w);
      }
    }
    frontier.swap(next);
  }
  shape_.assign(3 * static_cast<size_t>(n_), 0.0);
  for (int32_t v = 0; v < n_; ++v) {
    const double* c = &coefficients_[3 * static_cast<size_t>(source[v])];
    std::copy(c, c + 3, shape_.begin() + 3 * static_cast<std::ptrdiff_t>(v));
  }
}

Status IterativeReconstruction::solve(int32_t steps, std::vector<double>* positions) {
  if (graph_ == nullptr) return Status::Error(StatusCode::kInvalidArgument, "solve before init");
  if (steps < 0) return Status::Error(StatusCode::kInvalidArgument, "negative step count");
  if (shape_.empty()) nearest_anchor_start();
  const size_t m = 3 * static_cast<size_t>(n_);
  const double w2 = weight_ * weight_;
  const int32_t blocks = (n_ + kBlock - 1) / kBlock;
  // 1 / diag(L^T L + w^2 S): (L^T L)_vv = d^2 + d for L = D - A.
  std::vector<double> inv_diag(n_);
  for (int32_t v = 0; v < n_; ++v) {
    const double d = graph_->degree(v);
    inv_diag[v] = 1.0 / (d * d + d + (anchor_of_[v] >= 0 ? w2 : 0.0));
  }
  std::vector<double> r(m), p(m), q(m), t(m), partial(3 * static_cast<size_t>(blocks));
  double* x = shape_.data();
  const int32_t* offsets = graph_->offsets.data();
  const int32_t* neighbors = graph_->neighbors.data();
  // out_v = (L in)_v for v in [begin, end).
  auto laplacian_rows = [&](const double* in, double* out, int32_t begin, int32_t end) {
    for (int32_t v = begin; v < end; ++v) {
      const double d = offsets[v + 1] - offsets[v];
      double s0 = d * in[3 * v], s1 = d * in[3 * v + 1], s2 = d * in[3 * v + 2];
      for (int32_t e = offsets[v]; e < offsets[v + 1]; ++e) {
        const double* u = in + 3 * static_cast<size_t>(neighbors[e]);
        s0 -= u[0];
        s1 -= u[1];
        s2 -= u[2];
      }
      out[3 * v] = s0;
      out[3 * v + 1] = s1;
      out[3 * v + 2] = s2;
    }
  };
  // Every pass below runs over whole blocks, in parallel; a block's sums go
  // to partial[3 b ..], added in block order afterwards (the order the
  // header promises for any thread count).
  StepTeam team(threads_, n_);
  auto total = [&](double out[3]) {
    out[0] = out[1] = out[2] = 0.0;
    for (int32_t b = 0; b < blocks; ++b) {
      for (int c = 0; c < 3; ++c) out[c] += partial[3 * static_cast<size_t>(b) + c];
    }
  };
  // q = L (L y) + w^2 S y (t = L y first), and per block the sums of y q
  // when `dot`.
  auto product = [&](const double* y, bool dot) {
    team.run([&](int32_t begin, int32_t end, int32_t) { laplacian_rows(y, t.data(), begin, end); });
    team.run([&](int32_t begin, int32_t end, int32_t b) {
      laplacian_rows(t.data(), q.data(), begin, end);
      double s[3] = {0.0, 0.0, 0.0};
      for (int32_t v = begin; v < end; ++v) {
        for (int c = 0; c < 3; ++c) {
          const size_t k = 3 * static_cast<size_t>(v) + c;
          if (anchor_of_[v] >= 0) q[k] += w2 * y[k];
          s[c] += y[k] * q[k];
        }
      }
      if (dot) {
        for (int c = 0; c < 3; ++c) partial[3 * static_cast<size_t>(b) + c] = s[c];
      }
    });
  };
  // r = w^2 S c - (L^T L + w^2 S) x; p = M^-1 r; rz = r . p.
  product(x, false);
  team.run([&](int32_t begin, int32_t end, int32_t b) {
    double s[3] = {0.0, 0.0, 0.0};
    for (int32_t v = begin; v < end; ++v) {
      const int32_t a = anchor_of_[v];
      for (int c = 0; c < 3; ++c) {
        const size_t k = 3 * static_cast<size_t>(v) + c;
        r[k] = -q[k];
        if (a >= 0) r[k] += w2 * coefficients_[3 * static_cast<size_t>(a) + c];
        p[k] = inv_diag[v] * r[k];
        s[c] += r[k] * p[k];
      }
    }
    for (int c = 0; c < 3; ++c) partial[3 * static_cast<size_t>(b) + c] = s[c];
  });
  double rz[3];
  total(rz);
  for (int32_t step = 0; step < steps; ++step) {
    product(p.data(), true);
    double pq[3];
    total(pq);
    // A column already solved exactly (rz or pq zero) stays as it is.
    double alpha[3];
    for (int c = 0; c < 3; ++c) alpha[c] = (pq[c] > 0.0 && rz[c] > 0.0) ? rz[c] / pq[c] : 0.0;
    team.run([&](int32_t begin, int32_t end, int32_t b) {
      double s[3] = {0.0, 0.0, 0.0};
      for (int32_t v = begin; v < end; ++v) {
        for (int c = 0; c < 3; ++c) {
          const size_t k = 3 * static_cast<size_t>(v) + c;
          x[k] += alpha[c] * p[k];
          r[k] -= alpha[c] * q[k];
          s[c] += inv_diag[v] * r[k] * r[k];
        }
      }
      for (int c = 0; c < 3; ++c) partial[3 * static_cast<size_t>(b) + c] = s[c];
    });
    double rz_next[3], beta[3];
    total(rz_next);
    for (int c = 0; c < 3; ++c) {
      beta[c] = rz[c] > 0.0 ? rz_next[c] / rz[c] : 0.0;
      rz[c] = rz_next[c];
    }
    team.run([&](int32_t begin, int32_t end, int32_t) {
      for (int32_t v = begin; v < end; ++v) {
        for (int c = 0; c < 3; ++c) {
          const size_t k = 3 * static_cast<size_t>(v) + c;
          p[k] = inv_diag[v] * r[k] + beta[c] * p[k];
        }
      }
    });
  }
  *positions = shape_;
  return Status::Ok();
}

}  // namespace gab
