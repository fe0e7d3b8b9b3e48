// The Vulkan core features SPIR-V capabilities need (the SPIR-V environment appendix of the
// Vulkan spec): a module that declares one is valid only on a device that enabled the feature.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace fx {

// One capability whose only requirement is a VkPhysicalDeviceFeatures member.
struct ShaderCapabilityFeature {
  uint32_t capability;          // SPIR-V Capability enumerant
  const char* capability_name;  // "ClipDistance"
  const char* feature;          // the member, spelled as DeviceCaps::vulkan.features spells it
  size_t feature_offset;        // offsetof(VkPhysicalDeviceFeatures, member)
  const char* written_as;       // what shader code declares it with ("SV_ClipDistance")
};

// Every row; the Vulkan context enables each feature the device has.
std::span<const ShaderCapabilityFeature> shader_capability_features();

// The rows of the capabilities `spirv` declares (OpCapability), in table order, each once.
// Empty when the words are not a SPIR-V module.
std::vector<const ShaderCapabilityFeature*> features_needed_by(std::span<const uint32_t> spirv);

}  // namespace fx
