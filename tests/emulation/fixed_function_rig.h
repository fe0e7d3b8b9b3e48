// Draws a generated fixed-function pass (or any HLSL vertex and pixel shader pair) on the
// Vulkan device into a float target, with a D32 depth target when asked: the shaders
// compiled by fx::ShaderCompiler, one quad whose vertex colours, normals and positions the
// test chooses, 8-bit textures sampled at texel centres.
#pragma once
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "../vulkan/pass_test_util.h"
#include "fx/emulation/fixed_function.h"
#include "fx/vulkan/texture.h"

namespace fx::vk::testing {

// A generated shader as the compiler's input.
inline TranslationUnit unit(const FixedFunctionShader& s, ShaderStage stage) {
  TranslationUnit u;
  u.source = s.source;
  u.stage = stage;
  u.entry_point = s.entry;
  u.profile = s.profile;
  u.name = "fixed_function.hlsl";
  return u;
}

// One vertex of the rig's quads: object-space position, normal, both colours, uv.
struct FixedVertex {
  float x, y, z, nx, ny, nz;
  float diffuse[4], specular[4];
  float u, v;
};

// With `pretransformed`, POSITION is x, y, z and rhw (rhw in the nx slot).
inline VertexLayout fixed_vertex_layout(bool pretransformed = false) {
  return {{{"POSITION", pretransformed ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R32G32B32_SFLOAT, 0, 0},
           {"NORMAL", VK_FORMAT_R32G32B32_SFLOAT, 12, 0},
           {"COLOR0", VK_FORMAT_R32G32B32A32_SFLOAT, 24, 0},
           {"COLOR1", VK_FORMAT_R32G32B32A32_SFLOAT, 40, 0},
           {"TEXCOORD0", VK_FORMAT_R32G32_SFLOAT, 56, 0}},
          {{0, sizeof(FixedVertex), VK_VERTEX_INPUT_RATE_VERTEX}}};
}

// A random size x size RGBA8 image (bytes drawn from `rng`).
inline fx::Image random_image(uint32_t size, std::mt19937& rng) {
  fx::Image image = fx::Image::blank(size, size, 4);
  std::uniform_int_distribution<int> byte(0, 255);
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x)
      for (int c = 0; c < 4; ++c) image.at(x, y)[c] = static_cast<uint8_t>(byte(rng));
  return image;
}

// The generated program of one state, its resources and a float render of it.
class FixedFunctionRig {
 public:
  // With `depth` the target has a D32 depth attachment, tested and written (LESS_OR_EQUAL).
  FixedFunctionRig(Context& ctx, uint32_t size, bool depth = false)
      : ctx_(ctx), size_(size), samplers_(ctx), depth_(depth) {
    harness_ = std::make_unique<PassHarness>(ctx, DynamicStateSet::none(), size,
                                             depth ? DepthAttachment::d32 : DepthAttachment::none,
                                             VK_FORMAT_R32G32B32A32_SFLOAT);
  }

  // Compiles and links the generated shaders of `state` (or `pixel_shader`, entry PS, in
  // place of the generated pixel shader, or `vertex_shader`, entry VS, in place of the
  // generated vertex shader); false (with a failure) when they do not.
  bool build(const FixedFunctionState& state, const std::string& pixel_shader = {},
             const std::string& vertex_shader = {}) {
    return build(vertex_shader.empty() ? generate_fixed_function_vertex_shader(state)
                                       : FixedFunctionShader{vertex_shader, "VS", "vs_3_0"},
                 pixel_shader.empty() ? generate_fixed_function_pixel_shader(state)
                                      : FixedFunctionShader{pixel_shader, "PS", "ps_3_0"},
                 state.pretransformed);
  }

  // Compiles and links `vs` and `ps` (any generated or hand-written HLSL pair).
  bool build(const FixedFunctionShader& vs, const FixedFunctionShader& ps, bool pretransformed = false) {
    ShaderCompiler compiler;
    program_ = std::make_unique<TestProgram>();
    program_->vs = compiler.compile(unit(vs, ShaderStage::vertex));
    program_->ps = compiler.compile(unit(ps, ShaderStage::fragment));
    EXPECT_TRUE(program_->vs.ok && program_->ps.ok) << program_->vs.info_log << program_->ps.info_log;
    if (!program_->vs.ok || !program_->ps.ok) return false;
    DiagnosticSink sink;
    program_->layout = link_program({&program_->vs, &program_->ps}, sink);
    EXPECT_EQ(sink.warning_count() + sink.error_count(), 0u) << describe(sink);
    auto program =
        ShaderProgram::create(ctx_, {&program_->vs, &program_->ps}, program_->layout, DescriptorMode::sets, sink);
    EXPECT_TRUE(program.has_value()) << describe(sink);
    if (!program) return false;
    program_->program = std::move(*program);
    input_ = match_vertex_layout(fixed_vertex_layout(pretransformed), program_->program.vertex_inputs(), sink);
    EXPECT_TRUE(input_.has_value()) << describe(sink);
    resources_ = std::make_unique<PassResources>(program_->program);
    return input_.has_value();
  }

  // Whether the pixel shader samples stage `stage`'s texture.
  bool samples(int stage) const {
    for (const ImageBinding& i : program_->ps.reflection.images)
      if (i.name == "fx_stage" + std::to_string(stage)) return true;
    return false;
  }

  // Binds `image` (nearest, repeat) to stage `stage`'s sampler fx_stage<stage>.
  bool bind_texture(int stage, const fx::Image& image) {
    DiagnosticSink sink;
    auto tex = Texture::from_image(ctx_, image, ColorSpace::linear, sink);
    EXPECT_TRUE(tex.has_value()) << describe(sink);
    if (!tex) return false;
    textures_.push_back(std::make_unique<Texture>(std::move(*tex)));
    SamplerKey key;
    key.min_filter = key.mag_filter = VK_FILTER_NEAREST;
    key.mip_filter = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    key.address_u = key.address_v = key.address_w = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    const bool ok =
        resources_->bind("fx_stage" + std::to_string(stage), *textures_.back(), samplers_.get(key, sink), sink);
    EXPECT_TRUE(ok) << describe(sink);
    return ok;
  }

  bool set_uniform(const char* name, const void* data, uint32_t bytes) {
    DiagnosticSink sink;
    const bool ok = resources_->set_uniform(name, data, bytes, sink);
    EXPECT_TRUE(ok) << describe(sink);
    return ok;
  }

  // Draws `vertices` (a triangle list) and reads the float target back; cleared to -1 so a
  // discarded pixel shows.
  fx::ImageF render(const std::vector<FixedVertex>& vertices) {
    DiagnosticSink sink;
    auto b = Buffer::create(ctx_,
                            {vertices.size() * sizeof(FixedVertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                             MemoryUsage::upload, "fixed-function vertices"},
                            sink);
    EXPECT_TRUE(b && b->write(vertices.data(), vertices.size() * sizeof(FixedVertex))) << describe(sink);
    if (!b) return {};
    VkBuffer vb = b->handle();
    PipelineState state;  // no culling, no blending
    state.depth_test = state.depth_write = depth_;
    fx::ImageF image = harness_->render_floats(
        [&](VkCommandBuffer cmd, PassRecorder& r) {
          draw(cmd, r, {&program_->program, state, &*input_, resources_.get()}, vb,
               static_cast<uint32_t>(vertices.size()));
        },
        {-1, -1, -1, -1});
    buffers_.push_back(std::move(*b));
    return image;
  }

  // The depth the last render() left (a rig made with `depth`), row by row; cleared to 1.
  std::vector<float> depth() { return harness_->read_depth(); }

  uint32_t size() const { return size_; }

 private:
  Context& ctx_;
  uint32_t size_;
  SamplerCache samplers_;
  bool depth_ = false;
  std::unique_ptr<PassHarness> harness_;
  std::unique_ptr<TestProgram> program_;
  std::optional<VertexInput> input_;
  std::unique_ptr<PassResources> resources_;
  std::vector<std::unique_ptr<Texture>> textures_;
  std::vector<Buffer> buffers_;
};

}  // namespace fx::vk::testing
