// Frame-keyed deferred destruction.
#include "fx/vulkan/retire_queue.h"

namespace fx::vk {

void RetireQueue::retire(std::function<void()> destroy) {
  if (destroy) entries_.push_back({frame_, std::move(destroy)});
}

void RetireQueue::begin_frame() {
  ++frame_;
  if (frame_ >= frames_in_flight_) collect(frame_ - frames_in_flight_);
}

void RetireQueue::collect(uint64_t completed) {
  while (!entries_.empty() && entries_.front().frame <= completed) {
    // Pop before running: a destructor may retire more objects.
    std::function<void()> destroy = std::move(entries_.front().destroy);
    entries_.pop_front();
    destroy();
  }
}

void RetireQueue::flush() {
  while (!entries_.empty()) {
    std::function<void()> destroy = std::move(entries_.front().destroy);
    entries_.pop_front();
    destroy();
  }
}

}  // namespace fx::vk
