#include "tracked_vehicle_dynamics/io/home_path.h"

#include <cstdlib>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace io {

std::string expandHome(const std::string& path, const std::string& what) {
  if (path.empty() || path[0] != '~')
    return path;
  // "~user/x" is another user's home to a shell; taken literally it would name a directory
  // "~user" where the program runs, the very surprise this function exists for.
  if (path.size() > 1 && path[1] != '/')
    throw InputError(what + " '" + path + "': only a leading ~ or ~/ is expanded (to $HOME), " +
                     "not ~user: give the directory in full");
  const char* home = std::getenv("HOME");
  if (home == nullptr || *home != '/')
    throw InputError(what + " '" + path + "' starts with ~ but $HOME is " +
                     (home == nullptr ? std::string("not set") : "'" + std::string(home) + "'") +
                     ": give the directory in full");
  // "~/x" with HOME "/home/u/" gives "/home/u//x": harmless, and what a shell gives too.
  return std::string(home) + path.substr(1);
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
