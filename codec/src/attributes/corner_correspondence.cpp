#include "attributes/corner_correspondence.h"

#include <algorithm>
#include <array>

namespace gab {

namespace {

// A triangle's key: its vertices rotated so the smallest comes first (the
// rotation kept), orientation unchanged.
struct Rotated {
  std::array<int32_t, 3> key;
  int32_t triangle;
  int32_t shift;  // key[i] is corner (shift + i) % 3
};

std::vector<Rotated> rotated(const std::vector<int32_t>& t) {
  std::vector<Rotated> out(t.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) {
    const int32_t* v = &t[3 * i];
    int32_t s = 0;
    if (v[1] < v[s]) s = 1;
    if (v[2] < v[s]) s = 2;
    out[i] = {{v[s], v[(s + 1) % 3], v[(s + 2) % 3]}, static_cast<int32_t>(i), s};
  }
  std::sort(out.begin(), out.end(), [](const Rotated& a, const Rotated& b) {
    return a.key != b.key ? a.key < b.key : a.triangle < b.triangle;
  });
  return out;
}

}  // namespace

Status match_corners(const std::vector<int32_t>& input, const std::vector<int32_t>& coded,
                     std::vector<int32_t>* input_corner) {
  if (input.size() != coded.size()) {
    return Status::Error(StatusCode::kInvalidArgument, "the coded triangles are not the input's");
  }
  const std::vector<Rotated> a = rotated(input), b = rotated(coded);
  input_corner->assign(coded.size(), -1);
  for (size_t i = 0; i < a.size(); ++i) {
    if (a[i].key != b[i].key) return Status::Error(StatusCode::kInvalidArgument, "the coded triangles are not the input's");
    for (int32_t k = 0; k < 3; ++k) {
      (*input_corner)[3 * b[i].triangle + (b[i].shift + k) % 3] = 3 * a[i].triangle + (a[i].shift + k) % 3;
    }
  }
  return Status::Ok();
}

}  // namespace gab
