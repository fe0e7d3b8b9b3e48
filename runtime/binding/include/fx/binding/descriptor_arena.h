// fx::vk::DescriptorArena: descriptor sets that live as long as their owner (an
// EffectBinding's passes keep one set per frame in flight, rewritten only when their images
// change), from pools it adds as they fill; all freed when it is destroyed.
#pragma once
#include <vulkan/vulkan.h>

#include <vector>

#include "fx/binding/shader_program.h"
#include "fx/vulkan/context.h"

namespace fx::vk {

class DescriptorArena {
 public:
  explicit DescriptorArena(const Context& ctx) : ctx_(&ctx) {}
  DescriptorArena(const DescriptorArena&) = delete;  // the sets point into its pools
  DescriptorArena& operator=(const DescriptorArena&) = delete;
  ~DescriptorArena();

  // A set of `program`'s layout (DescriptorMode::sets), kept until the arena is destroyed.
  // Null and "vk-descriptor-arena" when no pool could be made for it.
  VkDescriptorSet allocate(const ShaderProgram& program, DiagnosticSink& sink);
  size_t pool_count() const { return pools_.size(); }

 private:
  // A pool for at least kSetsPerPool sets like `program`'s.
  VkDescriptorPool add_pool(const ShaderProgram& program, DiagnosticSink& sink);

  const Context* ctx_;
  std::vector<VkDescriptorPool> pools_;  // the last one has room, as far as is known
};

}  // namespace fx::vk
