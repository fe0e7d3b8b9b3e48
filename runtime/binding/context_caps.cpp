// DeviceCaps of a Context: the physical device's, less the shader features not enabled.
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
  return caps;
}

}  // namespace fx::vk
