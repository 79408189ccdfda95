// The numerical core stays ROS-free (ARCHITECTURE.md): no core header or source may include a
// ROS, catkin or message header. The ROS layer lives in include/.../ros and src/ros only.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

namespace fs = std::filesystem;

TEST(CoreBoundary, NoRosHeadersInTheCore) {
  const std::regex ros_include(
      R"(#\s*include\s*[<"](ros/|tf2|tf2_ros/|rosbag/|std_msgs/|geometry_msgs/|diagnostic_updater/|std_srvs/|tracked_vehicle_dynamics/[A-Z]\w*\.h))");
  const fs::path root(TVD_SOURCE_DIR);
  int files = 0;
  for (const char* top : {"include/tracked_vehicle_dynamics", "src"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (!entry.is_regular_file()) continue;
      const std::string path = entry.path().generic_string();
      if (path.find("/ros/") != std::string::npos) continue;  // the ROS layer itself
      std::ifstream in(entry.path());
      std::string line;
      int number = 0;
      while (std::getline(in, line)) {
        ++number;
        EXPECT_FALSE(std::regex_search(line, ros_include)) << path << ":" << number << ": " << line;
      }
      ++files;
    }
  }
  EXPECT_GT(files, 10);
}
