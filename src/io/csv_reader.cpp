#include "tracked_vehicle_dynamics/io/csv_reader.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/message_text.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

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

// A number's digits with a leading '+' dropped (from_chars refuses it), and what from_chars
// makes of them: errc() with the value, result_out_of_range for a number beyond double's range,
// invalid_argument for anything else.
std::errc scanNumber(const std::string& cell, double* value) {
  std::string_view digits(cell);
  if (digits.size() > 1 && digits.front() == '+')
    digits.remove_prefix(1);
  if (digits.empty())
    return std::errc::invalid_argument;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), *value);
  if (end != digits.data() + digits.size())
    return std::errc::invalid_argument;
  if (error == std::errc::result_out_of_range) {
    // A subnormal (a save's 4.9e-324) is a double all the same, as the YAML reader takes it;
    // only overflow and underflow to zero are out of range.
    const double subnormal = strtodC(cell.c_str(), nullptr);
    if (subnormal != 0.0 && std::abs(subnormal) < 1.0) {
      *value = subnormal;
      return std::errc();
    }
  }
  return error;
}

}  // namespace

std::optional<double> parseNumber(const std::string& cell) {
  double value = 0.0;
  if (scanNumber(cell, &value) != std::errc())
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

// A cell as a message shows it: control bytes as \xNN, at most 60 characters.
std::string shownCell(const std::string& cell) {
  constexpr std::size_t kShown = 60;
  return printable(cell, kShown);
}

}  // namespace

double CsvReader::number(const CsvRow& row, std::size_t column, const std::string& what) const {
  const std::string& cell = row.cells[column];
  double parsed = 0.0;
  const std::errc error = scanNumber(cell, &parsed);
  if (error == std::errc::result_out_of_range) {
    fail(row, column,
         what + " '" + shownCell(cell) + "' is out of range (a double holds 4.9e-324 .. 1.8e308)");
  }
  const std::optional<double> value =
      error == std::errc() ? std::optional<double>(parsed) : std::nullopt;
  if (!value)
    fail(row, column, what + " '" + shownCell(cell) + "' is not a number");
  if (!std::isfinite(*value))
    fail(row, column, what + " '" + shownCell(cell) + "' is not a finite number");
  return *value;
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
