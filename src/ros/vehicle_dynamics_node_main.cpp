// vehicle_dynamics_node: see doc/ros_node.md and
// include/tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h.
#include <cstdio>

#include <ros/ros.h>

#include "tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "vehicle_dynamics_node");
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  try {
    tracked_vehicle_dynamics::ros_layer::VehicleDynamicsNode node(nh, private_nh);
    ros::spin();
  } catch (const tracked_vehicle_dynamics::ros_layer::StartUpInterrupted& e) {
    // Asked to stop: not a failure. On the console (ROS_INFO's /rosout has shut down).
    std::printf("%s: %s\n", tracked_vehicle_dynamics::ros_layer::nodeName(), e.what());
    return 0;
  } catch (const std::exception& e) {
    ROS_FATAL("%s: %s", tracked_vehicle_dynamics::ros_layer::nodeName(), e.what());
    return 1;
  }
  return 0;
}
