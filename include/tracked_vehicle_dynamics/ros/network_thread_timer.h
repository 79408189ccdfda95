// A periodic timer that ticks in roscpp's network thread.
//
// roscpp writes every publication to the subscribers' sockets from its network (poll) thread,
// which therefore wakes up once per published message. A node that publishes at every tick of
// its own loop thread pays two wake-ups and a hand-off per tick; ticking in the network thread
// itself (a periodic timerfd in roscpp's PollSet) pays one. At 1 kHz on the reference machine
// that is about 1.5 % of a core (bench/ros_node_bench.sh, sections 3 and 4). The tick must be
// short: the network thread's other work waits for it.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>

namespace tracked_vehicle_dynamics {
namespace ros_layer {

class NetworkThreadTimer {
 public:
  /// Calls on_tick every period_ns nanoseconds (CLOCK_MONOTONIC) in roscpp's network thread,
  /// once per wake-up however many periods passed (the caller catches up by its own clock).
  /// roscpp must be started (a NodeHandle exists). Throws std::runtime_error when the timerfd
  /// cannot be created.
  NetworkThreadTimer(std::int64_t period_ns, std::function<void()> on_tick);
  /// Stops: waits for a tick in progress; none runs afterwards.
  ~NetworkThreadTimer();
  NetworkThreadTimer(const NetworkThreadTimer&) = delete;
  NetworkThreadTimer& operator=(const NetworkThreadTimer&) = delete;

 private:
  // The poll set's callback holds this, not the timer: a callback already on its way when the
  // timer stops finds on_tick empty.
  struct Target {
    std::mutex mutex;
    std::function<void()> on_tick;
  };
  std::shared_ptr<Target> target_;
  int fd_ = -1;
};

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
