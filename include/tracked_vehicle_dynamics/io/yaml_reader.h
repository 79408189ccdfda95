// Strict, path-aware reading of YAML documents, shared by the model and description loaders:
// every error names the file, the key path ("beams[2].material") and the line, and nothing is
// guessed or silently defaulted.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace io {

/// One value of a YAML document together with the file it came from and its key path.
///
/// Reads are strict: a number must be a plain (unquoted) finite decimal number ("1e9", "-0.5";
/// not "1e9" in quotes, not .nan or .inf); an integer must be a base-10 integer; a map may hold
/// only the keys the schema names (typo protection) and each key once. Every failure throws
/// InputError "<file>: <path>: <what> (line N)".
class YamlValue {
 public:
  YamlValue(YAML::Node node, std::string file, std::string path);

  /// Reads and parses a whole file. Throws InputError when the file is missing, unreadable,
  /// empty or not YAML (syntax errors carry the line and column).
  static YamlValue loadFile(const std::string& path);
  /// Parses YAML text; `file` names the source in messages. Throws InputError like loadFile().
  static YamlValue parse(const std::string& text, const std::string& file);

  bool isMap() const { return node_.IsMap(); }
  bool isSequence() const { return node_.IsSequence(); }
  bool isScalar() const { return node_.IsScalar(); }
  bool isNull() const { return !node_.IsDefined() || node_.IsNull(); }

  const std::string& file() const { return file_; }
  /// Key path from the document root, e.g. "springs[0].k[3]"; empty for the root.
  const std::string& path() const { return path_; }
  /// 1-based line in the file, 0 when unknown.
  int line() const;
  /// 1-based line of the key a map entry's value stands under (from entries()); line() for
  /// other values. A block map's own line() is its first key's, not the line that names it.
  int entryLine() const { return entry_line_ > 0 ? entry_line_ : line(); }

  /// Requires a map whose keys are all in `allowed`, each given once.
  void expectMap(std::initializer_list<const char*> allowed) const;
  /// Requires a map (of user-chosen keys, e.g. set names), each key given once.
  void expectMap() const;
  bool has(const std::string& key) const;
  /// The value of a required key; throws "<path>.<key>: required key is missing".
  YamlValue operator[](const std::string& key) const;
  /// The value of an optional key.
  std::optional<YamlValue> find(const std::string& key) const;
  /// Key/value pairs of a map, in file order.
  std::vector<std::pair<std::string, YamlValue>> entries() const;

  /// Elements of a sequence; `what` describes the expected content for the message.
  std::vector<YamlValue> elements(const std::string& what = "a list") const;
  /// Elements of a sequence that must have exactly `count` entries.
  std::vector<YamlValue> elements(std::size_t count, const std::string& what) const;

  /// A finite number.
  double asNumber() const;
  /// A base-10 integer.
  std::int64_t asInteger() const;
  /// Any scalar, quoted or not.
  std::string asString() const;
  /// An unquoted scalar that reads as a number ("5", "-1e3", ".inf"): where a text is expected,
  /// most likely a value typed under the wrong key.
  bool isPlainNumber() const;
  /// A list of 3 numbers.
  Vector3 asVector3() const;
  /// A list of numbers of any length.
  std::vector<double> asNumbers() const;

  /// Throws InputError "<file>: <path>: <what> (line N)".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  /// A value below this one; `line` (when > 0) is its key's line, used for empty values.
  YamlValue child(const YAML::Node& node, const std::string& path, int line = 0) const;
  std::string keyPath(const std::string& key) const;
  static int keyLine(const YAML::Node& key);
  /// "a list", "a map", "nothing", "the string \"abc\"", ... for "expected X, got Y" messages.
  std::string describe() const;

  YAML::Node node_;
  std::string file_;
  std::string path_;
  int fallback_line_ = 0;  // the parent's line, for values (e.g. null ones) without a mark
  int entry_line_ = 0;     // the key's line, for a map entry's value
};

}  // namespace io
}  // namespace tracked_vehicle_dynamics
