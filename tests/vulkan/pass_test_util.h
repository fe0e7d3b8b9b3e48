// Shared by the pipeline/pass tests: HLSL programs compiled through fx::ShaderCompiler, a
// quad vertex buffer, and a render-and-read-back loop driving PassRecorder.
#pragma once
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fx/binding/pass_recorder.h"
#include "fx/compile/program_link.h"
#include "fx/compile/shader_compiler.h"
#include "fx/vulkan/barrier.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/one_shot.h"
#include "fx/vulkan/render_target.h"
#include "fx/vulkan/sampler_cache.h"
#include "vulkan_fixture.h"

namespace fx::vk::testing {

// Clip-space position + texture coordinate; two triangles per quad.
struct Vertex {
  float x, y, z, u, v;
};

inline const char* kPassShaders = R"(
float4 Color;
sampler2D Tex;
struct VSIn { float4 pos : POSITION; float2 uv : TEXCOORD0; };
struct VSOut { float4 pos : POSITION; float2 uv : TEXCOORD0; };
VSOut VS(VSIn i) { VSOut o; o.pos = i.pos; o.uv = i.uv; return o; }
float4 VSColor(float4 pos : POSITION) : POSITION { return pos; }
float4 PSColor() : COLOR0 { return Color; }
float4 PSTex(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(Tex, uv); }
)";

// A compiled, linked program and the Vulkan objects made from it.
struct TestProgram {
  CompiledShader vs, ps;
  ProgramLayout layout;
  ShaderProgram program;
};

inline std::unique_ptr<TestProgram> make_program(const Context& ctx, const char* ps_entry,
                                                 DescriptorMode mode = DescriptorMode::sets) {
  auto p = std::make_unique<TestProgram>();
  ShaderCompiler compiler;
  auto unit = [](ShaderStage stage, const char* entry, const char* profile) {
    TranslationUnit u;
    u.source = kPassShaders;
    u.stage = stage;
    u.entry_point = entry;
    u.profile = profile;
    u.name = "pass_test.fx";
    return u;
  };
  // PSColor reads no varyings: its vertex shader writes none (no unconsumed-output warning).
  const bool color_only = std::string(ps_entry) == "PSColor";
  p->vs = compiler.compile(unit(ShaderStage::vertex, color_only ? "VSColor" : "VS", "vs_3_0"));
  p->ps = compiler.compile(unit(ShaderStage::fragment, ps_entry, "ps_3_0"));
  EXPECT_TRUE(p->vs.ok && p->ps.ok) << p->vs.info_log << p->ps.info_log;
  DiagnosticSink sink;
  p->layout = link_program({&p->vs, &p->ps}, sink);
  auto program = ShaderProgram::create(ctx, {&p->vs, &p->ps}, p->layout, mode, sink);
  EXPECT_TRUE(program.has_value()) << describe(sink);
  if (program) p->program = std::move(*program);
  return p;
}

inline VertexLayout quad_layout() {
  return {{{"POSITION", VK_FORMAT_R32G32B32_SFLOAT, 0, 0}, {"TEXCOORD0", VK_FORMAT_R32G32_SFLOAT, 12, 0}},
          {{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX}}};
}

// Appends a quad covering [x0,x1]x[y0,y1] in clip space at depth z, uv over [u0,u1]^2,
// wound counter-clockwise on screen (Vulkan's y points down) unless `clockwise`.
inline void add_quad(std::vector<Vertex>& v, float x0, float y0, float x1, float y1, float z, float u0 = 0,
                     float u1 = 1, bool clockwise = false) {
  Vertex a{x0, y0, z, u0, u0}, b{x1, y0, z, u1, u0}, c{x1, y1, z, u1, u1}, d{x0, y1, z, u0, u1};
  if (clockwise) v.insert(v.end(), {a, b, c, a, c, d});
  else v.insert(v.end(), {a, c, b, a, d, c});
}

// One render target, pipeline cache, frame resources and recorder for a test.
class PassHarness {
 public:
  PassHarness(Context& ctx, DynamicStateSet dynamic, uint32_t size = 8, DepthAttachment depth = DepthAttachment::d24s8,
              VkFormat color = VK_FORMAT_R8G8B8A8_UNORM)
      : ctx_(ctx) {
    DiagnosticSink sink;
    target_ =
        RenderTarget::create(ctx, {size, size, color, depth, 0, "pass test", VK_IMAGE_USAGE_TRANSFER_SRC_BIT}, sink);
    pipelines_ = PipelineCache::create(ctx, sink);
    frames_ = FrameResources::create(ctx, {}, sink);
    EXPECT_TRUE(target_ && pipelines_ && frames_) << describe(sink);
    recorder_.emplace(ctx, *pipelines_, *frames_, dynamic);
  }

  RenderingFormats formats() const { return target_->formats(); }

  // Uploads `vertices` into a new vertex buffer kept alive with the harness.
  VkBuffer vertices(const std::vector<Vertex>& vertices) {
    DiagnosticSink sink;
    auto b = Buffer::create(
        ctx_,
        {vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, MemoryUsage::upload, "test vertices"},
        sink);
    EXPECT_TRUE(b && b->write(vertices.data(), vertices.size() * sizeof(Vertex)));
    buffers_.push_back(std::move(*b));
    return buffers_.back().handle();
  }

  // One frame: begin_frame, clear, `record` between recorder begin/end, read back.
  fx::Image render(const std::function<void(VkCommandBuffer, PassRecorder&)>& record,
                   std::array<float, 4> clear = {0, 0, 0, 1}) {
    DiagnosticSink sink;
    draw_frame(record, clear);
    auto image = target_->readback_pixels(sink);
    EXPECT_TRUE(image.has_value()) << describe(sink);
    return image ? *image : fx::Image{};
  }

  // The same for an R32G32B32A32_SFLOAT harness: the float values as the shader wrote them.
  fx::ImageF render_floats(const std::function<void(VkCommandBuffer, PassRecorder&)>& record,
                           std::array<float, 4> clear = {0, 0, 0, 1}) {
    DiagnosticSink sink;
    draw_frame(record, clear);
    auto image = target_->readback_floats(sink);
    EXPECT_TRUE(image.has_value()) << describe(sink);
    return image ? *image : fx::ImageF{};
  }

  // The depth values the last frame left in a d32 harness, row by row (empty when the
  // target has another depth format or none).
  std::vector<float> read_depth() {
    DiagnosticSink sink;
    GpuImage* depth = target_->depth();
    if (!depth || depth->format() != VK_FORMAT_D32_SFLOAT) return {};
    const uint32_t width = target_->width(), height = target_->height();
    std::vector<float> values(size_t(width) * height);
    auto b = Buffer::create(
        ctx_,
        {values.size() * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback, "depth readback"},
        sink);
    EXPECT_TRUE(b) << describe(sink);
    if (!b) return {};
    const bool ok = submit_and_wait(
        ctx_,
        [&](VkCommandBuffer cmd) {
          depth->transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
          VkBufferImageCopy region{};
          region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
          region.imageExtent = {width, height, 1};
          vkCmdCopyImageToBuffer(cmd, depth->handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, b->handle(), 1, &region);
          memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                         VK_ACCESS_HOST_READ_BIT);
        },
        sink);
    EXPECT_TRUE(ok && b->read(values.data(), values.size() * sizeof(float))) << describe(sink);
    return values;
  }

  PassRecorder& recorder() { return *recorder_; }
  PipelineCache& pipelines() { return *pipelines_; }
  FrameResources& frames() { return *frames_; }

 private:
  // begin_frame, clear, `record` between recorder begin/end, readback recorded and waited for.
  void draw_frame(const std::function<void(VkCommandBuffer, PassRecorder&)>& record, std::array<float, 4> clear) {
    DiagnosticSink sink;
    frames_->begin_frame();
    const bool ok = submit_and_wait(
        ctx_,
        [&](VkCommandBuffer cmd) {
          ClearValues cv;
          cv.color = clear;
          target_->begin(cmd, cv);
          recorder_->begin(cmd, formats(), target_->viewport(), target_->scissor());
          record(cmd, *recorder_);
          recorder_->end();
          target_->end(cmd);
          target_->record_readback(cmd);
        },
        sink);
    EXPECT_TRUE(ok) << describe(sink);
  }

  Context& ctx_;
  std::optional<RenderTarget> target_;
  std::optional<PipelineCache> pipelines_;
  std::optional<FrameResources> frames_;
  std::optional<PassRecorder> recorder_;
  std::vector<Buffer> buffers_;
};

// Records apply + draw of `count` vertices from `vb` at `first`; fails the test on errors.
inline void draw(VkCommandBuffer cmd, PassRecorder& r, const PassDesc& pass, VkBuffer vb, uint32_t count,
                 uint32_t first = 0) {
  DiagnosticSink sink;
  ASSERT_TRUE(r.apply(pass, sink)) << describe(sink);
  VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
  vkCmdDraw(cmd, count, 1, first, 0);
}

inline std::array<int, 4> pixel(const fx::Image& image, uint32_t x, uint32_t y) {
  const uint8_t* p = image.at(x, y);
  return {p[0], p[1], p[2], p[3]};
}

}  // namespace fx::vk::testing
