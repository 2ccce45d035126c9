// What the attribute sections cost on real meshes: each mesh given
// area-weighted vertex normals from its own geometry (what most exporters
// write), coded at the normal bits asked, the section's bytes and bits per
// vertex with the largest angle error, and the decode time of the sections
// against the whole decode's. Optionally writes the mesh with its normals
// as PLY (for Draco's side of bench/attribute_compare.py).
//
// With --own, a mesh's own attributes (normals, texture coordinates,
// colours, ... as read) instead: every section's bytes and the sections'
// decode time against the geometry's.
//
//   attribute_sizes [--bits 8,10] [--error 1e-3] [--write-ply DIR] [--own] MESH...
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/vertex_normals.h"

namespace {

using gab::Mesh;

std::vector<int> parse_list(const std::string& s) {
  std::vector<int> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::atoi(item.c_str()));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> bits = {8, 10};
  double error = 1e-3;
  std::string ply_dir;
  bool own = false;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--bits" && i + 1 < argc) {
      bits = parse_list(argv[++i]);
    } else if (a == "--error" && i + 1 < argc) {
      error = std::atof(argv[++i]);
    } else if (a == "--own") {
      own = true;
    } else if (a == "--write-ply" && i + 1 < argc) {
      ply_dir = argv[++i];
    } else {
      meshes.push_back(a);
    }
  }
  std::printf("%-16s %8s %4s %10s %9s %10s %9s %9s\n", "mesh", "vertices", "bits", "bytes", "bits/v", "max deg",
              "attr s", "decode s");
  for (const std::string& path : meshes) {
    Mesh mesh;
    const gab::Status s = gab::read_mesh(path, &mesh);
    if (!s.ok()) {
      std::fprintf(stderr, "%s\n", s.message().c_str());
      return 1;
    }
    if (!own) {
      mesh.attributes.clear();
      mesh.attributes.push_back(gab::area_weighted_normals(mesh));
    }
    const std::string name = path.substr(path.find_last_of('/') + 1);
    if (!ply_dir.empty()) {
      gab::PlyWriteOptions ply;
      ply.float32 = true;
      const std::string stem = name.substr(0, name.find_last_of('.'));
      if (!gab::write_mesh(ply_dir + "/" + stem + ".normals.ply", mesh, ply).ok()) return 1;
    }
    for (int b : bits) {
      gab::EncodeOptions o;
      o.target_rms_rel = error;
      o.normal_bits = b;
      std::vector<uint8_t> file;
      gab::EncodeStats stats;
      if (!gab::encode_mesh(mesh, o, &file, &stats).ok()) return 1;
      // Median of 5 decodes.
      std::vector<double> attr_s, total_s;
      for (int r = 0; r < 5; ++r) {
        Mesh out;
        gab::DecodeStats ds;
        if (!gab::decode_mesh(file.data(), file.size(), gab::DecodeOptions(), &out, &ds).ok()) return 1;
        attr_s.push_back(ds.attributes_s);
        total_s.push_back(ds.decode_s);
      }
      std::sort(attr_s.begin(), attr_s.end());
      std::sort(total_s.begin(), total_s.end());
      for (const gab::AttributeStats& as : stats.attributes) {
        std::printf("%-16s %8d %4d %10zu %9.3f %10.3f %9.4f %9.4f  %s%s\n", name.c_str(), stats.num_vertices, as.bits,
                    as.bytes, 8.0 * static_cast<double>(as.bytes) / stats.num_vertices, as.max_error, attr_s[2],
                    total_s[2], as.label.c_str(), as.from_surface ? " (surface)" : "");
      }
    }
  }
  return 0;
}
