// ros_node_bench: performance figures of the node (bench/ros_node_bench.sh runs both modes).
//
//   ros_node_bench offline --vehicle FILE [--variant V] [--cache-dir DIR] [--track T]
//                          [--speed-kmh V] [--rate HZ] [--method modal|exact]
//     OnlineVehicle::step() on a paper track without ROS: step time mean / p50 / p99 / max, and
//     the share of the terrain sampling (the same steps on a bare Simulator).
//
//   ros_node_bench bare [--rate HZ] [--wheels N] [--own-thread]
//     The floor: a stand-in for the node with its topics, ~reset and tick (a periodic timerfd in
//     roscpp's network thread: take the messages, publish a RoadWheels sample) that computes
//     nothing. The same driver against it measures what roscpp and the kernel alone take at this
//     rate. --own-thread: the tick in a thread of its own sleeping to each tick instead.
//
//   ros_node_bench node --pid PID [--track T] [--speed-kmh V] [--duration S] [--laps N]
//     A load driver for a running node on real time: publishes the track's terrain patches at
//     the vehicle's pace and the speed at 50 Hz, alternating between two values every 0.25 s,
//     for N laps of the track (the node's ~reset service between them). Its callbacks run on a
//     spinner thread and it sleeps between messages, so it leaves the CPU to the node.
//     Measures the latency from a speed message to the first road_wheels message stepped with
//     it (published right after the tf of the same sample, so it bounds message -> tf), the
//     node's CPU use from /proc/PID/stat (and per thread from /proc/PID/task), and reads the
//     node's step-time diagnostics.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <dirent.h>
#include <pthread.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
#include <time.h>
#include <unistd.h>

#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/TerrainProfile.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/reduction/contact_groups.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/network_thread_timer.h"
#include "tracked_vehicle_dynamics/ros/node_parameters.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/ros/track_bag.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

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
  const tvd::vehicle::VehicleDescription description =
      tvd::vehicle::loadVehicleDescription(vehicle_file);
  const auto model = tvd::reduction::loadOrReduceVehicle(
      description, tvd::vehicle::parseVariant(variant), cache, {}, &report);
  // The node's pads (whole-pad records of the ground-contact check) and frames, as the node
  // forms them.
  const tvd::vehicle::VehicleModel layout =
      tvd::vehicle::buildVehicleModel(description, tvd::vehicle::parseVariant(variant));
  const std::vector<int> pads = tvd::reduction::roadInputGroups(layout, model);
  const rl::VehicleGeometry geometry = rl::vehicleGeometry(description, layout);
  rl::OnlineVehicleOptions options;
  options.rate = rate;
  options.method = rl::parseMethod(method, "--method");
  std::printf("model: %s %s, %ld DOFs, %ld road inputs, %ld outputs, method %s, %.0f Hz\n",
              vehicle_file.c_str(), variant.c_str(), static_cast<long>(model.size()),
              static_cast<long>(model.system.inputCount()),
              static_cast<long>(model.system.outputCount()), method.c_str(), rate);
  const rl::TrackRun run = rl::trackRun(track);
  const long steps = static_cast<long>(run.duration * rate);
  // One run of the track on a fresh vehicle, the patches added at their times; step(vehicle)
  // does (and times) each step.
  const auto run_track = [&](const std::function<void(rl::OnlineVehicle&)>& step) {
    rl::OnlineVehicle vehicle(model, geometry, options, pads);
    vehicle.setSpeed(track.speed);
    std::size_t next_patch = 0;
    for (long k = 0; k < steps; ++k) {
      const double t = static_cast<double>(k) / rate;
      while (next_patch < run.patches.size() && run.patches[next_patch].time <= t)
        vehicle.addTerrain(run.patches[next_patch++].patch);
      step(vehicle);
    }
  };
  rl::DurationStatistics step_stats;
  run_track([&](rl::OnlineVehicle& vehicle) {
    const auto a = Clock::now();
    vehicle.step();
    step_stats.add(seconds(a, Clock::now()));
  });
  printStats("OnlineVehicle::step", step_stats);

  // The same run again, timing a second sampler on the vehicle's terrain buffer at the station
  // of the coming step: the terrain sampling alone (its lookups are remembered like the
  // vehicle's). A separate run, so that neither timing finds the other's data in the cache.
  rl::DurationStatistics sample_stats;
  std::optional<rl::RoadInputSampler> probe;
  tvd::Vector probe_input;
  run_track([&](rl::OnlineVehicle& vehicle) {
    if (!probe) {
      probe.emplace(vehicle.sampler());
      probe_input.resize(2 * probe->size());
    }
    const auto a = Clock::now();
    probe->sample(vehicle.terrain(), vehicle.station() + track.speed / rate, track.speed,
                  options.lateral_offset, &probe_input);
    sample_stats.add(seconds(a, Clock::now()));
    vehicle.step();
  });
  printStats("terrain sampling alone", sample_stats);

  // The ground-contact check the node runs every round(rate / ~ground_contact_rate) steps
  // (OnlineVehicle::checkGroundContact: the contacts' coordinates, then the sole and pad forces).
  rl::DurationStatistics contact_stats;
  run_track([&](rl::OnlineVehicle& vehicle) {
    vehicle.step();
    const auto a = Clock::now();
    vehicle.checkGroundContact();
    contact_stats.add(seconds(a, Clock::now()));
  });
  printStats("OnlineVehicle::checkGroundContact", contact_stats);
  std::printf("  share of one core at the default ~ground_contact_rate 50 Hz: %.2f %%\n",
              100.0 * 50.0 * contact_stats.mean());

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
  printStats("Simulator::step, 1 input changing", sim_stats);
  std::printf("real-time factor of the step alone: %.1fx at %.0f Hz\n",
              1.0 / rate / step_stats.mean(), rate);
  return 0;
}

/// User and system CPU time [s] from a /proc/.../stat file (fields 14 and 15); false if it
/// cannot be read (the process or thread ended).
bool readCpuTimes(const std::string& stat_path, double* user, double* system) {
  std::ifstream in(stat_path);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = content.rfind(')');  // the command name may contain spaces
  if (close == std::string::npos)
    return false;
  std::istringstream rest(content.substr(close + 2));
  std::string field;
  const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
  for (int i = 3; i <= 15 && rest >> field; ++i) {
    if (i == 14)
      *user = std::stod(field) / tick;
    if (i == 15)
      *system = std::stod(field) / tick;
  }
  return true;
}

/// utime + stime of a process [s], -1 if it cannot be read.
double cpuSeconds(int pid) {
  double user = 0.0, system = 0.0;
  if (!readCpuTimes("/proc/" + std::to_string(pid) + "/stat", &user, &system))
    return -1.0;
  return user + system;
}

/// One thread of a process: name, user and system CPU [s], context switches.
struct ThreadSample {
  std::string name;
  double user = 0.0, system = 0.0;
  long voluntary = 0, involuntary = 0;
};

/// Every thread of a process, by thread id (threads that ended are absent).
std::map<int, ThreadSample> threadSamples(int pid) {
  std::map<int, ThreadSample> samples;
  const std::string task_dir = "/proc/" + std::to_string(pid) + "/task";
  DIR* dir = opendir(task_dir.c_str());
  if (dir == nullptr)
    return samples;
  while (const dirent* entry = readdir(dir)) {
    if (entry->d_name[0] == '.')
      continue;
    const std::string base = task_dir + "/" + entry->d_name;
    ThreadSample s;
    std::ifstream comm(base + "/comm");
    std::getline(comm, s.name);
    if (!readCpuTimes(base + "/stat", &s.user, &s.system))
      continue;
    std::ifstream status(base + "/status");
    std::string line;
    while (std::getline(status, line)) {
      if (line.rfind("voluntary_ctxt_switches:", 0) == 0)
        s.voluntary = std::atol(line.c_str() + 24);
      if (line.rfind("nonvoluntary_ctxt_switches:", 0) == 0)
        s.involuntary = std::atol(line.c_str() + 27);
    }
    samples[std::atoi(entry->d_name)] = s;
  }
  closedir(dir);
  return samples;
}

/// Where the node's CPU went: each thread's share of one core and its wake-ups per second.
void printThreads(const std::map<int, ThreadSample>& before,
                  const std::map<int, ThreadSample>& after, double wall) {
  std::printf("node threads (CPU %% of one core: user + system; context switches per second):\n");
  for (const auto& [tid, a] : after) {
    const auto b = before.find(tid);
    if (b == before.end())
      continue;
    const double user = a.user - b->second.user, system = a.system - b->second.system;
    const double switches = static_cast<double>(a.voluntary - b->second.voluntary);
    const double preempted = static_cast<double>(a.involuntary - b->second.involuntary);
    if (user + system == 0.0 && switches + preempted < wall)
      continue;  // idle threads (XML-RPC, rosout, ...)
    std::printf("  %-16s %5.1f %% = %4.1f + %4.1f   %6.0f/s voluntary, %5.0f/s preempted\n",
                a.name.c_str(), 100.0 * (user + system) / wall, 100.0 * user / wall,
                100.0 * system / wall, switches / wall, preempted / wall);
  }
}

/// The driver's view of the node. Callbacks run on a spinner thread, so every field they share
/// with the publishing loop is behind `mutex`.
struct Driver {
  std::mutex mutex;
  double v_new = 0.0;
  ros::WallTime sent;
  bool waiting = false;
  std::vector<double> latencies;
  std::size_t wheel_messages = 0;
  double step_p99_us = -1.0, step_mean_us = -1.0, tick_p99_us = -1.0, steps = -1.0, late = -1.0,
         resyncs = -1.0;

  void onWheels(const tvd::RoadWheels::ConstPtr& msg) {
    const ros::WallTime received = ros::WallTime::now();
    std::lock_guard<std::mutex> lock(mutex);
    ++wheel_messages;
    if (waiting && msg->speed == v_new) {
      latencies.push_back((received - sent).toSec());
      waiting = false;
    }
  }
  void onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& s : msg->status) {
      if (s.name.size() < 6 || s.name.compare(s.name.size() - 6, 6, ": loop") != 0)
        continue;
      for (const auto& kv : s.values) {
        const double value = std::atof(kv.value.c_str());
        if (kv.key == "step time p99 since start [us]")
          step_p99_us = value;
        if (kv.key == "step time mean since start [us]")
          step_mean_us = value;
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

int node(int argc, char** argv, int pid, const rl::TrackBagOptions& track, double duration,
         int laps, const std::string& reset_service) {
  ros::init(argc, argv, "ros_node_bench", ros::init_options::AnonymousName);
  ros::NodeHandle nh;
  Driver d;
  ros::Subscriber wheels =
      nh.subscribe("road_wheels", 1000, &Driver::onWheels, &d, ros::TransportHints().tcpNoDelay());
  ros::Subscriber diag = nh.subscribe("/diagnostics", 10, &Driver::onDiagnostics, &d);
  ros::Publisher terrain = nh.advertise<tvd::TerrainProfile>("terrain_profile", 100);
  ros::Publisher speed = nh.advertise<std_msgs::Float64>("speed", 10);
  // Callbacks on their own thread: a received sample is timed when it arrives, and the
  // publishing loop below sleeps until its next message instead of polling (a load driver that
  // spins would take the CPU the node is measured on; this machine has two cores).
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const ros::WallTime wait_end = ros::WallTime::now() + ros::WallDuration(60.0);
  while (ros::ok() &&
         (terrain.getNumSubscribers() == 0 || speed.getNumSubscribers() == 0 ||
          wheels.getNumPublishers() == 0) &&
         ros::WallTime::now() < wait_end) {
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
  {
    std::lock_guard<std::mutex> lock(d.mutex);
    d.v_new = v_low;
  }
  const ros::WallTime start = ros::WallTime::now();
  const double cpu_start = cpuSeconds(pid);
  const std::map<int, ThreadSample> threads_start = threadSamples(pid);
  std::size_t wheels_start = 0;
  {
    std::lock_guard<std::mutex> lock(d.mutex);
    wheels_start = d.wheel_messages;
  }
  std::size_t next_patch = 0;
  double next_speed = 0.0, next_change = 0.25, lap_start = 0.0;
  int lap = 0;
  while (ros::ok()) {
    const double t = (ros::WallTime::now() - start).toSec();
    if (t >= lap_start + run_time) {
      if (++lap == laps)
        break;
      // Next lap: the node back to equilibrium at station 0 (its ~reset service), the track
      // again from its first patch.
      std_srvs::Empty reset;
      if (!ros::service::call(reset_service, reset))
        throw std::runtime_error("could not call " + reset_service);
      lap_start = (ros::WallTime::now() - start).toSec();
      next_patch = 0;
      continue;
    }
    while (next_patch < run.patches.size() && run.patches[next_patch].time <= t - lap_start) {
      msg.header.stamp = ros::Time::now();
      rl::toMsg(run.patches[next_patch++].patch, &msg);
      terrain.publish(msg);
    }
    bool change = false;
    if (t >= next_change) {
      std::lock_guard<std::mutex> lock(d.mutex);
      if (!d.waiting) {  // the previous change has been seen
        d.v_new = d.v_new == v_low ? v_high : v_low;
        v.data = d.v_new;
        d.sent = ros::WallTime::now();
        d.waiting = true;
        change = true;
      }
    }
    if (change) {
      speed.publish(v);
      next_change += 0.25;
      next_speed = t + 0.02;
    } else if (t >= next_speed) {
      {
        std::lock_guard<std::mutex> lock(d.mutex);
        v.data = d.v_new;
      }
      speed.publish(v);
      next_speed += 0.02;
    }
    double wake = std::min({next_speed, next_change, lap_start + run_time});
    if (next_patch < run.patches.size())
      wake = std::min(wake, lap_start + run.patches[next_patch].time);
    const double now = (ros::WallTime::now() - start).toSec();
    if (wake > now)
      ros::WallDuration(wake - now).sleep();
  }
  const double wall = (ros::WallTime::now() - start).toSec();
  const double cpu = cpuSeconds(pid) - cpu_start;
  const std::map<int, ThreadSample> threads_end = threadSamples(pid);
  std::size_t received = 0;
  {
    std::lock_guard<std::mutex> lock(d.mutex);
    received = d.wheel_messages - wheels_start;
  }
  // One more diagnostics report, covering the whole run.
  ros::WallDuration(2.5).sleep();
  spinner.stop();
  std::lock_guard<std::mutex> lock(d.mutex);
  std::sort(d.latencies.begin(), d.latencies.end());
  auto pct = [&](double f) {
    if (d.latencies.empty())
      return -1.0;
    return d.latencies[std::min(d.latencies.size() - 1,
                                static_cast<std::size_t>(f * d.latencies.size()))];
  };
  std::printf("run: %s at %.1f km/h, %d lap(s), %.2f s wall, %zu road_wheels messages (%.0f Hz)\n",
              track.track.c_str(), track.speed * tracked_vehicle_dynamics::kKmhPerMs, laps, wall,
              received, received / wall);
  std::printf("node CPU: %.3f s in %.2f s = %.1f %% of one core\n", cpu, wall, 100.0 * cpu / wall);
  printThreads(threads_start, threads_end, wall);
  std::printf(
      "latency speed message -> next published sample (tf, then road_wheels): "
      "median %.2f ms, p95 %.2f ms, max %.2f ms (%zu changes)\n",
      pct(0.5) * 1e3, pct(0.95) * 1e3, d.latencies.empty() ? -1.0 : d.latencies.back() * 1e3,
      d.latencies.size());
  if (d.steps < 0)
    return 0;  // no diagnostics (the bare stand-in)
  std::printf(
      "node diagnostics: step time mean %.1f us, p99 %.0f us, tick time p99 %.0f us, %.0f steps, "
      "%.0f late ticks, %.0f resynchronisations\n",
      d.step_mean_us, d.step_p99_us, d.tick_p99_us, d.steps, d.late, d.resyncs);
  return 0;
}

/// The floor: a node with vehicle_dynamics_node's interface and tick (the same subscriptions
/// on a callback queue of its own, ~reset, a periodic timerfd in roscpp's network thread, a
/// RoadWheels sample published per tick to whoever listens) that computes nothing. Under the
/// same load driver its CPU use is what roscpp and the kernel take at this rate, whatever the
/// model. own_thread: the tick in a thread of its own (the node's earlier design).
int bare(int argc, char** argv, double rate, int wheels, bool own_thread) {
  ros::init(argc, argv, "vehicle_dynamics");
  ros::NodeHandle nh, private_nh("~");
  ros::CallbackQueue queue;
  ros::NodeHandle loop_nh(nh), loop_private_nh(private_nh);
  loop_nh.setCallbackQueue(&queue);
  loop_private_nh.setCallbackQueue(&queue);
  std::atomic<std::uint32_t> listeners{0};
  ros::Publisher pub;
  const auto recount = [&](const ros::SingleSubscriberPublisher&) {
    listeners.store(pub.getNumSubscribers(), std::memory_order_relaxed);
  };
  pub = nh.advertise<tvd::RoadWheels>("road_wheels", 10, recount, recount);
  double speed = 0.0;
  ros::Subscriber speed_sub = loop_nh.subscribe<std_msgs::Float64>(
      "speed", 10, [&](const std_msgs::Float64::ConstPtr& m) { speed = m->data; },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  ros::Subscriber terrain_sub = loop_nh.subscribe<tvd::TerrainProfile>(
      "terrain_profile", 100, [](const tvd::TerrainProfile::ConstPtr&) {}, ros::VoidConstPtr(),
      ros::TransportHints().tcpNoDelay());
  boost::function<bool(std_srvs::Empty::Request&, std_srvs::Empty::Response&)> on_reset =
      [](std_srvs::Empty::Request&, std_srvs::Empty::Response&) { return true; };
  ros::ServiceServer reset = loop_private_nh.advertiseService("reset", on_reset);
  tvd::RoadWheels msg;
  msg.header.frame_id = "base_link";
  msg.wheels.resize(static_cast<std::size_t>(wheels));
  for (int i = 0; i < wheels; ++i)
    msg.wheels[static_cast<std::size_t>(i)].name = "road_wheel_" + std::to_string(i);
  const auto tick = [&] {
    queue.callAvailable(ros::WallDuration(0));
    if (listeners.load(std::memory_order_relaxed) == 0)
      return;
    msg.header.stamp = ros::Time::now();
    msg.speed = speed;
    pub.publish(msg);
  };
  const long step_ns = std::lround(1e9 / rate);
  std::thread loop;
  std::unique_ptr<rl::NetworkThreadTimer> timer;
  if (own_thread) {
    // vehicle_dynamics_node's design before the network-thread tick.
    loop = std::thread([&] {
      pthread_setname_np(pthread_self(), "bare_loop");
      timespec next{};
      clock_gettime(CLOCK_MONOTONIC, &next);
      while (ros::ok()) {
        next.tv_nsec += step_ns;
        while (next.tv_nsec >= 1000000000L) {
          next.tv_nsec -= 1000000000L;
          ++next.tv_sec;
        }
        while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr) == EINTR) {
        }
        tick();
      }
    });
  } else {
    timer = std::make_unique<rl::NetworkThreadTimer>(step_ns, tick);  // the node's design
  }
  ros::spin();
  timer.reset();
  if (loop.joinable())
    loop.join();
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
  nd->add_option("--duration", duration, "[s] of each lap, at most the track's run")
      ->capture_default_str();
  int laps = 3;
  std::string reset_service = "/vehicle_dynamics/reset";
  nd->add_option("--laps", laps, "runs of the track, the node reset between them")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  nd->add_option("--reset-service", reset_service, "the node's ~reset service")
      ->capture_default_str();
  int wheels = 14;
  auto* bare_cmd = app.add_subcommand(
      "bare", "a stand-in node with the node's topics and loop that computes nothing");
  bare_cmd->add_option("--rate", rate, "[Hz]")->capture_default_str();
  bare_cmd->add_option("--wheels", wheels, "road wheels in each published sample")
      ->capture_default_str();
  bool bare_thread = false;
  bare_cmd->add_flag("--own-thread", bare_thread,
                     "tick in a thread of its own (clock_nanosleep) instead of roscpp's network "
                     "thread");
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
  track.speed = speed_kmh / tracked_vehicle_dynamics::kKmhPerMs;
  try {
    if (off->parsed())
      return offline(vehicle, variant, cache, track, rate, method);
    if (bare_cmd->parsed())
      return bare(argc, argv, rate, wheels, bare_thread);
    return node(argc, argv, pid, track, duration, laps, reset_service);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ros_node_bench: error: %s\n", e.what());
    return 1;
  }
}
