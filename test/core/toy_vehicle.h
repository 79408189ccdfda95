// A small vehicle with the output names of a reduced vehicle model, for the ROS-layer unit tests:
// a pitch-plane half car. q = [z_h, theta_y, z_1, z_2]: hull heave at its CoG, hull pitch (ry,
// positive nose down, REP-103), front and rear road-wheel heights. Each wheel hangs on a
// suspension (k_s, c_s) from the hull point above it and stands on a tyre (k_t, c_t) on the road
// input below it, so C_u != 0 and the road rate u' matters.
#pragma once

#include "tracked_vehicle_dynamics/online/online_vehicle.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"

namespace tracked_vehicle_dynamics {
namespace online {
namespace test {

struct ToyVehicle {
  static constexpr double kHullMass = 1000.0;        // [kg]
  static constexpr double kPitchInertia = 800.0;     // [kg m^2]
  static constexpr double kWheelMass = 50.0;         // [kg]
  static constexpr double kSuspension = 3e4;         // [N/m]
  static constexpr double kSuspensionDamping = 2e3;  // [N s/m]
  static constexpr double kTyre = 2e5;               // [N/m]
  static constexpr double kTyreDamping = 500.0;      // [N s/m]
  static constexpr double kWheelX[2] = {1.0, -1.0};  // [m], front then rear
  static constexpr double kCogHeight = 1.0;          // [m]
  static constexpr double kWheelHeight = 0.4;        // [m]
};

inline reduction::ReducedModel toyModel() {
  using T = ToyVehicle;
  reduction::ReducedModel model;
  dynamics::SecondOrderSystem& sys = model.system;
  const int n = 4;
  sys.mass = Vector(Eigen::Vector4d(T::kHullMass, T::kPitchInertia, T::kWheelMass, T::kWheelMass))
                 .asDiagonal();
  sys.stiffness = Matrix::Zero(n, n);
  sys.damping = Matrix::Zero(n, n);
  sys.input_stiffness = Matrix::Zero(n, 2);
  sys.input_damping = Matrix::Zero(n, 2);
  for (int i = 0; i < 2; ++i) {
    // Suspension deflection d = z_hull(x_i) - z_i with z_hull(x) = z_h - theta x (CoG at x = 0).
    Vector b = Vector::Zero(n);
    b(0) = 1.0;
    b(1) = -T::kWheelX[i];
    b(2 + i) = -1.0;
    sys.stiffness += T::kSuspension * b * b.transpose();
    sys.damping += T::kSuspensionDamping * b * b.transpose();
    sys.stiffness(2 + i, 2 + i) += T::kTyre;
    sys.damping(2 + i, 2 + i) += T::kTyreDamping;
    sys.input_stiffness(2 + i, i) = T::kTyre;
    sys.input_damping(2 + i, i) = T::kTyreDamping;
  }
  // Outputs: hull CoG (6), the two wheels, crew_seat at (0.5, 0.3, 1.5): u = theta x (p - p_G).
  sys.output_names = {"hull ux",
                      "hull uy",
                      "hull uz",
                      "hull rx",
                      "hull ry",
                      "hull rz",
                      "road_wheel_left_1 uz",
                      "road_wheel_left_2 uz",
                      "crew_seat ux",
                      "crew_seat uy",
                      "crew_seat uz"};
  sys.output = Matrix::Zero(11, n);
  sys.output(2, 0) = 1.0;
  sys.output(4, 1) = 1.0;
  sys.output(6, 2) = 1.0;
  sys.output(7, 3) = 1.0;
  sys.output(8, 1) = 1.5 - T::kCogHeight;  // theta_y (p_z - G_z)
  sys.output(10, 0) = 1.0;
  sys.output(10, 1) = -0.5;  // -theta_y (p_x - G_x)
  sys.input_stations = (Vector(2) << T::kWheelX[0], T::kWheelX[1]).finished();
  sys.input_lateral = Vector::Zero(2);
  model.gravity_load =
      -kStandardGravity * Vector(Eigen::Vector4d(T::kHullMass, 0.0, T::kWheelMass, T::kWheelMass));
  // Travel inertia per unit forward acceleration: the hull's -M a at its CoG, kCogHeight above
  // the ground, is a pitch moment -M kCogHeight a taken by the suspension (the model has no x
  // coordinate; the wheels' own inertia is neglected). Braking (a < 0) pitches the nose down.
  model.travel_load = Vector(Eigen::Vector4d(0.0, -T::kHullMass * T::kCogHeight, 0.0, 0.0));
  model.damping = "toy";
  return model;
}

inline VehicleGeometry toyGeometry() {
  using T = ToyVehicle;
  VehicleGeometry g;
  g.vehicle_name = "toy";
  g.cog = Vector3(0.0, 0.0, T::kCogHeight);
  g.wheels = {{"road_wheel_left_1", Vector3(T::kWheelX[0], 0.0, T::kWheelHeight)},
              {"road_wheel_left_2", Vector3(T::kWheelX[1], 0.0, T::kWheelHeight)}};
  g.points = {{"crew_seat", Vector3(0.5, 0.3, 1.5)}};
  return g;
}

}  // namespace test
}  // namespace online
}  // namespace tracked_vehicle_dynamics
