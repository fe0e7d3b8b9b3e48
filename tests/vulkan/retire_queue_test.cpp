// Frame-keyed deferred destruction.
#include "fx/vulkan/retire_queue.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace fx::vk {
namespace {

TEST(RetireQueue, DestroysOnlyAfterFramesInFlightHaveCompleted) {
  RetireQueue queue(2);
  std::vector<int> destroyed;
  queue.retire([&] { destroyed.push_back(0); });  // used by frame 0
  queue.begin_frame();                            // frame 1: frame 0 may still run
  EXPECT_TRUE(destroyed.empty());
  queue.retire([&] { destroyed.push_back(1); });
  queue.begin_frame();  // frame 2: the app waited on frame 0's fence
  EXPECT_EQ(destroyed, std::vector<int>{0});
  EXPECT_EQ(queue.pending(), 1u);
  queue.begin_frame();  // frame 3: frame 1 complete
  EXPECT_EQ(destroyed, (std::vector<int>{0, 1}));
  EXPECT_EQ(queue.frame(), 3u);
}

TEST(RetireQueue, SingleFrameInFlightDestroysAtTheNextFrame) {
  RetireQueue queue(1);
  int destroyed = 0;
  queue.retire([&] { ++destroyed; });
  queue.begin_frame();
  EXPECT_EQ(destroyed, 1);
}

TEST(RetireQueue, RetiredObjectsLiveUntilCollected) {
  RetireQueue queue(2);
  auto alive = std::make_shared<int>(42);
  std::weak_ptr<int> watch = alive;
  queue.retire_object(std::move(alive));
  queue.collect(0);  // frame 0 completed (timeline-semaphore style)
  EXPECT_TRUE(watch.expired());
}

TEST(RetireQueue, FlushAndDestructorRunEverythingOnce) {
  int destroyed = 0;
  {
    RetireQueue queue(3);
    queue.retire([&] { ++destroyed; });
    queue.retire([&] { ++destroyed; });
    queue.flush();
    EXPECT_EQ(destroyed, 2);
    queue.retire([&] { ++destroyed; });
  }
  EXPECT_EQ(destroyed, 3);
}

TEST(RetireQueue, DestructorsMayRetireMoreObjects) {
  RetireQueue queue(1);
  int destroyed = 0;
  queue.retire([&] {
    ++destroyed;
    queue.retire([&] { ++destroyed; });  // retired during frame 1: waits for frame 1
  });
  queue.begin_frame();
  EXPECT_EQ(destroyed, 1);
  EXPECT_EQ(queue.pending(), 1u);
  queue.begin_frame();
  EXPECT_EQ(destroyed, 2);
}

}  // namespace
}  // namespace fx::vk
