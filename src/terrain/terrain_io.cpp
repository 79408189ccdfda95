#include "tracked_vehicle_dynamics/terrain/terrain_io.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/io/csv_reader.h"
#include "tracked_vehicle_dynamics/io/file_type.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/io/yaml_file_kind.h"
#include "tracked_vehicle_dynamics/io/yaml_reader.h"
#include "tracked_vehicle_dynamics/terrain/terrain_yaml_plain.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

// The refusal of a height beyond kMaxTerrainHeight, for both readers (which name its row and
// column, or its YAML line; Terrain's own check knows only indices).
std::string heightBeyondRange(double height) {
  return "height " + brief(height) + " m is beyond +-" + brief(kMaxTerrainHeight) +
         " m (heights are in m, relative to the road: mm, or altitudes?)";
}

/// A YAML double-quoted scalar.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + '"';
}

std::string stem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

using io::CsvReader;
using io::CsvRow;
using io::parseNumber;

void writeFlowList(std::ostream& out, const Eigen::Ref<const Eigen::RowVectorXd>& values) {
  out << '[';
  for (Eigen::Index i = 0; i < values.size(); ++i)
    out << (i ? ", " : "") << io::roundTripText(values(i));
  out << ']';
}

/// Checks a strictly increasing YAML list, failing on the offending element.
void checkIncreasing(const std::vector<io::YamlValue>& items, const std::vector<double>& values,
                     const std::string& what) {
  for (std::size_t i = 1; i < values.size(); ++i) {
    if (values[i] == values[i - 1]) {
      items[i].fail("duplicate " + what + " " + brief(values[i]) + " m (same as entry " +
                    std::to_string(i - 1) + ")");
    }
    if (values[i] < values[i - 1]) {
      items[i].fail(what + " " + brief(values[i]) + " m is less than the previous one (" +
                    brief(values[i - 1]) + " m); " + what + "s must be strictly increasing");
    }
    if (closerThanMinSpacing(values[i - 1], values[i])) {
      items[i].fail(what + " " + brief(values[i]) + " m is " + brief(values[i] - values[i - 1]) +
                    " m from the previous one; at least " + brief(kMinTerrainSpacing) + " m apart");
    }
  }
}

}  // namespace

Terrain loadTerrainCsv(const std::string& path) {
  const CsvReader reader(path);
  const std::vector<CsvRow> rows = reader.readRows();
  if (rows.empty())
    reader.fail("empty (no header or data rows)");

  const CsvRow& first = rows.front();
  const bool has_header = !parseNumber(first.cells.front()).has_value();
  const std::size_t columns = first.cells.size();
  Vector lateral = Vector::Zero(1);
  if (has_header) {
    if (columns < 2) {
      // A whole line in one cell: most often another separator (a locale's ';' or a tab).
      const std::string& cell = first.cells.front();
      const bool other_separator = cell.find_first_of(";\t") != std::string::npos;
      reader.fail(first, std::string("the header needs a station label and at least one height "
                                     "column") +
                             (other_separator ? " (columns are separated by commas; this line "
                                                "has ';' or tabs)"
                                              : ""));
    }
    const bool labelled_single_line = columns == 2 && !parseNumber(first.cells[1]).has_value();
    if (!labelled_single_line) {
      lateral.resize(static_cast<Eigen::Index>(columns - 1));
      for (std::size_t c = 1; c < columns; ++c) {
        lateral(static_cast<Eigen::Index>(c - 1)) = reader.number(first, c, "lateral position");
        if (c > 1 && lateral(c - 1) <= lateral(c - 2)) {
          reader.fail(first, c,
                      "lateral position " + brief(lateral(c - 1)) + " m is not greater than " +
                          brief(lateral(c - 2)) +
                          " m; lateral positions must be strictly increasing");
        }
      }
    }
  } else if (columns != 2) {
    reader.fail(first, std::to_string(columns) +
                           " columns need a header row giving the lateral position y [m] of each "
                           "height column (only a 2-column x,h file may omit it)");
  }

  const std::size_t first_data = has_header ? 1 : 0;
  if (rows.size() <= first_data)
    reader.fail("no data rows (only a header)");
  const auto stations = static_cast<Eigen::Index>(rows.size() - first_data);
  Vector x(stations);
  Matrix h(lateral.size(), stations);
  for (Eigen::Index i = 0; i < stations; ++i) {
    const CsvRow& row = rows[first_data + static_cast<std::size_t>(i)];
    if (row.cells.size() != columns) {
      reader.fail(row, "expected " + std::to_string(columns) + " columns (x and " +
                           std::to_string(columns - 1) + " heights), got " +
                           std::to_string(row.cells.size()));
    }
    x(i) = reader.number(row, 0, "station");
    if (!(std::abs(x(i)) <= kMaxTerrainCoordinate))
      reader.fail(row, 0,
                  "station " + brief(x(i)) + " m is beyond +-" + brief(kMaxTerrainCoordinate) +
                      " m (stations are in m: mm, or a datum far away?)");
    if (i > 0 && x(i) == x(i - 1)) {
      reader.fail(row, "duplicate station x = " + brief(x(i)) + " m (also on row " +
                           std::to_string(rows[first_data + i - 1].line) + ")");
    }
    if (i > 0 && x(i) < x(i - 1)) {
      reader.fail(row, "station x = " + brief(x(i)) + " m is less than the previous station " +
                           brief(x(i - 1)) + " m; stations must be strictly increasing");
    }
    if (i > 0 && closerThanMinSpacing(x(i - 1), x(i))) {
      reader.fail(row, "station x = " + brief(x(i)) + " m is " + brief(x(i) - x(i - 1)) +
                           " m from the previous station; at least " + brief(kMinTerrainSpacing) +
                           " m apart");
    }
    for (std::size_t c = 1; c < columns; ++c) {
      const double height = reader.number(row, c, "height");
      if (!(std::abs(height) <= kMaxTerrainHeight))
        reader.fail(row, c, heightBeyondRange(height));
      h(static_cast<Eigen::Index>(c - 1), i) = height;
    }
  }
  try {
    return Terrain(x, lateral, h, stem(path));
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

Terrain loadTerrainYaml(const std::string& path) {
  if (std::optional<Terrain> plain = readPlainTerrainYaml(path))
    return std::move(*plain);
  return loadTerrainYamlGeneral(path);
}

Terrain loadTerrainYamlGeneral(const std::string& path) {
  const io::YamlValue root = io::YamlValue::loadFile(path);
  io::expectNotOtherYamlFile(root, io::YamlFileKind::Terrain);
  root.expectMap({"name", "spacing", "start", "x", "y", "heights"});
  const std::string name = root.has("name") ? root["name"].asString() : stem(path);
  const bool has_spacing = root.has("spacing");
  const bool has_x = root.has("x");
  if (has_spacing == has_x) {
    root.fail("give exactly one of 'spacing' (uniform stations) and 'x' (explicit stations)");
  }
  if (has_x && root.has("start"))
    root["start"].fail("'start' applies only with 'spacing'");

  // Lateral lines, then one height row per line.
  Vector lateral = Vector::Zero(1);
  std::vector<std::vector<double>> rows;
  const io::YamlValue heights = root["heights"];
  if (const std::optional<io::YamlValue> y = root.find("y")) {
    const std::vector<io::YamlValue> items = y->elements("a list of lateral positions [m]");
    if (items.empty())
      y->fail("expected at least one lateral position");
    std::vector<double> values;
    for (const io::YamlValue& item : items)
      values.push_back(item.asNumber());
    checkIncreasing(items, values, "lateral position");
    lateral = Eigen::Map<const Vector>(values.data(), static_cast<Eigen::Index>(values.size()));
    for (const io::YamlValue& row :
         heights.elements(items.size(), "one list of heights per lateral position in 'y'")) {
      rows.push_back(row.asNumbers());
    }
  } else {
    rows.push_back(heights.asNumbers());
  }
  const std::size_t count = rows.front().size();
  if (count == 0)
    heights.fail("expected at least one height");
  for (std::size_t j = 1; j < rows.size(); ++j) {
    if (rows[j].size() != count) {
      heights.elements()[j].fail("expected " + std::to_string(count) +
                                 " heights (one per station, as heights[0]), got " +
                                 std::to_string(rows[j].size()));
    }
  }

  Vector x(static_cast<Eigen::Index>(count));
  if (has_spacing) {
    const io::YamlValue spacing_value = root["spacing"];
    const double spacing = spacing_value.asNumber();
    if (!(spacing >= kMinTerrainSpacing))
      spacing_value.fail("spacing " + brief(spacing) + " m must be at least " +
                         brief(kMinTerrainSpacing) + " m");
    const double start = root.has("start") ? root["start"].asNumber() : 0.0;
    for (std::size_t i = 0; i < count; ++i) {
      const auto k = static_cast<Eigen::Index>(i);
      x(k) = start + static_cast<double>(i) * spacing;
      // A spacing lost to round-off beside a huge start (or a start beyond double range).
      if (!std::isfinite(x(k)) || (k > 0 && !(x(k) > x(k - 1))))
        (root.has("start") ? root["start"] : spacing_value)
            .fail("start " + brief(start) + " m and spacing " + brief(spacing) +
                  " m give station " + std::to_string(i) + " = " + brief(x(k)) +
                  " m, not finite or not beyond the one before it");
    }
  } else {
    const std::vector<io::YamlValue> items =
        root["x"].elements(count, "one station [m] per height (" + std::to_string(count) + ")");
    std::vector<double> values;
    for (const io::YamlValue& item : items)
      values.push_back(item.asNumber());
    checkIncreasing(items, values, "station");
    x = Eigen::Map<const Vector>(values.data(), static_cast<Eigen::Index>(count));
  }

  Matrix h(lateral.size(), static_cast<Eigen::Index>(count));
  for (std::size_t j = 0; j < rows.size(); ++j) {
    h.row(static_cast<Eigen::Index>(j)) =
        Eigen::Map<const Eigen::RowVectorXd>(rows[j].data(), static_cast<Eigen::Index>(count));
    for (std::size_t i = 0; i < count; ++i)
      if (!(std::abs(rows[j][i]) <= kMaxTerrainHeight)) {
        const io::YamlValue line = root.has("y") ? heights.elements()[j] : heights;
        line.elements()[i].fail(heightBeyondRange(rows[j][i]));
      }
  }
  try {
    return Terrain(x, lateral, h, name);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

Terrain loadTerrain(const std::string& path) {
  const std::string extension = io::lowerExtension(path);
  if (extension == ".csv")
    return loadTerrainCsv(path);
  if (extension == ".yaml" || extension == ".yml")
    return loadTerrainYaml(path);
  throw InputError(path + ": unknown terrain file type '" + extension +
                   "' (expected .csv, .yaml or .yml)");
}

Terrain loadTrack(const std::string& track, const TrackOptions& options) {
  // A half-round spec is the built-in obstacle even when malformed: halfRoundHeight() then throws
  // naming its fault, rather than calling it neither a track nor a file.
  if (isBuiltInTrack(track) || halfRoundHeight(track))
    return makeTrack(track, options);
  const std::string extension = io::lowerExtension(track);
  if (extension != ".csv" && extension != ".yaml" && extension != ".yml") {
    std::string known;
    for (const std::string& n : trackForms())
      known += (known.empty() ? "" : ", ") + n;
    throw InputError("track '" + track + "' is neither a built-in track (" + known +
                     ") nor a terrain file (.csv, .yaml)");
  }
  Terrain file = loadTerrain(track);
  if (!options.lateral_offset || *options.lateral_offset == 0.0)
    return file;
  return Terrain(file.stations(), file.lateral().array() - *options.lateral_offset, file.heights(),
                 file.name());
}

void saveTerrainCsv(const Terrain& terrain, const std::string& path) {
  io::AtomicTextFile file(path);
  std::ostream& out = file.stream();
  // Every value in its shortest exact text: 0.05, not 0.050000000000000003, and 0, not -0.
  out << "# tracked_vehicle_dynamics terrain '" << terrain.name()
      << "': station x [m], then the height [m] of each lateral line y [m]\n";
  out << 'x';
  for (Eigen::Index j = 0; j < terrain.lateral().size(); ++j)
    out << ',' << io::roundTripText(terrain.lateral()(j));
  out << '\n';
  for (Eigen::Index i = 0; i < terrain.stations().size(); ++i) {
    out << io::roundTripText(terrain.stations()(i));
    for (Eigen::Index j = 0; j < terrain.lateral().size(); ++j) {
      out << ',' << io::roundTripText(terrain.heights()(j, i));
    }
    out << '\n';
  }
  file.commit();
}

void saveTerrainYaml(const Terrain& terrain, const std::string& path) {
  io::AtomicTextFile file(path);
  std::ostream& out = file.stream();
  out << "# tracked_vehicle_dynamics terrain: stations x [m], lateral lines y [m] (y left),\n"
         "# heights [m], one list per y with one value per station.\n";
  out << "name: " << quoted(terrain.name()) << '\n';
  out << "x: ";
  writeFlowList(out, terrain.stations().transpose());
  out << "\ny: ";
  writeFlowList(out, terrain.lateral().transpose());
  out << "\nheights:\n";
  for (Eigen::Index j = 0; j < terrain.heights().rows(); ++j) {
    out << "  - ";
    writeFlowList(out, terrain.heights().row(j));
    out << '\n';
  }
  file.commit();
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
