#include "tracked_vehicle_dynamics/io/csv_reader.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace io {
namespace {

std::string trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos)
    return "";
  const auto last = text.find_last_not_of(" \t\r");
  return std::string(text.substr(first, last - first + 1));
}

}  // namespace

std::optional<double> parseNumber(const std::string& cell) {
  std::string_view digits(cell);
  if (digits.size() > 1 && digits.front() == '+')
    digits.remove_prefix(1);
  if (digits.empty())
    return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc() || end != digits.data() + digits.size())
    return std::nullopt;
  return value;
}

void CsvReader::fail(const std::string& what) const {
  throw InputError(path_ + ": " + what);
}

void CsvReader::fail(const CsvRow& row, const std::string& what) const {
  fail("row " + std::to_string(row.line) + ": " + what);
}

void CsvReader::fail(const CsvRow& row, std::size_t column, const std::string& what) const {
  fail("row " + std::to_string(row.line) + ", column " + std::to_string(column + 1) + ": " + what);
}

std::vector<CsvRow> CsvReader::readRows() const {
  std::error_code error;
  if (!std::filesystem::exists(path_, error))
    fail("file not found");
  std::ifstream in(path_);
  if (!in)
    fail("cannot be opened");
  std::vector<CsvRow> rows;
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad())
    fail("cannot be read");
  // Lines end in LF, CR LF, or a lone CR (classic Mac OS, and some spreadsheets' "CSV (Mac)"):
  // read as one line, such a file would be one comment or one ragged row.
  std::size_t at = 0;
  for (int line = 1; at < all.size(); ++line) {
    const std::size_t end = all.find_first_of("\r\n", at);
    std::string text = all.substr(at, end == std::string::npos ? std::string::npos : end - at);
    at = end == std::string::npos                                           ? all.size()
         : all[end] == '\r' && end + 1 < all.size() && all[end + 1] == '\n' ? end + 2
                                                                            : end + 1;
    // A UTF-8 byte-order mark (spreadsheets write one) is not part of the first cell.
    if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0)
      text.erase(0, 3);
    const std::string content = trim(text);
    if (content.empty() || content.front() == '#')
      continue;
    CsvRow row{line, {}};
    std::size_t begin = 0;
    while (true) {
      const std::size_t comma = content.find(',', begin);
      row.cells.push_back(trim(std::string_view(content).substr(begin, comma - begin)));
      if (comma == std::string::npos)
        break;
      begin = comma + 1;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

namespace {

// A cell as a message shows it: control bytes (a NUL would end the message there) as \xNN.
std::string printable(const std::string& cell) {
  std::string out;
  for (const char c : cell) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02x", static_cast<unsigned char>(c));
      out += hex;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

double CsvReader::number(const CsvRow& row, std::size_t column, const std::string& what) const {
  const std::string& cell = row.cells[column];
  const std::optional<double> value = parseNumber(cell);
  if (!value)
    fail(row, column, what + " '" + printable(cell) + "' is not a number");
  if (!std::isfinite(*value))
    fail(row, column, what + " '" + printable(cell) + "' is not a finite number");
  return *value;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
