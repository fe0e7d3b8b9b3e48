// Feature and property queries, and the matching enable chain.
#include "device_query.h"

#include <algorithm>
#include <cstring>

#include "fx/vulkan/shader_capabilities.h"

namespace fx::vk {
namespace {

constexpr const char* kPushDescriptor = VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME;
constexpr const char* kEds2 = VK_EXT_EXTENDED_DYNAMIC_STATE_2_EXTENSION_NAME;
constexpr const char* kEds3 = VK_EXT_EXTENDED_DYNAMIC_STATE_3_EXTENSION_NAME;
constexpr const char* kTransformFeedback = VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME;

// One table maps the Vulkan EDS3 feature bits to ours, both ways.
struct Eds3Field {
  VkBool32 VkPhysicalDeviceExtendedDynamicState3FeaturesEXT::*vk;
  bool DeviceFeatures::Eds3::*ours;
};
#define FXKIT_EDS3(vk_name, our_name)                                                                                  \
  Eds3Field {                                                                                                          \
    &VkPhysicalDeviceExtendedDynamicState3FeaturesEXT::extendedDynamicState3##vk_name, &DeviceFeatures::Eds3::our_name \
  }
constexpr Eds3Field kEds3Fields[] = {
    FXKIT_EDS3(TessellationDomainOrigin, tessellation_domain_origin),
    FXKIT_EDS3(DepthClampEnable, depth_clamp_enable),
    FXKIT_EDS3(PolygonMode, polygon_mode),
    FXKIT_EDS3(RasterizationSamples, rasterization_samples),
    FXKIT_EDS3(SampleMask, sample_mask),
    FXKIT_EDS3(AlphaToCoverageEnable, alpha_to_coverage_enable),
    FXKIT_EDS3(AlphaToOneEnable, alpha_to_one_enable),
    FXKIT_EDS3(LogicOpEnable, logic_op_enable),
    FXKIT_EDS3(ColorBlendEnable, color_blend_enable),
    FXKIT_EDS3(ColorBlendEquation, color_blend_equation),
    FXKIT_EDS3(ColorWriteMask, color_write_mask),
    FXKIT_EDS3(RasterizationStream, rasterization_stream),
    FXKIT_EDS3(ConservativeRasterizationMode, conservative_rasterization_mode),
    FXKIT_EDS3(ExtraPrimitiveOverestimationSize, extra_primitive_overestimation_size),
    FXKIT_EDS3(DepthClipEnable, depth_clip_enable),
    FXKIT_EDS3(SampleLocationsEnable, sample_locations_enable),
    FXKIT_EDS3(ColorBlendAdvanced, color_blend_advanced),
    FXKIT_EDS3(ProvokingVertexMode, provoking_vertex_mode),
    FXKIT_EDS3(LineRasterizationMode, line_rasterization_mode),
    FXKIT_EDS3(LineStippleEnable, line_stipple_enable),
    FXKIT_EDS3(DepthClipNegativeOneToOne, depth_clip_negative_one_to_one),
    FXKIT_EDS3(ViewportWScalingEnable, viewport_w_scaling_enable),
    FXKIT_EDS3(ViewportSwizzle, viewport_swizzle),
    FXKIT_EDS3(CoverageToColorEnable, coverage_to_color_enable),
    FXKIT_EDS3(CoverageToColorLocation, coverage_to_color_location),
    FXKIT_EDS3(CoverageModulationMode, coverage_modulation_mode),
    FXKIT_EDS3(CoverageModulationTableEnable, coverage_modulation_table_enable),
    FXKIT_EDS3(CoverageModulationTable, coverage_modulation_table),
    FXKIT_EDS3(CoverageReductionMode, coverage_reduction_mode),
    FXKIT_EDS3(RepresentativeFragmentTestEnable, representative_fragment_test_enable),
    FXKIT_EDS3(ShadingRateImageEnable, shading_rate_image_enable),
};
#undef FXKIT_EDS3

// DeviceFeatures from Vulkan's feature structs; a null struct means none of its features.
// The extended dynamic state commands are core in Vulkan 1.3, which the 1.3 struct stands for.
DeviceFeatures features_from(const VkPhysicalDeviceFeatures& core, const VkPhysicalDeviceVulkan13Features* f13,
                             const VkPhysicalDeviceExtendedDynamicState2FeaturesEXT* eds2,
                             const VkPhysicalDeviceExtendedDynamicState3FeaturesEXT* eds3, bool push_descriptor,
                             const VkPhysicalDeviceTransformFeedbackFeaturesEXT* xfb) {
  DeviceFeatures f;
  f.transform_feedback = xfb && xfb->transformFeedback;
  f.dynamic_rendering = f13 && f13->dynamicRendering;
  f.synchronization2 = f13 && f13->synchronization2;
  f.maintenance4 = f13 && f13->maintenance4;
  f.extended_dynamic_state = f13 != nullptr;
  f.extended_dynamic_state2 = f13 != nullptr;
  f.eds2_logic_op = eds2 && eds2->extendedDynamicState2LogicOp;
  f.eds2_patch_control_points = eds2 && eds2->extendedDynamicState2PatchControlPoints;
  if (eds3)
    for (const Eds3Field& field : kEds3Fields) f.eds3.*field.ours = eds3->*field.vk;
  f.push_descriptor = push_descriptor;
  f.sampler_anisotropy = core.samplerAnisotropy;
  f.fill_mode_non_solid = core.fillModeNonSolid;
  f.depth_clamp = core.depthClamp;
  f.depth_bias_clamp = core.depthBiasClamp;
  f.independent_blend = core.independentBlend;
  f.geometry_shader = core.geometryShader;
  f.tessellation_shader = core.tessellationShader;
  f.texture_compression_bc = core.textureCompressionBC;
  f.image_cube_array = core.imageCubeArray;
  f.image_gather_extended = core.shaderImageGatherExtended;
  f.fragment_stores_and_atomics = core.fragmentStoresAndAtomics;
  f.vertex_pipeline_stores_and_atomics = core.vertexPipelineStoresAndAtomics;
  const auto* bits = reinterpret_cast<const unsigned char*>(&core);
  for (const ShaderCapabilityFeature& row : shader_capability_features()) {
    VkBool32 on = VK_FALSE;
    std::memcpy(&on, bits + row.feature_offset, sizeof on);
    if (on) f.shader_features.emplace_back(row.feature);
  }
  std::sort(f.shader_features.begin(), f.shader_features.end());
  f.shader_features.erase(std::unique(f.shader_features.begin(), f.shader_features.end()), f.shader_features.end());
  return f;
}

}  // namespace

bool DeviceFeatures::Eds3::any() const {
  return std::any_of(std::begin(kEds3Fields), std::end(kEds3Fields),
                     [this](const Eds3Field& f) { return this->*f.ours; });
}

bool DeviceFeatures::has_shader_feature(std::string_view name) const {
  return std::binary_search(shader_features.begin(), shader_features.end(), name);
}

bool DeviceSupport::has_extension(std::string_view name) const {
  return std::find(extensions.begin(), extensions.end(), name) != extensions.end();
}

DeviceSupport query_device(VkPhysicalDevice physical_device, uint32_t index) {
  DeviceSupport s;
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &count, exts.data());
  exts.resize(count);
  for (const auto& e : exts) s.extensions.emplace_back(e.extensionName);

  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(physical_device, &props);
  s.info.name = props.deviceName;
  s.info.type = props.deviceType;
  s.info.api_version = props.apiVersion;
  s.info.driver_version = props.driverVersion;
  s.info.vendor_id = props.vendorID;
  s.info.device_id = props.deviceID;
  s.info.limits = props.limits;
  s.info.index = index;

  const bool v13 = props.apiVersion >= VK_API_VERSION_1_3;
  const bool has_push = s.has_extension(kPushDescriptor);
  const bool has_eds2 = s.has_extension(kEds2);
  const bool has_eds3 = s.has_extension(kEds3);
  const bool has_xfb = s.has_extension(kTransformFeedback);

  VkPhysicalDeviceVulkan11Properties p11 =
      structure<VkPhysicalDeviceVulkan11Properties>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES);
  VkPhysicalDevicePushDescriptorPropertiesKHR push_props = structure<VkPhysicalDevicePushDescriptorPropertiesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PUSH_DESCRIPTOR_PROPERTIES_KHR);
  VkPhysicalDeviceProperties2 props2 =
      structure<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
  if (props.apiVersion >= VK_API_VERSION_1_2) props2.pNext = &p11;  // Vulkan11Properties is 1.2+
  if (has_push) {
    push_props.pNext = props2.pNext;
    props2.pNext = &push_props;
  }
  VkPhysicalDeviceTransformFeedbackPropertiesEXT xfb_props = structure<VkPhysicalDeviceTransformFeedbackPropertiesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT);
  if (has_xfb) {
    xfb_props.pNext = props2.pNext;
    props2.pNext = &xfb_props;
  }
  vkGetPhysicalDeviceProperties2(physical_device, &props2);
  if (props.apiVersion >= VK_API_VERSION_1_2)
    std::copy(std::begin(p11.deviceUUID), std::end(p11.deviceUUID), s.info.uuid.begin());
  if (has_push) s.info.push_descriptor_max = push_props.maxPushDescriptors;
  if (has_xfb) s.info.transform_feedback_stride_max = xfb_props.maxTransformFeedbackBufferDataStride;

  VkPhysicalDeviceVulkan13Features f13 =
      structure<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  VkPhysicalDeviceExtendedDynamicState2FeaturesEXT f_eds2 = structure<VkPhysicalDeviceExtendedDynamicState2FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_2_FEATURES_EXT);
  VkPhysicalDeviceExtendedDynamicState3FeaturesEXT f_eds3 = structure<VkPhysicalDeviceExtendedDynamicState3FeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_3_FEATURES_EXT);
  VkPhysicalDeviceTransformFeedbackFeaturesEXT f_xfb = structure<VkPhysicalDeviceTransformFeedbackFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT);
  VkPhysicalDeviceFeatures2 f2 = structure<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  void** tail = &f2.pNext;
  auto link = [&tail](auto& s) {
    *tail = &s;
    tail = &s.pNext;
  };
  if (v13) link(f13);
  if (has_eds2) link(f_eds2);
  if (has_eds3) link(f_eds3);
  if (has_xfb) link(f_xfb);
  vkGetPhysicalDeviceFeatures2(physical_device, &f2);

  // Stream output needs the captured vertices drawable by their byte count (DrawAuto).
  const bool xfb = has_xfb && xfb_props.transformFeedbackDraw;
  s.features = features_from(f2.features, v13 ? &f13 : nullptr, has_eds2 ? &f_eds2 : nullptr,
                             has_eds3 ? &f_eds3 : nullptr, has_push, xfb ? &f_xfb : nullptr);

  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i) {
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      s.has_graphics_queue = true;
      s.graphics_family = i;
      break;
    }
  }
  return s;
}

FeatureChain::FeatureChain(const DeviceSupport& supported) {
  const DeviceFeatures& f = supported.features;
  enabled = f;
  VkPhysicalDeviceFeatures& core = head.features;
  core.samplerAnisotropy = f.sampler_anisotropy;
  core.fillModeNonSolid = f.fill_mode_non_solid;
  core.depthClamp = f.depth_clamp;
  core.depthBiasClamp = f.depth_bias_clamp;
  core.independentBlend = f.independent_blend;
  core.geometryShader = f.geometry_shader;
  core.tessellationShader = f.tessellation_shader;
  core.textureCompressionBC = f.texture_compression_bc;
  core.imageCubeArray = f.image_cube_array;
  core.shaderImageGatherExtended = f.image_gather_extended;
  core.fragmentStoresAndAtomics = f.fragment_stores_and_atomics;
  core.vertexPipelineStoresAndAtomics = f.vertex_pipeline_stores_and_atomics;
  // Technique validation accepts a shader's capability when the device has its feature;
  // creating the module is valid only with the feature enabled.
  auto* bits = reinterpret_cast<unsigned char*>(&core);
  for (const ShaderCapabilityFeature& row : shader_capability_features())
    if (f.has_shader_feature(row.feature)) {
      const VkBool32 on = VK_TRUE;
      std::memcpy(bits + row.feature_offset, &on, sizeof on);
    }

  v13.dynamicRendering = f.dynamic_rendering;
  v13.synchronization2 = f.synchronization2;
  v13.maintenance4 = f.maintenance4;
  head.pNext = &v13;
  void** tail = &v13.pNext;

  if (f.push_descriptor) extensions.push_back(kPushDescriptor);
  if (f.eds2_logic_op || f.eds2_patch_control_points) {
    eds2.extendedDynamicState2 = VK_TRUE;
    eds2.extendedDynamicState2LogicOp = f.eds2_logic_op;
    eds2.extendedDynamicState2PatchControlPoints = f.eds2_patch_control_points;
    extensions.push_back(kEds2);
    *tail = &eds2;
    tail = &eds2.pNext;
  }
  if (f.eds3.any()) {
    for (const Eds3Field& field : kEds3Fields) eds3.*field.vk = f.eds3.*field.ours;
    extensions.push_back(kEds3);
    *tail = &eds3;
    tail = &eds3.pNext;
  }
  if (f.transform_feedback) {
    xfb.transformFeedback = VK_TRUE;
    extensions.push_back(kTransformFeedback);
    *tail = &xfb;
    tail = &xfb.pNext;
  }
}

DeviceFunctions load_device_functions(VkInstance instance, VkDevice device, const DeviceFeatures& f, bool debug_utils) {
  DeviceFunctions fn;
  auto load = [device](auto& slot, const char* name) {
    slot = reinterpret_cast<std::remove_reference_t<decltype(slot)>>(vkGetDeviceProcAddr(device, name));
  };
  if (f.push_descriptor) load(fn.push_descriptor_set, "vkCmdPushDescriptorSetKHR");
  if (f.eds2_logic_op) load(fn.set_logic_op, "vkCmdSetLogicOpEXT");
  if (f.eds2_patch_control_points) load(fn.set_patch_control_points, "vkCmdSetPatchControlPointsEXT");
  const auto& e = f.eds3;
  if (e.polygon_mode) load(fn.set_polygon_mode, "vkCmdSetPolygonModeEXT");
  if (e.depth_clamp_enable) load(fn.set_depth_clamp_enable, "vkCmdSetDepthClampEnableEXT");
  if (e.rasterization_samples) load(fn.set_rasterization_samples, "vkCmdSetRasterizationSamplesEXT");
  if (e.sample_mask) load(fn.set_sample_mask, "vkCmdSetSampleMaskEXT");
  if (e.alpha_to_coverage_enable) load(fn.set_alpha_to_coverage_enable, "vkCmdSetAlphaToCoverageEnableEXT");
  if (e.alpha_to_one_enable) load(fn.set_alpha_to_one_enable, "vkCmdSetAlphaToOneEnableEXT");
  if (e.logic_op_enable) load(fn.set_logic_op_enable, "vkCmdSetLogicOpEnableEXT");
  if (e.color_blend_enable) load(fn.set_color_blend_enable, "vkCmdSetColorBlendEnableEXT");
  if (e.color_blend_equation) load(fn.set_color_blend_equation, "vkCmdSetColorBlendEquationEXT");
  if (e.color_write_mask) load(fn.set_color_write_mask, "vkCmdSetColorWriteMaskEXT");
  if (e.depth_clip_enable) load(fn.set_depth_clip_enable, "vkCmdSetDepthClipEnableEXT");
  if (e.provoking_vertex_mode) load(fn.set_provoking_vertex_mode, "vkCmdSetProvokingVertexModeEXT");
  if (e.line_rasterization_mode) load(fn.set_line_rasterization_mode, "vkCmdSetLineRasterizationModeEXT");
  if (e.tessellation_domain_origin) load(fn.set_tessellation_domain_origin, "vkCmdSetTessellationDomainOriginEXT");
  if (f.transform_feedback) {
    load(fn.bind_transform_feedback_buffers, "vkCmdBindTransformFeedbackBuffersEXT");
    load(fn.begin_transform_feedback, "vkCmdBeginTransformFeedbackEXT");
    load(fn.end_transform_feedback, "vkCmdEndTransformFeedbackEXT");
    load(fn.draw_indirect_byte_count, "vkCmdDrawIndirectByteCountEXT");
  }
  if (debug_utils && instance)
    fn.set_object_name = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance, "vkSetDebugUtilsObjectNameEXT"));
  return fn;
}

DeviceFeatures enabled_features(VkPhysicalDevice physical_device, const VkDeviceCreateInfo& created_with) {
  const DeviceSupport support = query_device(physical_device, 0);
  auto enabled = [&created_with](std::string_view name) {
    for (uint32_t i = 0; i < created_with.enabledExtensionCount; ++i)
      if (name == created_with.ppEnabledExtensionNames[i]) return true;
    return false;
  };
  VkPhysicalDeviceFeatures core =
      created_with.pEnabledFeatures ? *created_with.pEnabledFeatures : VkPhysicalDeviceFeatures{};
  // The 1.3 features, gathered from the 1.3 struct or from the structs they were promoted from.
  VkPhysicalDeviceVulkan13Features f13{};
  const VkPhysicalDeviceExtendedDynamicState2FeaturesEXT* eds2 = nullptr;
  const VkPhysicalDeviceExtendedDynamicState3FeaturesEXT* eds3 = nullptr;
  const VkPhysicalDeviceTransformFeedbackFeaturesEXT* xfb = nullptr;
  for (auto* next = static_cast<const VkBaseInStructure*>(created_with.pNext); next; next = next->pNext) {
    switch (next->sType) {
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2:
        core = reinterpret_cast<const VkPhysicalDeviceFeatures2*>(next)->features;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES: {
        const auto* v = reinterpret_cast<const VkPhysicalDeviceVulkan13Features*>(next);
        f13.dynamicRendering |= v->dynamicRendering;
        f13.synchronization2 |= v->synchronization2;
        f13.maintenance4 |= v->maintenance4;
        break;
      }
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES:
        f13.dynamicRendering |=
            reinterpret_cast<const VkPhysicalDeviceDynamicRenderingFeatures*>(next)->dynamicRendering;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES:
        f13.synchronization2 |=
            reinterpret_cast<const VkPhysicalDeviceSynchronization2Features*>(next)->synchronization2;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES:
        f13.maintenance4 |= reinterpret_cast<const VkPhysicalDeviceMaintenance4Features*>(next)->maintenance4;
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_2_FEATURES_EXT:
        if (enabled(kEds2)) eds2 = reinterpret_cast<const VkPhysicalDeviceExtendedDynamicState2FeaturesEXT*>(next);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTENDED_DYNAMIC_STATE_3_FEATURES_EXT:
        if (enabled(kEds3)) eds3 = reinterpret_cast<const VkPhysicalDeviceExtendedDynamicState3FeaturesEXT*>(next);
        break;
      case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT:
        // Drawable by byte count only where the device says so (query_device).
        if (enabled(kTransformFeedback) && support.features.transform_feedback)
          xfb = reinterpret_cast<const VkPhysicalDeviceTransformFeedbackFeaturesEXT*>(next);
        break;
      default: break;
    }
  }
  const bool v13 = support.info.api_version >= VK_API_VERSION_1_3;
  return features_from(core, v13 ? &f13 : nullptr, eds2, eds3, enabled(kPushDescriptor), xfb);
}

}  // namespace fx::vk
