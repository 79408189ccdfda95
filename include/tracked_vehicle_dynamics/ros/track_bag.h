// Rosbags of the paper's test tracks (terrain/tracks.h) or of terrain files driven at a constant
// speed, as the node consumes them online: terrain patches published ahead of the vehicle, the
// speed, and optionally /clock. Replay with `rosbag play --clock` and use_sim_time
// (launch/replay_track.launch).
//
// The run: the vehicle reference point starts at station 0 at bag time start_time and drives at
// speed v (or along a speed profile) until station s_end = track end + behind (the rear contacts
// have left the track), so it lasts s_end / v. The terrain is the track sampled on its own grid
// (stations k * spacing, its lateral lines), held flat beyond both ends (Terrain's edge rule), from
// station -behind to s_end + lookahead, cut into patches of patch_length (at least one sample);
// a patch starting at station a is written at the time the reference point reaches
// a - spacing - lookahead (at the start for the first ones): heights between two samples are
// interpolated, so the terrain up to `lookahead` ahead of the reference point is always known,
// even where a breakpoint file's samples lie metres apart.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ros/time.h>

#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

/// The fastest a bag drives [m/s]: 200 km/h, the range of `tvd simulate --speed-kmh` (the model
/// is not meant for more).
constexpr double kMaxTrackBagSpeed = dynamics::kMaxSpeedKmh / kKmhPerMs;
/// The longest run a bag holds [s]: it is replayed in real time, and `tvd simulate` stops at 1e7
/// steps of its default 1 ms; a longer one is a crawl or a stray far station, not a test drive.
constexpr double kMaxTrackBagDuration = 1e4;

/// How a track bag carries the speed: geometry_msgs/TwistStamped on /speed_stamped (the node
/// takes each at its header.stamp, so a replay drives through the same stations every time), or
/// std_msgs/Float64 on /speed (taken when it arrives).
enum class BagSpeedMessage { Stamped, Float64 };

struct TrackBagOptions {
  /// long_hill, separated_waves, oop_waves, half_round:H (tracks.h), or a terrain file
  /// (.csv/.yaml, terrain_io.h, e.g. from `tvd terrain --iso8608 C`): its first station becomes
  /// station 0, where the vehicle starts.
  std::string track = "long_hill";
  double speed = 30.0 / kKmhPerMs;  ///< [m/s], in (0, kMaxTrackBagSpeed]
  /// A speed varying in time instead of `speed` (dynamics/speed_profile.h): the reference point
  /// moves by its exact station, the speed messages carry v(t), and the run ends where the
  /// station reaches its end, or where the profile stops for good.
  std::optional<dynamics::SpeedProfile> speed_profile;
  double patch_length = 2.0;  ///< terrain per message [m]
  double lookahead = 10.0;    ///< terrain published ahead of the reference point [m]
  double behind = 5.0;        ///< terrain before station 0 and run-out after the track [m]
  double speed_rate = 50.0;   ///< speed messages [Hz]
  double clock_rate = 0.0;    ///< /clock messages in the bag [Hz]; 0: none
  /// Vehicle centre line on the track, y_t [m]; unset: the track's default (terrain/tracks.h),
  /// 0 for a terrain file.
  std::optional<double> lateral_offset;
  double start_time = 1000.0;  ///< bag time of the start [s] (> 0: time 0 means "no clock")
  std::string terrain_topic = "/terrain_profile";
  BagSpeedMessage speed_message = BagSpeedMessage::Stamped;
  std::string speed_topic;                   ///< empty: /speed_stamped or /speed, by speed_message
  std::string frame_id = "odom";             ///< of the terrain patches
  std::string speed_frame_id = "base_link";  ///< of a stamped speed (the node's, unprefixed)
};

struct TrackBagSummary {
  std::size_t patches = 0;
  std::size_t speed_messages = 0;
  std::size_t clock_messages = 0;
  double duration = 0.0;                           ///< [s]
  double end_station = 0.0;                        ///< s_end [m]
  double covered_from = 0.0, covered_until = 0.0;  ///< terrain written [m]
};

/// A patch and the time after the start [s] at which it is published.
struct TimedPatch {
  double time = 0.0;
  TerrainPatch patch;
};

/// The run a bag holds, before it is written: patches in time order, end station, duration.
/// Throws InputError naming the option for invalid options or an unknown track.
struct TrackRun {
  std::vector<TimedPatch> patches;
  double end_station = 0.0;                        ///< s_end [m]
  double duration = 0.0;                           ///< [s]
  double covered_from = 0.0, covered_until = 0.0;  ///< [m]
};
TrackRun trackRun(const TrackBagOptions& options);

/// trackRun() without its patches: the end station, duration and covered stations, checked the
/// same way (what `tvd_make_bag --peak-speed` needs to say whether a bag could be made).
TrackRun trackRunExtent(const TrackBagOptions& options);

/// Writes the bag. Throws InputError naming the option for invalid options or an unknown track,
/// rosbag::BagException when the file cannot be written.
TrackBagSummary writeTrackBag(const std::string& path, const TrackBagOptions& options);

/// What a track bag holds, in core terms, in bag order.
struct TrackBagContent {
  std::vector<std::pair<ros::Time, TerrainPatch>> patches;
  std::vector<std::pair<ros::Time, double>> speeds;  ///< [m/s], at the bag's time
  /// header.stamp of each speed, in the same order (zero for a std_msgs/Float64).
  std::vector<ros::Time> speed_stamps;
  std::vector<ros::Time> clocks;
};

/// The topic the speeds are written on: options.speed_topic, or the message's default.
std::string speedTopic(const TrackBagOptions& options);

/// Reads the terrain, speed and /clock messages of a bag. Throws rosbag::BagException when the
/// file cannot be read, InputError for a malformed terrain message. The speeds are read from
/// `speed_topic` as either message; empty: from /speed_stamped and /speed.
TrackBagContent readTrackBag(const std::string& path,
                             const std::string& terrain_topic = "/terrain_profile",
                             const std::string& speed_topic = "");

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
