// fxkit::detail::ScriptQuad: the quad a DXSAS `Draw=Buffer` draws, written in the
// application's vertex layout and conventions (Target), so that the passes' pipelines for the
// application's meshes draw it.
#pragma once
#include <optional>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/context.h"
#include "fxkit/target.h"

namespace fxkit::detail {

class ScriptQuad {
 public:
  // Four vertices covering clip space, POSITION and TEXCOORD0 (v = 0 at the top of the
  // screen) written where the layout has them as 2 to 4 floats, every other attribute zero;
  // its front faces as the Target's meshes', seen as they are seen.
  static std::optional<ScriptQuad> create(const fx::vk::Context& ctx, const Target& target, fx::DiagnosticSink& sink);
  // Binds its vertex buffers at the layout's bindings and draws it.
  void draw(VkCommandBuffer cmd) const;

 private:
  std::vector<fx::vk::Buffer> vertices_;  // one per VertexBinding
  std::vector<uint32_t> bindings_;
  fx::vk::Buffer indices_;
};

}  // namespace fxkit::detail
