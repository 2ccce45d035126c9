// Untrusted .gab files: every single-byte corruption and every truncation of
// a small file gives a clear error or a valid (possibly coarser) mesh, never
// a crash, a hang or a huge allocation (ASan/UBSan builds run this too).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <cmath>
#include <string>

#include "common/gab_files.h"
#include "container/crc32.h"
#include "container/framing.h"
#include "container/gab_header.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/file_io.h"

namespace gab {
namespace {

// The size of a file's header (its counts are varints).
size_t header_size(const std::vector<uint8_t>& file) {
  GabFileInfo info;
  EXPECT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  return info.header_bytes;
}

std::vector<uint8_t> small_file(bool geometry_only, bool refine = false,
                                FileLayout layout = FileLayout::kLevels, bool reorder = false,
                                bool detail = false) {
  EncodeOptions options;
  options.reorder = reorder;
  options.layout = layout;
  options.refine = refine;
  options.max_anchors = 24;
  if (detail) {  // anchors to 3e-3, then the detail chunk
    options.max_anchors = 0;
    options.target_rms_rel = 1e-4;
    options.detail = DetailMode::kOn;
  }
  options.initial_anchors = 4;
  options.chunk_growth = 1.6;
  options.geometry_only = geometry_only;
  EncodeStats es;
  return testing_util::encode_or_die(testing_util::bumpy_torus(10, 6), options, &es);
}

// A decode result is acceptable if it failed with a message, or produced a
// mesh of the declared size with finite coordinates.
void expect_clean(const std::vector<uint8_t>& bytes, const DecodeOptions& options, const std::string& what) {
  Mesh out;
  DecodeStats ds;
  const Status s = decode_mesh(bytes.data(), bytes.size(), options, &out, &ds);
  if (!s.ok()) {
    EXPECT_FALSE(s.message().empty()) << what;
    return;
  }
  ASSERT_EQ(out.positions.size(), 3 * static_cast<size_t>(ds.num_vertices)) << what;
  for (double x : out.positions) ASSERT_TRUE(std::isfinite(x)) << what;
  for (int32_t i : out.triangles) ASSERT_TRUE(i >= 0 && i < ds.num_vertices) << what;
  GabFileInfo info;
  static_cast<void>(read_gab_info(bytes.data(), bytes.size(), &info));  // must not crash either
}

TEST(FileSafety, EveryByteFlipIsAnErrorOrAValidMesh) {
  const Mesh connectivity = testing_util::bumpy_torus(10, 6);
  // plain, geometry only, refined; levels, then selection order; then reordered (valence connectivity);
  // then with a detail chunk
  for (int variant : {0, 1, 2, 3, 4, 5, 6, 7}) {
    const bool geometry_only = variant % 3 == 1 && variant < 6;
    const FileLayout layout = variant < 3 || variant >= 6 ? FileLayout::kLevels : FileLayout::kSelectionOrder;
    const std::vector<uint8_t> file =
        small_file(geometry_only, variant % 3 == 2 && variant < 6, layout, variant == 6, variant == 7);
    DecodeOptions options;
    options.connectivity = geometry_only ? &connectivity : nullptr;
    int errors = 0;
    for (size_t i = 0; i < file.size(); ++i) {
      for (uint8_t mask : {0x01, 0x80, 0xFF}) {
        std::vector<uint8_t> bad = file;
        bad[i] ^= mask;
        Mesh out;
        DecodeStats ds;
        if (decode_mesh(bad.data(), bad.size(), options, &out, &ds).ok()) {
          // Checksums cover every byte but the frame lengths; a length
          // grown past the end reads as a truncated file, never as a
          // complete one.
          EXPECT_TRUE(ds.truncated) << "byte " << i << " ^ " << int{mask};
        } else {
          ++errors;
        }
        expect_clean(bad, options, "byte " + std::to_string(i) + " ^ " + std::to_string(mask));
      }
    }
    EXPECT_GT(errors, static_cast<int>(2 * file.size()));
  }
}

TEST(FileSafety, AFileReadAsAnotherOperatorIsAnErrorOrAFiniteMesh) {
  // Header byte 12 swapped with the header's checksum made whole again: the
  // chunks are then predicted by an operator they were not coded with
  // (operators 2 and 3's local predictions read as operator 1's or the
  // global one's, and the other way round; operator 3's parameters read as
  // chunk 0's first bytes, or those bytes as its parameters). Wrong shapes,
  // but never a crash, never a non-finite coordinate: a refusal or a mesh.
  const std::string corpus = std::string(GAB_FUZZ_DIR) + "/corpus/gab/";
  int decoded = 0;
  for (const char* name : {"torus-iterative-large", "torus-iterative", "torus-operator2", "torus-operator1",
                           "torus-levels"}) {
    std::string bytes;
    ASSERT_TRUE(read_file(corpus + name, &bytes).ok()) << name;
    const std::vector<uint8_t> file(bytes.begin() + 1, bytes.end());  // past the options byte
    const size_t header = header_size(file);
    for (uint8_t code : {kGabReconstructionGlobal, kGabReconstructionIterative, kGabReconstructionIterativeLocal,
                         kGabReconstructionIterativeTuned}) {
      if (code == file[12]) continue;
      std::vector<uint8_t> bad = file;
      bad[12] = code;
      const uint32_t crc = crc32(bad.data(), header - 4);
      for (int b = 0; b < 4; ++b) bad[header - 4 + b] = static_cast<uint8_t>(crc >> (8 * b));
      Mesh out;
      DecodeStats ds;
      const Status s = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
      if (!s.ok()) {
        // Corrupt, or (read as the global operator) a factor over the budget.
        EXPECT_TRUE(s.code() == StatusCode::kParseError || s.code() == StatusCode::kResourceExhausted)
            << name << " as " << int(code) << ": " << s.message();
        continue;
      }
      ++decoded;
      for (double x : out.positions) ASSERT_TRUE(std::isfinite(x)) << name << " as " << int(code);
    }
  }
  EXPECT_GT(decoded, 0);
}

TEST(FileSafety, DamageInsideAConnectivityBlockIsAnErrorOrAValidMesh) {
  // Every byte of the connectivity block flipped with the block's checksum
  // made whole again, so the damage reaches the decoders: the variants the
  // encoder writes (order kept, reordered), and two golden seeds.
  const std::string corpus = std::string(GAB_FUZZ_DIR) + "/corpus/gab/";
  std::vector<std::pair<std::string, std::vector<uint8_t>>> files = {
      {"order kept", small_file(false)}, {"reordered", small_file(false, false, FileLayout::kLevels, true)}};
  for (const char* name : {"torus-full", "torus-reordered"}) {
    std::string bytes;
    ASSERT_TRUE(read_file(corpus + name, &bytes).ok()) << name;
    files.push_back({name, std::vector<uint8_t>(bytes.begin() + 1, bytes.end())});  // past the options byte
  }
  for (const auto& [name, file] : files) {
    // Frames after the header: the connectivity block, and with the order
    // kept the vertex order's block.
    const int frames = name == "order kept" ? 2 : 1;
    size_t begin = header_size(file);
    for (int frame = 0; frame < frames; ++frame) {
      const size_t length = file[begin] | (file[begin + 1] << 8) | (file[begin + 2] << 16);
      const size_t payload = begin + 8;
      ASSERT_LE(payload + length, file.size()) << name;
      int errors = 0;
      for (size_t i = payload; i < payload + length; ++i) {
        for (uint8_t mask : {0x01, 0x80, 0xFF}) {
          std::vector<uint8_t> bad = file;
          bad[i] ^= mask;
          const uint32_t crc = crc32(bad.data() + payload, length);
          for (int b = 0; b < 4; ++b) bad[begin + 4 + b] = static_cast<uint8_t>(crc >> (8 * b));
          Mesh out;
          DecodeStats ds;
          if (!decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds).ok()) ++errors;
          expect_clean(bad, DecodeOptions(), name + " byte " + std::to_string(i) + " ^ " + std::to_string(mask));
        }
      }
      EXPECT_GT(errors, static_cast<int>(length)) << name << ", frame " << frame;  // most damage is caught
      begin = payload + length;
    }
  }
}

TEST(FileSafety, EveryTruncationIsAnErrorOrTheCompleteChunks) {
  // plain, refined; levels, then selection order; then with a detail chunk
  for (int variant : {0, 1, 2, 3, 4}) {
    const bool refine = variant % 2 == 1;
    const std::vector<uint8_t> file = small_file(
        false, refine, variant < 2 || variant == 4 ? FileLayout::kLevels : FileLayout::kSelectionOrder, false,
        variant == 4);
    GabFileInfo full;
    ASSERT_TRUE(read_gab_info(file.data(), file.size(), &full).ok());
    ASSERT_GE(full.chunks, 3);
    ASSERT_EQ(full.refined, refine);
    ASSERT_EQ(full.detail, variant == 4);
    const size_t chunk0_end = file.size() - [&] {
      size_t rest = full.refinement_bytes + full.detail_bytes;
      for (size_t c = 1; c < full.chunk_bytes.size(); ++c) rest += full.chunk_bytes[c];
      return rest;
    }();
    for (size_t length = 0; length < file.size(); ++length) {
      const std::vector<uint8_t> cut(file.begin(), file.begin() + length);
      Mesh out;
      DecodeStats ds;
      const Status s = decode_mesh(cut.data(), cut.size(), DecodeOptions(), &out, &ds);
      if (length < chunk0_end) {
        EXPECT_FALSE(s.ok()) << length;
      } else {
        ASSERT_TRUE(s.ok()) << length << ": " << s.message();
        EXPECT_TRUE(ds.truncated);
        EXPECT_LT(ds.chunks, full.chunks);
        EXPECT_EQ(out.num_vertices(), full.num_vertices);
      }
      expect_clean(cut, DecodeOptions(), "length " + std::to_string(length));
    }
  }
}

TEST(FileSafety, ForgedPayloadsWithValidChecksumsAreErrorsOrValidMeshes) {
  // Checksums stop random damage; these bytes get past them: every payload
  // byte of every chunk changed and its frame's CRC recomputed, so the
  // decoders (a level plan, subsets, farthest-point levels, positions) see
  // well-framed garbage.
  for (int variant : {0, 1, 2}) {  // levels, selection order (both refined); a detail chunk
    const FileLayout layout = variant == 1 ? FileLayout::kSelectionOrder : FileLayout::kLevels;
    const std::vector<uint8_t> file = small_file(false, variant < 2, layout, false, variant == 2);
    GabFileInfo info;
    ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
    size_t at = info.header_bytes + info.connectivity_bytes;  // the frames after the connectivity block
    int errors = 0, forged = 0;
    while (at + kGabFrameBytes <= file.size()) {
      const size_t length = file[at] | file[at + 1] << 8 | file[at + 2] << 16 | static_cast<size_t>(file[at + 3]) << 24;
      const size_t payload = at + kGabFrameBytes;
      ASSERT_LE(payload + length, file.size());
      for (size_t i = payload; i < payload + length; ++i) {
        for (uint8_t mask : {0x01, 0x10, 0xFF}) {
          std::vector<uint8_t> bad = file;
          bad[i] ^= mask;
          const uint32_t crc = crc32(bad.data() + payload, length);
          for (int b = 0; b < 4; ++b) bad[at + 4 + b] = static_cast<uint8_t>(crc >> (8 * b));
          Mesh out;
          DecodeStats ds;
          errors += decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds).ok() ? 0 : 1;
          ++forged;
          expect_clean(bad, DecodeOptions(), "payload byte " + std::to_string(i) + " ^ " + std::to_string(mask));
          DecodeOptions lod;
          lod.max_anchors = 9;
          expect_clean(bad, lod, "level of detail, payload byte " + std::to_string(i));
        }
      }
      at = payload + length;
    }
    EXPECT_GT(forged, 300);
    EXPECT_GT(errors, 0);
  }
}

TEST(FileSafety, HeaderErrorsNameTheProblem) {
  std::vector<uint8_t> file = small_file(false);
  Mesh out;
  DecodeStats ds;
  auto message = [&](std::vector<uint8_t> bytes) {
    return decode_mesh(bytes.data(), bytes.size(), DecodeOptions(), &out, &ds).message();
  };
  std::vector<uint8_t> bad = file;
  bad[1] = 'X';
  EXPECT_EQ(message(bad), "not a .gab file (bad magic)");
  bad = file;
  bad[8] = 9;
  EXPECT_EQ(message(bad), "unsupported .gab version 9 (this build reads version 2)");
  // The first version's files (a different header and connectivity coders)
  // are not read: the message names the version.
  bad[8] = 1;
  const Status first = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(first.code(), StatusCode::kUnsupported);
  EXPECT_EQ(first.message(), "unsupported .gab version 1 (this build reads version 2; re-encode the mesh)");
  // A newer writer's flag, with the header's checksum made whole again: a
  // well-formed file this build cannot read, not a corrupt one.
  const size_t header = header_size(file);
  const auto with_header_crc = [header](std::vector<uint8_t> f) {
    const uint32_t crc = crc32(f.data(), header - 4);
    for (int b = 0; b < 4; ++b) f[header - 4 + b] = static_cast<uint8_t>(crc >> (8 * b));
    return f;
  };
  bad = file;
  bad[9] |= 0x40;
  bad = with_header_crc(bad);
  const Status unknown_flag = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(unknown_flag.code(), StatusCode::kUnsupported);
  char flags[8];
  std::snprintf(flags, sizeof flags, "0x%02x", bad[9]);
  EXPECT_EQ(unknown_flag.message(), "unsupported .gab flags " + std::string(flags) + " (this build knows 0x1f)");
  // A newer writer's ordering (byte 11) or reconstruction operator (byte
  // 12), or a use of the reserved byte (13): unsupported, not corrupt.
  const struct {
    size_t at;
    uint8_t value;
    const char* message;
  } newer[] = {
      {11, 2, "unsupported .gab ordering 2 (this build knows 0: amd, 1: nd)"},
      {12, 4,
       "unsupported .gab reconstruction operator 4 (this build knows 0: global least squares, 1: iterative, 2: "
       "iterative, local predictions, 3: iterative, local predictions, tuned)"},
      {13, 7, "unsupported .gab header: reserved byte 13 is 0x07"},
  };
  for (const auto& n : newer) {
    bad = file;
    bad[n.at] = n.value;
    bad = with_header_crc(bad);
    const Status s = decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds);
    EXPECT_EQ(s.code(), StatusCode::kUnsupported) << n.at;
    EXPECT_EQ(s.message(), n.message);
  }
  // Fields each finite but whose products would overflow the solve: a
  // weight past 1e100, a grid reaching past 2e100 (its origin, or its step
  // times 2^bits - 1).
  size_t weight_at = 14;  // past the magic, version and five bytes: then the n and faces varints
  for (int varint = 0; varint < 2; ++varint) {
    while (file[weight_at++] & 0x80) {
    }
  }
  const auto with_f64 = [&](size_t at, double value) {
    std::vector<uint8_t> f = file;
    uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int b = 0; b < 8; ++b) f[at + b] = static_cast<uint8_t>(bits >> (8 * b));
    return with_header_crc(f);
  };
  EXPECT_EQ(message(with_f64(weight_at, 1e101)), "bad .gab header: anchor weight is not in (0, 1e100]");
  EXPECT_EQ(message(with_f64(weight_at + 8, -3e100)), "bad .gab header: the grid reaches past 2e100");
  EXPECT_EQ(message(with_f64(weight_at + 32, 1e99)), "bad .gab header: the grid reaches past 2e100");
  GabFileInfo at_bound;  // an origin at -1e100: the header reads (its anchors then lie off the moved grid)
  const std::vector<uint8_t> moved = with_f64(weight_at + 8, -1e100);
  EXPECT_TRUE(read_gab_info(moved.data(), moved.size(), &at_bound).ok());
  bad = file;
  bad[24] ^= 1;  // inside the weight
  EXPECT_EQ(message(bad), "bad .gab header: checksum mismatch (the header is corrupt)");
  EXPECT_EQ(message(std::vector<uint8_t>(file.begin(), file.begin() + 30)),
            "bad .gab header: file ends inside the header");
  bad = file;
  bad[header + 9] ^= 4;  // inside the connectivity block
  EXPECT_EQ(message(bad), "connectivity block is corrupt (checksum mismatch)");
  bad = file;
  bad[bad.size() - 1] ^= 4;  // inside the last chunk
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  EXPECT_EQ(message(bad), "chunk " + std::to_string(info.chunks - 1) + " is corrupt (checksum mismatch)");
  bad = file;
  bad.push_back(0);
  EXPECT_EQ(message(bad), "trailing bytes after the last chunk");
}

// Sections after the geometry (gab_format.h): a kind this build does not
// know is skipped unless the section is required.
TEST(FileSafety, UnknownSectionsAreSkippedUnlessRequired) {
  const std::vector<uint8_t> file = small_file(false);
  Mesh plain, out;
  DecodeStats ds;
  ASSERT_TRUE(decode_mesh(file.data(), file.size(), DecodeOptions(), &plain, &ds).ok());
  const auto with_section = [&](uint8_t flags) {
    // The same file with a section count of 1 (a one-byte varint before the
    // header's CRC, as the 0 it replaces) and a section at the end.
    std::vector<uint8_t> f = file;
    const size_t header = header_size(file);
    f[header - 5] = 1;
    const uint32_t crc = crc32(f.data(), header - 4);
    for (int b = 0; b < 4; ++b) f[header - 4 + b] = static_cast<uint8_t>(crc >> (8 * b));
    ByteWriter w;
    const uint8_t payload[] = {200, flags, 1, 2, 3};
    write_framed(payload, sizeof payload, &w);
    f.insert(f.end(), w.data().begin(), w.data().end());
    return f;
  };
  std::vector<uint8_t> optional = with_section(0);
  Status s = decode_mesh(optional.data(), optional.size(), DecodeOptions(), &out, &ds);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(ds.skipped_sections, 1);
  EXPECT_EQ(out.positions, plain.positions);
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(optional.data(), optional.size(), &info).ok());
  EXPECT_EQ(info.sections, 1);
  std::vector<uint8_t> required = with_section(kGabSectionRequired);
  s = decode_mesh(required.data(), required.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.code(), StatusCode::kUnsupported);
  EXPECT_EQ(s.message(), "section 0 is of kind 200, which this build does not know and the file requires");
  optional.back() ^= 1;
  EXPECT_EQ(decode_mesh(optional.data(), optional.size(), DecodeOptions(), &out, &ds).message(),
            "section 0 is corrupt (checksum mismatch)");
  optional = with_section(0);
  optional.push_back(0);
  EXPECT_EQ(decode_mesh(optional.data(), optional.size(), DecodeOptions(), &out, &ds).message(),
            "trailing bytes after the last section");
}

TEST(FileSafety, ForgedCountsCannotForceHugeAllocations) {
  // n = 2^31 - 1 with a valid checksum: refused from the file size alone.
  ByteWriter w;
  GabHeader h;
  h.num_vertices = 0x7FFFFFFF;
  h.num_triangles = 1;
  h.anchors = 1;
  h.chunks = 1;
  write_gab_header(h, &w);
  std::vector<uint8_t> forged = w.take();
  Mesh out;
  DecodeStats ds;
  EXPECT_EQ(decode_mesh(forged.data(), forged.size(), DecodeOptions(), &out, &ds).message(),
            "bad .gab header: vertex count is implausible for a file of this size");

  // A real file whose header (checksum made whole) declares 100M
  // triangles: refused against the connectivity block's size before the
  // block is decoded.
  const std::vector<uint8_t> file = small_file(false);
  ByteReader in(file.data(), file.size());
  ASSERT_TRUE(read_gab_header(&in, file.size(), &h).ok());
  const size_t rest = in.offset();
  h.num_triangles = 100000000;
  h.num_vertices = std::min<int32_t>(h.num_vertices, 1000);
  ByteWriter rewritten;
  write_gab_header(h, &rewritten);
  forged = rewritten.take();
  forged.insert(forged.end(), file.begin() + static_cast<std::ptrdiff_t>(rest), file.end());
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  const size_t block = info.connectivity_bytes - kGabFrameBytes;
  // The default memory budget (64 MiB for a file this small) refuses the
  // count from the header alone.
  Status s = decode_mesh(forged.data(), forged.size(), DecodeOptions(), &out, &ds);
  EXPECT_EQ(s.code(), StatusCode::kResourceExhausted);
  EXPECT_EQ(s.message(), "decoding needs about 1145 MiB (" + std::to_string(h.num_vertices) +
                             " vertices, 100000000 triangles), over its memory limit of 64 MiB: raise it "
                             "(DecodeOptions::max_memory, gab decompress --max-memory)");
  // Without a budget, the connectivity block's size refuses it.
  DecodeOptions unbounded;
  unbounded.max_memory = -1;
  s = decode_mesh(forged.data(), forged.size(), unbounded, &out, &ds);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), "connectivity block: connectivity: the header's 100000000 triangles are more than a block of " +
                             std::to_string(block) + " bytes can describe");
}

TEST(FileSafety, EveryOtherDeclaredCountIsBoundedByTheFile) {
  // The anchors, chunks and sections a real file's header (checksum made
  // whole) declares, forged one at a time.
  const std::vector<uint8_t> file = small_file(false);
  ByteReader in(file.data(), file.size());
  GabHeader real;
  ASSERT_TRUE(read_gab_header(&in, file.size(), &real).ok());
  const size_t rest = in.offset();
  auto decode_with = [&](const GabHeader& h) {
    ByteWriter w;
    write_gab_header(h, &w);
    std::vector<uint8_t> forged = w.take();
    forged.insert(forged.end(), file.begin() + static_cast<std::ptrdiff_t>(rest), file.end());
    Mesh out;
    DecodeStats ds;
    return decode_mesh(forged.data(), forged.size(), DecodeOptions(), &out, &ds).message();
  };
  GabHeader h = real;
  h.anchors = real.num_vertices + 1;  // at most one anchor per vertex
  EXPECT_EQ(decode_with(h), "bad .gab header: anchor count out of range");
  h = real;
  h.chunks = real.anchors + 2;  // at most one chunk per anchor, and the detail or refinement chunk
  EXPECT_EQ(decode_with(h), "bad .gab header: chunk count out of range");
  h = real;
  ASSERT_GT(real.anchors, real.chunks);
  h.chunks = real.anchors;  // in range, but the level layout's first chunk says how many follow
  const std::string message = decode_with(h);
  EXPECT_EQ(message.rfind("chunk 0: level plan makes ", 0), 0u) << message;
  EXPECT_NE(message.find("levels; the header declares "), std::string::npos) << message;
  h = real;
  h.sections = 100000000;  // each a frame the file would have to hold: the first missing ends the walk
  EXPECT_EQ(decode_with(h), "");
  h.sections = 0x7FFFFFFF;
  EXPECT_EQ(decode_with(h), "bad .gab header: section count out of range");
}

TEST(FileSafety, HeaderCountsAreMinimal32BitVarints) {
  const std::vector<uint8_t> file = small_file(false);
  Mesh out;
  DecodeStats ds;
  // n is the varint at byte 14; a padded (non-minimal) form of it, or one
  // of more than 32 bits, is refused before the checksum is read.
  for (const std::vector<uint8_t>& n : {std::vector<uint8_t>{0x80, 0x80, 0x80, 0x80, 0x80, 0x01},
                                       std::vector<uint8_t>{0xff, 0xff, 0xff, 0xff, 0x7f}}) {
    size_t end = 14;
    while (file[end] & 0x80) ++end;
    std::vector<uint8_t> bad(file.begin(), file.begin() + 14);
    bad.insert(bad.end(), n.begin(), n.end());
    bad.insert(bad.end(), file.begin() + static_cast<std::ptrdiff_t>(end + 1), file.end());
    EXPECT_EQ(decode_mesh(bad.data(), bad.size(), DecodeOptions(), &out, &ds).message(),
              "bad .gab header: a count in the header is not a minimal 32-bit varint");
  }
}

}  // namespace
}  // namespace gab
