// Deferred destruction keyed to frame numbers: an object the GPU may still be using is
// retired now and destroyed once the frames that could reference it have completed.
#pragma once
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <utility>

namespace fx::vk {

class RetireQueue {
 public:
  // `frames_in_flight`: how many frames the application records ahead of the GPU.
  explicit RetireQueue(uint32_t frames_in_flight = 2) : frames_in_flight_(frames_in_flight) {}
  RetireQueue(const RetireQueue&) = delete;
  RetireQueue& operator=(const RetireQueue&) = delete;
  // Destroys everything still pending: the device must be idle by then.
  ~RetireQueue() { flush(); }

  // The frame being recorded.
  uint64_t frame() const { return frame_; }
  uint32_t frames_in_flight() const { return frames_in_flight_; }

  // Runs `destroy` once the current frame has completed on the GPU.
  void retire(std::function<void()> destroy);
  // Keeps a move-only RAII object (Buffer, GpuImage, ...) alive until the current frame completes.
  template <class T>
  void retire_object(T&& object) {
    auto holder = std::make_shared<std::decay_t<T>>(std::forward<T>(object));
    retire([holder]() mutable { holder.reset(); });
  }

  // Starts the next frame. Call after waiting for the fence of the frame that is
  // `frames_in_flight` older: destroys what frames <= frame() - frames_in_flight retired.
  void begin_frame();
  // Destroys what frames <= `completed` retired (for timeline-semaphore applications).
  void collect(uint64_t completed);
  // Destroys everything now (after vkDeviceWaitIdle).
  void flush();
  size_t pending() const { return entries_.size(); }

 private:
  struct Entry {
    uint64_t frame;
    std::function<void()> destroy;
  };
  std::deque<Entry> entries_;  // in retire order, so frames are non-decreasing
  uint64_t frame_ = 0;
  uint32_t frames_in_flight_;
};

}  // namespace fx::vk
