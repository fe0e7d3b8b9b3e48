// DeviceCaps of a Context: the physical device's, less the shader features and stream output not enabled.
#include "fx/binding/context_caps.h"

#include <algorithm>

#include "fx/select/caps_sources.h"
#include "fx/vulkan/shader_capabilities.h"

namespace fx::vk {

DeviceCaps context_caps(const Context& ctx) {
  DeviceCaps caps = caps_from_physical_device(ctx.physical_device());
  std::vector<std::string>& features = caps.vulkan.features;
  for (const ShaderCapabilityFeature& row : shader_capability_features())
    if (!ctx.features().has_shader_feature(row.feature))
      features.erase(std::remove(features.begin(), features.end(), row.feature), features.end());
  // Stream output runs only where the extension is enabled (a wrapped device may not have).
  if (!ctx.features().transform_feedback)
    std::erase(caps.vulkan.extensions, std::string(VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME));
  return caps;
}

}  // namespace fx::vk
