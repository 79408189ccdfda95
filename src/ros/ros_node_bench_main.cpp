// ros_node_bench: performance figures of the node (bench/ros_node_bench.sh runs both modes).
//
//   ros_node_bench offline --vehicle FILE [--variant V] [--cache-dir DIR] [--track T]
//                          [--speed-kmh V] [--rate HZ] [--method modal|exact]
//     OnlineVehicle::step() on a paper track without ROS: step time mean / p50 / p99 / max, and
//     the share of the terrain sampling (the same steps on a bare Simulator).
//
//   ros_node_bench node --pid PID [--track T] [--speed-kmh V] [--duration S]
//     A load driver for a running node on real time: publishes the track's terrain patches at
//     the vehicle's pace and the speed at 50 Hz, alternating between two values every 0.25 s.
//     Measures the latency from a speed message to the first road_wheels message stepped with
//     it (published right after the tf of the same sample, so it bounds message -> tf), the
//     node's CPU use from /proc/PID/stat, and reads the node's step-time diagnostics.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <unistd.h>

#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/TerrainProfile.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/duration_statistics.h"
#include "tracked_vehicle_dynamics/ros/node_parameters.h"
#include "tracked_vehicle_dynamics/ros/online_vehicle.h"
#include "tracked_vehicle_dynamics/ros/track_bag.h"

namespace tvd = tracked_vehicle_dynamics;
namespace rl = tracked_vehicle_dynamics::ros_layer;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

void printStats(const char* what, const rl::DurationStatistics& s) {
  std::printf("%-28s mean %7.1f us  p50 %7.1f us  p99 %7.1f us  max %7.1f us  (%lu steps)\n", what,
              s.mean() * 1e6, s.percentile(0.5) * 1e6, s.percentile(0.99) * 1e6, s.max() * 1e6,
              static_cast<unsigned long>(s.count()));
}

int offline(const std::string& vehicle_file, const std::string& variant, const std::string& cache,
            const rl::TrackBagOptions& track, double rate, const std::string& method) {
  tvd::reduction::VehicleReductionReport report;
  const tvd::vehicle::VehicleDescription description = tvd::vehicle::loadVehicleDescription(vehicle_file);
  const auto model = tvd::reduction::loadOrReduceVehicle(
      description, tvd::vehicle::parseVariant(variant), cache, {}, &report);
  rl::OnlineVehicleOptions options;
  options.rate = rate;
  options.method = rl::parseMethod(method, "--method");
  rl::OnlineVehicle vehicle(model, rl::vehicleGeometry(description), options);
  std::printf("model: %s %s, %ld DOFs, %ld road inputs, %ld outputs, method %s, %.0f Hz\n",
              vehicle_file.c_str(), variant.c_str(), static_cast<long>(model.size()),
              static_cast<long>(model.system.inputCount()),
              static_cast<long>(model.system.outputCount()), method.c_str(), rate);
  const rl::TrackRun run = rl::trackRun(track);
  vehicle.setSpeed(track.speed);
  rl::DurationStatistics step_stats;
  std::size_t next_patch = 0;
  const long steps = static_cast<long>(run.duration * rate);
  for (long k = 0; k < steps; ++k) {
    const double t = static_cast<double>(k) / rate;
    while (next_patch < run.patches.size() && run.patches[next_patch].time <= t) {
      vehicle.addTerrain(run.patches[next_patch++].patch);
    }
    const auto a = Clock::now();
    vehicle.step();
    step_stats.add(seconds(a, Clock::now()));
  }
  printStats("OnlineVehicle::step", step_stats);

  // The simulator alone, same sizes, constant input: what the terrain sampling adds.
  const tvd::dynamics::SimulatorOptions sim_options = rl::simulatorOptions(model, options);
  tvd::dynamics::Simulator sim(model.system, sim_options);
  tvd::Vector w = tvd::Vector::Constant(sim.inputCount(), 1e-3);
  rl::DurationStatistics sim_stats;
  for (long k = 0; k < steps; ++k) {
    w(0) = 1e-3 * static_cast<double>(k % 7);
    const auto a = Clock::now();
    sim.step(w);
    sim_stats.add(seconds(a, Clock::now()));
  }
  printStats("Simulator::step alone", sim_stats);
  std::printf("terrain sampling + bookkeeping: %.1f us per step (mean)\n",
              (step_stats.mean() - sim_stats.mean()) * 1e6);
  std::printf("real-time factor of the step alone: %.1fx at %.0f Hz\n",
              1.0 / rate / step_stats.mean(), rate);
  return 0;
}

/// utime + stime of a process [s].
double cpuSeconds(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = content.rfind(')');
  if (close == std::string::npos)
    return -1.0;
  std::istringstream rest(content.substr(close + 2));
  std::string field;
  double utime = 0.0, stime = 0.0;
  for (int i = 3; i <= 15 && rest >> field; ++i) {
    if (i == 14)
      utime = std::stod(field);
    if (i == 15)
      stime = std::stod(field);
  }
  return (utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

struct Driver {
  double v_old = 0.0, v_new = 0.0;
  ros::WallTime sent;
  bool waiting = false;
  std::vector<double> latencies;
  std::size_t wheel_messages = 0;
  double step_p99_us = -1.0, tick_p99_us = -1.0, steps = -1.0, late = -1.0, resyncs = -1.0;

  void onWheels(const tvd::RoadWheels::ConstPtr& msg) {
    ++wheel_messages;
    if (waiting && msg->speed == v_new) {
      latencies.push_back((ros::WallTime::now() - sent).toSec());
      waiting = false;
    }
  }
  void onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
    for (const auto& s : msg->status) {
      if (s.name.size() < 6 || s.name.compare(s.name.size() - 6, 6, ": loop") != 0)
        continue;
      for (const auto& kv : s.values) {
        const double value = std::atof(kv.value.c_str());
        if (kv.key == "step time p99 since start [us]")
          step_p99_us = value;
        if (kv.key == "tick time p99 since start [us]")
          tick_p99_us = value;
        if (kv.key == "steps")
          steps = value;
        if (kv.key == "late ticks (total)")
          late = value;
        if (kv.key == "resynchronisations (total)")
          resyncs = value;
      }
    }
  }
};

int node(int argc, char** argv, int pid, const rl::TrackBagOptions& track, double duration) {
  ros::init(argc, argv, "ros_node_bench", ros::init_options::AnonymousName);
  ros::NodeHandle nh;
  Driver d;
  ros::Subscriber wheels =
      nh.subscribe("road_wheels", 1000, &Driver::onWheels, &d, ros::TransportHints().tcpNoDelay());
  ros::Subscriber diag = nh.subscribe("/diagnostics", 10, &Driver::onDiagnostics, &d);
  ros::Publisher terrain = nh.advertise<tvd::TerrainProfile>("terrain_profile", 100);
  ros::Publisher speed = nh.advertise<std_msgs::Float64>("speed", 10);
  const ros::WallTime wait_end = ros::WallTime::now() + ros::WallDuration(60.0);
  while (ros::ok() &&
         (terrain.getNumSubscribers() == 0 || speed.getNumSubscribers() == 0 ||
          wheels.getNumPublishers() == 0) &&
         ros::WallTime::now() < wait_end) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  ros::WallDuration(0.5).sleep();

  rl::TrackBagOptions opts = track;
  const rl::TrackRun run = rl::trackRun(opts);
  const double run_time = std::min(duration, run.duration);
  tvd::TerrainProfile msg;
  msg.header.frame_id = "odom";
  std_msgs::Float64 v;
  // Speed alternates v / v + 1 mm/s every 0.25 s; the latency is measured on each change.
  const double v_low = track.speed, v_high = track.speed + 1e-3;
  d.v_new = v_low;
  const ros::WallTime start = ros::WallTime::now();
  const double cpu_start = cpuSeconds(pid);
  const std::size_t wheels_start = d.wheel_messages;
  std::size_t next_patch = 0;
  double next_speed = 0.0, next_change = 0.25;
  while (ros::ok()) {
    const double t = (ros::WallTime::now() - start).toSec();
    if (t >= run_time)
      break;
    while (next_patch < run.patches.size() && run.patches[next_patch].time <= t) {
      msg.header.stamp = ros::Time::now();
      rl::toMsg(run.patches[next_patch++].patch, &msg);
      terrain.publish(msg);
    }
    if (t >= next_change && !d.waiting) {
      d.v_old = d.v_new;
      d.v_new = d.v_old == v_low ? v_high : v_low;
      v.data = d.v_new;
      d.sent = ros::WallTime::now();
      d.waiting = true;
      speed.publish(v);
      next_change += 0.25;
      next_speed = t + 0.02;
    } else if (t >= next_speed) {
      v.data = d.v_new;
      speed.publish(v);
      next_speed += 0.02;
    }
    ros::spinOnce();
    ros::WallDuration(0.0002).sleep();
  }
  const double wall = (ros::WallTime::now() - start).toSec();
  const double cpu = cpuSeconds(pid) - cpu_start;
  const std::size_t received = d.wheel_messages - wheels_start;
  // One more diagnostics report, covering the whole run.
  const ros::WallTime diag_end = ros::WallTime::now() + ros::WallDuration(2.5);
  while (ros::ok() && ros::WallTime::now() < diag_end) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  std::sort(d.latencies.begin(), d.latencies.end());
  auto pct = [&](double f) {
    if (d.latencies.empty())
      return -1.0;
    return d.latencies[std::min(d.latencies.size() - 1,
                                static_cast<std::size_t>(f * d.latencies.size()))];
  };
  std::printf("run: %s at %.1f km/h, %.2f s wall, %zu road_wheels messages (%.0f Hz)\n",
              track.track.c_str(), track.speed * 3.6, wall, received, received / wall);
  std::printf("node CPU: %.3f s in %.2f s = %.1f %% of one core\n", cpu, wall, 100.0 * cpu / wall);
  std::printf(
      "latency speed message -> next published sample (tf, then road_wheels): "
      "median %.2f ms, p95 %.2f ms, max %.2f ms (%zu changes)\n",
      pct(0.5) * 1e3, pct(0.95) * 1e3, d.latencies.empty() ? -1.0 : d.latencies.back() * 1e3,
      d.latencies.size());
  std::printf(
      "node diagnostics: step time p99 %.0f us, tick time p99 %.0f us, %.0f steps, "
      "%.0f late ticks, %.0f resynchronisations\n",
      d.step_p99_us, d.tick_p99_us, d.steps, d.late, d.resyncs);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ros_node_bench: performance of vehicle_dynamics_node"};
  app.require_subcommand(1);
  rl::TrackBagOptions track;
  double speed_kmh = 30.0;
  std::string vehicle, variant = "tracked", cache = "/tmp/tvd_bench_cache", method = "modal";
  double rate = 1000.0, duration = 1e9;
  int pid = 0;
  auto* off = app.add_subcommand("offline", "OnlineVehicle::step timing, no ROS");
  off->add_option("--vehicle", vehicle, "vehicle description")->required();
  off->add_option("--variant", variant)->capture_default_str();
  off->add_option("--cache-dir", cache)->capture_default_str();
  off->add_option("--rate", rate, "[Hz]")->capture_default_str();
  off->add_option("--method", method, "modal | exact")->capture_default_str();
  auto* nd = app.add_subcommand("node", "load driver for a running node (real time)");
  nd->add_option("--pid", pid, "the node's process id")->required();
  nd->add_option("--duration", duration, "[s] at most the track's run")->capture_default_str();
  for (CLI::App* sub : {off, nd}) {
    sub->add_option("--track", track.track)->capture_default_str();
    sub->add_option("--speed-kmh", speed_kmh)->capture_default_str();
  }
  // ROS remapping arguments are not ours.
  std::vector<std::string> args;
  for (int i = argc - 1; i > 0; --i) {
    if (std::string(argv[i]).find(":=") == std::string::npos)
      args.emplace_back(argv[i]);
  }
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  track.speed = speed_kmh / 3.6;
  try {
    if (off->parsed())
      return offline(vehicle, variant, cache, track, rate, method);
    return node(argc, argv, pid, track, duration);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ros_node_bench: error: %s\n", e.what());
    return 1;
  }
}
