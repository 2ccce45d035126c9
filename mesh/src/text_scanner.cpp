#include "text_scanner.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace gab {
namespace mesh_detail {

namespace {

// Blank bytes that do not end a line. A line ends at '\n', '\r\n' or a
// lone '\r' (old Mac OS, Rhino's exports): a '\r' counts as a line end
// unless a '\n' follows it, which then ends the line itself.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v'; }
inline bool is_line_end(char c) { return c == '\n' || c == '\r'; }

}  // namespace

TextScanner::TextScanner(std::string_view text, const std::string& name, char comment)
    : text_(text), name_(name), comment_(comment) {
  pos_ = bom_length(text);
}

bool TextScanner::next(std::string_view* token) {
  const size_t n = text_.size();
  const char* s = text_.data();
  while (pos_ < n) {
    const char c = s[pos_];
    if (c == '\n' || (c == '\r' && (pos_ + 1 == n || s[pos_ + 1] != '\n'))) {
      ++line_;
      ++pos_;
    } else if (is_blank(c) || c == '\r') {
      ++pos_;
    } else if (c == comment_ && c != '\0') {
      while (pos_ < n && !is_line_end(s[pos_])) ++pos_;
    } else {
      break;
    }
  }
  if (pos_ >= n) {
    token_line_ = line_;
    return false;
  }
  const size_t start = pos_;
  while (pos_ < n) {
    const char c = s[pos_];
    if (is_line_end(c) || is_blank(c) || (c == comment_ && c != '\0')) break;
    ++pos_;
  }
  *token = std::string_view(s + start, pos_ - start);
  token_line_ = line_;
  return true;
}

void TextScanner::skip_line() {
  const size_t n = text_.size();
  while (pos_ < n && !is_line_end(text_[pos_])) ++pos_;
  if (pos_ < n) {
    if (text_[pos_] == '\r' && pos_ + 1 < n && text_[pos_ + 1] == '\n') ++pos_;
    ++pos_;
    ++line_;
  }
}

bool TextScanner::at_line_end() {
  const size_t n = text_.size();
  while (pos_ < n && is_blank(text_[pos_])) ++pos_;
  return pos_ >= n || is_line_end(text_[pos_]) || (text_[pos_] == comment_ && comment_ != '\0');
}

Status TextScanner::error(const std::string& what) const {
  return Status::Error(StatusCode::kParseError, name_ + ":" + std::to_string(token_line_) + ": " + what);
}

Status TextScanner::error_here(const std::string& what) const {
  return Status::Error(StatusCode::kParseError, name_ + ":" + std::to_string(line_) + ": " + what);
}

bool parse_int(std::string_view token, int64_t* out) {
  size_t i = 0;
  bool negative = false;
  if (!token.empty() && (token[0] == '-' || token[0] == '+')) {
    negative = token[0] == '-';
    i = 1;
  }
  if (i == token.size() || token.size() - i > 18) return false;
  int64_t v = 0;
  for (; i < token.size(); ++i) {
    const char c = token[i];
    if (c < '0' || c > '9') return false;
    v = v * 10 + (c - '0');
  }
  *out = negative ? -v : v;
  return true;
}

bool parse_real(std::string_view token, double* out) {
  const char* begin = token.data();
  const char* end = begin + token.size();
  // from_chars takes no leading '+'; "+-1" must stay an error.
  if (begin != end && *begin == '+') {
    ++begin;
    if (begin != end && *begin == '-') return false;
  }
  if (begin == end) return false;
  const std::from_chars_result r = std::from_chars(begin, end, *out);
  if (r.ec == std::errc::result_out_of_range) {
    // Overflow reads as infinity (the caller rejects it); underflow as 0.
    bool exponent_negative = false;
    for (const char* p = begin; p != end; ++p) {
      if ((*p == 'e' || *p == 'E') && p + 1 != end && p[1] == '-') exponent_negative = true;
    }
    const bool negative = *begin == '-';
    *out = exponent_negative ? (negative ? -0.0 : 0.0) : (negative ? -HUGE_VAL : HUGE_VAL);
    return r.ptr == end;
  }
  return r.ec == std::errc() && r.ptr == end;
}

std::string printable(std::string_view token) {
  std::string out;
  const size_t shown = token.size() < 32 ? token.size() : 32;
  for (size_t i = 0; i < shown; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\x%02x", c);
      out += buf;
    }
  }
  if (shown < token.size()) out += "...";
  return out;
}

void append_real(std::string* out, double value) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), value);
  out->append(buf, r.ptr);
}

void append_int(std::string* out, int64_t value) {
  char buf[24];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), value);
  out->append(buf, r.ptr);
}

size_t bom_length(std::string_view text) {
  return text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
}

}  // namespace mesh_detail
}  // namespace gab
