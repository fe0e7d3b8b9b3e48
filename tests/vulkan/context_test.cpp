// Context creation, feature queries, validation capture and wrapping.
#include "fx/vulkan/context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "fx/binding/context_caps.h"
#include "fx/select/caps_sources.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/shader_capabilities.h"
#include "vulkan_fixture.h"

namespace fx::vk {
namespace {

using testing::describe;
using testing::describe_messages;

class ContextTest : public testing::VulkanTest {};

TEST_F(ContextTest, HeadlessContextHasDeviceQueueAndVulkan13) {
  const Context& c = ctx();
  EXPECT_NE(c.instance(), VK_NULL_HANDLE);
  EXPECT_NE(c.physical_device(), VK_NULL_HANDLE);
  EXPECT_NE(c.device(), VK_NULL_HANDLE);
  EXPECT_NE(c.queue(), VK_NULL_HANDLE);
  EXPECT_TRUE(c.owns_handles());
  EXPECT_FALSE(c.info().name.empty());
  EXPECT_GE(c.info().api_version, VK_API_VERSION_1_3);
  EXPECT_TRUE(std::any_of(c.info().uuid.begin(), c.info().uuid.end(), [](uint8_t b) { return b; }))
      << "device UUID is all zero";
  EXPECT_GE(c.info().limits.maxImageDimension2D, 4096u);
  EXPECT_GT(c.memory_properties().memoryTypeCount, 0u);
}

TEST_F(ContextTest, CoreFeaturesAreEnabledAndExtensionEntryPointsMatchFeatures) {
  const DeviceFeatures& f = ctx().features();
  EXPECT_TRUE(f.dynamic_rendering);
  EXPECT_TRUE(f.synchronization2);
  EXPECT_TRUE(f.extended_dynamic_state);
  const DeviceFunctions& fn = ctx().functions();
  // A function pointer is loaded exactly when its feature is enabled.
  EXPECT_EQ(f.push_descriptor, fn.push_descriptor_set != nullptr);
  EXPECT_EQ(f.eds3.polygon_mode, fn.set_polygon_mode != nullptr);
  EXPECT_EQ(f.eds3.color_blend_enable, fn.set_color_blend_enable != nullptr);
  EXPECT_EQ(f.eds3.color_write_mask, fn.set_color_write_mask != nullptr);
  EXPECT_EQ(f.eds2_logic_op, fn.set_logic_op != nullptr);
  if (f.push_descriptor) {
    EXPECT_GT(ctx().info().push_descriptor_max, 0u);
  }
  if (f.eds3.polygon_mode) {
    EXPECT_TRUE(f.eds3.any());
  }
}

// Every feature a SPIR-V capability needs is enabled exactly when the device has it, since
// technique validation accepts the capability from the device's features.
TEST_F(ContextTest, ShaderCapabilityFeaturesAreEnabledWhereSupported) {
  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(ctx().physical_device(), &supported);
  const auto* bits = reinterpret_cast<const unsigned char*>(&supported);
  for (const ShaderCapabilityFeature& row : shader_capability_features()) {
    VkBool32 on = VK_FALSE;
    std::memcpy(&on, bits + row.feature_offset, sizeof on);
    EXPECT_EQ(ctx().features().has_shader_feature(row.feature), on == VK_TRUE) << row.feature;
  }
  EXPECT_TRUE(std::is_sorted(ctx().features().shader_features.begin(), ctx().features().shader_features.end()));
}

TEST(DeviceFeaturesEds3, AnyIsTrueWhenOneDynamicStateIsSupported) {
  DeviceFeatures::Eds3 none;
  EXPECT_FALSE(none.any());
  DeviceFeatures::Eds3 one;
  one.shading_rate_image_enable = true;  // the last row of the table
  EXPECT_TRUE(one.any());
}

TEST_F(ContextTest, DepthFormatQueryReturnsAUsableFormat) {
  VkFormat depth = ctx().best_depth_format();
  ASSERT_NE(depth, VK_FORMAT_UNDEFINED);
  EXPECT_TRUE(ctx().supports_format(depth, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT));
  VkFormat stencil = ctx().best_depth_format(/*need_stencil=*/true);
  if (stencil != VK_FORMAT_UNDEFINED) {
    EXPECT_TRUE(stencil == VK_FORMAT_D24_UNORM_S8_UINT || stencil == VK_FORMAT_D32_SFLOAT_S8_UINT);
  }
  EXPECT_TRUE(ctx().supports_format(VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT));
}

// The messenger must actually catch errors, or "zero validation errors" proves nothing.
TEST_F(ContextTest, ValidationErrorsAreRecordedWithIdAndCounted) {
  ASSERT_EQ(ctx().validation_error_count(), 0u);
  const size_t listened = testing::teardown_validation_errors();
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 0;  // invalid: VUID-VkBufferCreateInfo-size-00912
  info.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkResult r = vkCreateBuffer(ctx().device(), &info, nullptr, &buffer);
  if (r == VK_SUCCESS && buffer) vkDestroyBuffer(ctx().device(), buffer, nullptr);

  ASSERT_GE(ctx().validation_error_count(), 1u);
  EXPECT_GT(testing::teardown_validation_errors(), listened) << "on_validation_message was called";
  auto messages = ctx().validation_messages();
  auto it = std::find_if(messages.begin(), messages.end(), [](const ValidationMessage& m) {
    return m.severity == Severity::error && m.id_name.find("size-00912") != std::string::npos;
  });
  ASSERT_NE(it, messages.end()) << describe_messages(ctx());
  EXPECT_NE(it->id_number, 0);
  EXPECT_FALSE(it->text.empty());

  DiagnosticSink sink;
  ctx().drain_validation_into(sink);
  EXPECT_GE(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics().front().id, "vk-validation");
  EXPECT_EQ(ctx().validation_error_count(), 0u);  // drained
}

TEST_F(ContextTest, WrapBorrowsHandlesWithoutDestroyingThem) {
  {
    Context borrowed =
        Context::wrap(ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(), ctx().queue_family());
    EXPECT_FALSE(borrowed.owns_handles());
    EXPECT_EQ(borrowed.device(), ctx().device());
    EXPECT_EQ(borrowed.info().name, ctx().info().name);
    EXPECT_EQ(borrowed.info().index, ctx().info().index);
    EXPECT_EQ(borrowed.info().uuid, ctx().info().uuid);
    EXPECT_FALSE(borrowed.validation_enabled());
    DiagnosticSink sink;
    // Work through the wrapper on the borrowed device.
    EXPECT_TRUE(submit_and_wait(
        borrowed, [](VkCommandBuffer) {}, sink))
        << describe(sink);
    Context moved = std::move(borrowed);  // moving a borrowed context must not destroy either
    EXPECT_EQ(moved.device(), ctx().device());
  }
  // The owner's device still works after the wrappers are gone.
  DiagnosticSink sink;
  EXPECT_TRUE(submit_and_wait(
      ctx(), [](VkCommandBuffer) {}, sink))
      << describe(sink);
}

TEST_F(ContextTest, WrapReportsTheFeaturesTheApplicationEnabled) {
  DeviceFeatures enabled;
  enabled.dynamic_rendering = true;  // the application says: nothing else
  Context borrowed = Context::wrap(ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(),
                                   ctx().queue_family(), enabled);
  EXPECT_TRUE(borrowed.features().dynamic_rendering);
  EXPECT_FALSE(borrowed.features().push_descriptor);
  EXPECT_EQ(borrowed.functions().push_descriptor_set, nullptr);
}

// Validation reads the caps of the device as it was created: an application device that
// did not enable shaderClipDistance does not offer it, though its physical device has it.
TEST_F(ContextTest, CapsOfAContextHaveOnlyTheShaderFeaturesItsDeviceEnabled) {
  const DeviceCaps physical = caps_from_physical_device(ctx().physical_device());
  const DeviceCaps own = context_caps(ctx());
  EXPECT_EQ(own.vulkan.features, physical.vulkan.features) << "a headless context enables every one it has";
  DeviceFeatures enabled;
  enabled.dynamic_rendering = true;
  Context borrowed = Context::wrap(ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(),
                                   ctx().queue_family(), enabled);
  const DeviceCaps caps = context_caps(borrowed);
  for (const ShaderCapabilityFeature& row : shader_capability_features())
    EXPECT_FALSE(std::binary_search(caps.vulkan.features.begin(), caps.vulkan.features.end(), std::string(row.feature)))
        << row.feature;
  auto in_table = [](const std::string& f) {
    const auto rows = shader_capability_features();
    return std::any_of(rows.begin(), rows.end(), [&](const ShaderCapabilityFeature& row) { return f == row.feature; });
  };
  for (const std::string& f : physical.vulkan.features) {  // the others stay
    if (!in_table(f)) {
      EXPECT_TRUE(std::binary_search(caps.vulkan.features.begin(), caps.vulkan.features.end(), f)) << f;
    }
  }
}

TEST(ContextOwnership, MovedFromContextIsEmptyAndContextWithoutValidationWorks) {
  DiagnosticSink sink;
  auto ctx = Context::headless({}, sink);
  ASSERT_TRUE(ctx) << describe(sink);
  EXPECT_FALSE(ctx->validation_enabled());
  EXPECT_EQ(ctx->validation_error_count(), 0u);
  Context moved = std::move(*ctx);
  EXPECT_EQ(ctx->device(), VK_NULL_HANDLE);
  EXPECT_NE(moved.device(), VK_NULL_HANDLE);
  EXPECT_TRUE(submit_and_wait(
      moved, [](VkCommandBuffer) {}, sink))
      << describe(sink);
}

TEST(ContextOwnership, MissingDeviceExtensionIsADiagnosticNotACrash) {
  DiagnosticSink sink;
  ContextOptions options;
  options.device_extensions = {"VK_FXKIT_no_such_extension"};
  auto ctx = Context::headless(options, sink);
  EXPECT_FALSE(ctx);
  ASSERT_EQ(sink.error_count(), 1u) << describe(sink);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-extension-missing");
}

TEST(VkNames, ResultAndDeviceTypeNames) {
  EXPECT_EQ(to_string(VK_ERROR_DEVICE_LOST), "VK_ERROR_DEVICE_LOST");
  EXPECT_EQ(to_string(VkResult(-12345)), "VkResult(-12345)");
  EXPECT_STREQ(to_string(VK_PHYSICAL_DEVICE_TYPE_CPU), "CPU");
  EXPECT_STREQ(to_string(VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU), "discrete GPU");
}

}  // namespace
}  // namespace fx::vk
