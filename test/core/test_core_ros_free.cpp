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
  // Every message and service package (*_msgs/, *_srvs/: sensor_msgs, nav_msgs, rosgraph_msgs,
  // diagnostic_msgs, ...), roscpp, tf2, rosbag and the tools around them, and this package's
  // generated messages (tracked_vehicle_dynamics/TerrainProfile.h: capitalised).
  const std::regex ros_include(
      R"(#\s*include\s*[<"](ros/|tf2|rosbag/|diagnostic_updater/|actionlib|dynamic_reconfigure/|message_filters/|\w+_msgs/|\w+_srvs/|tracked_vehicle_dynamics/[A-Z]\w*\.h))");
  for (const char* line :
       {"#include <nav_msgs/Odometry.h>", "#include <sensor_msgs/Imu.h>", "# include <ros/ros.h>",
        "#include <rosgraph_msgs/Clock.h>", "#include <diagnostic_msgs/DiagnosticArray.h>",
        "#include <tf2_ros/buffer.h>", "#include <std_srvs/Empty.h>",
        "#include \"tracked_vehicle_dynamics/TerrainProfile.h\""})
    EXPECT_TRUE(std::regex_search(std::string(line), ros_include)) << line;
  for (const char* line : {"#include \"tracked_vehicle_dynamics/terrain/terrain.h\"",
                           "#include <Eigen/Dense>", "#include <string>"})
    EXPECT_FALSE(std::regex_search(std::string(line), ros_include)) << line;
  const fs::path root(TVD_SOURCE_DIR);
  int files = 0;
  for (const char* top : {"include/tracked_vehicle_dynamics", "src"}) {
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      if (!entry.is_regular_file())
        continue;
      const std::string path = entry.path().generic_string();
      if (path.find("/ros/") != std::string::npos)
        continue;  // the ROS layer itself
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
