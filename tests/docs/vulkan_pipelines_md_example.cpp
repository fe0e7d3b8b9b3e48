// docs/vulkan-pipelines.md, "The pass API": compiled, not run here (it needs compiled
// shaders, a texture and an open command buffer; tests/vulkan/pass_recorder_test.cpp runs
// the same calls).
// The examples are the docs' text, verbatim (examples_compiled_test.cpp): not reformatted.
// clang-format off
#include <functional>

#include "fx/compile/program_link.h"
#include "fx/binding/pass_recorder.h"
#include "fx/vulkan/sampler_cache.h"
#include "fx/vulkan/texture.h"

namespace fx::vk::docs {

// What the application brings, and the example as something it does.
struct App {
  std::filesystem::path path;
  CompiledShader vs, ps;
  VertexLayout app_layout;
  float dir[3] = {0, -1, 0};
  const Texture& texture;
  SamplerKey desc;
  std::vector<PipelineState> pass_states;
  uint32_t frame_slot = 0;
  std::function<void(uint32_t)> wait_for_fence;
  std::function<void(VkCommandBuffer)> app_draw;

  void pass_api(const Context& ctx, SamplerCache& samplers, VkCommandBuffer cmd, const VkRenderingInfo& rendering,
                const RenderingFormats& formats, const VkViewport& viewport, const VkRect2D& scissor,
                DiagnosticSink& sink);
};

void App::pass_api(const Context& ctx, SamplerCache& samplers, VkCommandBuffer cmd, const VkRenderingInfo& rendering,
                   const RenderingFormats& formats, const VkViewport& viewport, const VkRect2D& scissor,
                   DiagnosticSink& sink) {
  fx::vk::PipelineCache pipelines = *PipelineCache::create(ctx, sink, PipelineCache::load_file(ctx, path, sink));
  fx::vk::FrameResources frames = *FrameResources::create(ctx, {.frames_in_flight = 2}, sink);
  fx::vk::PassRecorder recorder(ctx, pipelines, frames, DynamicStateSet::from_features(ctx.features()));

  // per pass, once: program + matched vertex input + resources
  ShaderProgram program = *ShaderProgram::create(ctx, {&vs, &ps}, link_program({&vs, &ps}, sink),
                                                 DescriptorMode::sets, sink);
  VertexInput input = *match_vertex_layout(app_layout, program.vertex_inputs(), sink);
  PassResources res(program);
  res.set_uniform("LightDir", &dir, sizeof dir, sink);      // dirty only if the bytes change
  res.bind("DiffuseSampler", texture, samplers.get(desc, sink), sink);

  // per frame
  wait_for_fence(frame_slot); frames.begin_frame();           // recycles that slot's ring + pool
  vkCmdBeginRendering(cmd, &rendering);                        // the app owns attachments
  recorder.begin(cmd, formats, viewport, scissor);
  for (const PipelineState& state : pass_states) {            // the technique's passes
    recorder.apply({&program, state, &input, &res}, sink);
    app_draw(cmd);
  }
  recorder.end();
  vkCmdEndRendering(cmd);
}

}  // namespace fx::vk::docs
