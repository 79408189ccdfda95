// A leading "~" in a path the user typed where no shell expands it: a ROS parameter (roslaunch
// passes it as written) or tvd's --cache-dir=~/x (bash expands "~" after "=" in assignments
// only). Taken literally it names a directory "~" under the working directory, created there
// without a word.
#pragma once

#include <string>

namespace tracked_vehicle_dynamics {
namespace io {

/// `path` with a leading "~" alone or "~/" replaced by $HOME, as a shell does; a path not
/// starting with "~" unchanged. Throws InputError naming `what` for "~user..." (not looked up:
/// refused rather than taken as a directory "~user" here) and when the path needs $HOME and it
/// is unset or not absolute.
std::string expandHome(const std::string& path, const std::string& what);

}  // namespace io
}  // namespace tracked_vehicle_dynamics
