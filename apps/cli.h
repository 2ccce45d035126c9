// Shared pieces of the gab sub-commands: argument parsing, the error
// contract (exit 1 + "gab: error: ..." for bad input, exit 2 for bad usage),
// a one-object JSON writer, timing.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gab/mesh/mesh_io.h"
#include "gab/sparse/ordering.h"

namespace gab {
namespace cli {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

// Prints "gab: error: <message>" on stderr and returns kExitFailure.
int fail(const std::string& message);
// Prints "gab <command>: <message>" and the command's usage (commands.h) on
// stderr; returns kExitUsage.
int usage_error(const std::string& command, const std::string& message);

// What reading the mesh `path` left out or forgave, on stderr, one line
// each: the reader's warnings ("gab: warning: <warning>"), then, when
// something was dropped, "gab: warning: PATH: not carried: <counts>; gab
// keeps positions, triangles, normals, ...". --quiet does not silence it (it
// silences the progress line only): data left out is never silent.
void warn_read_notes(const std::string& path, const MeshReadNotes& notes);
// read_mesh, then warn_read_notes on success; `notes` (optional) receives them.
Status read_mesh_warning(const std::string& path, Mesh* mesh, MeshReadNotes* notes = nullptr);

// Before `command` does its work: whether it can write its output `out`
// (check_output_file). kExitOk when it can; else the usage error (the
// output is one of `inputs`) or the failure (a directory, a folder that
// does not exist), printed.
int check_output(const std::string& command, const std::string& out, const std::vector<std::string>& inputs);

// Options of one sub-command: "--name value" pairs, flags, positionals.
class Args {
 public:
  // `valued` lists the options taking a value, `flags` those that do not.
  // Returns false (and sets error()) on an unknown option or missing value.
  bool parse(int argc, char** argv, const std::vector<std::string>& valued,
             const std::vector<std::string>& flags);
  const std::string& error() const { return error_; }

  bool has(const std::string& name) const;
  std::string get(const std::string& name, const std::string& fallback = "") const;
  const std::vector<std::string>& positionals() const { return positionals_; }

  // Integer / double option with range check; false + error() on bad text.
  bool get_int(const std::string& name, int64_t lo, int64_t hi, int64_t* value);
  bool get_double(const std::string& name, double lo, double hi, double* value);
  // --threads T (1..64); absent: every hardware thread (at most 64). The
  // results never depend on it, only the time.
  bool get_threads(int32_t* value);
  // --ordering NAME, one of the orderings this command takes (`accepted`,
  // named as in gab/sparse/ordering.h); absent: `fallback`. Any other name,
  // known or not, is an error listing what the command takes.
  bool get_ordering(const std::vector<Ordering>& accepted, Ordering fallback, Ordering* value);
  // The same for a comma list, each ordering once (gab study).
  bool get_orderings(const std::vector<Ordering>& accepted, Ordering fallback, std::vector<Ordering>* values);

 private:
  std::vector<std::pair<std::string, std::string>> values_;
  std::vector<std::string> flags_;
  std::vector<std::string> positionals_;
  std::string error_;
};

// Builds one JSON object; keys keep insertion order.
class JsonObject {
 public:
  void add(const std::string& key, int64_t value);
  void add(const std::string& key, double value);
  void add(const std::string& key, const std::string& value);
  void add_bool(const std::string& key, bool value);  // true / false (not an overload of add:
                                                      // a string literal would convert to bool)
  void add_null(const std::string& key);
  void add(const std::string& key, const std::vector<JsonObject>& items);  // an array of objects
  void add(const std::string& key, const JsonObject& object);              // a nested object
  std::string str() const;

 private:
  std::vector<std::pair<std::string, std::string>> fields_;
};

// Wall-clock seconds since some fixed point (steady clock).
inline double now_seconds() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(clock::now().time_since_epoch()).count();
}

double median(std::vector<double> values);

// Threads when --threads is not given: every hardware thread (1..64).
int32_t default_threads();

// The orderings of the codec's commands (compress, decompress) and of the
// engine's benchmarks (factor, study: a named ordering, measured as such).
extern const std::vector<Ordering> kCodecOrderings;
extern const std::vector<Ordering> kBenchmarkOrderings;

// Lower-cased extension of a path without the dot ("" if none).
std::string extension(const std::string& path);


}  // namespace cli
}  // namespace gab
