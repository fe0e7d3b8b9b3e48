#include "wake_source.h"

#include <poll.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/timerfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace fx::detail {
namespace {

void drain_counter(int fd) {
  uint64_t value;
  while (::read(fd, &value, sizeof value) > 0) {
  }
}

int epoll_add(int epoll_fd, int fd) {
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.fd = fd;
  return epoll_ctl(epoll_fd, EPOLL_CTL_ADD, fd, &ev);
}

}  // namespace

WakeSource::WakeSource() {
  epoll_fd_ = epoll_create1(EPOLL_CLOEXEC);
  if (epoll_fd_ < 0) error_ = errno;
  // CLOCK_MONOTONIC is what std::chrono::steady_clock reads on Linux.
  timer_fd_ = timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
  if (timer_fd_ < 0) error_ = errno;
  event_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (event_fd_ < 0) error_ = errno;
  if (event_fd_ >= 0) sources_.push_back(event_fd_);
  if (timer_fd_ >= 0) sources_.push_back(timer_fd_);
  if (epoll_fd_ >= 0) {
    for (int fd : sources_) epoll_add(epoll_fd_, fd);
  }
}

WakeSource::~WakeSource() {
  for (int fd : {epoll_fd_, timer_fd_, event_fd_})
    if (fd >= 0) ::close(fd);
}

void WakeSource::add(int fd) {
  if (fd < 0) return;
  sources_.push_back(fd);
  if (epoll_fd_ >= 0 && epoll_add(epoll_fd_, fd) != 0) error_ = errno;
}

void WakeSource::arm(std::optional<Clock::time_point> deadline) {
  if (timer_fd_ < 0) return;
  itimerspec spec{};  // all zero disarms
  if (deadline) {
    auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(deadline->time_since_epoch()).count();
    if (ns <= 0) ns = 1;  // zero would disarm; fire at once instead
    spec.it_value.tv_sec = time_t(ns / 1'000'000'000);
    spec.it_value.tv_nsec = long(ns % 1'000'000'000);
  }
  timerfd_settime(timer_fd_, deadline ? TFD_TIMER_ABSTIME : 0, &spec, nullptr);
}

void WakeSource::interrupt() {
  if (event_fd_ < 0) return;
  uint64_t one = 1;
  [[maybe_unused]] ssize_t n = ::write(event_fd_, &one, sizeof one);
}

WakeSource::WaitResult WakeSource::wait(std::chrono::milliseconds timeout) {
  int ms = int(std::min<int64_t>(std::max<int64_t>(timeout.count(), 0), 1 << 30));
  bool interrupted = false, ready = false;
  auto classify = [&](int fd) {
    if (fd == event_fd_) {
      drain_counter(fd);
      interrupted = true;
    } else if (fd == timer_fd_) {
      drain_counter(fd);
      ready = true;
    } else {
      ready = true;
    }
  };
  if (epoll_fd_ >= 0) {
    epoll_event events[8];
    int n = epoll_wait(epoll_fd_, events, 8, ms);
    for (int i = 0; i < n; ++i) classify(events[i].data.fd);
  } else {
    std::vector<pollfd> fds;
    for (int fd : sources_) fds.push_back({fd, POLLIN, 0});
    int n = ::poll(fds.data(), nfds_t(fds.size()), ms);
    for (int i = 0; n > 0 && i < int(fds.size()); ++i)
      if (fds[size_t(i)].revents & POLLIN) classify(fds[size_t(i)].fd);
  }
  if (interrupted) return WaitResult::interrupted;
  return ready ? WaitResult::ready : WaitResult::timed_out;
}

}  // namespace fx::detail
