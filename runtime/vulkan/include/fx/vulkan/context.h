// fx::vk::Context: a Vulkan 1.3 instance, physical device, device and one graphics queue,
// either created headless by fxkit (owned) or wrapped from the application (borrowed),
// plus what the device can do and what the validation layers said.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/vulkan/device_selection.h"

namespace fx::vk {

// One message from the validation layers (or the loader/driver through debug utils).
struct ValidationMessage {
  Severity severity = Severity::note;  // error / warning / note (info, verbose)
  int32_t id_number = 0;
  std::string id_name;  // e.g. "VUID-vkCmdDraw-None-02699"
  std::string text;
};

// Options for Context::headless().
struct ContextOptions {
  // Enables VK_LAYER_KHRONOS_validation and a debug-utils messenger that records messages.
  bool validation = false;
  // Also records INFO-severity validation messages (noisy; off by default).
  bool validation_info = false;
  // Forces a device: an index into vkEnumeratePhysicalDevices or a case-insensitive name
  // substring. Empty: use the FXKIT_DEVICE environment variable, else the best-ranked device.
  std::string device;
  // Extra device extensions to enable; missing ones are an error ("vk-extension-missing").
  std::vector<std::string> device_extensions;
  std::string application_name = "fxkit";
  // Called for each validation message as it is recorded (also while the context is being
  // destroyed, when leaked objects are reported), from whichever thread triggered it.
  std::function<void(const ValidationMessage&)> on_validation_message;
};

// Which optional Vulkan features the context has ENABLED on its device (for a wrapped
// device: what the physical device supports, unless the application said otherwise).
struct DeviceFeatures {
  bool dynamic_rendering = false;          // Vulkan 1.3 core, always on for headless contexts
  bool synchronization2 = false;           // Vulkan 1.3 core
  bool extended_dynamic_state = false;     // EDS1 (cull mode, depth test, topology... : 1.3 core)
  bool extended_dynamic_state2 = false;    // EDS2 base (rasterizer discard, depth bias enable)
  bool eds2_logic_op = false;              // vkCmdSetLogicOpEXT
  bool eds2_patch_control_points = false;  // vkCmdSetPatchControlPointsEXT
  // VK_EXT_extended_dynamic_state3: each member is one dynamic state the device accepts.
  struct Eds3 {
    bool tessellation_domain_origin = false, depth_clamp_enable = false, polygon_mode = false,
         rasterization_samples = false, sample_mask = false, alpha_to_coverage_enable = false,
         alpha_to_one_enable = false, logic_op_enable = false, color_blend_enable = false, color_blend_equation = false,
         color_write_mask = false, rasterization_stream = false, conservative_rasterization_mode = false,
         extra_primitive_overestimation_size = false, depth_clip_enable = false, sample_locations_enable = false,
         color_blend_advanced = false, provoking_vertex_mode = false, line_rasterization_mode = false,
         line_stipple_enable = false, depth_clip_negative_one_to_one = false, viewport_w_scaling_enable = false,
         viewport_swizzle = false, coverage_to_color_enable = false, coverage_to_color_location = false,
         coverage_modulation_mode = false, coverage_modulation_table_enable = false, coverage_modulation_table = false,
         coverage_reduction_mode = false, representative_fragment_test_enable = false,
         shading_rate_image_enable = false;
    bool any() const;
  } eds3;
  bool push_descriptor = false;  // VK_KHR_push_descriptor
  bool sampler_anisotropy = false;
  bool fill_mode_non_solid = false;  // wireframe / point fill modes
  bool depth_clamp = false;
  bool depth_bias_clamp = false;  // DepthBiasClamp != 0; without it the bias is unclamped
  bool independent_blend = false;
  bool geometry_shader = false;
  bool tessellation_shader = false;
  bool texture_compression_bc = false;
  // What HLSL resources need where the device has it: TextureCubeArray (SampledCubeArray),
  // Gather with offsets, RW resources written from pixel and vertex shaders.
  bool image_cube_array = false;
  bool image_gather_extended = false;
  bool fragment_stores_and_atomics = false;
  bool vertex_pipeline_stores_and_atomics = false;
  // Vulkan 1.3 maintenance4: among others, a vertex output the next stage does not read is
  // well defined (Direct3D links stages by semantic), so the layer does not warn about it.
  bool maintenance4 = false;
  // VK_EXT_transform_feedback with its transformFeedback feature (and transformFeedbackDraw,
  // so captured vertices can be drawn by their byte count): stream output, docs/rendering.md.
  bool transform_feedback = false;
  // The core features SPIR-V capabilities need (fx/vulkan/shader_capabilities.h: clip and
  // cull distances, 64-bit floats, sample-rate shading, ...) that are enabled, named as
  // VkPhysicalDeviceFeatures names them; sorted.
  std::vector<std::string> shader_features;
  bool has_shader_feature(std::string_view name) const;
};

// Identity and limits of the physical device.
struct DeviceInfo {
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  uint32_t api_version = 0;
  uint32_t driver_version = 0;
  uint32_t vendor_id = 0, device_id = 0;
  std::array<uint8_t, VK_UUID_SIZE> uuid{};
  uint32_t index = 0;  // position in vkEnumeratePhysicalDevices
  VkPhysicalDeviceLimits limits{};
  uint32_t push_descriptor_max = 0;  // maxPushDescriptors (0 without the extension)
  // maxTransformFeedbackBufferDataStride (0 without VK_EXT_transform_feedback).
  uint32_t transform_feedback_stride_max = 0;
};

// Entry points that are not core Vulkan 1.3, loaded per device; null when unavailable.
struct DeviceFunctions {
  PFN_vkCmdPushDescriptorSetKHR push_descriptor_set = nullptr;
  PFN_vkCmdSetLogicOpEXT set_logic_op = nullptr;
  PFN_vkCmdSetPatchControlPointsEXT set_patch_control_points = nullptr;
  PFN_vkCmdSetPolygonModeEXT set_polygon_mode = nullptr;
  PFN_vkCmdSetDepthClampEnableEXT set_depth_clamp_enable = nullptr;
  PFN_vkCmdSetRasterizationSamplesEXT set_rasterization_samples = nullptr;
  PFN_vkCmdSetSampleMaskEXT set_sample_mask = nullptr;
  PFN_vkCmdSetAlphaToCoverageEnableEXT set_alpha_to_coverage_enable = nullptr;
  PFN_vkCmdSetAlphaToOneEnableEXT set_alpha_to_one_enable = nullptr;
  PFN_vkCmdSetLogicOpEnableEXT set_logic_op_enable = nullptr;
  PFN_vkCmdSetColorBlendEnableEXT set_color_blend_enable = nullptr;
  PFN_vkCmdSetColorBlendEquationEXT set_color_blend_equation = nullptr;
  PFN_vkCmdSetColorWriteMaskEXT set_color_write_mask = nullptr;
  PFN_vkCmdSetDepthClipEnableEXT set_depth_clip_enable = nullptr;
  PFN_vkCmdSetProvokingVertexModeEXT set_provoking_vertex_mode = nullptr;
  PFN_vkCmdSetLineRasterizationModeEXT set_line_rasterization_mode = nullptr;
  PFN_vkCmdSetTessellationDomainOriginEXT set_tessellation_domain_origin = nullptr;
  PFN_vkCmdBindTransformFeedbackBuffersEXT bind_transform_feedback_buffers = nullptr;
  PFN_vkCmdBeginTransformFeedbackEXT begin_transform_feedback = nullptr;
  PFN_vkCmdEndTransformFeedbackEXT end_transform_feedback = nullptr;
  PFN_vkCmdDrawIndirectByteCountEXT draw_indirect_byte_count = nullptr;
  PFN_vkSetDebugUtilsObjectNameEXT set_object_name = nullptr;  // only with validation
};

class ValidationLog;  // thread-safe message store shared with the messenger callback

class Context {
 public:
  // Creates an owned instance + device + graphics queue. Reports "vk-*" diagnostics and
  // returns nullopt on failure; never throws.
  static std::optional<Context> headless(const ContextOptions& options, DiagnosticSink& sink);

  // Borrows the application's objects: the destructor destroys nothing. `enabled` says which
  // features the application enabled; without it, the physical device's support is assumed.
  // Non-core entry points are loaded if the device exposes them.
  static Context wrap(VkInstance instance, VkPhysicalDevice physical_device, VkDevice device, VkQueue queue,
                      uint32_t queue_family, std::optional<DeviceFeatures> enabled = std::nullopt);

  Context(Context&& other) noexcept;
  Context& operator=(Context&& other) noexcept;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  // The graphics queue. Vulkan requires external synchronisation: submit from one thread.
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  bool owns_handles() const { return owned_; }

  const DeviceInfo& info() const { return info_; }
  const DeviceFeatures& features() const { return features_; }
  const DeviceFunctions& functions() const { return functions_; }
  const VkPhysicalDeviceMemoryProperties& memory_properties() const { return memory_; }

  // Format support (optimal tiling) for `features` (e.g. COLOR_ATTACHMENT_BIT).
  bool supports_format(VkFormat format, VkFormatFeatureFlags features) const;
  // First of D32_SFLOAT, D24_UNORM_S8_UINT, D32_SFLOAT_S8_UINT, D16_UNORM usable as a
  // depth attachment; `need_stencil` skips stencil-less formats. UNDEFINED if none.
  VkFormat best_depth_format(bool need_stencil = false) const;

  // Validation is active (layer found and messenger attached).
  bool validation_enabled() const;
  // Copies of all recorded messages, oldest first.
  std::vector<ValidationMessage> validation_messages() const;
  size_t validation_error_count() const;
  size_t validation_warning_count() const;
  void clear_validation_messages();
  // Moves recorded validation messages into `sink` as "vk-validation" diagnostics.
  void drain_validation_into(DiagnosticSink& sink);

  // Names a Vulkan object for validation messages and debuggers; no-op without debug utils.
  void set_object_name(VkObjectType type, uint64_t handle, const char* name) const;

  // Waits until the device is idle (used before destroying in-flight objects).
  void wait_idle() const;

 private:
  Context() = default;
  void destroy();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  bool owned_ = false;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  std::unique_ptr<ValidationLog> log_;  // stable address: the messenger callback points at it
  DeviceInfo info_;
  DeviceFeatures features_;
  DeviceFunctions functions_;
  VkPhysicalDeviceMemoryProperties memory_{};

  friend struct ContextBuilder;
};

// What `created_with` (the VkDeviceCreateInfo the application passed to vkCreateDevice)
// enabled: its pEnabledFeatures or VkPhysicalDeviceFeatures2, the 1.3 feature structs (or
// those they were promoted from) and the extensions fxkit uses. For Context::wrap.
DeviceFeatures enabled_features(VkPhysicalDevice physical_device, const VkDeviceCreateInfo& created_with);

// "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other".
const char* to_string(VkPhysicalDeviceType type);
// Name of a VkResult ("VK_ERROR_DEVICE_LOST"); "VkResult(<n>)" if unknown.
std::string to_string(VkResult result);

}  // namespace fx::vk
