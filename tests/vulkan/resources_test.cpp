// Buffers, images and one-shot submission against a real device.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "fx/vulkan/barrier.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/image.h"
#include "fx/vulkan/memory.h"
#include "fx/vulkan/one_shot.h"
#include "vulkan_fixture.h"

namespace fx::vk {
namespace {

using testing::describe;

class ResourcesTest : public testing::VulkanTest {
 protected:
  Buffer make_buffer(VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory) {
    DiagnosticSink sink;
    auto b = Buffer::create(ctx(), {size, usage, memory, "test buffer"}, sink);
    EXPECT_TRUE(b) << describe(sink);
    return b ? std::move(*b) : Buffer{};
  }
};

std::vector<uint8_t> pattern(size_t n, uint8_t seed) {
  std::vector<uint8_t> v(n);
  for (size_t i = 0; i < n; ++i) v[i] = uint8_t(i * 31 + seed + (i >> 8));
  return v;
}

TEST_F(ResourcesTest, HostBuffersAreMappedAndDeviceLocalOnesAreNot) {
  Buffer upload = make_buffer(256, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryUsage::upload);
  Buffer local = make_buffer(256, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUsage::device_local);
  ASSERT_TRUE(upload && local);
  EXPECT_TRUE(upload.host_visible());
  EXPECT_EQ(upload.size(), 256u);
  auto data = pattern(256, 7);
  EXPECT_TRUE(upload.write(data.data(), data.size()));
  std::vector<uint8_t> back(256);
  EXPECT_TRUE(upload.read(back.data(), back.size()));
  EXPECT_EQ(back, data);
  EXPECT_FALSE(upload.write(data.data(), 16, 250)) << "out-of-range write must be refused";
  // Device-local memory may be host-visible on unified-memory devices; only check the contract.
  if (!local.host_visible()) {
    EXPECT_FALSE(local.write(data.data(), 4));
  }
}

TEST_F(ResourcesTest, InvalidBufferIsADiagnostic) {
  DiagnosticSink sink;
  EXPECT_FALSE(Buffer::create(ctx(), {0, VK_BUFFER_USAGE_TRANSFER_SRC_BIT}, sink));
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-invalid-buffer");
}

TEST_F(ResourcesTest, StagingToDeviceLocalAndBackThroughOneShotSubmissions) {
  const VkDeviceSize n = 64 * 1024;
  Buffer staging = make_buffer(n, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::upload);
  Buffer local =
      make_buffer(n, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::device_local);
  Buffer readback = make_buffer(n, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback);
  auto data = pattern(n, 3);
  ASSERT_TRUE(staging.write(data.data(), n));

  DiagnosticSink sink;
  auto commands = OneShotCommands::create(ctx(), sink);
  ASSERT_TRUE(commands) << describe(sink);
  VkBufferCopy region{0, 0, n};
  ASSERT_TRUE(commands->run(
      [&](VkCommandBuffer cmd) { vkCmdCopyBuffer(cmd, staging.handle(), local.handle(), 1, &region); }, sink))
      << describe(sink);
  // A second run reuses the same pool, buffer and fence.
  ASSERT_TRUE(commands->run(
      [&](VkCommandBuffer cmd) {
        vkCmdCopyBuffer(cmd, local.handle(), readback.handle(), 1, &region);
        memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                       VK_ACCESS_HOST_READ_BIT);
      },
      sink))
      << describe(sink);
  std::vector<uint8_t> back(n);
  ASSERT_TRUE(readback.read(back.data(), n));
  EXPECT_EQ(back, data);
}

TEST_F(ResourcesTest, MipCountAndFormatFacts) {
  EXPECT_EQ(full_mip_count(1, 1), 1u);
  EXPECT_EQ(full_mip_count(256, 256), 9u);
  EXPECT_EQ(full_mip_count(300, 17), 9u);
  EXPECT_EQ(full_mip_count(4, 4, 64), 7u);
  EXPECT_EQ(format_aspect(VK_FORMAT_D24_UNORM_S8_UINT),
            VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT));
  EXPECT_EQ(format_aspect(VK_FORMAT_D32_SFLOAT), VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT));
  EXPECT_EQ(format_aspect(VK_FORMAT_R8G8B8A8_SRGB), VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT));
  EXPECT_EQ(format_texel_bytes(VK_FORMAT_R16G16B16A16_SFLOAT), 8u);
  EXPECT_EQ(format_texel_bytes(VK_FORMAT_BC1_RGB_UNORM_BLOCK), 0u);
}

TEST_F(ResourcesTest, Creates2DMipmapped3DAndCubeImages) {
  DiagnosticSink sink;
  ImageDesc tex;
  tex.width = 64;
  tex.height = 32;
  tex.mip_levels = 0;  // full chain
  auto t2d = GpuImage::create(ctx(), tex, sink);
  ASSERT_TRUE(t2d) << describe(sink);
  EXPECT_EQ(t2d->desc().mip_levels, 7u);
  EXPECT_NE(t2d->view(), VK_NULL_HANDLE);
  EXPECT_EQ(t2d->layout(), VK_IMAGE_LAYOUT_UNDEFINED);

  ImageDesc vol;
  vol.kind = ImageKind::image3d;
  vol.width = vol.height = vol.depth = 16;
  auto t3d = GpuImage::create(ctx(), vol, sink);
  ASSERT_TRUE(t3d) << describe(sink);
  EXPECT_EQ(t3d->extent().depth, 16u);

  ImageDesc cube;
  cube.kind = ImageKind::cube;
  cube.width = cube.height = 32;
  auto tcube = GpuImage::create(ctx(), cube, sink);
  ASSERT_TRUE(tcube) << describe(sink);
  EXPECT_EQ(tcube->desc().array_layers, 6u);
  EXPECT_EQ(tcube->full_range().layerCount, 6u);
}

TEST_F(ResourcesTest, InvalidImageShapesAreDiagnostics) {
  DiagnosticSink sink;
  ImageDesc cube;
  cube.kind = ImageKind::cube;
  cube.width = 32;
  cube.height = 16;
  EXPECT_FALSE(GpuImage::create(ctx(), cube, sink));
  ImageDesc flat;
  flat.depth = 4;  // 2D images have depth 1
  EXPECT_FALSE(GpuImage::create(ctx(), flat, sink));
  ImageDesc huge;
  huge.width = huge.height = ctx().info().limits.maxImageDimension2D * 2;
  EXPECT_FALSE(GpuImage::create(ctx(), huge, sink));
  ASSERT_EQ(sink.error_count(), 3u) << describe(sink);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-invalid-image");
  EXPECT_EQ(sink.diagnostics()[1].id, "vk-invalid-image");
  EXPECT_EQ(sink.diagnostics()[2].id, "vk-format-unsupported");
}

// Upload every slice of a 3D texture, copy it back, compare: exercises layout tracking.
TEST_F(ResourcesTest, VolumeUploadAndReadbackThroughLayoutTransitions) {
  DiagnosticSink sink;
  ImageDesc vol;
  vol.kind = ImageKind::image3d;
  vol.width = 8;
  vol.height = 4;
  vol.depth = 3;
  vol.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  auto image = GpuImage::create(ctx(), vol, sink);
  ASSERT_TRUE(image) << describe(sink);
  const VkDeviceSize n = 8 * 4 * 3 * 4;
  Buffer staging = make_buffer(n, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::upload);
  Buffer readback = make_buffer(n, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback);
  auto data = pattern(n, 11);
  ASSERT_TRUE(staging.write(data.data(), n));
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = image->extent();
  ASSERT_TRUE(submit_and_wait(
      ctx(),
      [&](VkCommandBuffer cmd) {
        image->transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        vkCmdCopyBufferToImage(cmd, staging.handle(), image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                               &region);
        image->transition(cmd, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        image->transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        vkCmdCopyImageToBuffer(cmd, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1,
                               &region);
        memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                       VK_ACCESS_HOST_READ_BIT);
      },
      sink))
      << describe(sink);
  EXPECT_EQ(image->layout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  std::vector<uint8_t> back(n);
  ASSERT_TRUE(readback.read(back.data(), n));
  EXPECT_EQ(back, data);
}

TEST(MemoryTypes, FindsRequiredAndPrefersPreferred) {
  VkPhysicalDeviceMemoryProperties props{};
  props.memoryTypeCount = 3;
  props.memoryTypes[0].propertyFlags = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  props.memoryTypes[1].propertyFlags = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  props.memoryTypes[2].propertyFlags =
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
  EXPECT_EQ(find_memory_type(props, 0b111, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, VK_MEMORY_PROPERTY_HOST_CACHED_BIT),
            2u);
  EXPECT_EQ(find_memory_type(props, 0b011, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, VK_MEMORY_PROPERTY_HOST_CACHED_BIT),
            1u);  // preferred unavailable in the allowed types: fall back
  EXPECT_FALSE(find_memory_type(props, 0b001, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT));
  EXPECT_EQ(find_memory_type(props, 0b110, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT), 1u);
}

}  // namespace
}  // namespace fx::vk
