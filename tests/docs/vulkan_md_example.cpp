// docs/vulkan.md, "Quick tour": a headless context, a render target, one frame, readback.
// The examples are the docs' text, verbatim (examples_compiled_test.cpp): not reformatted.
// clang-format off
#include <cassert>

#include "example_fixture.h"
#include "fx/image.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/render_target.h"

namespace fx::docs {
namespace {

TEST_F(ExampleTest, VulkanQuickTour) {
  fx::DiagnosticSink sink;
  auto ctx = fx::vk::Context::headless({.validation = true}, sink);   // nullopt + "vk-*" diagnostics on failure
  auto rt  = fx::vk::RenderTarget::create(*ctx, {.width = 256, .height = 256,
                                                 .depth = fx::vk::DepthAttachment::best}, sink);
  const fx::vk::RenderingFormats formats = rt->formats();
  VkPipelineRenderingCreateInfo rendering = formats.pipeline_info();  // pipeline pNext; points into `formats`
  fx::vk::submit_and_wait(*ctx, [&](VkCommandBuffer cmd) {
    rt->begin(cmd, {.color = std::array{0.f, 0.f, 0.f, 1.f}});          // vkCmdBeginRendering
    /* bind pipeline, set viewport = rt->viewport(), draw */
    rt->end(cmd);
  }, sink);
  std::optional<fx::Image> pixels = rt->read_color(*ctx, sink);         // RGBA8
  fx::write_png("out.png", *pixels, sink);
  assert(ctx->validation_error_count() == 0);

  EXPECT_EQ(rendering.colorAttachmentCount, 1u);
  EXPECT_EQ(rendering.depthAttachmentFormat, ctx->best_depth_format());
  ASSERT_TRUE(pixels);
  EXPECT_EQ(pixels->width, 256u);
  EXPECT_TRUE(std::filesystem::exists("out.png"));
  EXPECT_EQ(ctx->validation_error_count(), 0u);
  EXPECT_FALSE(sink.has_errors());
}

}  // namespace
}  // namespace fx::docs
