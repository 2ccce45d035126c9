// Internal to the mesh layer: a whitespace tokenizer over text in memory that
// counts lines for error messages (a line ends at '\n', '\r\n' or a lone
// '\r'), and strict number parsing (the whole token
// must be a number; std::from_chars, so the locale never changes the result).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "gab/status.h"

namespace gab {
namespace mesh_detail {

class TextScanner {
 public:
  // `comment` starts a comment running to the end of the line ('\0': none).
  TextScanner(std::string_view text, const std::string& name, char comment);

  // Next whitespace-separated token; false at the end of the text. O(token).
  bool next(std::string_view* token);
  // Skips to the start of the next line (extras after a record). O(line).
  void skip_line();
  // True if only blanks (and a comment) remain on the current line.
  bool at_line_end();

  // Line number of the text's first line (for text that starts mid-file).
  void set_line(int64_t line) { line_ = token_line_ = line; }

  size_t position() const { return pos_; }
  size_t remaining() const { return text_.size() - pos_; }
  // Line of the last token returned / of the current position (1-based).
  int64_t token_line() const { return token_line_; }
  int64_t line() const { return line_; }

  // "<name>:<line>: <what>" at the last token / at the current position.
  Status error(const std::string& what) const;
  Status error_here(const std::string& what) const;

 private:
  std::string_view text_;
  const std::string& name_;
  char comment_;
  size_t pos_ = 0;
  int64_t line_ = 1;
  int64_t token_line_ = 1;
};

// Whole-token integer (optional sign, at most 18 digits). False otherwise.
bool parse_int(std::string_view token, int64_t* out);
// Whole-token real number (decimal or exponent form, optional leading '+';
// "nan" / "inf" parse, so callers check finiteness and say so). False otherwise.
bool parse_real(std::string_view token, double* out);

// A token as it may appear in a message: at most 32 characters, bytes that
// are not printable ASCII shown as \xNN.
std::string printable(std::string_view token);

// Shortest text that reads back to exactly `value` (std::to_chars).
void append_real(std::string* out, double value);
void append_int(std::string* out, int64_t value);
// The most characters those write for a double (shortest round trip: sign,
// 17 digits, point, "e-308") and for a vertex index (int32 with sign). The
// writers reserve with them: a string that grows copies itself and faults
// in fresh memory every time (a 134k-vertex OFF reserved 11 MB and grew to
// 22.5 MB).
constexpr size_t kMaxRealChars = 24;
constexpr size_t kMaxIndexChars = 11;

// Bytes of a UTF-8 byte-order mark at the start of `text` (0 or 3).
size_t bom_length(std::string_view text);

}  // namespace mesh_detail
}  // namespace gab
