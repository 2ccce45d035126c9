// Matrix Market coordinate files: a strict, fast reader and an atomic writer.
//
// Format: Boisvert, Pozo & Remington, "The Matrix Market Exchange Formats:
// Initial Design" (NIST IR 5935, 1996), coordinate section.
//
// The reader streams the file through one reused block (fread, no iostreams)
// and walks it line by line with pointers: indices go through a hand-written
// integer parser, values through std::from_chars (locale-free, correctly
// rounded). Every rejection names the file and the 1-based line, because the
// person reading the message has the file open in an editor. The engine
// builds with -fno-exceptions, so failures are Status values, and nothing is
// allocated from a header count until the input's size has bounded it (a
// failed allocation would abort the process).
#include "gab/sparse/matrix_market.h"

#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#if __has_include(<unistd.h>)
#include <unistd.h>  // fsync: durability of the temporary before it is renamed
#define GAB_HAVE_FSYNC 1
#endif

namespace gab {

namespace {

constexpr int64_t kIndexLimit = std::numeric_limits<int32_t>::max();

// Dimensions cost memory (colptr and the assembly cursors) whatever the
// entries are, so a header alone could ask for gigabytes. Up to this size a
// dimension is always believed; above it the file must show at least one
// byte per kRowsPerByte rows/columns (real matrices are far denser).
constexpr int64_t kFreeDimension = int64_t{1} << 24;
constexpr int64_t kRowsPerByte = 16;

// The shortest entry line is "1 1\n": the file size bounds the entry count.
constexpr size_t kMinEntryBytes = 4;

enum class Field { kReal, kInteger, kPattern };

// A run of non-blank characters on a line.
struct Token {
  const char* begin;
  const char* end;
  size_t size() const { return static_cast<size_t>(end - begin); }
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Splits [begin, end) into blank-separated tokens; stores at most `capacity`
// and returns how many there are in all (so messages can say "got 4").
int split_tokens(const char* begin, const char* end, Token* tokens, int capacity) {
  int count = 0;
  const char* p = begin;
  for (;;) {
    while (p < end && is_blank(*p)) ++p;
    if (p == end) return count;
    const char* start = p;
    while (p < end && !is_blank(*p)) ++p;
    if (count < capacity) tokens[count] = Token{start, p};
    ++count;
  }
}

bool iequals(const Token& t, const char* word) {
  const size_t n = std::strlen(word);
  if (t.size() != n) return false;
  for (size_t k = 0; k < n; ++k) {
    char c = t.begin[k];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != word[k]) return false;
  }
  return true;
}

// A token for a message: quoted, cut short, unprintable bytes shown as '?'
// so one bad byte cannot break the one-line message.
std::string quoted(const Token& t) {
  constexpr size_t kMaxShown = 40;
  std::string s = "'";
  for (size_t k = 0; k < t.size() && k < kMaxShown; ++k) {
    const unsigned char c = static_cast<unsigned char>(t.begin[k]);
    s += (c >= 0x20 && c < 0x7f) ? static_cast<char>(c) : '?';
  }
  if (t.size() > kMaxShown) s += "...";
  s += "'";
  return s;
}

// Shortest text that reads back as the same double.
std::string format_double(double v) {
  char buf[32];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

enum class IntegerParse { kOk, kNotInteger, kTooLarge };

// Decimal integer with an optional sign, the whole token. Keeps scanning past
// an overflow so "99999999999999999999x" is reported as not an integer.
IntegerParse parse_integer(const Token& t, int64_t* out) {
  const char* p = t.begin;
  bool negative = false;
  if (p < t.end && (*p == '+' || *p == '-')) {
    negative = *p == '-';
    ++p;
  }
  if (p == t.end) return IntegerParse::kNotInteger;
  constexpr uint64_t kMax = static_cast<uint64_t>(std::numeric_limits<int64_t>::max());
  uint64_t v = 0;
  bool too_large = false;
  for (; p < t.end; ++p) {
    if (!is_digit(*p)) return IntegerParse::kNotInteger;
    const uint64_t d = static_cast<uint64_t>(*p - '0');
    // Constant bound first: the exact test (a division) runs only near the limit.
    if (v > (kMax - 9) / 10 && v > (kMax - d) / 10) {
      too_large = true;
    } else {
      v = v * 10 + d;
    }
  }
  if (too_large) return IntegerParse::kTooLarge;
  *out = negative ? -static_cast<int64_t>(v) : static_cast<int64_t>(v);
  return IntegerParse::kOk;
}

// For a decimal token from_chars found out of range: true when its magnitude
// is below one (it underflows to zero, which is a fine value), false when it
// is above (it overflows to infinity, which is not). Exponent saturates.
bool magnitude_below_one(const Token& t) {
  const char* p = t.begin;
  if (p < t.end && (*p == '+' || *p == '-')) ++p;
  bool nonzero_seen = false;
  int64_t integer_digits = 0;  // significant digits before the point
  int64_t leading_zeros = 0;   // zeros after the point before the first nonzero
  for (; p < t.end && is_digit(*p); ++p) {
    if (nonzero_seen || *p != '0') {
      nonzero_seen = true;
      ++integer_digits;
    }
  }
  if (p < t.end && *p == '.') {
    ++p;
    for (; !nonzero_seen && p < t.end && *p == '0'; ++p) ++leading_zeros;
    while (p < t.end && is_digit(*p)) ++p;
  }
  int64_t exponent = 0;
  if (p < t.end && (*p == 'e' || *p == 'E')) {
    ++p;
    bool negative = false;
    if (p < t.end && (*p == '+' || *p == '-')) {
      negative = *p == '-';
      ++p;
    }
    for (; p < t.end && is_digit(*p); ++p) {
      if (exponent < 1000000000) exponent = exponent * 10 + (*p - '0');
    }
    if (negative) exponent = -exponent;
  }
  const int64_t order = nonzero_seen ? integer_digits - 1 + exponent : exponent - leading_zeros - 1;
  return order < 0;
}

enum class ValueParse { kOk, kNotNumber, kNotInteger, kNotFinite };

// A finite double, the whole token. `integer_field`: the banner said
// "integer", so only [+-]digits is accepted.
ValueParse parse_value(const Token& t, bool integer_field, double* out) {
  const char* p = t.begin;
  // from_chars takes no '+'; allow one, but not "+-1".
  if (p + 1 < t.end && *p == '+' && p[1] != '-' && p[1] != '+') ++p;
  double v = 0.0;
  const std::from_chars_result r = std::from_chars(p, t.end, v);
  if (r.ptr != t.end || r.ec == std::errc::invalid_argument) return ValueParse::kNotNumber;
  if (integer_field) {
    int64_t ignored = 0;
    if (parse_integer(t, &ignored) == IntegerParse::kNotInteger) return ValueParse::kNotInteger;
  }
  if (r.ec == std::errc::result_out_of_range) {
    if (!magnitude_below_one(t)) return ValueParse::kNotFinite;
    v = (*t.begin == '-') ? -0.0 : 0.0;
  } else if (!std::isfinite(v)) {
    return ValueParse::kNotFinite;
  }
  *out = v;
  return ValueParse::kOk;
}

// What a file says, before assembly into CSC.
struct ParsedFile {
  MatrixMarketInfo info;
  int32_t nrows = 0;
  int32_t ncols = 0;
  int64_t size_line = 0;
  std::vector<Triplet> entries;      // 0-based; upper entries of symmetric files mirrored
  std::vector<int64_t> entry_lines;  // line of each entry (only when asked for)
};

// The text being parsed, handed out line by line. From memory the text is
// one window; from a file the window is a reused block refilled as lines are
// consumed. Streaming, not slurping: touching a fresh buffer the size of the
// file costs more than parsing it (measured: 0.15 s of page faults for a
// 45 MB file against 2 ms through a reused 1 MiB block). A stream whose size
// cannot be asked (a pipe) is read whole at open, so the total is always
// known to the guards that bound allocation by the input's size.
class TextSource {
 public:
  TextSource() = default;
  TextSource(const char* data, size_t size)
      : next_(data),
        end_(data + size),
        bytes_read_(static_cast<int64_t>(size)),
        total_bytes_(static_cast<int64_t>(size)) {}
  TextSource(const TextSource&) = delete;
  TextSource& operator=(const TextSource&) = delete;
  ~TextSource() {
    if (file_ != nullptr) std::fclose(file_);
  }

  Status open(const std::string& path) {
    path_ = path;
    file_ = std::fopen(path.c_str(), "rb");
    if (file_ == nullptr) {
      return Status::Error(StatusCode::kIoError,
                           "cannot open '" + path + "': " + std::strerror(errno));
    }
    // A directory opens and reports some size here; its first read fails,
    // before anything is allocated from that size.
    if (std::fseek(file_, 0, SEEK_END) == 0) {
      const long size = std::ftell(file_);
      if (std::fseek(file_, 0, SEEK_SET) != 0) {
        return Status::Error(StatusCode::kIoError,
                             "cannot read '" + path + "': " + std::strerror(errno));
      }
      if (size >= 0) {
        total_bytes_ = size;
        return Status::Ok();
      }
    }
    while (refill()) {
      // Not seekable: keep everything (refill grows a full window).
    }
    total_bytes_ = bytes_read_;
    return io_status();
  }

  // The next line as [*begin, *end), without its '\n'; false at the end of
  // the text (or at a read failure, which io_status() then reports). A final
  // line without '\n' still counts.
  bool next_line(const char** begin, const char** end) {
    size_t searched = 0;  // bytes of a partial line already searched
    for (;;) {
      const size_t unsearched = static_cast<size_t>(end_ - next_) - searched;
      // memchr wants a real pointer even for zero bytes (the window starts null).
      const void* nl = unsearched > 0 ? std::memchr(next_ + searched, '\n', unsearched) : nullptr;
      if (nl != nullptr) {
        *begin = next_;
        *end = static_cast<const char*>(nl);
        next_ = *end + 1;
        return true;
      }
      searched = static_cast<size_t>(end_ - next_);
      if (!refill()) break;
    }
    if (next_ == end_) return false;
    *begin = next_;
    *end = end_;
    next_ = end_;
    return true;
  }

  // Size of the whole input, and of what has not been handed out yet.
  int64_t total_bytes() const { return total_bytes_; }
  int64_t remaining_bytes() const {
    const int64_t consumed = bytes_read_ - static_cast<int64_t>(end_ - next_);
    return total_bytes_ > consumed ? total_bytes_ - consumed : 0;
  }

  Status io_status() const {
    if (out_of_memory_) {
      return Status::Error(StatusCode::kIoError,
                           "cannot read '" + path_ + "': a line too long to hold in memory");
    }
    if (read_failed_) {
      return Status::Error(StatusCode::kIoError,
                           "cannot read '" + path_ + "': " + std::strerror(read_errno_));
    }
    return Status::Ok();
  }

 private:
  static constexpr size_t kWindow = size_t{1} << 20;

  // Keeps the unconsumed tail (a partial line) at the front of the window
  // and reads after it, growing the window when the tail fills it. False
  // when nothing more came.
  bool refill() {
    if (file_ == nullptr || at_end_) return false;
    const size_t tail = static_cast<size_t>(end_ - next_);
    if (tail == capacity_) {
      // nothrow: a huge line is an error value, not an abort.
      const size_t capacity = capacity_ == 0 ? kWindow : capacity_ * 2;
      std::unique_ptr<char[]> bigger(new (std::nothrow) char[capacity]);
      if (!bigger) {
        out_of_memory_ = at_end_ = true;
        return false;
      }
      if (tail > 0) std::memcpy(bigger.get(), next_, tail);
      window_ = std::move(bigger);
      capacity_ = capacity;
    } else if (tail > 0 && next_ != window_.get()) {
      std::memmove(window_.get(), next_, tail);
    }
    char* base = window_.get();
    const size_t want = capacity_ - tail;
    const size_t got = std::fread(base + tail, 1, want, file_);
    next_ = base;
    end_ = base + tail + got;
    bytes_read_ += static_cast<int64_t>(got);
    if (got < want) {
      at_end_ = true;
      if (std::ferror(file_) != 0) {
        read_failed_ = true;
        read_errno_ = errno;
      }
    }
    return got > 0;
  }

  const char* next_ = nullptr;
  const char* end_ = nullptr;
  int64_t bytes_read_ = 0;
  int64_t total_bytes_ = 0;
  std::FILE* file_ = nullptr;
  std::string path_;
  std::unique_ptr<char[]> window_;
  size_t capacity_ = 0;
  bool at_end_ = false;
  bool out_of_memory_ = false;
  bool read_failed_ = false;
  int read_errno_ = 0;
};

// Walks the text one line at a time; the parse steps are its methods so that
// every message gets the file name and the current line for free.
class Parser {
 public:
  Parser(TextSource* source, const std::string& name) : source_(source), name_(name) {}

  Status parse(bool keep_lines, ParsedFile* out) {
    const Status parsed = parse_steps(keep_lines, out);
    // A read failure ends the text early; report it, not what it caused.
    GAB_RETURN_IF_ERROR(source_->io_status());
    return parsed;
  }

 private:
  Status parse_steps(bool keep_lines, ParsedFile* out) {
    GAB_RETURN_IF_ERROR(parse_banner(out));
    GAB_RETURN_IF_ERROR(parse_size_line(out, &declared_));
    return parse_entries(keep_lines, out);
  }

  // Moves to the next line; false at the end of the text.
  bool next_line() {
    if (!source_->next_line(&line_begin_, &line_end_)) return false;
    ++line_;
    return true;
  }

  // Moves to the next line that is neither blank nor a '%' comment.
  bool next_content_line() {
    while (next_line()) {
      const char* p = line_begin_;
      while (p < line_end_ && is_blank(*p)) ++p;
      if (p < line_end_ && *p != '%') return true;
    }
    return false;
  }

  Status fail(const std::string& what, StatusCode code = StatusCode::kParseError) const {
    return Status::Error(code, name_ + ":" + std::to_string(line_ == 0 ? 1 : line_) + ": " + what);
  }

  Status parse_banner(ParsedFile* out) {
    static const char kExpected[] =
        "expected '%%MatrixMarket matrix coordinate <real|integer|pattern> "
        "<general|symmetric>'";
    if (!next_line()) return fail(std::string("empty file; ") + kExpected);
    Token words[6];
    const int count = split_tokens(line_begin_, line_end_, words, 6);
    if (count == 0 || !iequals(words[0], "%%matrixmarket")) {
      if (count > 0 && words[0].size() >= 2 && words[0].begin[0] == '%' &&
          words[0].begin[1] == '%') {
        return fail("garbled banner " + quoted(words[0]) + "; " + kExpected);
      }
      return fail(std::string("missing '%%MatrixMarket' banner; ") + kExpected);
    }
    if (count < 5) return fail("incomplete banner; " + std::string(kExpected));
    if (!iequals(words[1], "matrix")) {
      return fail("unsupported object " + quoted(words[1]) + " (only 'matrix' is read)");
    }
    if (iequals(words[2], "array")) {
      return fail("unsupported format 'array' (dense); only 'coordinate' files are read");
    }
    if (!iequals(words[2], "coordinate")) {
      return fail("unknown format " + quoted(words[2]) + " (expected 'coordinate')");
    }
    if (iequals(words[3], "real")) {
      field_ = Field::kReal;
    } else if (iequals(words[3], "integer")) {
      field_ = Field::kInteger;
    } else if (iequals(words[3], "pattern")) {
      field_ = Field::kPattern;
    } else if (iequals(words[3], "complex")) {
      return fail("unsupported field 'complex'; only real, integer and pattern files are read");
    } else {
      return fail("unknown field " + quoted(words[3]) + " (expected real, integer or pattern)");
    }
    if (iequals(words[4], "general")) {
      out->info.symmetry = MatrixMarketSymmetry::kGeneral;
    } else if (iequals(words[4], "symmetric")) {
      out->info.symmetry = MatrixMarketSymmetry::kSymmetric;
    } else if (iequals(words[4], "hermitian") || iequals(words[4], "skew-symmetric")) {
      return fail("unsupported symmetry " + quoted(words[4]) +
                  "; only general and symmetric files are read");
    } else {
      return fail("unknown symmetry " + quoted(words[4]) + " (expected general or symmetric)");
    }
    if (count > 5) return fail("unexpected text " + quoted(words[5]) + " after the banner");
    out->info.pattern = field_ == Field::kPattern;
    return Status::Ok();
  }

  // One count of the size line: a non-negative integer within int32.
  Status parse_count(const Token& t, const char* what, int64_t* out) {
    const IntegerParse r = parse_integer(t, out);
    if (r == IntegerParse::kNotInteger) {
      return fail(std::string("size line: ") + what + " " + quoted(t) + " is not an integer");
    }
    if (r == IntegerParse::kTooLarge || *out > kIndexLimit) {
      return fail(std::string("size line: ") + what + " " + quoted(t) +
                      " exceeds the int32 index limit " + std::to_string(kIndexLimit),
                  StatusCode::kOverflow);
    }
    if (*out < 0) {
      return fail(std::string("size line: ") + what + " " + quoted(t) + " is negative");
    }
    return Status::Ok();
  }

  Status parse_size_line(ParsedFile* out, int64_t* declared) {
    if (!next_content_line()) return fail("missing size line (rows cols entries) after the banner");
    out->size_line = line_;
    Token fields[3];
    const int count = split_tokens(line_begin_, line_end_, fields, 3);
    if (count != 3) {
      return fail("expected 3 fields (rows cols entries) in the size line, got " +
                  std::to_string(count));
    }
    int64_t rows = 0, cols = 0;
    GAB_RETURN_IF_ERROR(parse_count(fields[0], "row count", &rows));
    GAB_RETURN_IF_ERROR(parse_count(fields[1], "column count", &cols));
    GAB_RETURN_IF_ERROR(parse_count(fields[2], "entry count", declared));
    const std::string dims = std::to_string(rows) + " x " + std::to_string(cols);
    if ((rows == 0 || cols == 0) && *declared > 0) {
      return fail("a " + dims + " matrix cannot hold the " + std::to_string(*declared) +
                  " entries declared");
    }
    if (out->info.symmetry == MatrixMarketSymmetry::kSymmetric && rows != cols) {
      return fail("a symmetric matrix must be square, the size line says " + dims);
    }
    const int64_t file_bytes = source_->total_bytes();
    const int64_t largest = rows > cols ? rows : cols;
    if (largest > kFreeDimension && largest / kRowsPerByte > file_bytes) {
      return fail("size line declares " + dims + ", implausibly large for a " +
                  std::to_string(file_bytes) + "-byte file (refusing to allocate for it)");
    }
    out->nrows = static_cast<int32_t>(rows);
    out->ncols = static_cast<int32_t>(cols);
    return Status::Ok();
  }

  Status index_error(const char* what, const Token& t, int64_t limit) {
    return fail(std::string(what) + " index " + quoted(t) + " is out of range [1, " +
                std::to_string(limit) + "]");
  }

  Status parse_entries(bool keep_lines, ParsedFile* out) {
    const bool pattern = field_ == Field::kPattern;
    const bool integer_field = field_ == Field::kInteger;
    const int expected = pattern ? 2 : 3;
    const char* const shape = pattern ? "(row col)" : "(row col value)";
    const bool symmetric = out->info.symmetry == MatrixMarketSymmetry::kSymmetric;
    // The header count is a claim; the remaining bytes are a fact.
    const uint64_t room = static_cast<uint64_t>(source_->remaining_bytes()) / kMinEntryBytes + 1;
    const size_t reserve = static_cast<size_t>(
        room < static_cast<uint64_t>(declared_) ? room : static_cast<uint64_t>(declared_));
    out->entries.reserve(reserve);
    if (keep_lines) out->entry_lines.reserve(reserve);

    int64_t found = 0;
    Token fields[3];
    while (next_content_line()) {
      if (found == declared_) {
        return fail("more entries than the " + std::to_string(declared_) +
                    " declared in the size line (line " + std::to_string(out->size_line) + ")");
      }
      const int count = split_tokens(line_begin_, line_end_, fields, 3);
      if (count != expected) {
        return fail("expected " + std::to_string(expected) + " fields " + shape + ", got " +
                    std::to_string(count));
      }
      int64_t row = 0, col = 0;
      IntegerParse r = parse_integer(fields[0], &row);
      if (r == IntegerParse::kNotInteger) {
        return fail("row index " + quoted(fields[0]) + " is not an integer");
      }
      if (r == IntegerParse::kTooLarge || row < 1 || row > out->nrows) {
        return index_error("row", fields[0], out->nrows);
      }
      r = parse_integer(fields[1], &col);
      if (r == IntegerParse::kNotInteger) {
        return fail("column index " + quoted(fields[1]) + " is not an integer");
      }
      if (r == IntegerParse::kTooLarge || col < 1 || col > out->ncols) {
        return index_error("column", fields[1], out->ncols);
      }
      double value = 1.0;
      if (!pattern) {
        switch (parse_value(fields[2], integer_field, &value)) {
          case ValueParse::kOk:
            break;
          case ValueParse::kNotNumber:
            return fail("value " + quoted(fields[2]) + " is not a number");
          case ValueParse::kNotInteger:
            return fail("value " + quoted(fields[2]) +
                        " is not an integer (the banner says 'integer')");
          case ValueParse::kNotFinite:
            return fail("value " + quoted(fields[2]) + " is not finite");
        }
      }
      int32_t i = static_cast<int32_t>(row - 1), j = static_cast<int32_t>(col - 1);
      if (symmetric && i < j) std::swap(i, j);  // keep the lower triangle
      out->entries.push_back(Triplet{i, j, value});
      if (keep_lines) out->entry_lines.push_back(line_);
      ++found;
    }
    if (found < declared_) {
      return fail("truncated: found " + std::to_string(found) + " of " + std::to_string(declared_) +
                  " declared entries");
    }
    return Status::Ok();
  }

  TextSource* const source_;
  const std::string& name_;
  const char* line_begin_ = nullptr;
  const char* line_end_ = nullptr;
  int64_t line_ = 0;
  int64_t declared_ = 0;
  Field field_ = Field::kReal;
};

Status assemble(const ParsedFile& parsed, CscMatrix* out, MatrixMarketInfo* info) {
  GAB_RETURN_IF_ERROR(csc_from_triplets(parsed.nrows, parsed.ncols, parsed.entries, out));
  if (info != nullptr) *info = parsed.info;
  return Status::Ok();
}

// A general matrix meant as symmetric: its values must equal their mirrors
// exactly (a missing entry counts as zero). Walks column j of A and of A^T
// together; both have sorted rows, so this is one merge per column, O(nnz).
Status check_symmetric_values(const CscMatrix& a, const ParsedFile& parsed,
                              const std::string& name) {
  const CscMatrix t = transpose(a);
  for (int32_t j = 0; j < a.ncols; ++j) {
    int32_t pa = a.colptr[j], pt = t.colptr[j];
    const int32_t ea = a.colptr[j + 1], et = t.colptr[j + 1];
    while (pa < ea || pt < et) {
      const int32_t ia = pa < ea ? a.rowind[pa] : std::numeric_limits<int32_t>::max();
      const int32_t it = pt < et ? t.rowind[pt] : std::numeric_limits<int32_t>::max();
      // (row, col) is a stored entry whose mirror (col, row) holds `mirror`.
      int32_t row = 0, col = 0;
      double value = 0.0, mirror = 0.0;
      bool mirror_stored = true;
      if (ia == it) {
        value = a.values[pa++];
        mirror = t.values[pt++];
        row = ia;
        col = j;
      } else if (ia < it) {
        value = a.values[pa++];
        mirror_stored = false;
        row = ia;
        col = j;
      } else {
        value = t.values[pt++];  // A(j, it)
        mirror_stored = false;
        row = j;
        col = it;
      }
      if (value == mirror) continue;
      int64_t line = parsed.size_line;
      for (size_t k = 0; k < parsed.entries.size(); ++k) {
        if (parsed.entries[k].row == row && parsed.entries[k].col == col) {
          line = parsed.entry_lines[k];
          break;
        }
      }
      const std::string at = "(" + std::to_string(row + 1) + ", " + std::to_string(col + 1) + ")";
      const std::string mirror_at =
          "(" + std::to_string(col + 1) + ", " + std::to_string(row + 1) + ")";
      return Status::Error(StatusCode::kParseError,
                           name + ":" + std::to_string(line) + ": entry " + at + " = " +
                               format_double(value) + " but " + mirror_at +
                               (mirror_stored ? " = " + format_double(mirror) : " is absent") +
                               "; a general file read as symmetric must have symmetric values");
    }
  }
  return Status::Ok();
}

// Unique name for a temporary beside `path` (same directory, so the final
// rename stays within one file system and is atomic). Exclusive creation
// settles collisions, so this only needs to make them unlikely.
std::string temporary_name(const std::string& path) {
  static std::atomic<uint64_t> counter{0};
  uint64_t x = counter.fetch_add(1, std::memory_order_relaxed) * 0x9e3779b97f4a7c15ULL;
  x ^= static_cast<uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
  // The counter's address differs between processes (ASLR).
  x ^= static_cast<uint64_t>(reinterpret_cast<uintptr_t>(&counter)) << 7;
  // splitmix64 finalizer: spread the bits.
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  x ^= x >> 31;
  static const char kHex[] = "0123456789abcdef";
  std::string name = path + ".tmp-";
  for (int k = 0; k < 12; ++k) name += kHex[(x >> (4 * k)) & 15];
  return name;
}

// Buffered output that remembers the first failure, so the writer's loop
// stays free of error plumbing.
class FileWriter {
 public:
  explicit FileWriter(std::FILE* f) : file_(f) { buffer_.reserve(kCapacity); }

  void append(const char* begin, const char* end) {
    buffer_.append(begin, end);
    if (buffer_.size() >= kCapacity - kMaxLine) flush_buffer();
  }
  void append(const std::string& s) { append(s.data(), s.data() + s.size()); }

  // Flushes everything down to the device; false (errno set) on any failure.
  bool finish() {
    flush_buffer();
    if (ok_ && std::fflush(file_) != 0) fail();
#ifdef GAB_HAVE_FSYNC
    if (ok_ && fsync(fileno(file_)) != 0) fail();
#endif
    return ok_;
  }
  int error() const { return errno_; }

 private:
  static constexpr size_t kCapacity = size_t{1} << 20;
  static constexpr size_t kMaxLine = 128;  // longer than any entry line

  void flush_buffer() {
    if (ok_ && !buffer_.empty() &&
        std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
      fail();
    }
    buffer_.clear();
  }
  void fail() {
    ok_ = false;
    errno_ = errno;
  }

  std::FILE* file_;
  std::string buffer_;
  bool ok_ = true;
  int errno_ = 0;
};

// The entries as text, column by column. Entry lines are at most
// 2 * 11 + 25 + 3 characters, well under kMaxLine.
void write_body(const CscMatrix& a, bool symmetric, FileWriter* out) {
  const bool pattern = a.values.empty() && a.nnz() > 0;
  std::string header = "%%MatrixMarket matrix coordinate ";
  header += pattern ? "pattern " : "real ";
  header += symmetric ? "symmetric\n" : "general\n";
  header += std::to_string(a.nrows) + " " + std::to_string(a.ncols) + " " +
            std::to_string(a.nnz()) + "\n";
  out->append(header);
  char line[128];
  // Numbers stop short of the buffer's end so the separators always fit
  // (to_chars returns its limit on failure, which cannot happen here).
  char* const end = line + sizeof(line) - 8;
  for (int32_t j = 0; j < a.ncols; ++j) {
    for (int32_t p = a.colptr[j]; p < a.colptr[j + 1]; ++p) {
      char* q = std::to_chars(line, end, int64_t{a.rowind[p]} + 1).ptr;
      *q++ = ' ';
      q = std::to_chars(q, end, int64_t{j} + 1).ptr;
      if (!pattern) {
        *q++ = ' ';
        // Same text as printf("%.17g"): enough digits to read back bit-exact.
        q = std::to_chars(q, end, a.values[p], std::chars_format::general, 17).ptr;
      }
      *q++ = '\n';
      out->append(line, q);
    }
  }
}

Status check_writable(const CscMatrix& a, bool symmetric) {
  const Status valid = check_csc(a);
  if (!valid.ok()) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "write_matrix_market: invalid matrix: " + valid.message());
  }
  if (symmetric && a.nrows != a.ncols) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "write_matrix_market: a symmetric file needs a square matrix, got " +
                             std::to_string(a.nrows) + " x " + std::to_string(a.ncols));
  }
  for (int32_t j = 0; j < a.ncols; ++j) {
    for (int32_t p = a.colptr[j]; p < a.colptr[j + 1]; ++p) {
      const bool above = symmetric && a.rowind[p] < j;
      // The reader rejects non-finite values, so writing one would make an
      // unreadable file.
      const bool non_finite = !a.values.empty() && !std::isfinite(a.values[p]);
      if (!above && !non_finite) continue;
      const std::string at =
          "(" + std::to_string(a.rowind[p] + 1) + ", " + std::to_string(j + 1) + ")";
      return Status::Error(StatusCode::kInvalidArgument,
                           "write_matrix_market: entry " + at +
                               (above ? " is above the diagonal; a symmetric file takes a lower "
                                        "triangle"
                                      : " is not finite"));
    }
  }
  return Status::Ok();
}

}  // namespace

Status parse_matrix_market(const std::string& text, const std::string& name, CscMatrix* out,
                           MatrixMarketInfo* info) {
  TextSource source(text.data(), text.size());
  ParsedFile parsed;
  GAB_RETURN_IF_ERROR(Parser(&source, name).parse(/*keep_lines=*/false, &parsed));
  return assemble(parsed, out, info);
}

Status read_matrix_market(const std::string& path, CscMatrix* out, MatrixMarketInfo* info) {
  ParsedFile parsed;
  {
    TextSource source;  // closed before assembly, which needs memory of its own
    GAB_RETURN_IF_ERROR(source.open(path));
    GAB_RETURN_IF_ERROR(Parser(&source, path).parse(/*keep_lines=*/false, &parsed));
  }
  return assemble(parsed, out, info);
}

Status read_symmetric_matrix_market(const std::string& path, CscMatrix* lower) {
  ParsedFile parsed;
  {
    TextSource source;
    GAB_RETURN_IF_ERROR(source.open(path));
    GAB_RETURN_IF_ERROR(Parser(&source, path).parse(/*keep_lines=*/true, &parsed));
  }
  if (parsed.nrows != parsed.ncols) {
    return Status::Error(StatusCode::kParseError,
                         path + ":" + std::to_string(parsed.size_line) +
                             ": a symmetric matrix must be square, the size line says " +
                             std::to_string(parsed.nrows) + " x " + std::to_string(parsed.ncols));
  }
  CscMatrix a;
  GAB_RETURN_IF_ERROR(csc_from_triplets(parsed.nrows, parsed.ncols, parsed.entries, &a));
  if (parsed.info.symmetry == MatrixMarketSymmetry::kSymmetric) {
    *lower = std::move(a);  // already the lower triangle
    return Status::Ok();
  }
  GAB_RETURN_IF_ERROR(check_symmetric_values(a, parsed, path));
  *lower = lower_triangle(a);
  return Status::Ok();
}

Status write_matrix_market(const std::string& path, const CscMatrix& a, bool symmetric) {
  GAB_RETURN_IF_ERROR(check_writable(a, symmetric));
  // Exclusive creation ("x"): never write into someone else's file; retry
  // on a name collision only.
  std::string temp;
  std::FILE* f = nullptr;
  for (int attempt = 0; attempt < 64 && f == nullptr; ++attempt) {
    temp = temporary_name(path);
    f = std::fopen(temp.c_str(), "wbx");
    if (f == nullptr && errno != EEXIST) break;
  }
  if (f == nullptr) {
    return Status::Error(StatusCode::kIoError, "cannot write '" + path +
                                                   "': cannot create temporary '" + temp +
                                                   "': " + std::strerror(errno));
  }
  FileWriter writer(f);
  write_body(a, symmetric, &writer);
  bool ok = writer.finish();
  int error = writer.error();
  if (std::fclose(f) != 0 && ok) {
    ok = false;
    error = errno;
  }
  if (!ok) {
    std::remove(temp.c_str());
    return Status::Error(StatusCode::kIoError,
                         "cannot write '" + path + "': " + std::strerror(error));
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    error = errno;
    std::remove(temp.c_str());
    return Status::Error(StatusCode::kIoError, "cannot write '" + path + "': rename from '" + temp +
                                                   "' failed: " + std::strerror(error));
  }
  return Status::Ok();
}

}  // namespace gab
