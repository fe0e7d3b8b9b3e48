// DeviceCaps from Vulkan: a live physical device or a `vulkaninfo --json` report. Both
// paths fill the same VulkanFacts so they derive identical caps for the same device.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <nlohmann/json.hpp>

#include "fx/ascii_case.h"
#include "fx/select/caps_sources.h"

namespace fx {
namespace {

// The raw numbers the D3D-level caps are derived from.
struct VulkanFacts {
  std::string name;
  uint32_t api_version = 0;
  std::string device_type;
  uint32_t max_sampled_images = 0, max_samplers = 0, max_uniform_range = 0;
  uint32_t max_vertex_outputs = 0, max_fragment_inputs = 0;
  uint32_t max_image_2d = 0, max_image_3d = 0, max_image_cube = 0, max_color_attachments = 0;
  std::vector<std::string> features, extensions;
  std::vector<FormatSupport> formats;
};

struct CoreFeatureRow {
  const char* name;
  size_t offset;
};
#define FX_CORE_FEATURE(n) \
  CoreFeatureRow { #n, offsetof(VkPhysicalDeviceFeatures, n) }
constexpr CoreFeatureRow kCoreFeatures[] = {
    FX_CORE_FEATURE(robustBufferAccess),
    FX_CORE_FEATURE(fullDrawIndexUint32),
    FX_CORE_FEATURE(imageCubeArray),
    FX_CORE_FEATURE(independentBlend),
    FX_CORE_FEATURE(geometryShader),
    FX_CORE_FEATURE(tessellationShader),
    FX_CORE_FEATURE(sampleRateShading),
    FX_CORE_FEATURE(dualSrcBlend),
    FX_CORE_FEATURE(logicOp),
    FX_CORE_FEATURE(multiDrawIndirect),
    FX_CORE_FEATURE(drawIndirectFirstInstance),
    FX_CORE_FEATURE(depthClamp),
    FX_CORE_FEATURE(depthBiasClamp),
    FX_CORE_FEATURE(fillModeNonSolid),
    FX_CORE_FEATURE(depthBounds),
    FX_CORE_FEATURE(wideLines),
    FX_CORE_FEATURE(largePoints),
    FX_CORE_FEATURE(alphaToOne),
    FX_CORE_FEATURE(multiViewport),
    FX_CORE_FEATURE(samplerAnisotropy),
    FX_CORE_FEATURE(textureCompressionETC2),
    FX_CORE_FEATURE(textureCompressionASTC_LDR),
    FX_CORE_FEATURE(textureCompressionBC),
    FX_CORE_FEATURE(occlusionQueryPrecise),
    FX_CORE_FEATURE(pipelineStatisticsQuery),
    FX_CORE_FEATURE(vertexPipelineStoresAndAtomics),
    FX_CORE_FEATURE(fragmentStoresAndAtomics),
    FX_CORE_FEATURE(shaderTessellationAndGeometryPointSize),
    FX_CORE_FEATURE(shaderImageGatherExtended),
    FX_CORE_FEATURE(shaderStorageImageExtendedFormats),
    FX_CORE_FEATURE(shaderStorageImageMultisample),
    FX_CORE_FEATURE(shaderStorageImageReadWithoutFormat),
    FX_CORE_FEATURE(shaderStorageImageWriteWithoutFormat),
    FX_CORE_FEATURE(shaderUniformBufferArrayDynamicIndexing),
    FX_CORE_FEATURE(shaderSampledImageArrayDynamicIndexing),
    FX_CORE_FEATURE(shaderStorageBufferArrayDynamicIndexing),
    FX_CORE_FEATURE(shaderStorageImageArrayDynamicIndexing),
    FX_CORE_FEATURE(shaderClipDistance),
    FX_CORE_FEATURE(shaderCullDistance),
    FX_CORE_FEATURE(shaderFloat64),
    FX_CORE_FEATURE(shaderInt64),
    FX_CORE_FEATURE(shaderInt16),
    FX_CORE_FEATURE(shaderResourceResidency),
    FX_CORE_FEATURE(shaderResourceMinLod),
    FX_CORE_FEATURE(sparseBinding),
    FX_CORE_FEATURE(sparseResidencyBuffer),
    FX_CORE_FEATURE(sparseResidencyImage2D),
    FX_CORE_FEATURE(sparseResidencyImage3D),
    FX_CORE_FEATURE(sparseResidency2Samples),
    FX_CORE_FEATURE(sparseResidency4Samples),
    FX_CORE_FEATURE(sparseResidency8Samples),
    FX_CORE_FEATURE(sparseResidency16Samples),
    FX_CORE_FEATURE(sparseResidencyAliased),
    FX_CORE_FEATURE(variableMultisampleRate),
    FX_CORE_FEATURE(inheritedQueries),
};
#undef FX_CORE_FEATURE
static_assert(std::size(kCoreFeatures) * sizeof(VkBool32) == sizeof(VkPhysicalDeviceFeatures),
              "every core feature has a row");

// Formats effects name in render targets and textures; the rest of the 180+ are noise.
struct FormatRow {
  VkFormat format;
  const char* name;
};
constexpr FormatRow kFormats[] = {
    {VK_FORMAT_R8_UNORM, "R8_UNORM"},
    {VK_FORMAT_R8G8_UNORM, "R8G8_UNORM"},
    {VK_FORMAT_R8G8B8A8_UNORM, "R8G8B8A8_UNORM"},
    {VK_FORMAT_R8G8B8A8_SRGB, "R8G8B8A8_SRGB"},
    {VK_FORMAT_B8G8R8A8_UNORM, "B8G8R8A8_UNORM"},
    {VK_FORMAT_B8G8R8A8_SRGB, "B8G8R8A8_SRGB"},
    {VK_FORMAT_R5G6B5_UNORM_PACK16, "R5G6B5_UNORM_PACK16"},
    {VK_FORMAT_A2B10G10R10_UNORM_PACK32, "A2B10G10R10_UNORM_PACK32"},
    {VK_FORMAT_B10G11R11_UFLOAT_PACK32, "B10G11R11_UFLOAT_PACK32"},
    {VK_FORMAT_R16_SFLOAT, "R16_SFLOAT"},
    {VK_FORMAT_R16G16_SFLOAT, "R16G16_SFLOAT"},
    {VK_FORMAT_R16G16B16A16_SFLOAT, "R16G16B16A16_SFLOAT"},
    {VK_FORMAT_R16G16B16A16_UNORM, "R16G16B16A16_UNORM"},
    {VK_FORMAT_R32_SFLOAT, "R32_SFLOAT"},
    {VK_FORMAT_R32G32_SFLOAT, "R32G32_SFLOAT"},
    {VK_FORMAT_R32G32B32A32_SFLOAT, "R32G32B32A32_SFLOAT"},
    {VK_FORMAT_D16_UNORM, "D16_UNORM"},
    {VK_FORMAT_D24_UNORM_S8_UINT, "D24_UNORM_S8_UINT"},
    {VK_FORMAT_D32_SFLOAT, "D32_SFLOAT"},
    {VK_FORMAT_D32_SFLOAT_S8_UINT, "D32_SFLOAT_S8_UINT"},
    {VK_FORMAT_BC1_RGBA_UNORM_BLOCK, "BC1_RGBA_UNORM_BLOCK"},
    {VK_FORMAT_BC2_UNORM_BLOCK, "BC2_UNORM_BLOCK"},
    {VK_FORMAT_BC3_UNORM_BLOCK, "BC3_UNORM_BLOCK"},
    {VK_FORMAT_BC5_UNORM_BLOCK, "BC5_UNORM_BLOCK"},
    {VK_FORMAT_BC7_UNORM_BLOCK, "BC7_UNORM_BLOCK"},
};

struct FormatBitRow {
  VkFormatFeatureFlagBits bit;
  const char* json_name;
  bool FormatSupport::*member;
};
constexpr FormatBitRow kFormatBits[] = {
    {VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT, "VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT", &FormatSupport::sampled},
    {VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT, "VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT",
     &FormatSupport::filter_linear},
    {VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT, "VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT",
     &FormatSupport::color_attachment},
    {VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT, "VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT",
     &FormatSupport::blend},
    {VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT, "VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT",
     &FormatSupport::depth_stencil},
    {VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT, "VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT", &FormatSupport::storage},
};

// Vulkan 1.2 / 1.3 features worth recording; read from the VulkanNNFeatures structs.
constexpr const char* kVulkan12Features[] = {"timelineSemaphore", "scalarBlockLayout", "bufferDeviceAddress",
                                             "shaderFloat16", "descriptorIndexing"};
constexpr const char* kVulkan13Features[] = {"dynamicRendering", "synchronization2", "maintenance4"};

std::string device_type_name(std::string_view vk_name) {
  constexpr std::string_view prefix = "VK_PHYSICAL_DEVICE_TYPE_";
  if (vk_name.starts_with(prefix)) vk_name.remove_prefix(prefix.size());
  return ascii_lower(vk_name);
}

const char* device_type_name(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
    default: return "other";
  }
}

bool has(const std::vector<std::string>& sorted, std::string_view name) {
  return std::binary_search(sorted.begin(), sorted.end(), name);
}

DeviceCaps derive_caps(VulkanFacts facts) {
  DeviceCaps caps;
  caps.name = facts.name;
  caps.description = "Vulkan " + std::to_string(VK_API_VERSION_MAJOR(facts.api_version)) + "." +
                     std::to_string(VK_API_VERSION_MINOR(facts.api_version)) + " " + facts.device_type + " device";
  caps.generation = CapsGeneration::vulkan;
  std::sort(facts.features.begin(), facts.features.end());
  // What glslang's HLSL front end compiles, and shader model 1 assembly, which the legacy
  // layer translates to HLSL (fx/emulation/assembly.h).
  for (const char* p : {"vs_1_0", "vs_1_1", "ps_1_0", "ps_1_1", "ps_1_2", "ps_1_3", "ps_1_4", "vs_2_0", "ps_2_0",
                        "vs_3_0", "ps_3_0", "vs_4_0", "ps_4_0", "vs_4_1", "ps_4_1", "vs_5_0", "ps_5_0", "cs_5_0"})
    caps.shader_profiles.push_back(p);
  if (has(facts.features, "geometryShader"))
    for (const char* p : {"gs_4_0", "gs_4_1", "gs_5_0"}) caps.shader_profiles.push_back(p);
  if (has(facts.features, "tessellationShader"))
    for (const char* p : {"hs_5_0", "ds_5_0"}) caps.shader_profiles.push_back(p);
  // glslang rejects desktop GLSL below 140 for Vulkan SPIR-V.
  for (int v : {140, 150, 330, 400, 410, 420, 430, 440, 450, 460})
    caps.shader_profiles.push_back("glsl_" + std::to_string(v));

  caps.limits.samplers = facts.max_samplers;
  caps.limits.simultaneous_textures = std::min(facts.max_sampled_images, facts.max_samplers);
  caps.limits.uniform_bytes = facts.max_uniform_range;
  caps.limits.interpolators = std::min(facts.max_vertex_outputs, facts.max_fragment_inputs) / 4;
  caps.limits.texture_size = facts.max_image_2d;
  caps.limits.render_targets = facts.max_color_attachments;

  caps.vulkan.present = true;
  caps.vulkan.api_version = facts.api_version;
  caps.vulkan.device_type = facts.device_type;
  caps.vulkan.features = std::move(facts.features);
  caps.vulkan.extensions = std::move(facts.extensions);
  caps.vulkan.formats = std::move(facts.formats);
  normalize(caps);

  // Texture-stage ops and alpha test are fixed-function: false until fxkit emulates them.
  CapsFeatures& f = caps.features;
  f.cube_maps = facts.max_image_cube > 0;
  f.volume_textures = facts.max_image_3d > 0;
  const FormatSupport* half4 = find_format(caps, "R16G16B16A16_SFLOAT");
  const FormatSupport* float4 = find_format(caps, "R32G32B32A32_SFLOAT");
  f.float_textures = (half4 && half4->sampled) || (float4 && float4->sampled);
  f.anisotropic_filtering = has(caps.vulkan.features, "samplerAnisotropy");
  f.separate_alpha_blend = true;  // core: separate colour/alpha blend factors
  // Texture stages (every D3DTOP, DOTPRODUCT3 and SUBTRACT included) are generated shaders.
  f.fixed_function_stages = f.dot3 = f.subtract = true;
  f.two_sided_stencil = true;  // core: front and back stencil state
  return caps;
}

std::vector<std::string> string_list(const nlohmann::json& j) {
  std::vector<std::string> out;
  if (j.is_array())
    for (const auto& s : j)
      if (s.is_string()) out.push_back(s.get<std::string>());
  return out;
}

uint32_t u32(const nlohmann::json& obj, const char* key) {
  auto it = obj.find(key);
  if (it == obj.end() || !(it->is_number_unsigned() || it->is_number_integer())) return 0;
  int64_t v = it->get<int64_t>();
  return v < 0 ? 0 : uint32_t(std::min<int64_t>(v, UINT32_MAX));
}

void read_bool_members(const nlohmann::json& features, const char* struct_name, std::span<const char* const> names,
                       std::vector<std::string>& out) {
  auto it = features.find(struct_name);
  if (it == features.end() || !it->is_object()) return;
  for (const char* n : names) {
    auto v = it->find(n);
    if (v != it->end() && v->is_boolean() && v->get<bool>()) out.push_back(n);
  }
}

}  // namespace

DeviceCaps caps_from_physical_device(VkPhysicalDevice device) {
  VulkanFacts facts;
  VkPhysicalDeviceProperties props{};
  vkGetPhysicalDeviceProperties(device, &props);
  facts.name = props.deviceName;
  facts.api_version = props.apiVersion;
  facts.device_type = device_type_name(props.deviceType);
  const VkPhysicalDeviceLimits& l = props.limits;
  facts.max_sampled_images = l.maxPerStageDescriptorSampledImages;
  facts.max_samplers = l.maxPerStageDescriptorSamplers;
  facts.max_uniform_range = l.maxUniformBufferRange;
  facts.max_vertex_outputs = l.maxVertexOutputComponents;
  facts.max_fragment_inputs = l.maxFragmentInputComponents;
  facts.max_image_2d = l.maxImageDimension2D;
  facts.max_image_3d = l.maxImageDimension3D;
  facts.max_image_cube = l.maxImageDimensionCube;
  facts.max_color_attachments = l.maxColorAttachments;

  VkPhysicalDeviceVulkan13Features v13{};
  v13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  VkPhysicalDeviceVulkan12Features v12{};
  v12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
  VkPhysicalDeviceFeatures2 f2{};
  f2.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  // Chaining a struct newer than the device's version is invalid usage.
  if (props.apiVersion >= VK_API_VERSION_1_2) {
    f2.pNext = &v12;
    if (props.apiVersion >= VK_API_VERSION_1_3) v12.pNext = &v13;
    vkGetPhysicalDeviceFeatures2(device, &f2);
  } else {
    vkGetPhysicalDeviceFeatures(device, &f2.features);
  }
  const auto* core = reinterpret_cast<const unsigned char*>(&f2.features);
  for (const auto& row : kCoreFeatures) {
    VkBool32 on = VK_FALSE;
    std::memcpy(&on, core + row.offset, sizeof on);
    if (on) facts.features.push_back(row.name);
  }
  auto add_if = [&](bool on, const char* name) {
    if (on) facts.features.push_back(name);
  };
  if (props.apiVersion >= VK_API_VERSION_1_2) {
    add_if(v12.timelineSemaphore, "timelineSemaphore");
    add_if(v12.scalarBlockLayout, "scalarBlockLayout");
    add_if(v12.bufferDeviceAddress, "bufferDeviceAddress");
    add_if(v12.shaderFloat16, "shaderFloat16");
    add_if(v12.descriptorIndexing, "descriptorIndexing");
  }
  if (props.apiVersion >= VK_API_VERSION_1_3) {
    add_if(v13.dynamicRendering, "dynamicRendering");
    add_if(v13.synchronization2, "synchronization2");
    add_if(v13.maintenance4, "maintenance4");
  }

  uint32_t count = 0;
  if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr) == VK_SUCCESS) {
    std::vector<VkExtensionProperties> exts(count);
    if (vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data()) >= VK_SUCCESS) {
      exts.resize(count);
      for (const auto& e : exts) facts.extensions.push_back(e.extensionName);
    }
  }

  for (const auto& row : kFormats) {
    VkFormatProperties fp{};
    vkGetPhysicalDeviceFormatProperties(device, row.format, &fp);
    FormatSupport fs{.format = row.name};
    for (const auto& bit : kFormatBits) fs.*(bit.member) = (fp.optimalTilingFeatures & bit.bit) != 0;
    facts.formats.push_back(std::move(fs));
  }
  return derive_caps(std::move(facts));
}

std::optional<DeviceCaps> caps_from_vulkaninfo_json(const nlohmann::json& report, DiagnosticSink& sink) {
  auto missing = [&](const std::string& what) {
    sink.error("caps-vulkaninfo", {}, "vulkaninfo report has no " + what);
  };
  if (!report.is_object()) {
    missing("top-level object");
    return std::nullopt;
  }
  // `vulkaninfo --json` writes a Vulkan profiles document: capabilities.<block>.{...}.
  auto caps_it = report.find("capabilities");
  if (caps_it == report.end() || !caps_it->is_object()) {
    missing("'capabilities' object");
    return std::nullopt;
  }
  const nlohmann::json* device = nullptr;
  for (const auto& [key, block] : caps_it->items()) {
    if (block.is_object() && block.contains("properties")) {
      device = &block;
      break;
    }
  }
  if (!device) {
    missing("device block with 'properties'");
    return std::nullopt;
  }
  const nlohmann::json empty = nlohmann::json::object();
  auto section = [&](const char* key) -> const nlohmann::json& {
    auto it = device->find(key);
    if (it == device->end() || !it->is_object()) {
      missing(std::string("'") + key + "' section");
      return empty;
    }
    return *it;
  };
  const nlohmann::json& properties = section("properties");
  auto props_it = properties.find("VkPhysicalDeviceProperties");
  if (props_it == properties.end() || !props_it->is_object()) {
    missing("VkPhysicalDeviceProperties");
    return std::nullopt;
  }
  const nlohmann::json& props = *props_it;
  VulkanFacts facts;
  if (auto it = props.find("deviceName"); it != props.end() && it->is_string()) facts.name = it->get<std::string>();
  facts.api_version = u32(props, "apiVersion");
  if (auto it = props.find("deviceType"); it != props.end() && it->is_string())
    facts.device_type = device_type_name(it->get<std::string>());
  auto limits_it = props.find("limits");
  const nlohmann::json& limits = limits_it != props.end() && limits_it->is_object() ? *limits_it : empty;
  if (limits.empty()) missing("VkPhysicalDeviceProperties.limits");
  facts.max_sampled_images = u32(limits, "maxPerStageDescriptorSampledImages");
  facts.max_samplers = u32(limits, "maxPerStageDescriptorSamplers");
  facts.max_uniform_range = u32(limits, "maxUniformBufferRange");
  facts.max_vertex_outputs = u32(limits, "maxVertexOutputComponents");
  facts.max_fragment_inputs = u32(limits, "maxFragmentInputComponents");
  facts.max_image_2d = u32(limits, "maxImageDimension2D");
  facts.max_image_3d = u32(limits, "maxImageDimension3D");
  facts.max_image_cube = u32(limits, "maxImageDimensionCube");
  facts.max_color_attachments = u32(limits, "maxColorAttachments");

  const nlohmann::json& features = section("features");
  std::vector<const char*> core_names;
  for (const auto& row : kCoreFeatures) core_names.push_back(row.name);
  read_bool_members(features, "VkPhysicalDeviceFeatures", core_names, facts.features);
  if (facts.api_version >= VK_API_VERSION_1_2)
    read_bool_members(features, "VkPhysicalDeviceVulkan12Features", kVulkan12Features, facts.features);
  if (facts.api_version >= VK_API_VERSION_1_3)
    read_bool_members(features, "VkPhysicalDeviceVulkan13Features", kVulkan13Features, facts.features);

  for (const auto& [name, version] : section("extensions").items()) facts.extensions.push_back(name);

  const nlohmann::json& formats = section("formats");
  for (const auto& row : kFormats) {
    FormatSupport fs{.format = row.name};
    auto it = formats.find(std::string("VK_FORMAT_") + row.name);
    if (it != formats.end() && it->is_object()) {
      auto fp = it->find("VkFormatProperties");
      if (fp != it->end() && fp->is_object() && fp->contains("optimalTilingFeatures")) {
        std::vector<std::string> bits = string_list(*fp->find("optimalTilingFeatures"));
        for (const auto& bit : kFormatBits)
          fs.*(bit.member) = std::find(bits.begin(), bits.end(), bit.json_name) != bits.end();
      }
    }
    facts.formats.push_back(std::move(fs));
  }
  return derive_caps(std::move(facts));
}

std::optional<DeviceCaps> caps_from_vulkaninfo_json(const nlohmann::json& report) {
  DiagnosticSink sink;
  return caps_from_vulkaninfo_json(report, sink);
}

}  // namespace fx
