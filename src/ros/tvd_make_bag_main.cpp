// tvd_make_bag: writes a rosbag of one of the paper's test tracks or a terrain file driven at a
// constant speed or along a speed profile (terrain patches ahead of the vehicle + speed
// [+ /clock]); see ros/track_bag.h.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include <ros/time.h>

#include <ros/names.h>

#include "command_line_errors.h"
#include "commands.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile_io.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/staged_files.h"
#include "tracked_vehicle_dynamics/ros/track_bag.h"

namespace {

int run(int argc, char** argv) {
  namespace rl = tracked_vehicle_dynamics::ros_layer;
  // A bag stopped half way (Ctrl-C, or play_track_bag.sh stopped by roslaunch) leaves no staged
  // "BAG.~XXXXXX" of tens of MB beside it (staged_files.h).
  tracked_vehicle_dynamics::io::removeStagedFilesOnSignals();
  rl::TrackBagOptions options;
  std::string out;
  double speed_kmh = options.speed * tracked_vehicle_dynamics::kKmhPerMs;
  double lateral_offset = 0.0;
  CLI::App app{"tvd_make_bag: rosbag of a paper test track or a terrain file at a constant speed"};
  app.add_option("--track", options.track,
                 "long_hill, separated_waves, oop_waves, half_round:H (the NRMM obstacle, H its "
                 "height in m) or a "
                 "terrain file (.csv/.yaml, e.g. from tvd terrain)")
      ->capture_default_str();
  CLI::Option* speed_option =
      app.add_option("--speed-kmh", speed_kmh, "vehicle speed [km/h]")->capture_default_str();
  std::string profile_file;
  app.add_option(
         "--speed-profile", profile_file,
         "speed varying in time instead: CSV time_s,speed_kmh (or speed_m_s), as tvd simulate")
      ->check(CLI::ExistingFile)
      ->excludes(speed_option);
  CLI::Option* out_option =
      app.add_option("--out", out, "bag file to write (required unless --peak-speed)")
          ->check(tracked_vehicle_dynamics::tools::outputFile({".bag"}));
  bool peak_only = false;
  app.add_flag("--peak-speed", peak_only,
               "print the run's highest speed [m/s] (the constant speed, or the profile's largest "
               "sample) and exit without writing: play_track_bag.sh compares it with the node's "
               "~max_speed")
      ->excludes(out_option);
  app.add_option("--patch-length", options.patch_length, "terrain per message [m]")
      ->capture_default_str();
  app.add_option("--lookahead", options.lookahead, "terrain published ahead [m]")
      ->capture_default_str();
  app.add_option("--behind", options.behind, "terrain before station 0 and run-out [m]")
      ->capture_default_str();
  app.add_option("--speed-rate", options.speed_rate, "speed messages [Hz]")->capture_default_str();
  app.add_option("--clock-rate", options.clock_rate,
                 "/clock messages in the bag [Hz] (0: none; rosbag play --clock publishes it)")
      ->capture_default_str();
  auto* offset = app.add_option("--lateral-offset", lateral_offset,
                                "vehicle centre line on the track y_t [m] (default: the track's)");
  app.add_option("--start-time", options.start_time, "bag time of the start [s]")
      ->capture_default_str();
  std::string speed_message = "stamped";
  app.add_option("--speed-message", speed_message,
                 "stamped: geometry_msgs/TwistStamped on /speed_stamped, taken by the node at "
                 "its stamp (a replay repeats its stations); float64: std_msgs/Float64 on "
                 "/speed, taken when it arrives")
      ->check(CLI::IsMember({"stamped", "float64"}))
      ->capture_default_str();
  std::string ns;
  app.add_option("--namespace", ns,
                 "write the topics in this namespace, e.g. /veh1: /veh1/terrain_profile and "
                 "/veh1/speed_stamped, for a node in it; bags of several vehicles then play "
                 "together from one rosbag play --clock (default: /terrain_profile, "
                 "/speed_stamped)");
  tracked_vehicle_dynamics::tools::checkNumberTexts(app.get_options());
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; any other command-line error is bad input, reported on one line with
    // status 2 as tvd does.
    if (e.get_exit_code() == 0)
      return app.exit(e);
    std::cerr << "tvd_make_bag: error: "
              << tracked_vehicle_dynamics::tools::describeParseError(
                     app, e, std::vector<std::string>(argv + 1, argv + argc), "tvd_make_bag")
              << "\n";
    return 2;
  }
  // Checked in the unit given (writeTrackBag would say "m/s" of a km/h argument), and the range
  // of tvd simulate: the model is not meant for more.
  if (profile_file.empty() &&
      !(std::isfinite(speed_kmh) && speed_kmh > 0.0 &&
        speed_kmh <= rl::kMaxTrackBagSpeed * tracked_vehicle_dynamics::kKmhPerMs)) {
    std::cerr << "tvd_make_bag: error: --speed-kmh must be in (0, "
              << tracked_vehicle_dynamics::brief(rl::kMaxTrackBagSpeed *
                                                 tracked_vehicle_dynamics::kKmhPerMs)
              << "], got "
              << tracked_vehicle_dynamics::beyond(
                     speed_kmh, rl::kMaxTrackBagSpeed * tracked_vehicle_dynamics::kKmhPerMs)
              << "\n";
    return 2;
  }
  if (out.empty() && !peak_only) {
    std::cerr << "tvd_make_bag: error: --out is required (the bag file to write)\n";
    return 2;
  }
  if (!ns.empty()) {
    // A global graph name: the bag's topics are absolute (a relative one would resolve in the
    // player's namespace, not the node's).
    std::string why;
    while (ns.size() > 1 && ns.back() == '/')
      ns.pop_back();
    if (ns.front() != '/' || ns == "/" || !ros::names::validate(ns, why)) {
      std::cerr << "tvd_make_bag: error: --namespace must be a global namespace such as /veh1, "
                   "got '"
                << ns << "'" << (why.empty() ? "" : ": " + why) << "\n";
      return 2;
    }
  }
  options.speed_message =
      speed_message == "float64" ? rl::BagSpeedMessage::Float64 : rl::BagSpeedMessage::Stamped;
  if (!ns.empty()) {
    options.terrain_topic = ns + options.terrain_topic;
    options.speed_topic = ns + rl::speedTopic(options);
  }
  options.speed = speed_kmh / tracked_vehicle_dynamics::kKmhPerMs;
  if (offset->count() > 0)
    options.lateral_offset = lateral_offset;
  try {
    // The track may be a terrain file: a bag written over it, or over the profile, destroys it.
    tracked_vehicle_dynamics::tools::refuseOutputOverInput(
        "", "--out", out, {{"--track", options.track}, {"--speed-profile", profile_file}});
    if (!profile_file.empty()) {
      options.speed_profile = tracked_vehicle_dynamics::dynamics::loadSpeedProfile(profile_file);
    }
    if (peak_only) {
      // The run is checked as for writing (speeds up to 200 km/h, the track, the duration), so a
      // bag that could not be made is said so now. Full precision: the caller compares it with a
      // parameter, and a profile read in km/h converts to m/s inexactly.
      rl::trackRunExtent(options);
      std::printf("%.17g\n",
                  options.speed_profile ? options.speed_profile->maxSpeed() : options.speed);
      return 0;
    }
    ros::Time::init();
    const rl::TrackBagSummary s = rl::writeTrackBag(out, options);
    const std::string how = profile_file.empty()
                                ? "at " + tracked_vehicle_dynamics::brief(speed_kmh) + " km/h"
                                : "with the speed profile " + profile_file;
    std::printf(
        "%s: %s %s, %.2f s, %zu terrain patches (%.2f .. %.2f m), %zu speed, %zu clock messages\n",
        out.c_str(), options.track.c_str(), how.c_str(), s.duration, s.patches, s.covered_from,
        s.covered_until, s.speed_messages, s.clock_messages);
  } catch (const tracked_vehicle_dynamics::InputError& e) {
    std::cerr << "tvd_make_bag: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "tvd_make_bag: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tracked_vehicle_dynamics::tools::runReportingErrors("tvd_make_bag", run, argc, argv);
}
