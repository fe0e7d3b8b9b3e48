// Private: what a physical device supports, and the feature chain that enables it.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "fx/vulkan/context.h"
#include "fx/vulkan/vk_check.h"

namespace fx::vk {

// Everything fxkit reads from one physical device before creating (or wrapping) a device.
struct DeviceSupport {
  DeviceInfo info;
  DeviceFeatures features;  // supported, not necessarily enabled
  std::vector<std::string> extensions;
  bool has_graphics_queue = false;
  uint32_t graphics_family = 0;

  bool has_extension(std::string_view name) const;
};

DeviceSupport query_device(VkPhysicalDevice physical_device, uint32_t index);

// The VkPhysicalDeviceFeatures2 chain passed to vkCreateDevice, enabling every optional
// feature fxkit uses that `supported` has. Not movable: the structs point at each other.
struct FeatureChain {
  explicit FeatureChain(const DeviceSupport& supported);
  FeatureChain(const FeatureChain&) = delete;
  FeatureChain& operator=(const FeatureChain&) = delete;

  VkPhysicalDeviceFeatures2 head = structure<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  VkPhysicalDeviceVulkan13Features v13 =
      structure<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  VkPhysicalDeviceExtendedDynamicState2FeaturesEXT eds2 = structure<VkPhysicalDeviceExtendedDynamicState2FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_2_FEATURES_EXT);
  VkPhysicalDeviceExtendedDynamicState3FeaturesEXT eds3 = structure<VkPhysicalDeviceExtendedDynamicState3FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_3_FEATURES_EXT);
  VkPhysicalDeviceTransformFeedbackFeaturesEXT xfb = structure<VkPhysicalDeviceTransformFeedbackFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT);
  std::vector<const char*> extensions;  // to enable, pointing into the DeviceSupport
  DeviceFeatures enabled;
};

// Loads the non-core entry points `enabled` makes available.
DeviceFunctions load_device_functions(VkInstance instance, VkDevice device, const DeviceFeatures& enabled,
                                      bool debug_utils);

}  // namespace fx::vk
