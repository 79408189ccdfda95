#include "tracked_vehicle_dynamics/terrain/terrain_yaml_plain.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

using Numbers = std::vector<double>;

/// What the file's lines gave; each key at most once.
struct PlainFile {
  std::optional<std::string> name;
  std::optional<double> spacing;
  std::optional<double> start;
  std::optional<Numbers> x;
  std::optional<Numbers> y;
  std::optional<Numbers> flat_heights;              // heights: [..]
  std::optional<std::vector<Numbers>> height_rows;  // heights: then "- [..]" lines
};

/// Thrown inside this file only: the file is not (entirely) in the plain layout.
struct NotPlain {};

std::string_view trimmedLeft(std::string_view text) {
  while (!text.empty() && text.front() == ' ')
    text.remove_prefix(1);
  return text;
}

/// After a value: nothing but blanks, or blanks then a comment ("# ..." after at least one).
void expectEndOfLine(std::string_view rest) {
  const std::string_view after = trimmedLeft(rest);
  if (after.empty())
    return;
  if (after.front() == '#' && after.size() < rest.size())
    return;
  throw NotPlain();
}

/// A plain decimal, -?(d+(.d*)?|.d+)([eE][+-]?d+)?, finite: the texts YamlValue::asNumber reads
/// to the same value by the same from_chars (it also takes '+', and YAML's non-finite spellings
/// to refuse them). A subnormal that from_chars reports out of range (some standard libraries
/// do; GCC 12's reads it) asNumber reads by strtod: here it goes to the general reader.
double plainNumber(std::string_view text) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9')
      ++i;
    return i - from;
  };
  if (i < text.size() && text[i] == '-')
    ++i;
  std::size_t mantissa = digits();
  if (i < text.size() && text[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0)
    throw NotPlain();
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-'))
      ++i;
    if (digits() == 0)
      throw NotPlain();
  }
  if (i != text.size())
    throw NotPlain();
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw NotPlain();
  return value;
}

/// "[a, b, c]" then the end of the line.
Numbers flowList(std::string_view text) {
  if (text.empty() || text.front() != '[')
    throw NotPlain();
  const std::size_t close = text.find(']');
  if (close == std::string_view::npos)
    throw NotPlain();
  expectEndOfLine(text.substr(close + 1));
  std::string_view items = text.substr(1, close - 1);
  Numbers values;
  if (trimmedLeft(items).empty())
    return values;
  while (true) {
    const std::size_t comma = items.find(',');
    std::string_view item = trimmedLeft(items.substr(0, comma));
    while (!item.empty() && item.back() == ' ')
      item.remove_suffix(1);
    values.push_back(plainNumber(item));
    if (comma == std::string_view::npos)
      return values;
    items.remove_prefix(comma + 1);
  }
}

/// A number alone on its line (spacing, start).
double scalarNumber(std::string_view text) {
  const std::size_t end = text.find(' ');
  const double value = plainNumber(text.substr(0, end));
  if (end != std::string_view::npos)
    expectEndOfLine(text.substr(end));
  return value;
}

/// "text" of printable ASCII without '"' or '\\' (no escapes to interpret), then the line's end.
std::string quotedName(std::string_view text) {
  if (text.size() < 2 || text.front() != '"')
    throw NotPlain();
  const std::size_t close = text.find('"', 1);
  if (close == std::string_view::npos)
    throw NotPlain();
  const std::string_view inside = text.substr(1, close - 1);
  for (const char c : inside)
    if (c < 0x20 || c > 0x7e || c == '\\')
      throw NotPlain();
  expectEndOfLine(text.substr(close + 1));
  return std::string(inside);
}

/// A name as PyYAML and hand writers leave it unquoted: a letter, digit or '_', then those and
/// ". - / ( ) +" and single spaces, then the line's end (" # comment" allowed). yaml-cpp reads
/// any such plain scalar as its own text, except YAML's nulls, which are left to the general
/// reader (it refuses them).
std::string plainName(std::string_view text) {
  const std::size_t comment = text.find(" #");
  std::string_view name = text.substr(0, comment);
  while (!name.empty() && name.back() == ' ')
    name.remove_suffix(1);
  const auto word = [](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  };
  if (name.empty() || !word(name.front()) || name == "null" || name == "Null" || name == "NULL")
    throw NotPlain();
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool space = c == ' ' && name[i - 1] != ' ';
    if (!word(c) && !space && std::string_view("._-/()+").find(c) == std::string_view::npos)
      throw NotPlain();
  }
  return std::string(name);
}

template <typename T>
void setOnce(std::optional<T>& slot, T value) {
  if (slot)
    throw NotPlain();  // a key given twice: the general reader names it
  slot = std::move(value);
}

/// A line with content: its text after the indentation, and the indentation (spaces).
struct Line {
  std::string_view content;
  std::size_t indent = 0;
};

/// The lines with content, blank ones and comment lines left out (both are only white space
/// and comments within a list, block or flow, as between keys).
std::vector<Line> contentLines(const std::string& text) {
  std::vector<Line> lines;
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos)
      end = text.size();
    std::string_view line(text.data() + at, end - at);
    at = end + 1;
    if (!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    for (const char c : line)  // tabs, a lone CR, other controls, non-ASCII: the general reader
      if (c < 0x20 || c > 0x7e)
        throw NotPlain();
    const std::string_view content = trimmedLeft(line);
    if (!content.empty() && content.front() != '#')
      lines.push_back({content, line.size() - content.size()});
  }
  return lines;
}

/// Reads the lines from `at` on: past what it takes when a reader returns.
class LineCursor {
 public:
  explicit LineCursor(const std::vector<Line>& lines) : lines_(lines) {}
  bool done() const { return at_ == lines_.size(); }
  const Line& peek() const { return lines_[at_]; }
  const Line& take() { return lines_[at_++]; }

  /// A flow list that starts with `first` ("[a, b," ...) and goes on over the following lines,
  /// each indented more than `parent`, up to the line holding its ']' (PyYAML wraps long lists
  /// so). A '#' inside the list (a comment between its lines) is left to the general reader.
  Numbers flowListFrom(std::string_view first, std::size_t parent) {
    if (first.find(']') != std::string_view::npos)
      return flowList(first);
    if (first.find('#') != std::string_view::npos)
      throw NotPlain();
    std::string joined(first);
    while (true) {
      if (done() || peek().indent <= parent)
        throw NotPlain();
      const std::string_view more = take().content;
      const std::size_t close = more.find(']');
      if (more.substr(0, close).find('#') != std::string_view::npos)
        throw NotPlain();
      joined += ' ';
      joined += more;
      if (close != std::string_view::npos)
        return flowList(joined);
    }
  }

  /// "- number" lines at one indentation, from the next line on, while they last (at least
  /// one): a block list of numbers.
  Numbers blockNumbers(std::size_t indent) {
    Numbers values;
    while (!done() && peek().indent == indent && isItem(peek().content))
      values.push_back(scalarNumber(trimmedLeft(take().content.substr(2))));
    if (values.empty())
      throw NotPlain();
    return values;
  }

  /// After a block: the next line, if any, is a key at column 0. A deeper line that no item
  /// took (a multi-line scalar, a deeper list) is another form.
  void expectKeyOrEnd() const {
    if (!done() && (peek().indent != 0 || peek().content.front() == '-'))
      throw NotPlain();
  }

  static bool isItem(std::string_view content) {
    return content.size() >= 2 && content[0] == '-' && content[1] == ' ';
  }

 private:
  const std::vector<Line>& lines_;
  std::size_t at_ = 0;
};

/// The items of "heights:" given as a block (its lines indented, or "- " at column 0): rows as
/// flow lists ("- [..]", over one line or more) or as nested blocks ("- - a" then "  - b" lines),
/// or numbers ("- a": a flat list, no y). One form throughout.
void heightsBlock(LineCursor& lines, PlainFile& file) {
  if (lines.done() || !LineCursor::isItem(lines.peek().content))
    throw NotPlain();  // "heights:" with no items under it
  const std::size_t indent = lines.peek().indent;
  std::vector<Numbers> rows;
  Numbers flat;
  while (!lines.done() && lines.peek().indent == indent &&
         LineCursor::isItem(lines.peek().content)) {
    const std::string_view content = lines.take().content;
    const std::string_view item = trimmedLeft(content.substr(2));
    if (!item.empty() && item.front() == '[') {
      rows.push_back(lines.flowListFrom(item, indent));
    } else if (LineCursor::isItem(item)) {
      // "- - a": the row's first number; its inner items stand where this inner '-' does.
      const std::size_t inner = indent + (content.size() - item.size());
      Numbers row{scalarNumber(trimmedLeft(item.substr(2)))};
      if (!lines.done() && lines.peek().indent == inner) {
        const Numbers rest = lines.blockNumbers(inner);
        row.insert(row.end(), rest.begin(), rest.end());
      }
      rows.push_back(std::move(row));
    } else {
      flat.push_back(scalarNumber(item));
    }
    if (!rows.empty() && !flat.empty())
      throw NotPlain();
  }
  lines.expectKeyOrEnd();
  if (rows.empty())
    setOnce(file.flat_heights, std::move(flat));
  else
    setOnce(file.height_rows, std::move(rows));
}

PlainFile parse(const std::string& text) {
  PlainFile file;
  const std::vector<Line> all = contentLines(text);
  LineCursor lines(all);
  while (!lines.done()) {
    const Line& line = lines.take();
    const std::string_view content = line.content;
    if (line.indent != 0 || content.front() == '-')
      throw NotPlain();
    const std::size_t colon = content.find(':');
    if (colon == std::string_view::npos)
      throw NotPlain();
    const std::string_view key = content.substr(0, colon);
    const std::string_view rest = content.substr(colon + 1);
    if (!rest.empty() && rest.front() != ' ')
      throw NotPlain();  // "key:value" is one plain scalar in YAML, not a key and its value
    const std::string_view value = trimmedLeft(rest);
    if (value.empty() || value.front() == '#') {
      // A block under the key: "- " items, indented or at column 0.
      if (key == "heights") {
        heightsBlock(lines, file);
      } else if ((key == "x" || key == "y") && !lines.done()) {
        const std::size_t indent = lines.peek().indent;
        Numbers values = lines.blockNumbers(indent);
        lines.expectKeyOrEnd();
        setOnce(key == "x" ? file.x : file.y, std::move(values));
      } else {
        throw NotPlain();
      }
    } else if (key == "name") {
      setOnce(file.name, value.front() == '"' ? quotedName(value) : plainName(value));
    } else if (key == "spacing") {
      setOnce(file.spacing, scalarNumber(value));
    } else if (key == "start") {
      setOnce(file.start, scalarNumber(value));
    } else if (key == "x") {
      setOnce(file.x, lines.flowListFrom(value, 0));
    } else if (key == "y") {
      setOnce(file.y, lines.flowListFrom(value, 0));
    } else if (key == "heights") {
      setOnce(file.flat_heights, lines.flowListFrom(value, 0));
    } else {
      throw NotPlain();
    }
  }
  if (file.flat_heights && file.height_rows)
    throw NotPlain();
  return file;
}

/// loadTerrainYaml's checks of the file's shape and spacing, then the Terrain's own (finite,
/// strictly increasing stations and lines at least kMinTerrainSpacing apart, heights within
/// kMaxTerrainHeight: the general reader repeats them only to name the key); any failure leaves
/// the file to the general reader.
Terrain build(PlainFile file, const std::string& path) {
  if (file.spacing.has_value() == file.x.has_value() || (file.x && file.start))
    throw NotPlain();
  Vector lateral = Vector::Zero(1);
  std::vector<Numbers> rows;
  if (file.y) {
    // A list of lists, one per lateral line.
    if (file.y->empty() || !file.height_rows || file.height_rows->size() != file.y->size())
      throw NotPlain();
    lateral = Eigen::Map<const Vector>(file.y->data(), static_cast<Eigen::Index>(file.y->size()));
    rows = std::move(*file.height_rows);
  } else {
    if (!file.flat_heights)
      throw NotPlain();
    rows.push_back(std::move(*file.flat_heights));
  }
  const std::size_t count = rows.front().size();
  if (count == 0)
    throw NotPlain();
  for (const Numbers& row : rows)
    if (row.size() != count)
      throw NotPlain();

  const auto stations = static_cast<Eigen::Index>(count);
  Vector x(stations);
  if (file.spacing) {
    const double spacing = *file.spacing;
    if (!(spacing >= kMinTerrainSpacing))
      throw NotPlain();
    const double start = file.start.value_or(0.0);
    for (Eigen::Index k = 0; k < stations; ++k)
      x(k) = start + static_cast<double>(k) * spacing;
  } else {
    if (file.x->size() != count)
      throw NotPlain();
    x = Eigen::Map<const Vector>(file.x->data(), stations);
  }

  Matrix h(lateral.size(), stations);
  for (std::size_t j = 0; j < rows.size(); ++j)
    for (std::size_t i = 0; i < count; ++i)
      h(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = rows[j][i];
  const std::string name = file.name ? *file.name : std::filesystem::path(path).stem().string();
  try {
    return Terrain(x, lateral, h, name);
  } catch (const InputError&) {
    throw NotPlain();  // the general reader gives the message, with the file's name
  }
}

}  // namespace

std::optional<Terrain> readPlainTerrainYaml(const std::string& path) {
  // A regular file only: the general reader opens the file again, and a named pipe read here
  // would leave it nothing (it waited for a writer for ever).
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return std::nullopt;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
    return std::nullopt;
  try {
    return build(parse(text), path);
  } catch (const NotPlain&) {
    return std::nullopt;
  }
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
