// OFF reader. The format is token-based (a record may span lines), so the
// parser walks tokens while counting lines for the error messages.
#include "gab/mesh/off_io.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace gab {

namespace {

class Tokens {
 public:
  Tokens(const std::string& text, const std::string& name) : text_(text), name_(name) {}

  // Next whitespace-separated token, skipping '#' comments; false at end.
  bool next(const char** begin, size_t* len) {
    const size_t n = text_.size();
    while (pos_ < n) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (c == '#') {
        while (pos_ < n && text_[pos_] != '\n') ++pos_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else {
        break;
      }
    }
    if (pos_ >= n) return false;
    const size_t start = pos_;
    while (pos_ < n && !std::strchr(" \t\r\n\f\v#", text_[pos_])) ++pos_;
    *begin = text_.data() + start;
    *len = pos_ - start;
    token_line_ = line_;
    return true;
  }

  // Skips the rest of the current line (extras after a record).
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }

  Status error(const std::string& what) const {
    return Status::Error(StatusCode::kParseError,
                         name_ + ":" + std::to_string(token_line_) + ": " + what);
  }
  Status error_at_end(const std::string& what) const {
    return Status::Error(StatusCode::kParseError, name_ + ":" + std::to_string(line_) + ": " + what);
  }
  size_t size() const { return text_.size(); }

 private:
  const std::string& text_;
  const std::string& name_;
  size_t pos_ = 0;
  int64_t line_ = 1;
  int64_t token_line_ = 1;
};

bool parse_int(const char* s, size_t len, int64_t* out) {
  if (len == 0 || len > 18) return false;
  size_t i = 0;
  bool neg = false;
  if (s[0] == '-' || s[0] == '+') {
    neg = s[0] == '-';
    if (++i == len) return false;
  }
  int64_t v = 0;
  for (; i < len; ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    v = v * 10 + (s[i] - '0');
  }
  *out = neg ? -v : v;
  return true;
}

bool parse_double(const char* s, size_t len, double* out) {
  char buf[64];
  if (len == 0 || len >= sizeof(buf)) return false;
  std::memcpy(buf, s, len);
  buf[len] = '\0';
  char* end = nullptr;
  *out = std::strtod(buf, &end);
  return end == buf + len;
}

}  // namespace

Status parse_off(const std::string& text, const std::string& name, Mesh* mesh) {
  Tokens tok(text, name);
  const char* t;
  size_t len;
  if (!tok.next(&t, &len)) return tok.error_at_end("empty file, expected an OFF header");
  const std::string magic(t, len);
  const bool has_normals = magic.find('N') != std::string::npos;
  const bool has_colors = magic.find('C') != std::string::npos;
  if (magic != "OFF" && magic != "COFF" && magic != "NOFF" && magic != "CNOFF" && magic != "NCOFF") {
    return tok.error("not an OFF file (header '" + magic.substr(0, 16) + "')");
  }
  int64_t counts[3];
  for (int i = 0; i < 3; ++i) {
    if (!tok.next(&t, &len)) return tok.error_at_end("truncated header: expected vertex, face and edge counts");
    if (!parse_int(t, len, &counts[i]) || counts[i] < 0) {
      return tok.error("bad count '" + std::string(t, len < 32 ? len : 32) + "' in header");
    }
  }
  const int64_t nv = counts[0], nf = counts[1];
  // Never trust a count for allocation: every vertex needs at least 6 bytes
  // ("0 0 0\n") and every face 8 ("3 0 1 2\n").
  if (nv > static_cast<int64_t>(tok.size() / 6) + 1 || nf > static_cast<int64_t>(tok.size() / 8) + 1) {
    return tok.error("header claims " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                     " faces, more than the file's " + std::to_string(tok.size()) + " bytes can hold");
  }
  if (nv == 0) return tok.error("mesh has no vertices");
  tok.skip_line();
  Mesh m;
  m.positions.resize(static_cast<size_t>(nv) * 3);
  for (int64_t v = 0; v < nv; ++v) {
    for (int c = 0; c < 3; ++c) {
      if (!tok.next(&t, &len)) {
        return tok.error_at_end("truncated: file ends in vertex " + std::to_string(v) + " of " +
                                std::to_string(nv));
      }
      double x;
      if (!parse_double(t, len, &x)) {
        return tok.error("vertex " + std::to_string(v) + ": bad coordinate '" +
                         std::string(t, len < 32 ? len : 32) + "'");
      }
      if (!std::isfinite(x)) return tok.error("vertex " + std::to_string(v) + ": coordinate is not finite");
      m.positions[static_cast<size_t>(v) * 3 + c] = x;
    }
    if (has_normals || has_colors) tok.skip_line();
  }
  m.triangles.reserve(static_cast<size_t>(nf) * 3);
  for (int64_t f = 0; f < nf; ++f) {
    int64_t k;
    if (!tok.next(&t, &len)) {
      return tok.error_at_end("truncated: file ends in face " + std::to_string(f) + " of " + std::to_string(nf));
    }
    if (!parse_int(t, len, &k)) return tok.error("face " + std::to_string(f) + ": bad vertex count");
    if (k < 3) return tok.error("face " + std::to_string(f) + " has " + std::to_string(k) + " vertices (need 3 or more)");
    if (k > nv && k > 1000000) return tok.error("face " + std::to_string(f) + ": absurd vertex count " + std::to_string(k));
    int32_t first = 0, prev = 0;
    for (int64_t c = 0; c < k; ++c) {
      int64_t idx;
      if (!tok.next(&t, &len)) {
        return tok.error_at_end("truncated: file ends in face " + std::to_string(f) + " of " + std::to_string(nf));
      }
      if (!parse_int(t, len, &idx)) {
        return tok.error("face " + std::to_string(f) + ": bad vertex index '" + std::string(t, len < 32 ? len : 32) + "'");
      }
      if (idx < 0 || idx >= nv) {
        return tok.error("face " + std::to_string(f) + ": vertex index " + std::to_string(idx) +
                         " out of range [0, " + std::to_string(nv) + ")");
      }
      // Fan triangulation (v0, v_{c-1}, v_c).
      if (c == 0) first = static_cast<int32_t>(idx);
      if (c >= 2) {
        m.triangles.push_back(first);
        m.triangles.push_back(prev);
        m.triangles.push_back(static_cast<int32_t>(idx));
      }
      prev = static_cast<int32_t>(idx);
    }
    tok.skip_line();  // per-face colour, if any
  }
  *mesh = std::move(m);
  return Status::Ok();
}

Status read_off(const std::string& path, Mesh* mesh) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    return Status::Error(StatusCode::kIoError, path + ": cannot open: " + std::strerror(errno));
  }
  std::string text;
  char buf[1 << 16];
  size_t got;
  while ((got = std::fread(buf, 1, sizeof(buf), file)) > 0) text.append(buf, got);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) return Status::Error(StatusCode::kIoError, path + ": read error");
  return parse_off(text, path, mesh);
}

}  // namespace gab
