#include "tracked_vehicle_dynamics/dynamics/speed_profile_io.h"

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/csv_reader.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

SpeedProfile loadSpeedProfile(const std::string& path) {
  const io::CsvReader reader(path);
  const std::vector<io::CsvRow> rows = reader.readRows();
  if (rows.empty())
    reader.fail("empty (expected a header time_s,speed_kmh and data rows)");
  const io::CsvRow& header = rows.front();
  if (header.cells.size() != 2 || header.cells[0] != "time_s" ||
      (header.cells[1] != "speed_kmh" && header.cells[1] != "speed_m_s"))
    reader.fail(header, "expected the header time_s,speed_kmh or time_s,speed_m_s");
  const double to_m_s = header.cells[1] == "speed_kmh" ? 1.0 / kKmhPerMs : 1.0;
  std::vector<double> time, speed;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const io::CsvRow& row = rows[i];
    if (row.cells.size() != 2)
      reader.fail(row, "expected 2 columns (time, speed), got " + std::to_string(row.cells.size()));
    time.push_back(reader.number(row, 0, "time"));
    speed.push_back(reader.number(row, 1, "speed"));
    // Checked here as well as in SpeedProfile, so that the message names the row.
    if (speed.back() < 0)
      reader.fail(row, 1, "speed " + row.cells[1] + " is negative (forward travel only)");
    if (time.size() == 1 && time.back() != 0)
      reader.fail(row, 0, "the first time must be 0");
    if (time.size() > 1 && !(time.back() > time[time.size() - 2]))
      reader.fail(row, 0,
                  "time " + row.cells[0] +
                      " s is not after the previous row's; times must be strictly increasing");
    speed.back() *= to_m_s;
  }
  return SpeedProfile(std::move(time), std::move(speed), path);
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
