#include "cli.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <thread>
#include <utility>

#include "commands.h"
#include "gab/mesh/file_io.h"
#include "gab/sparse/symbolic.h"

namespace gab {
namespace cli {

int fail(const std::string& message) {
  std::fprintf(stderr, "gab: error: %s\n", message.c_str());
  return kExitFailure;
}

int usage_error(const std::string& command, const std::string& message) {
  const Command* c = find_command(command);
  std::fprintf(stderr, "gab %s: %s\nusage: %s\n", command.c_str(), message.c_str(),
               c != nullptr ? usage_text(*c).c_str() : "gab help");
  return kExitUsage;
}

int check_output(const std::string& command, const std::string& out, const std::vector<std::string>& inputs) {
  const Status s = check_output_file(out, inputs);
  if (s.ok()) return kExitOk;
  return s.code() == StatusCode::kInvalidArgument ? usage_error(command, s.message()) : fail(s.message());
}

bool Args::parse(int argc, char** argv, const std::vector<std::string>& valued,
                 const std::vector<std::string>& flags) {
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.size() > 1 && a[0] == '-') {
      if (std::find(flags.begin(), flags.end(), a) != flags.end()) {
        flags_.push_back(a);
      } else if (std::find(valued.begin(), valued.end(), a) != valued.end()) {
        if (i + 1 >= argc) {
          error_ = "option " + a + " needs a value";
          return false;
        }
        values_.emplace_back(a, argv[++i]);
      } else {
        error_ = "unknown option " + a;
        return false;
      }
    } else {
      positionals_.push_back(a);
    }
  }
  return true;
}

bool Args::has(const std::string& name) const {
  if (std::find(flags_.begin(), flags_.end(), name) != flags_.end()) return true;
  for (const auto& kv : values_) {
    if (kv.first == name) return true;
  }
  return false;
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
  std::string v = fallback;
  for (const auto& kv : values_) {
    if (kv.first == name) v = kv.second;  // the last occurrence wins
  }
  return v;
}

bool Args::get_int(const std::string& name, int64_t lo, int64_t hi, int64_t* value) {
  if (!has(name)) return true;
  const std::string text = get(name);
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno != 0 || v < lo || v > hi) {
    error_ = name + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
             "], got '" + text + "'";
    return false;
  }
  *value = v;
  return true;
}

bool Args::get_double(const std::string& name, double lo, double hi, double* value) {
  if (!has(name)) return true;
  const std::string text = get(name);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) {
    char buf[160];
    std::snprintf(buf, sizeof(buf), "%s must be a number in [%g, %g], got '%s'", name.c_str(), lo, hi,
                  text.c_str());
    error_ = buf;
    return false;
  }
  *value = v;
  return true;
}

namespace {

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof(buf), "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

void JsonObject::add(const std::string& key, int64_t value) {
  fields_.emplace_back(key, std::to_string(value));
}

void JsonObject::add(const std::string& key, double value) {
  if (!std::isfinite(value)) {
    add_null(key);
    return;
  }
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.9g", value);
  fields_.emplace_back(key, buf);
}

void JsonObject::add(const std::string& key, const std::string& value) {
  fields_.emplace_back(key, quote(value));
}

void JsonObject::add_bool(const std::string& key, bool value) { fields_.emplace_back(key, value ? "true" : "false"); }

void JsonObject::add_null(const std::string& key) { fields_.emplace_back(key, "null"); }

void JsonObject::add(const std::string& key, const std::vector<JsonObject>& items) {
  std::string array = "[";
  for (size_t i = 0; i < items.size(); ++i) array += (i ? ", " : "") + items[i].str();
  fields_.emplace_back(key, array + "]");
}

void JsonObject::add(const std::string& key, const JsonObject& object) { fields_.emplace_back(key, object.str()); }

std::string JsonObject::str() const {
  std::string out = "{";
  for (size_t i = 0; i < fields_.size(); ++i) {
    if (i) out += ", ";
    out += quote(fields_[i].first) + ": " + fields_[i].second;
  }
  return out + "}";
}

int32_t default_threads() {
  const unsigned hardware = std::thread::hardware_concurrency();
  return static_cast<int32_t>(std::min<int64_t>(std::max(1u, hardware), kMaxFactorThreads));
}

bool Args::get_threads(int32_t* value) {
  int64_t threads = default_threads();
  if (!get_int("--threads", 1, kMaxFactorThreads, &threads)) return false;
  *value = static_cast<int32_t>(threads);
  return true;
}

const std::vector<Ordering> kCodecOrderings = {Ordering::kAuto, Ordering::kAmd, Ordering::kNestedDissection};
const std::vector<Ordering> kBenchmarkOrderings = {Ordering::kAmd, Ordering::kNestedDissection, Ordering::kNatural};

namespace {

// "a, b or c".
std::string name_list(const std::vector<Ordering>& orderings) {
  std::string text;
  for (size_t i = 0; i < orderings.size(); ++i) {
    if (i > 0) text += i + 1 == orderings.size() ? " or " : ", ";
    text += ordering_name(orderings[i]);
  }
  return text;
}

// One name through the one parser (parse_ordering), then the command's list.
bool parse_accepted(const std::string& name, const std::vector<Ordering>& accepted, Ordering* value) {
  Ordering parsed;
  if (!parse_ordering(name, &parsed)) return false;
  if (std::find(accepted.begin(), accepted.end(), parsed) == accepted.end()) return false;
  *value = parsed;
  return true;
}

}  // namespace

bool Args::get_ordering(const std::vector<Ordering>& accepted, Ordering fallback, Ordering* value) {
  if (!has("--ordering")) {
    *value = fallback;
    return true;
  }
  const std::string text = get("--ordering");
  if (parse_accepted(text, accepted, value)) return true;
  error_ = "--ordering must be " + name_list(accepted) + ", got '" + text + "'";
  return false;
}

bool Args::get_orderings(const std::vector<Ordering>& accepted, Ordering fallback, std::vector<Ordering>* values) {
  values->clear();
  if (!has("--ordering")) {
    values->push_back(fallback);
    return true;
  }
  const std::string text = get("--ordering");
  for (size_t begin = 0;;) {
    const size_t end = text.find(',', begin);
    const std::string name = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    Ordering o;
    if (!parse_accepted(name, accepted, &o)) {
      error_ = "--ordering must be " + name_list(accepted) + " (or a comma list of them), got '" + name + "'";
      return false;
    }
    if (std::find(values->begin(), values->end(), o) != values->end()) {
      error_ = "--ordering lists '" + name + "' twice";
      return false;
    }
    values->push_back(o);
    if (end == std::string::npos) return true;
    begin = end + 1;
  }
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string extension(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

void warn_read_notes(const std::string& path, const MeshReadNotes& notes) {
  for (const std::string& w : notes.warnings) std::fprintf(stderr, "gab: warning: %s\n", w.c_str());
  if (notes.warnings_not_listed > 0) {
    std::fprintf(stderr, "gab: warning: %s: %lld more warnings like these\n", path.c_str(),
                 static_cast<long long>(notes.warnings_not_listed));
  }
  if (notes.dropped.empty()) return;
  std::fprintf(stderr,
               "gab: warning: %s: not carried: %s; gab keeps positions, triangles, normals, texture coordinates, "
               "colours and vertex properties\n",
               path.c_str(), notes.dropped_summary().c_str());
}

Status read_mesh_warning(const std::string& path, Mesh* mesh, MeshReadNotes* notes) {
  MeshReadNotes seen;
  GAB_RETURN_IF_ERROR(read_mesh(path, mesh, &seen));
  warn_read_notes(path, seen);
  if (notes != nullptr) *notes = std::move(seen);
  return Status::Ok();
}

}  // namespace cli
}  // namespace gab
