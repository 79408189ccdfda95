#include "mass_breakdown_report.h"

#include <array>
#include <iomanip>
#include <sstream>

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

// (JSON key, text label, mass) of each part, in report order.
struct Part {
  const char* key;
  const char* label;
  double kg;
};

std::array<Part, 6> parts(const vehicle::MassBreakdown& m) {
  return {{{"hull", "hull", m.hull},
           {"road_wheels", "road wheels", m.road_wheels},
           {"track_assemblies", "track assemblies", m.track_assemblies},
           {"sprockets", "sprockets", m.sprockets},
           {"idlers", "idlers", m.idlers},
           {"return_rollers", "return rollers", m.return_rollers}}};
}

}  // namespace

void writeMassBreakdown(io::JsonWriter& json, const vehicle::MassBreakdown& mass) {
  json.key("mass_breakdown_kg").beginObject();
  for (const Part& p : parts(mass))
    json.field(p.key, p.kg);
  json.endObject();
}

std::string massBreakdownText(const vehicle::MassBreakdown& mass) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << "mass breakdown:";
  const char* separator = " ";
  for (const Part& p : parts(mass)) {
    if (p.kg == 0.0)
      continue;
    text << separator << p.label << " " << p.kg << " kg";
    separator = ", ";
  }
  text << " (total " << mass.total << " kg)";
  return text.str();
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
