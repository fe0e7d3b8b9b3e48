// The SPIR-V capability -> Vulkan feature table, and the capabilities a module declares.
#include "fx/vulkan/shader_capabilities.h"

#include <vulkan/vulkan.h>

#include <algorithm>

namespace fx {
namespace {

#define FX_NEEDS(cap, name, feature, written_as) \
  ShaderCapabilityFeature { cap, name, #feature, offsetof(VkPhysicalDeviceFeatures, feature), written_as }
// Capability numbers from the SPIR-V spec (spirv.hpp's Capability enum). Left out: those a
// Vulkan 1.3 device may also meet without the feature (StorageImageReadWithoutFormat,
// StorageImageWriteWithoutFormat, StorageImageExtendedFormats), those of newer structs, and
// GeometryPointSize / TessellationPointSize: with shaderTessellationAndGeometryPointSize
// enabled every geometry shader that emits points must write PointSize
// (VUID-VkGraphicsPipelineCreateInfo-Geometry-07725), and Direct3D 10's stream-out
// geometry shaders (particles) never do, since Direct3D 10 has no point size.
constexpr ShaderCapabilityFeature kRows[] = {
    FX_NEEDS(2, "Geometry", geometryShader, "a geometry shader"),
    FX_NEEDS(3, "Tessellation", tessellationShader, "tessellation"),
    FX_NEEDS(10, "Float64", shaderFloat64, "double"),
    FX_NEEDS(11, "Int64", shaderInt64, "64-bit integers"),
    FX_NEEDS(22, "Int16", shaderInt16, "16-bit integers"),
    FX_NEEDS(25, "ImageGatherExtended", shaderImageGatherExtended, "Gather with an offset or of a component"),
    FX_NEEDS(27, "StorageImageMultisample", shaderStorageImageMultisample, "a multisampled RW texture"),
    FX_NEEDS(28, "UniformBufferArrayDynamicIndexing", shaderUniformBufferArrayDynamicIndexing,
             "a constant buffer array indexed dynamically"),
    FX_NEEDS(29, "SampledImageArrayDynamicIndexing", shaderSampledImageArrayDynamicIndexing,
             "a texture array indexed dynamically"),
    FX_NEEDS(30, "StorageBufferArrayDynamicIndexing", shaderStorageBufferArrayDynamicIndexing,
             "a structured buffer array indexed dynamically"),
    FX_NEEDS(31, "StorageImageArrayDynamicIndexing", shaderStorageImageArrayDynamicIndexing,
             "an RW texture array indexed dynamically"),
    FX_NEEDS(32, "ClipDistance", shaderClipDistance, "SV_ClipDistance"),
    FX_NEEDS(33, "CullDistance", shaderCullDistance, "SV_CullDistance"),
    FX_NEEDS(34, "ImageCubeArray", imageCubeArray, "an RW cube texture array"),
    FX_NEEDS(35, "SampleRateShading", sampleRateShading, "SV_SampleIndex or sample interpolation"),
    FX_NEEDS(41, "SparseResidency", shaderResourceResidency, "a residency status (CheckAccessFullyMapped)"),
    FX_NEEDS(42, "MinLod", shaderResourceMinLod, "a sample with a level-of-detail clamp"),
    FX_NEEDS(45, "SampledCubeArray", imageCubeArray, "TextureCubeArray"),
    FX_NEEDS(48, "ImageMSArray", shaderStorageImageMultisample, "a multisampled RW texture array"),
    FX_NEEDS(52, "InterpolationFunction", sampleRateShading, "EvaluateAttributeAt*"),
    FX_NEEDS(57, "MultiViewport", multiViewport, "SV_ViewportArrayIndex"),
};
#undef FX_NEEDS

constexpr uint32_t kMagic = 0x07230203;
constexpr uint32_t kOpCapability = 17;
constexpr size_t kHeaderWords = 5;

}  // namespace

std::span<const ShaderCapabilityFeature> shader_capability_features() { return kRows; }

std::vector<const ShaderCapabilityFeature*> features_needed_by(std::span<const uint32_t> spirv) {
  std::vector<const ShaderCapabilityFeature*> out;
  if (spirv.size() < kHeaderWords || spirv[0] != kMagic) return out;
  std::vector<uint32_t> declared;
  for (size_t i = kHeaderWords; i < spirv.size();) {
    const uint32_t count = spirv[i] >> 16, opcode = spirv[i] & 0xffffu;
    if (count == 0 || i + count > spirv.size()) break;
    // Capabilities come first in a module; the first other instruction ends them.
    if (opcode != kOpCapability) break;
    if (count >= 2) declared.push_back(spirv[i + 1]);
    i += count;
  }
  for (const ShaderCapabilityFeature& row : kRows)
    if (std::find(declared.begin(), declared.end(), row.capability) != declared.end()) out.push_back(&row);
  return out;
}

}  // namespace fx
