// The ROS layer drives the core's online vehicle (online/: the vehicle stepped sample by sample
// on a terrain that arrives in patches, its frames and timing statistics, all ROS-free so that a
// simulator without ROS can use them too). Its names, used unqualified in the ROS layer.
#pragma once

#include "tracked_vehicle_dynamics/online/duration_statistics.h"
#include "tracked_vehicle_dynamics/online/online_vehicle.h"
#include "tracked_vehicle_dynamics/online/road_input_sampler.h"
#include "tracked_vehicle_dynamics/online/vehicle_frames.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

using online::baseLinkTwist;
using online::bodyAcceleration;
using online::bodyRate;
using online::DurationStatistics;
using online::hullDisplacement;
using online::hullPointDisplacement;
using online::hullPose;
using online::kCrewSeatPoint;
using online::kMaxResetStation;
using online::OnlineVehicle;
using online::OnlineVehicleOptions;
using online::relativePosition;
using online::relativeToPath;
using online::ResetTerrain;
using online::resolveComfortPoint;
using online::rigidPointAcceleration;
using online::RigidPose;
using online::RoadInputSampler;
using online::rollPitchYaw;
using online::rotationFromRollPitchYaw;
using online::simulatorOptions;
using online::specificForce;
using online::StepResult;
using online::TerrainPatch;
using online::VehicleGeometry;
using online::vehicleGeometry;
using online::WheelState;

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
