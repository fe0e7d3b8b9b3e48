// docs/rendering.md: an effect bound once, then drawn per frame into the application's
// command buffer (here a RenderTarget's, with a quad as "my mesh").
// The examples are the docs' text, verbatim (examples_compiled_test.cpp): not reformatted.
// clang-format off
#include "example_fixture.h"
#include "fx/mesh.h"
#include "fx/binding/effect_binding.h"
#include "fx/compile/effect_file.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/render_target.h"

namespace fx::docs {
namespace {

TEST_F(ExampleTest, RenderingAnEffect) {
  const fx::vk::Context& ctx = this->ctx();
  fx::DiagnosticSink sink;
  fx::FrontEndOptions options;
  options.preprocessor.include_dirs = {"effects"};
  std::unique_ptr<fx::EffectFile> file = fx::EffectFile::load("effects/per_pixel_lighting.fx", options, sink);
  ASSERT_TRUE(file);
  const uint32_t technique = file->find_technique("diffuse_ps20");
  auto target = fx::vk::RenderTarget::create(ctx, {.width = 32, .height = 32, .depth = fx::vk::DepthAttachment::d24s8}, sink);
  ASSERT_TRUE(target);
  const VkViewport viewport{0, 32, 32, -32, 0, 1};  // Y flipped: negative_viewport_height
  const fx::Mesh quad = fx::quad();
  auto vertices = fx::vk::Buffer::create(ctx, {quad.vertices.size() * sizeof(fx::Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "quad"}, sink);
  auto indices = fx::vk::Buffer::create(ctx, {quad.indices.size() * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "quad"}, sink);
  ASSERT_TRUE(vertices && indices);
  vertices->write(quad.vertices.data(), quad.vertices.size() * sizeof(fx::Vertex));
  indices->write(quad.indices.data(), quad.indices.size() * sizeof(uint32_t));
  auto draw_my_mesh = [&](VkCommandBuffer cmd) {
    const VkBuffer buffer = vertices->handle();
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
    vkCmdBindIndexBuffer(cmd, indices->handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, uint32_t(quad.indices.size()), 1, 0, 0, 0);
  };

  fx::vk::EffectTextureCache textures(ctx);                 // shared by all bindings
  auto frames = fx::vk::FrameResources::create(ctx, {}, sink);
  fx::vk::EffectBindingDesc desc{.target = {.depth_bits = 24, .mesh_front_face = fx::FrontFace::counter_clockwise},
                                 .effect_dir = "effects"};  // PassTargetInfo: pass_state_mapping.h
  auto binding = fx::vk::EffectBinding::create(ctx, *file->model, *file->programs, *file->params, textures,
                                               *frames, desc, sink);
  uint32_t layout = binding->add_vertex_layout(fx::vk::to_vertex_layout(fx::mesh_vertex_layout()));

  bool drawn = false;
  fx::vk::submit_and_wait(ctx, [&](VkCommandBuffer cmd) {
    frames->begin_frame();                                  // once per frame in flight
    target->begin(cmd);                                     // the app's vkCmdBeginRendering
    if (binding->begin(cmd, technique, target->formats(), viewport, target->scissor(), sink))
      for (uint32_t p = 0; p < binding->pass_count(technique); ++p)
        if (binding->apply(p, layout, sink)) draw_my_mesh(cmd);
    binding->end();
    target->end(cmd);
    drawn = !sink.has_errors();
  }, sink);
  EXPECT_TRUE(drawn);
  EXPECT_FALSE(sink.has_errors()) << fx::vk::testing::describe(sink);
}

}  // namespace
}  // namespace fx::docs
