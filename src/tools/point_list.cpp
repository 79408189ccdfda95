#include "point_list.h"

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace tools {

std::vector<std::string> splitPointList(const std::string& command,
                                        const std::vector<std::string>& specs) {
  std::vector<std::string> names;
  for (const std::string& spec : specs) {
    std::string::size_type start = 0;
    for (;;) {
      const std::string::size_type comma = spec.find(',', start);
      const std::string name =
          spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (name.empty())
        throw InputError(command + ": --points: an empty name in '" + spec +
                         "' (names are separated by single commas; leave --points out for its "
                         "default)");
      names.push_back(name);
      if (comma == std::string::npos)
        break;
      start = comma + 1;
    }
  }
  return names;
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
