// Offscreen render targets: clear + readback, a real triangle through a minimal dynamic
// rendering pipeline, depth testing, PNG output of the result.
#include "fx/vulkan/render_target.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>

#include "fx/image.h"
#include "fx/vulkan/graphics_pipeline.h"
#include "fx/vulkan/one_shot.h"
#include "triangle_frag.h"
#include "triangle_vert.h"
#include "vulkan_fixture.h"

namespace fx::vk {
namespace {

using testing::describe;

struct PushConstants {
  float color[4];
  float depth;
};

// The smallest pipeline that draws the test triangle into a RenderTarget: no vertex input,
// push-constant color and depth, dynamic viewport/scissor and depth test state.
class TrianglePipeline {
 public:
  TrianglePipeline(VkDevice device, const RenderingFormats& formats) : device_(device) {
    VkShaderModule vs = module(triangle_vert, sizeof triangle_vert);
    VkShaderModule fs = module(triangle_frag, sizeof triangle_frag);
    VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(PushConstants)};
    VkPipelineLayoutCreateInfo layout{};
    layout.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layout.pushConstantRangeCount = 1;
    layout.pPushConstantRanges = &range;
    EXPECT_EQ(vkCreatePipelineLayout(device_, &layout, nullptr, &layout_), VK_SUCCESS);

    VkPipelineShaderStageCreateInfo stages[2]{};
    for (auto& s : stages) {
      s.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
      s.pName = "main";
    }
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vs;
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fs;

    // Depth test state is dynamic (Vulkan 1.3 core extended dynamic state); the rest is
    // GraphicsPipelineDesc's full-screen default.
    const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                             VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE, VK_DYNAMIC_STATE_DEPTH_WRITE_ENABLE,
                                             VK_DYNAMIC_STATE_DEPTH_COMPARE_OP};
    GraphicsPipelineDesc desc;
    desc.stages = stages;
    desc.layout = layout_;
    desc.formats = formats;
    desc.dynamic_states = dynamic_states;
    DiagnosticSink sink;
    pipeline_ = create_graphics_pipeline(device_, VK_NULL_HANDLE, desc, sink);
    EXPECT_NE(pipeline_, VK_NULL_HANDLE) << testing::describe(sink);
    vkDestroyShaderModule(device_, vs, nullptr);
    vkDestroyShaderModule(device_, fs, nullptr);
  }
  ~TrianglePipeline() {
    vkDestroyPipeline(device_, pipeline_, nullptr);
    vkDestroyPipelineLayout(device_, layout_, nullptr);
  }

  void draw(VkCommandBuffer cmd, const RenderTarget& target, const PushConstants& push, bool depth_test) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
    VkViewport viewport = target.viewport();
    VkRect2D scissor = target.scissor();
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdSetDepthTestEnable(cmd, depth_test);
    vkCmdSetDepthWriteEnable(cmd, depth_test);
    vkCmdSetDepthCompareOp(cmd, VK_COMPARE_OP_LESS);
    vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof push, &push);
    vkCmdDraw(cmd, 3, 1, 0, 0);
  }

 private:
  VkShaderModule module(const uint32_t* code, size_t bytes) {
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule m = VK_NULL_HANDLE;
    EXPECT_EQ(vkCreateShaderModule(device_, &info, nullptr, &m), VK_SUCCESS);
    return m;
  }

  VkDevice device_;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

class RenderTargetTest : public testing::VulkanTest {
 protected:
  std::optional<RenderTarget> make_target(uint32_t w, uint32_t h, VkFormat format,
                                          DepthAttachment depth = DepthAttachment::none) {
    DiagnosticSink sink;
    RenderTargetDesc desc;
    desc.width = w;
    desc.height = h;
    desc.color_format = format;
    desc.depth = depth;
    desc.debug_name = "test target";
    auto rt = RenderTarget::create(ctx(), desc, sink);
    EXPECT_TRUE(rt) << describe(sink);
    return rt;
  }

  static std::array<uint8_t, 4> pixel(const fx::Image& image, uint32_t x, uint32_t y) {
    const uint8_t* p = image.at(x, y);
    return {p[0], p[1], p[2], p[3]};
  }
};

using Rgba = std::array<uint8_t, 4>;

TEST_F(RenderTargetTest, ClearAndReadbackGivesTheClearColorEverywhere) {
  auto target = make_target(32, 16, VK_FORMAT_R8G8B8A8_UNORM);
  ASSERT_TRUE(target);
  RenderTarget& rt = *target;
  DiagnosticSink sink;
  ClearValues clear;
  clear.color = std::array<float, 4>{0.2f, 0.4f, 0.6f, 1.0f};
  ASSERT_TRUE(submit_and_wait(
      ctx(),
      [&](VkCommandBuffer cmd) {
        rt.begin(cmd, clear);
        rt.end(cmd);
        rt.record_readback(cmd);
      },
      sink))
      << describe(sink);
  auto image = rt.readback_pixels(sink);
  ASSERT_TRUE(image) << describe(sink);
  ASSERT_EQ(image->width, 32u);
  ASSERT_EQ(image->height, 16u);
  ASSERT_EQ(image->channels, 4u);
  fx::Image expected = fx::Image::blank(32, 16, 4);
  for (size_t i = 0; i < expected.pixels.size(); i += 4) {
    expected.pixels[i] = 51;  // 0.2 * 255
    expected.pixels[i + 1] = 102;
    expected.pixels[i + 2] = 153;
    expected.pixels[i + 3] = 255;
  }
  fx::ImageDiff diff = fx::compare(*image, expected, 1);
  EXPECT_TRUE(diff.comparable);
  EXPECT_EQ(diff.channels_over, 0u) << "max diff " << diff.max_abs;
}

TEST_F(RenderTargetTest, BgraTargetsReadBackAsRgba) {
  DiagnosticSink sink;
  if (!ctx().supports_format(VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT))
    GTEST_SKIP() << "B8G8R8A8_UNORM is not a color attachment format here";
  auto target = make_target(4, 4, VK_FORMAT_B8G8R8A8_UNORM);
  ASSERT_TRUE(target);
  RenderTarget& rt = *target;
  ClearValues clear;
  clear.color = std::array<float, 4>{1.0f, 0.0f, 0.0f, 1.0f};
  ASSERT_TRUE(submit_and_wait(
      ctx(),
      [&](VkCommandBuffer cmd) {
        rt.begin(cmd, clear);
        rt.end(cmd);
      },
      sink));
  auto image = rt.read_color(ctx(), sink);
  ASSERT_TRUE(image) << describe(sink);
  EXPECT_EQ(pixel(*image, 2, 2), (Rgba{255, 0, 0, 255}));
}

TEST_F(RenderTargetTest, UnreadableFormatIsADiagnostic) {
  if (!ctx().supports_format(VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT))
    GTEST_SKIP() << "no RGBA16F attachments";
  auto target = make_target(4, 4, VK_FORMAT_R16G16B16A16_SFLOAT);
  ASSERT_TRUE(target);
  RenderTarget& rt = *target;
  DiagnosticSink sink;
  EXPECT_FALSE(rt.read_color(ctx(), sink));
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-readback-format");
}

TEST_F(RenderTargetTest, TriangleIsRasterizedUprightAndWrittenAsPng) {
  auto target = make_target(64, 64, VK_FORMAT_R8G8B8A8_UNORM);
  ASSERT_TRUE(target);
  RenderTarget& rt = *target;
  TrianglePipeline pipeline(ctx().device(), rt.formats());
  DiagnosticSink sink;
  ClearValues clear;
  clear.color = std::array<float, 4>{0.0f, 0.0f, 1.0f, 1.0f};
  ASSERT_TRUE(submit_and_wait(
      ctx(),
      [&](VkCommandBuffer cmd) {
        rt.begin(cmd, clear);
        pipeline.draw(cmd, rt, {{1.0f, 0.0f, 0.0f, 1.0f}, 0.5f}, false);
        rt.end(cmd);
        rt.record_readback(cmd);
      },
      sink))
      << describe(sink);
  auto image = rt.readback_pixels(sink);
  ASSERT_TRUE(image) << describe(sink);
  const Rgba red{255, 0, 0, 255}, blue{0, 0, 255, 255};
  EXPECT_EQ(pixel(*image, 32, 32), red) << "centre";
  EXPECT_EQ(pixel(*image, 32, 20), red) << "below the apex";
  EXPECT_EQ(pixel(*image, 10, 52), red) << "bottom-left of the base";
  EXPECT_EQ(pixel(*image, 10, 12), blue) << "a flipped triangle would cover this";
  EXPECT_EQ(pixel(*image, 0, 0), blue);
  EXPECT_EQ(pixel(*image, 63, 63), blue);
  EXPECT_EQ(pixel(*image, 32, 60), blue) << "below the base";
  size_t covered = 0;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) covered += pixel(*image, x, y) == red;
  // Area = 0.5 * base(48 px) * height(48 px) = 1152 pixels.
  EXPECT_NEAR(double(covered), 1152.0, 40.0);

  // The PNG of the frame reads back identical.
  auto path = std::filesystem::temp_directory_path() / "fxkit_vk_triangle.png";
  ASSERT_TRUE(fx::write_png(path, *image, sink)) << describe(sink);
  auto loaded = fx::read_png(path, sink);
  ASSERT_TRUE(loaded) << describe(sink);
  fx::ImageDiff diff = fx::compare(*image, *loaded);
  EXPECT_TRUE(diff.comparable);
  EXPECT_EQ(diff.channels_over, 0u);
  std::filesystem::remove(path);
}

TEST_F(RenderTargetTest, DepthAttachmentHidesTrianglesBehindTheClearDepth) {
  auto target = make_target(16, 16, VK_FORMAT_R8G8B8A8_UNORM, DepthAttachment::best);
  ASSERT_TRUE(target);
  RenderTarget& rt = *target;
  ASSERT_NE(rt.depth(), nullptr);
  RenderingFormats formats = rt.formats();
  EXPECT_EQ(formats.depth, ctx().best_depth_format());
  TrianglePipeline pipeline(ctx().device(), formats);
  DiagnosticSink sink;
  auto draw_with_clear_depth = [&](float clear_depth) {
    ClearValues clear;
    clear.color = std::array<float, 4>{0.0f, 0.0f, 0.0f, 1.0f};
    clear.depth = clear_depth;
    EXPECT_TRUE(submit_and_wait(
        ctx(),
        [&](VkCommandBuffer cmd) {
          rt.begin(cmd, clear);
          pipeline.draw(cmd, rt, {{0.0f, 1.0f, 0.0f, 1.0f}, 0.5f}, true);
          rt.end(cmd);
        },
        sink))
        << describe(sink);
    auto image = rt.read_color(ctx(), sink);
    EXPECT_TRUE(image) << describe(sink);
    return image ? pixel(*image, 8, 8) : Rgba{};
  };
  EXPECT_EQ(draw_with_clear_depth(1.0f), (Rgba{0, 255, 0, 255})) << "z 0.5 < 1.0 passes";
  EXPECT_EQ(draw_with_clear_depth(0.25f), (Rgba{0, 0, 0, 255})) << "z 0.5 > 0.25 fails";
}

TEST_F(RenderTargetTest, LoadKeepsPreviousContents) {
  auto target = make_target(8, 8, VK_FORMAT_R8G8B8A8_UNORM, DepthAttachment::d32);
  ASSERT_TRUE(target);
  RenderTarget& rt = *target;
  TrianglePipeline pipeline(ctx().device(), rt.formats());
  DiagnosticSink sink;
  ClearValues first;
  first.color = std::array<float, 4>{1.0f, 1.0f, 1.0f, 1.0f};
  ClearValues keep;
  keep.color.reset();
  keep.depth.reset();
  ASSERT_TRUE(submit_and_wait(
      ctx(),
      [&](VkCommandBuffer cmd) {
        rt.begin(cmd, first);
        rt.end(cmd);
        rt.record_readback(cmd);  // moves the color to TRANSFER_SRC in between
        rt.begin(cmd, keep);
        rt.end(cmd);
      },
      sink))
      << describe(sink);
  auto image = rt.read_color(ctx(), sink);
  ASSERT_TRUE(image) << describe(sink);
  EXPECT_EQ(pixel(*image, 3, 3), (Rgba{255, 255, 255, 255}));
}

// pipeline_info() points into its RenderingFormats: callable on a named object only.
template <class F>
concept HasPipelineInfo = requires(F&& f) {
  static_cast<F&&>(f).pipeline_info();
};
static_assert(HasPipelineInfo<const RenderingFormats&>);
static_assert(!HasPipelineInfo<RenderingFormats>);

TEST_F(RenderTargetTest, FormatsAreTheAttachmentsInPipelineShape) {
  auto target = make_target(4, 4, VK_FORMAT_B8G8R8A8_UNORM, DepthAttachment::d32);
  ASSERT_TRUE(target);
  const RenderingFormats formats = target->formats();
  EXPECT_EQ(formats.color_count, 1u);
  EXPECT_EQ(formats.color[0], VK_FORMAT_B8G8R8A8_UNORM);
  EXPECT_EQ(formats.depth, VK_FORMAT_D32_SFLOAT);
  EXPECT_EQ(formats.stencil, VK_FORMAT_UNDEFINED);
  const VkPipelineRenderingCreateInfo info = formats.pipeline_info();
  EXPECT_EQ(info.sType, VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  EXPECT_EQ(info.colorAttachmentCount, 1u);
  EXPECT_EQ(info.pColorAttachmentFormats, formats.color);
  EXPECT_EQ(info.depthAttachmentFormat, VK_FORMAT_D32_SFLOAT);
  EXPECT_EQ(info.stencilAttachmentFormat, VK_FORMAT_UNDEFINED);
}

TEST_F(RenderTargetTest, ZeroSizeIsADiagnostic) {
  DiagnosticSink sink;
  RenderTargetDesc desc;
  EXPECT_FALSE(RenderTarget::create(ctx(), desc, sink));
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-invalid-image");
}

}  // namespace
}  // namespace fx::vk
