#include "tracked_vehicle_dynamics/io/csv_reader.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
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
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
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
  if (in.bad())
    fail("cannot be read");
  return rows;
}

double CsvReader::number(const CsvRow& row, std::size_t column, const std::string& what) const {
  const std::string& cell = row.cells[column];
  const std::optional<double> value = parseNumber(cell);
  if (!value)
    fail(row, column, what + " '" + cell + "' is not a number");
  if (!std::isfinite(*value))
    fail(row, column, what + " '" + cell + "' is not a finite number");
  return *value;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
