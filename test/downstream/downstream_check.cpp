// Uses each part of tracked_vehicle_dynamics a downstream package would: a generated message
// (RoadWheels), the ROS layer (tvd_ros: its message conversions) and the ROS-free core (tvd_core:
// a vehicle description and its statics). Prints one line per check; exits non-zero on failure.
#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

#include <tracked_vehicle_dynamics/RoadWheels.h>
#include <tracked_vehicle_dynamics/fem/system.h>
#include <tracked_vehicle_dynamics/ros/conversions.h>
#include <tracked_vehicle_dynamics/vehicle/vehicle_description.h>
#include <tracked_vehicle_dynamics/vehicle/vehicle_model.h>

namespace tvd = tracked_vehicle_dynamics;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: downstream_check VEHICLE.yaml\n");
    return 2;
  }
  try {
    // The ROS layer and a generated message.
    std::vector<tvd::ros_layer::WheelState> wheels(2);
    wheels[0].name = "road_wheel_left_1";
    wheels[0].displacement = 0.012;
    tvd::RoadWheels msg;
    tvd::ros_layer::toMsg(wheels, 3.5, 8.0, &msg, "veh1/");
    double station = 0.0;
    const auto back = tvd::ros_layer::fromMsg(msg, &station);
    const bool ros_ok = back.size() == 2 && back[0].name == "veh1/road_wheel_left_1" &&
                        back[0].displacement == 0.012 && station == 3.5;
    std::printf("ros layer: %s\n", ros_ok ? "ok" : "FAILED");

    // The core: the description and its un-tracked FE model (Eigen objects cross the boundary).
    const tvd::vehicle::VehicleDescription d = tvd::vehicle::loadVehicleDescription(argv[1]);
    const tvd::vehicle::VehicleModel model =
        tvd::vehicle::buildVehicleModel(d, tvd::vehicle::Variant::Untracked);
    const double mass = model.model.totalMass();
    // Sparse matrices made in tvd_core and freed here: the SIMD level the package exports keeps
    // Eigen's allocation the same on both sides.
    const tvd::fem::System system = tvd::fem::assemble(model.model);
    std::printf("core: %s, hull mass %.0f kg, model mass %.0f kg, %ld active DOFs\n",
                d.name.c_str(), d.hull.mass, mass, static_cast<long>(system.size()));
    const bool core_ok =
        d.hull.mass > 0 && mass > d.hull.mass && std::isfinite(mass) && system.size() > 6;
    return ros_ok && core_ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "downstream_check: %s\n", e.what());
    return 1;
  }
}
