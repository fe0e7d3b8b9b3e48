// fx::vk::ApplyStats: what the pass recorder recorded (and so what Technique::apply recorded),
// for profiling, tests and benchmarks; the public API names it fxkit::ApplyStats
// (fxkit/effect.h).
#pragma once
#include <cstdint>

namespace fx::vk {

struct ApplyStats {
  uint64_t passes = 0;
  uint64_t pipeline_binds = 0;
  uint64_t dynamic_state_calls = 0;  // vkCmdSet* calls
  uint64_t descriptor_binds = 0;     // vkCmdBindDescriptorSets
  uint64_t descriptor_pushes = 0;    // vkCmdPushDescriptorSetKHR
  uint64_t descriptor_writes = 0;    // vkUpdateDescriptorSets calls
  uint64_t uniform_uploads = 0;      // uniform blocks written into the frame's memory
};

}  // namespace fx::vk
