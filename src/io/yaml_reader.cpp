#include "tracked_vehicle_dynamics/io/yaml_reader.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/message_text.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace io {
namespace {

// Tags yaml-cpp gives scalars: "?" plain, "!" quoted; explicit numeric tags are accepted too.
const char* const kPlainTag = "?";
const char* const kIntTag = "tag:yaml.org,2002:int";
const char* const kFloatTag = "tag:yaml.org,2002:float";

std::string lowercase(std::string text) {
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool isNumericTag(const std::string& tag) {
  return tag == kPlainTag || tag == kIntTag || tag == kFloatTag;
}

/// from_chars rejects a leading '+', which YAML allows; "+-1" stays invalid.
std::string_view withoutPlus(const std::string& text) {
  std::string_view view(text);
  if (view.size() > 1 && view.front() == '+' && view[1] != '-' && view[1] != '+') {
    view.remove_prefix(1);
  }
  return view;
}

/// YAML (.nan, .inf) and C (nan, inf, infinity) spellings of non-finite values, any case/sign.
bool isNonFiniteSpelling(const std::string& text) {
  std::string_view word(text);
  if (!word.empty() && (word.front() == '+' || word.front() == '-'))
    word.remove_prefix(1);
  const std::string lower = lowercase(std::string(word));
  return lower == ".nan" || lower == "nan" || lower == ".inf" || lower == "inf" ||
         lower == "infinity";
}

/// Events of a document walk that keep only where each document starts.
class DocumentStarts : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> starts;
  void OnDocumentStart(const YAML::Mark& mark) override { starts.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

/// yaml-cpp 0.7's parser does not consume a ',' where a document or the text after a document's
/// flow collection should start ("[1],", "{a: 1},", a stray ',' on the first line): every
/// further document it is asked for is another empty one at the same place, and LoadAll asks
/// until memory runs out (bad_alloc after gigabytes). Walk the documents' events first, and
/// refuse a document that starts where the one before it did. Costs a second parse of the text;
/// large terrain files in the tools' layout never come here (terrain_yaml_plain.h).
void refuseStalledDocuments(const std::string& text, const std::string& file) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentStarts walk;
  while (parser.HandleNextDocument(walk)) {
    const std::size_t n = walk.starts.size();
    if (n >= 2 && walk.starts[n - 1].pos == walk.starts[n - 2].pos) {
      const YAML::Mark& at = walk.starts.back();
      const auto pos = static_cast<std::size_t>(at.pos);
      const std::string found = pos < text.size() ? "'" + text.substr(pos, 1) + "'" : "the end";
      throw InputError(printable(file + ": line " + std::to_string(at.line + 1) + ", column " +
                                 std::to_string(at.column + 1) + ": invalid YAML: unexpected " +
                                 found + " (not a value, nor after one)"));
    }
  }
}

std::string joined(std::initializer_list<const char*> words) {
  std::string out;
  for (const char* word : words) {
    if (!out.empty())
      out += ", ";
    out += word;
  }
  return out;
}

}  // namespace

YamlValue::YamlValue(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

YamlValue YamlValue::loadFile(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) {
    throw InputError(path + ": file not found");
  }
  if (std::filesystem::is_directory(status)) {
    throw InputError(path + ": is a directory, not a YAML file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(path + ": cannot be opened: " + std::strerror(errno));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw InputError(path + ": cannot be read: " + std::strerror(errno));
  }
  return parse(text.str(), path);
}

YamlValue YamlValue::parse(const std::string& text, const std::string& file) {
  // A MATLAB Level 5 file opens with this text (tvd's reduced models and results are such files).
  if (text.rfind("MATLAB 5.0 MAT-file", 0) == 0)
    throw InputError(file + ": not a YAML text file: a MATLAB .mat file (a reduced model or a " +
                     "result of tvd)");
  if (text.find('\0') != std::string::npos) {
    throw InputError(file + ": not a YAML text file (binary content)");
  }
  // A lone CR (old Mac line endings) is a line break in YAML (1.2, §5.4) but not to yaml-cpp,
  // which read such a file as one line: "the file is empty" after a first comment line, or an
  // illegal map value. Read as LF, as the CSV readers do; CR LF is left to yaml-cpp.
  // The text is copied only when it holds one (a road of millions of heights is tens of MB).
  std::string lines;
  const std::string* source = &text;
  for (std::size_t i = text.find('\r'); i != std::string::npos; i = text.find('\r', i + 1)) {
    if (i + 1 < text.size() && text[i + 1] == '\n')
      continue;
    if (source == &text) {
      lines = text;
      source = &lines;
    }
    lines[i] = '\n';
  }
  std::vector<YAML::Node> documents;
  try {
    refuseStalledDocuments(*source, file);
    documents = YAML::LoadAll(*source);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's guard against a stack overflow (2000 calls deep, about 500 levels) says only
    // "bad file".
    throw InputError(printable(file + ": line " + std::to_string(e.mark.line + 1) + ", column " +
                               std::to_string(e.mark.column + 1) +
                               ": invalid YAML: nested too deep (lists and maps more than about "
                               "500 levels within one another; the package's files need fewer "
                               "than 10)"));
  } catch (const YAML::Exception& e) {
    throw InputError(printable(file + ": line " + std::to_string(e.mark.line + 1) + ", column " +
                               std::to_string(e.mark.column + 1) + ": invalid YAML: " + e.msg));
  }
  if (documents.empty() || documents.front().IsNull()) {
    throw InputError(file + ": the file is empty (no YAML document)");
  }
  if (documents.size() > 1) {
    throw InputError(file + ": holds " + std::to_string(documents.size()) +
                     " YAML documents ('---'); expected one");
  }
  return YamlValue(documents.front(), file, "");
}

int YamlValue::line() const {
  // An empty value's mark points at the next token, so it takes its key's line instead.
  if (node_.IsDefined() && !node_.IsNull() && !node_.Mark().is_null()) {
    return node_.Mark().line + 1;
  }
  return fallback_line_;
}

void YamlValue::fail(const std::string& what) const {
  std::string message = file_ + ": ";
  if (!path_.empty())
    message += path_ + ": ";
  message += what;
  if (line() > 0)
    message += " (line " + std::to_string(line()) + ")";
  // Keys and values come from the file: one line whatever they hold.
  throw InputError(printable(message));
}

YamlValue YamlValue::child(const YAML::Node& node, const std::string& path, int line) const {
  YamlValue value(node, file_, path);
  value.fallback_line_ = line > 0 ? line : this->line();
  return value;
}

std::string YamlValue::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

int YamlValue::keyLine(const YAML::Node& key) {
  return key.Mark().is_null() ? 0 : key.Mark().line + 1;
}

std::string YamlValue::describe() const {
  if (isNull())
    return "nothing (an empty value)";
  if (node_.IsSequence())
    return "a list";
  if (node_.IsMap())
    return "a map";
  // A file of another kind (a CSV given as a description) is one long plain scalar: its start
  // says what it is, the whole of it would fill the terminal.
  constexpr std::size_t kShown = 60;
  const std::string& text = node_.Scalar();
  const std::string shown =
      text.size() <= kShown
          ? text
          : text.substr(0, kShown) + "... (" + std::to_string(text.size()) + " characters)";
  if (node_.Tag() == "!")
    return "the string \"" + shown + "\"";
  return "'" + shown + "'";
}

void YamlValue::expectMap() const {
  if (!node_.IsMap()) {
    fail("expected a map (key: value pairs), got " + describe());
  }
  std::map<std::string, int> lines;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (!it->first.IsScalar()) {
      child(it->first, path_).fail("map keys must be plain names");
    }
    const std::string key = it->first.Scalar();
    const YamlValue key_value = child(it->first, keyPath(key));
    const auto [previous, inserted] = lines.emplace(key, key_value.line());
    if (!inserted) {
      key_value.fail("key given twice (also on line " + std::to_string(previous->second) + ")");
    }
  }
}

void YamlValue::expectMap(std::initializer_list<const char*> allowed) const {
  if (!node_.IsMap()) {
    fail("expected a map with keys " + joined(allowed) + ", got " + describe());
  }
  expectMap();
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.Scalar();
    bool known = false;
    for (const char* name : allowed)
      known = known || key == name;
    if (!known) {
      // In a flow map {value: 14,000, ...} the comma ends the value: "000" becomes a key.
      const bool digits = !key.empty() && key.find_first_not_of("0123456789") == std::string::npos;
      child(it->first, keyPath(key))
          .fail("unknown key (allowed keys: " + joined(allowed) + ")" +
                (digits ? "; a number with a thousands separator? Write 14000, not 14,000" : ""));
    }
  }
}

bool YamlValue::has(const std::string& key) const {
  return find(key).has_value();
}

std::optional<YamlValue> YamlValue::find(const std::string& key) const {
  if (!node_.IsMap()) {
    fail("expected a map (key: value pairs), got " + describe());
  }
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    if (it->first.IsScalar() && it->first.Scalar() == key) {
      return child(it->second, keyPath(key), keyLine(it->first));
    }
  }
  return std::nullopt;
}

YamlValue YamlValue::operator[](const std::string& key) const {
  std::optional<YamlValue> value = find(key);
  if (!value) {
    child(YAML::Node(), keyPath(key)).fail("required key is missing");
  }
  return *value;
}

std::vector<std::pair<std::string, YamlValue>> YamlValue::entries() const {
  expectMap();
  std::vector<std::pair<std::string, YamlValue>> out;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.Scalar();
    YamlValue value = child(it->second, keyPath(key), keyLine(it->first));
    value.entry_line_ = keyLine(it->first);
    out.emplace_back(key, std::move(value));
  }
  return out;
}

std::vector<YamlValue> YamlValue::elements(const std::string& what) const {
  if (!node_.IsSequence()) {
    fail("expected " + what + ", got " + describe());
  }
  std::vector<YamlValue> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    out.push_back(child(node_[i], path_ + "[" + std::to_string(i) + "]"));
  }
  return out;
}

std::vector<YamlValue> YamlValue::elements(std::size_t count, const std::string& what) const {
  std::vector<YamlValue> out = elements(what);
  if (out.size() != count) {
    fail("expected " + what + ", got " + std::to_string(out.size()) + " entries");
  }
  return out;
}

double YamlValue::asNumber() const {
  if (!node_.IsScalar()) {
    fail("expected a number, got " + describe());
  }
  const std::string& text = node_.Scalar();
  if (!isNumericTag(node_.Tag())) {
    fail("expected a number, got " + describe() + " (write numbers without quotes)");
  }
  if (isNonFiniteSpelling(text)) {
    fail("value " + text + " is not a finite number");
  }
  const std::string_view digits = withoutPlus(text);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range) {
    // Subnormal values (e.g. written by a save) are representable; only overflow is an error.
    char* strtod_end = nullptr;
    const double subnormal = strtodC(text.c_str(), &strtod_end);
    if (*strtod_end == '\0' && subnormal != 0.0 && std::abs(subnormal) < 1.0) {
      return subnormal;
    }
    fail("number " + text + " is out of range");
  }
  if (error != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
    fail("expected a number, got " + describe());
  }
  if (!std::isfinite(value)) {
    fail("value " + text + " is not a finite number");
  }
  return value;
}

std::int64_t YamlValue::asInteger() const {
  if (!node_.IsScalar()) {
    fail("expected an integer, got " + describe());
  }
  const std::string& text = node_.Scalar();
  if (!isNumericTag(node_.Tag())) {
    fail("expected an integer, got " + describe() + " (write numbers without quotes)");
  }
  const std::string_view digits = withoutPlus(text);
  std::int64_t value = 0;
  const auto [end, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value, 10);
  if (error == std::errc::result_out_of_range) {
    fail("integer " + text + " is out of range");
  }
  if (error != std::errc() || end != digits.data() + digits.size() || digits.empty()) {
    fail("expected an integer, got " + describe());
  }
  return value;
}

std::string YamlValue::asString() const {
  if (!node_.IsScalar()) {
    fail("expected a string, got " + describe());
  }
  return node_.Scalar();
}

bool YamlValue::isPlainNumber() const {
  if (!node_.IsScalar() || node_.Tag() != kPlainTag)
    return false;
  const std::string& text = node_.Scalar();
  if (isNonFiniteSpelling(text))
    return true;
  const std::string_view digits = withoutPlus(text);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  return !digits.empty() && end == digits.data() + digits.size() &&
         (error == std::errc() || error == std::errc::result_out_of_range);
}

Vector3 YamlValue::asVector3() const {
  const std::vector<YamlValue> items = elements(3, "a list of 3 numbers [x, y, z]");
  return Vector3(items[0].asNumber(), items[1].asNumber(), items[2].asNumber());
}

std::vector<double> YamlValue::asNumbers() const {
  std::vector<double> out;
  for (const YamlValue& item : elements("a list of numbers"))
    out.push_back(item.asNumber());
  return out;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
