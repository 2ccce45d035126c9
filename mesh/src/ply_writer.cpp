// PLY writer: vertex x y z (double or float) and face lists of uchar count
// and int indices, in ASCII or either binary byte order.
#include <cmath>
#include <cstring>
#include <limits>

#include "gab/mesh/file_io.h"
#include "gab/mesh/ply_io.h"
#include "text_scanner.h"

namespace gab {

namespace {

// Stores the low `n` bytes of `bits` at *at in the file's byte order and
// moves *at past them (into a string sized beforehand: an append per value
// took most of a binary file's writing time).
inline void put(char** at, uint64_t bits, int n, bool big_endian) {
  for (int i = 0; i < n; ++i) (*at)[big_endian ? n - 1 - i : i] = static_cast<char>((bits >> (8 * i)) & 0xff);
  *at += n;
}

// x as a float; beyond float's range +-infinity (a plain cast would be
// undefined behaviour). write_ply refuses such meshes.
float to_float(double x) {
  constexpr double kMax = std::numeric_limits<float>::max();
  if (x > kMax) return std::numeric_limits<float>::infinity();
  if (x < -kMax) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(x);
}

}  // namespace

std::string format_ply(const Mesh& mesh, const PlyWriteOptions& options) {
  const bool ascii = options.encoding == PlyEncoding::kAscii;
  const bool big = options.encoding == PlyEncoding::kBinaryBigEndian;
  const char* format = ascii ? "ascii" : big ? "binary_big_endian" : "binary_little_endian";
  const char* real = options.float32 ? "float" : "double";
  std::string out = std::string("ply\nformat ") + format + " 1.0\ncomment written by gab\nelement vertex " +
                    std::to_string(mesh.num_vertices()) + "\nproperty " + real + " x\nproperty " + real +
                    " y\nproperty " + real + " z\nelement face " + std::to_string(mesh.num_triangles()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  if (!ascii) {
    const size_t header = out.size();
    const int real_bytes = options.float32 ? 4 : 8;
    out.resize(header + mesh.positions.size() * real_bytes + mesh.triangles.size() / 3 * 13);
    char* at = &out[header];
    for (double x : mesh.positions) {
      if (options.float32) {
        const float f = to_float(x);
        uint32_t u;
        std::memcpy(&u, &f, sizeof(u));
        put(&at, u, 4, big);
      } else {
        uint64_t u;
        std::memcpy(&u, &x, sizeof(u));
        put(&at, u, 8, big);
      }
    }
    for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
      put(&at, 3, 1, big);
      for (int c = 0; c < 3; ++c) put(&at, static_cast<uint32_t>(mesh.triangles[t + c]), 4, big);
    }
    return out;
  }
  out.reserve(out.size() + mesh.positions.size() * (mesh_detail::kMaxRealChars + 1) +
              mesh.triangles.size() / 3 * (2 + 3 * (mesh_detail::kMaxIndexChars + 1)));
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const double x = mesh.positions[i];
    if (options.float32) {
      mesh_detail::append_real(&out, static_cast<double>(to_float(x)));
    } else {
      mesh_detail::append_real(&out, x);
    }
    out += i % 3 == 2 ? '\n' : ' ';
  }
  for (size_t t = 0; t < mesh.triangles.size(); t += 3) {
    out += "3";
    for (int c = 0; c < 3; ++c) {
      out += ' ';
      mesh_detail::append_int(&out, mesh.triangles[t + c]);
    }
    out += '\n';
  }
  return out;
}

Status write_ply(const std::string& path, const Mesh& mesh, const PlyWriteOptions& options) {
  GAB_RETURN_IF_ERROR(validate_mesh(mesh, path));
  if (options.float32) {
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      if (std::isinf(to_float(mesh.positions[i]))) {
        return Status::Error(StatusCode::kInvalidArgument,
                             path + ": vertex " + std::to_string(i / 3) + ": coordinate does not fit a float");
      }
    }
  }
  return write_output_file(path, format_ply(mesh, options));
}

}  // namespace gab
