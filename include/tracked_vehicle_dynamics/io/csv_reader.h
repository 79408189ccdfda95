// Strict reading of small numeric CSV files (terrain, speed profiles): comma separated, blank
// lines and lines starting with '#' skipped, cells trimmed, a leading UTF-8 byte-order mark and
// CR-LF line ends accepted; every error throws InputError naming
// the file, the file line and the column: "<file>: row 7, column 3: height 'nan' is not a
// finite number".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace io {

/// Parses a whole cell as a number (locale-independent); non-finite spellings ("nan", "inf")
/// parse too, so the caller can report them as such rather than as "not a number".
std::optional<double> parseNumber(const std::string& cell);

/// One CSV line that is neither blank nor a comment.
struct CsvRow {
  int line;  ///< 1-based line in the file
  std::vector<std::string> cells;
};

class CsvReader {
 public:
  explicit CsvReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void fail(const CsvRow& row, const std::string& what) const;
  [[noreturn]] void fail(const CsvRow& row, std::size_t column, const std::string& what) const;

  /// Every row that is neither blank nor a comment. Fails for a missing or unreadable file.
  std::vector<CsvRow> readRows() const;
  /// A finite number from a cell; `what` names the quantity ("station", "height", ...).
  double number(const CsvRow& row, std::size_t column, const std::string& what) const;

 private:
  std::string path_;
};

}  // namespace io
}  // namespace tracked_vehicle_dynamics
