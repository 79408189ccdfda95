#include "tracked_vehicle_dynamics/ros/network_thread_timer.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <poll.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <ros/poll_manager.h>

namespace tracked_vehicle_dynamics {
namespace ros_layer {

NetworkThreadTimer::NetworkThreadTimer(std::int64_t period_ns, std::function<void()> on_tick) {
  fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
  if (fd_ < 0)
    throw std::runtime_error(std::string("timerfd_create: ") + std::strerror(errno));
  itimerspec period{};
  period.it_interval.tv_sec = static_cast<time_t>(period_ns / 1000000000LL);
  period.it_interval.tv_nsec = static_cast<long>(period_ns % 1000000000LL);
  period.it_value = period.it_interval;
  if (timerfd_settime(fd_, 0, &period, nullptr) != 0) {
    const std::string why = std::strerror(errno);
    close(fd_);
    throw std::runtime_error("timerfd_settime: " + why);
  }
  target_ = std::make_shared<Target>();
  target_->on_tick = std::move(on_tick);
  const std::shared_ptr<Target> target = target_;
  const int fd = fd_;
  ros::PollSet& poll_set = ros::PollManager::instance()->getPollSet();
  poll_set.addSocket(fd, [target, fd](int) {
    std::lock_guard<std::mutex> lock(target->mutex);
    if (!target->on_tick)
      return;  // stopped (and the descriptor perhaps closed)
    std::uint64_t expirations = 0;
    if (read(fd, &expirations, sizeof expirations) != static_cast<ssize_t>(sizeof expirations))
      return;
    target->on_tick();
  });
  poll_set.addEvents(fd, POLLIN);
}

NetworkThreadTimer::~NetworkThreadTimer() {
  ros::PollManager::instance()->getPollSet().delSocket(fd_);
  {
    std::lock_guard<std::mutex> lock(target_->mutex);  // waits for a tick in progress
    target_->on_tick = nullptr;
  }
  close(fd_);
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
