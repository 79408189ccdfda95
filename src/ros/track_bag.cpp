#include "tracked_vehicle_dynamics/ros/track_bag.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <geometry_msgs/TwistStamped.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Float64.h>

#include "tracked_vehicle_dynamics/TerrainProfile.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/io/staged_files.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace {

void require(bool valid, const std::string& field, double value, const std::string& what) {
  if (!valid) {
    std::ostringstream message;
    message << "track bag: " << field << " = " << value << " must be " << what;
    throw InputError(message.str());
  }
}

constexpr double kMaxMessages = 1e7;

void checkOptions(const TrackBagOptions& o) {
  require(
      std::isfinite(o.speed) && o.speed > 0.0 && o.speed <= kMaxTrackBagSpeed, "speed", o.speed,
      "in (0, " + brief(kMaxTrackBagSpeed) + "] m/s (" + brief(dynamics::kMaxSpeedKmh) + " km/h)");
  if (o.speed_profile && o.speed_profile->maxSpeed() > kMaxTrackBagSpeed)
    throw InputError(o.speed_profile->name() + ": the speed profile reaches " +
                     beyond(o.speed_profile->maxSpeed() * kKmhPerMs, dynamics::kMaxSpeedKmh) +
                     " km/h; at most " + brief(dynamics::kMaxSpeedKmh) + " km/h");
  require(std::isfinite(o.patch_length) && o.patch_length > 0.0, "patch_length", o.patch_length,
          "> 0 m");
  require(std::isfinite(o.lookahead) && o.lookahead >= 0.0, "lookahead", o.lookahead, ">= 0 m");
  require(std::isfinite(o.behind) && o.behind >= 0.0, "behind", o.behind, ">= 0 m");
  require(std::isfinite(o.speed_rate) && o.speed_rate > 0.0, "speed_rate", o.speed_rate, "> 0 Hz");
  require(std::isfinite(o.clock_rate) && o.clock_rate >= 0.0, "clock_rate", o.clock_rate,
          ">= 0 Hz");
  // At least ros::TIME_MIN (1 ns): rosbag refuses a message stamped before it, and a smaller
  // start rounds to time 0.
  require(std::isfinite(o.start_time) && o.start_time >= 1e-9 && o.start_time < 4e9, "start_time",
          o.start_time, "in [1e-9, 4e9) s");
}

/// The run's terrain in the vehicle path frame (terrain_io.h: loadTrack), its first station moved
/// to station 0, where the vehicle starts (built-in tracks start there already).
terrain::Terrain runTerrain(const TrackBagOptions& options) {
  terrain::TrackOptions track_options;
  track_options.lateral_offset = options.lateral_offset;
  terrain::Terrain t = terrain::loadTrack(options.track, track_options);  // not const: moved out
  if (t.startStation() == 0.0)
    return t;
  return terrain::Terrain(t.stations().array() - t.startStation(), t.lateral(), t.heights(),
                          t.name());
}

/// Station step of the patches: the terrain's own on a uniform grid, else its smallest one, so
/// that no sample of the file falls between two of the bag's by more than that step.
double patchSpacing(const terrain::Terrain& t) {
  if (t.isUniform())
    return t.spacing();
  const Vector& x = t.stations();
  return (x.tail(x.size() - 1) - x.head(x.size() - 1)).minCoeff();
}

/// How the reference point moves from the start of the run: at the constant speed, or along the
/// speed profile (its station is the exact integral of v, speed_profile.h).
class Motion {
 public:
  explicit Motion(const TrackBagOptions& o) : o_(o) {}
  double speed(double t) const { return o_.speed_profile ? o_.speed_profile->speed(t) : o_.speed; }
  /// The first time [s] at which the station reaches s [m]; +inf when it never does (a profile
  /// that ends standing still short of s). s(t) is non-decreasing, so bisection finds it.
  double timeAt(double s) const {
    if (s <= 0.0)
      return 0.0;
    if (!o_.speed_profile)
      return s / o_.speed;
    const dynamics::SpeedProfile& p = *o_.speed_profile;
    const double end = p.endTime(), s_end = p.station(end);
    if (s_end < s) {
      const double v = p.speeds().back();  // held after the profile's end
      return v > 0.0 ? end + (s - s_end) / v : std::numeric_limits<double>::infinity();
    }
    double lo = 0.0, hi = end;
    while (hi - lo > 1e-12 * (1.0 + hi)) {
      const double mid = 0.5 * (lo + hi);
      (p.station(mid) >= s ? hi : lo) = mid;
    }
    return hi;
  }

 private:
  const TrackBagOptions& o_;
};

/// The run's end, duration and covered stations (no patches), checked: what trackRun() and
/// trackRunExtent() share. `first` and `last` are the indices of the first and last stations
/// k * spacing the patches cover.
struct Extent {
  TrackRun run;
  double spacing = 0.0;  ///< [m]
  long first = 0, last = 0;
};

Extent extentOf(const TrackBagOptions& options, const terrain::Terrain& track,
                const Motion& motion) {
  Extent extent;
  TrackRun& run = extent.run;
  const double spacing = patchSpacing(track);
  run.end_station = track.endStation() + options.behind;
  run.duration = motion.timeAt(run.end_station);
  if (!std::isfinite(run.duration)) {
    // A profile that stops short ends with it; a constant speed so small that s / v overflows
    // (a denormal) never arrives.
    if (!options.speed_profile)
      throw InputError("track bag: at " + brief(options.speed) + " m/s the run to station " +
                       brief(run.end_station) + " m never ends: use a higher speed");
    run.duration = options.speed_profile->endTime();
  }
  // A bag is replayed in real time: refuse a run that would write millions of timed messages (a
  // terrain file with a stray far station, a crawl speed) instead of filling the disk.
  const double messages = run.duration * (options.speed_rate + options.clock_rate);
  if (run.duration > kMaxTrackBagDuration || messages > kMaxMessages ||
      options.start_time + run.duration >= 4e9) {
    std::ostringstream message;
    message << "track bag: the run to station " << brief(run.end_station) << " m lasts "
            << brief(run.duration) << " s";
    if (run.duration > kMaxTrackBagDuration)
      message << "; at most " << brief(kMaxTrackBagDuration) << " s (2.8 h, replayed in real time)";
    else
      message << ", " << brief(messages) << " speed and clock messages; at most "
              << brief(kMaxMessages);
    message << ": use a shorter terrain or a higher speed";
    throw InputError(message.str());
  }
  // Terrain on the track's own grid, stations k * spacing.
  extent.spacing = spacing;
  extent.first = static_cast<long>(std::floor(-options.behind / spacing + 1e-9));
  extent.last =
      static_cast<long>(std::ceil((run.end_station + options.lookahead) / spacing - 1e-9));
  run.covered_from = static_cast<double>(extent.first) * spacing;
  run.covered_until = static_cast<double>(extent.last) * spacing;
  return extent;
}

}  // namespace

TrackRun trackRunExtent(const TrackBagOptions& options) {
  checkOptions(options);
  return extentOf(options, runTerrain(options), Motion(options)).run;
}

TrackRun trackRun(const TrackBagOptions& options) {
  checkOptions(options);
  const terrain::Terrain track = runTerrain(options);
  const Motion motion(options);
  Extent extent = extentOf(options, track, motion);
  TrackRun& run = extent.run;
  const double spacing = extent.spacing;
  const long first = extent.first, last = extent.last;
  // Patch by patch.
  const auto per_patch = std::max(1L, std::lround(options.patch_length / spacing));
  for (long k0 = first; k0 <= last; k0 += per_patch) {
    const long n = std::min(per_patch, last - k0 + 1);
    TimedPatch timed;
    TerrainPatch& patch = timed.patch;
    patch.spacing = spacing;
    patch.lateral = track.lateral();
    patch.start_station = static_cast<double>(k0) * spacing;
    patch.heights.resize(track.lateral().size(), n);
    for (Eigen::Index j = 0; j < track.lateral().size(); ++j) {
      for (long i = 0; i < n; ++i) {
        patch.heights(j, i) =
            track.height(static_cast<double>(k0 + i) * spacing, track.lateral()(j));
      }
    }
    // Due one spacing early: the heights between the previous sample and this patch's first
    // need it (a breakpoint file's 15 m spacing would leave the front contacts without terrain).
    timed.time =
        std::min(motion.timeAt(patch.start_station - spacing - options.lookahead), run.duration);
    run.patches.push_back(std::move(timed));
  }
  return std::move(extent.run);
}

namespace {

// The messages of `run`, in a bag at `path`.
void writeTrackBagFile(const std::string& path, const TrackRun& run, const TrackBagOptions& options,
                       TrackBagSummary* out) {
  TrackBagSummary& summary = *out;
  const ros::Time start(options.start_time);
  const auto at = [&](double t) { return start + ros::Duration(t); };
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  TerrainProfile msg;
  msg.header.frame_id = options.frame_id;
  for (const TimedPatch& timed : run.patches) {
    msg.header.seq = static_cast<std::uint32_t>(summary.patches);
    msg.header.stamp = at(timed.time);
    toMsg(timed.patch, &msg);
    bag.write(options.terrain_topic, at(timed.time), msg);
    ++summary.patches;
  }
  const Motion motion(options);
  const std::string speed_topic = speedTopic(options);
  std_msgs::Float64 speed;
  geometry_msgs::TwistStamped stamped;
  stamped.header.frame_id = options.speed_frame_id;
  const auto speed_count = static_cast<long>(std::floor(run.duration * options.speed_rate)) + 1;
  for (long k = 0; k < speed_count; ++k) {
    const double t = static_cast<double>(k) / options.speed_rate;
    if (options.speed_message == BagSpeedMessage::Stamped) {
      // Stamped at the time it is written: the node drives on it from there (in the run, the
      // speed between two messages is the earlier one's, as the node holds it).
      stamped.header.seq = static_cast<std::uint32_t>(k);
      stamped.header.stamp = at(t);
      stamped.twist.linear.x = motion.speed(t);
      bag.write(speed_topic, at(t), stamped);
    } else {
      speed.data = motion.speed(t);
      bag.write(speed_topic, at(t), speed);
    }
    ++summary.speed_messages;
  }
  if (options.clock_rate > 0.0) {
    rosgraph_msgs::Clock clock;
    const auto clock_count = static_cast<long>(std::floor(run.duration * options.clock_rate)) + 1;
    for (long k = 0; k < clock_count; ++k) {
      clock.clock = at(static_cast<double>(k) / options.clock_rate);
      bag.write("/clock", clock.clock, clock);
      ++summary.clock_messages;
    }
  }
  bag.close();
}

}  // namespace

TrackBagSummary writeTrackBag(const std::string& path, const TrackBagOptions& options) {
  const TrackRun run = trackRun(options);
  TrackBagSummary summary;
  summary.end_station = run.end_station;
  summary.duration = run.duration;
  summary.covered_from = run.covered_from;
  summary.covered_until = run.covered_until;
  // Written under a temporary name next to `path` and renamed onto it once closed, as tvd's
  // outputs are: a run that fails half way (a full disk, rosbag refusing a message) leaves no
  // partial bag under the final name, nor an older bag there damaged.
  // A name of its own (io::createTemporaryBeside): two writers of one bag never share it.
  const std::string temporary = io::createTemporaryBeside(path);
  try {
    writeTrackBagFile(temporary, run, options, &summary);
  } catch (const rosbag::BagException& e) {
    io::removeStagedFile(temporary);
    throw InputError("cannot write the bag " + path + ": " + e.what());
  } catch (...) {
    io::removeStagedFile(temporary);
    throw;
  }
  if (io::renameStagedFile(temporary, path) != 0) {
    const int error = errno;
    io::removeStagedFile(temporary);
    throw InputError("cannot move the written bag onto " + path + ": " + std::strerror(error));
  }
  return summary;
}

std::string speedTopic(const TrackBagOptions& options) {
  if (!options.speed_topic.empty())
    return options.speed_topic;
  return options.speed_message == BagSpeedMessage::Stamped ? "/speed_stamped" : "/speed";
}

TrackBagContent readTrackBag(const std::string& path, const std::string& terrain_topic,
                             const std::string& speed_topic) {
  rosbag::Bag bag(path, rosbag::bagmode::Read);
  std::vector<std::string> speed_topics = {speed_topic};
  if (speed_topic.empty())
    speed_topics = {"/speed_stamped", "/speed"};
  std::vector<std::string> topics = speed_topics;
  topics.push_back(terrain_topic);
  topics.push_back("/clock");
  rosbag::View view(bag, rosbag::TopicQuery(topics));
  TrackBagContent content;
  for (const rosbag::MessageInstance& m : view) {
    if (m.getTopic() == terrain_topic) {
      if (const auto msg = m.instantiate<TerrainProfile>()) {
        content.patches.emplace_back(m.getTime(), fromMsg(*msg));
      }
    } else if (std::find(speed_topics.begin(), speed_topics.end(), m.getTopic()) !=
               speed_topics.end()) {
      if (const auto msg = m.instantiate<geometry_msgs::TwistStamped>()) {
        content.speeds.emplace_back(m.getTime(), msg->twist.linear.x);
        content.speed_stamps.push_back(msg->header.stamp);
      } else if (const auto msg = m.instantiate<std_msgs::Float64>()) {
        content.speeds.emplace_back(m.getTime(), msg->data);
        content.speed_stamps.emplace_back();
      }
    } else if (const auto msg = m.instantiate<rosgraph_msgs::Clock>()) {
      content.clocks.push_back(msg->clock);
    }
  }
  return content;
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
