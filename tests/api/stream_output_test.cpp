// Stream output (ConstructGSWithSO) through the public API on the real device, validation on:
// a capture read back word by word, the captured vertices drawn by a later pass (DrawAuto),
// declarations with gaps, masks and a second buffer, a vertex shader streamed out, the
// refusals, and a device without VK_EXT_transform_feedback.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include "../vulkan/effect_test_util.h"
#include "fx/vulkan/barrier.h"
#include "fxkit/fxkit.h"

namespace fx::vk::testing {
namespace {

// A geometry shader that emits one known triangle per input triangle: primitive 0 covers the
// whole target in orange, primitive 1 is a blue sliver in a corner. Pass 1 draws what pass 0
// captured. The vertex shader reads no attribute: the test draws 6 vertices with no buffer.
constexpr const char* kParticles = R"(
struct Seed { float4 pos : POSITION; };
struct Particle { float4 pos : POSITION; float3 colour : COLOR0; };
struct Pixel { float4 pos : SV_Position; float3 colour : COLOR0; };
RasterizerState NoCull { CullMode = None; };
Seed Emit(uint id : SV_VertexID) { Seed s; s.pos = float4(id, 0, 0, 1); return s; }
[maxvertexcount(3)]
void Spawn(triangle Seed seeds[3], uint prim : SV_PrimitiveID, inout TriangleStream<Particle> stream) {
  const float2 corners[3] = { float2(-1, -1), float2(3, -1), float2(-1, 3) };
  for (int i = 0; i < 3; ++i) {
    Particle p;
    p.pos = prim == 0 ? float4(corners[i], 0.5, 1) : float4(corners[i] * 0.05 - 0.95, 0.25, 1);
    p.colour = prim == 0 ? float3(1, 0.5, 0.25) : float3(0, 0, 1);
    stream.Append(p);
  }
}
Pixel Show(Particle p) { Pixel o; o.pos = p.pos; o.colour = p.colour; return o; }
float4 Shade(Pixel p) : SV_Target { return float4(p.colour, 1); }
technique10 Particles {
  pass Simulate < int StreamOutVertices = 64; > {
    SetVertexShader(CompileShader(vs_4_0, Emit()));
    SetGeometryShader(ConstructGSWithSO(CompileShader(gs_4_0, Spawn()), "POSITION.xyzw; COLOR0.xyz"));
    SetPixelShader(NULL);
  }
  pass Draw {
    SetVertexShader(CompileShader(vs_4_0, Show()));
    SetGeometryShader(NULL);
    SetPixelShader(CompileShader(ps_4_0, Shade()));
    SetRasterizerState(NoCull);
  }
}
)";

fxkit::DeviceOptions options() {
  fxkit::DeviceOptions o;
  o.target = {.formats = {.color = {VK_FORMAT_R8G8B8A8_UNORM}, .depth = VK_FORMAT_D32_SFLOAT},
              .vertex_layout = fxkit::Mesh::vertex_layout(),
              .front_faces = fxkit::Winding::counter_clockwise,
              .y_flip = fxkit::YFlip::negative_viewport};
  return o;
}

std::string text(const std::vector<fxkit::Message>& messages) {
  std::string out;
  for (const fxkit::Message& m : messages) out += m.rendered + "\n";
  return out;
}

class StreamOutputTest : public VulkanTest {
 protected:
  void SetUp() override {
    VulkanTest::SetUp();
    device_ = fxkit::Device::create(
        {ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(), ctx().queue_family()}, options(),
        errors_);
    ASSERT_TRUE(device_) << text(errors_);
  }
  // Captures stream-output pass `pass` of `technique` from 6 vertices (two triangles) and
  // copies its buffer `slot` and its counter out; the counter's bytes come first.
  std::vector<float> capture(fxkit::Technique& technique, uint32_t pass, uint32_t slot = 0) {
    const fxkit::StreamOutputBuffer out = technique.stream_output_buffer(pass, slot);
    EXPECT_TRUE(out.buffer && out.counter) << "slot " << slot;
    if (!out.buffer) return {};
    DiagnosticSink sink;
    auto copy = Buffer::create(ctx(), {4 + out.size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::readback}, sink);
    EXPECT_TRUE(copy);
    if (!copy) return {};
    device_->begin_frame();
    bool captured = false;
    EXPECT_TRUE(device_->submit([&](VkCommandBuffer cmd) {
      captured = technique.begin_capture(cmd, pass);
      if (captured) vkCmdDraw(cmd, 6, 1, 0, 0);
      technique.end_capture();
      const VkBufferCopy count{0, 0, 4}, vertices{0, 4, out.size};
      vkCmdCopyBuffer(cmd, out.counter, copy->handle(), 1, &count);
      vkCmdCopyBuffer(cmd, out.buffer, copy->handle(), 1, &vertices);
      memory_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                     VK_ACCESS_HOST_READ_BIT);
    }));
    EXPECT_TRUE(captured);
    std::vector<float> words(size_t(out.size / 4) + 1);
    EXPECT_TRUE(copy->read(words.data(), words.size() * 4));
    return words;
  }
  static uint32_t byte_count(const std::vector<float>& words) {
    uint32_t n = 0;
    std::memcpy(&n, words.data(), 4);
    return n;
  }
  std::vector<fxkit::Message> errors_;
  std::unique_ptr<fxkit::Device> device_;
};

TEST_F(StreamOutputTest, CapturesTheTrianglesTheGeometryShaderEmits) {
  fxkit::Effect effect = device_->load(write_effect("so_particles.fx", kParticles));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  fxkit::Technique technique = effect.technique("Particles");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  EXPECT_TRUE(technique.stream_output_pass(0));
  EXPECT_FALSE(technique.stream_output_pass(1));
  const fxkit::StreamOutputBuffer out = technique.stream_output_buffer(0);
  EXPECT_EQ(out.stride, 28u);  // float4 + float3
  EXPECT_EQ(out.size, 64u * 28u) << "StreamOutVertices";
  EXPECT_FALSE(technique.stream_output_buffer(0, 1).buffer) << "the declaration writes slot 0 only";

  const std::vector<float> words = capture(technique, 0);
  ASSERT_FALSE(words.empty());
  EXPECT_EQ(byte_count(words), 6u * 28u) << "two triangles of three vertices";
  const float expected[6][7] = {
      {-1, -1, 0.5f, 1, 1, 0.5f, 0.25f}, {3, -1, 0.5f, 1, 1, 0.5f, 0.25f}, {-1, 3, 0.5f, 1, 1, 0.5f, 0.25f},
      {-1, -1, 0.25f, 1, 0, 0, 1},       {-0.8f, -1, 0.25f, 1, 0, 0, 1},   {-1, -0.8f, 0.25f, 1, 0, 0, 1},
  };
  for (size_t v = 0; v < 6; ++v)
    for (size_t c = 0; c < 7; ++c)
      EXPECT_NEAR(words[1 + v * 7 + c], expected[v][c], 1e-5f) << "vertex " << v << " component " << c;
}

// The D3D10 particle pattern: capture, then a later pass draws every captured vertex.
TEST_F(StreamOutputTest, ALaterPassDrawsTheCapturedVertices) {
  std::vector<fxkit::Message> errors;
  auto image = fxkit::Offscreen::create(*device_, 32, 32, errors);
  ASSERT_TRUE(image) << text(errors);
  fxkit::Effect effect = device_->load(write_effect("so_particles_drawn.fx", kParticles));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  fxkit::Technique technique = effect.technique("Particles");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  device_->begin_frame();
  bool captured = false, refused = false, drawn = false;
  ASSERT_TRUE(device_->submit([&](VkCommandBuffer cmd) {
    captured = technique.begin_capture(cmd, 0);
    if (captured) vkCmdDraw(cmd, 6, 1, 0, 0);
    technique.end_capture();
    image->begin(cmd);
    if (technique.begin(cmd, image->viewport(), image->scissor())) {
      refused = !technique.apply(0);
      drawn = technique.draw_stream_output(cmd, 1, 0);
    }
    technique.end();
    image->end(cmd);
  }));
  EXPECT_TRUE(captured) << text(effect.messages());
  EXPECT_TRUE(refused) << "a stream-output pass is captured, not applied";
  EXPECT_TRUE(drawn) << text(effect.messages());
  const std::vector<uint8_t> rgba = image->read_rgba8();
  auto pixel = [&](uint32_t x, uint32_t y) {
    const size_t at = (size_t(y) * image->width() + x) * 4;
    return std::array<int, 3>{rgba.at(at), rgba.at(at + 1), rgba.at(at + 2)};
  };
  EXPECT_EQ(pixel(16, 16), (std::array<int, 3>{255, 128, 64}));  // the big triangle
  EXPECT_EQ(pixel(31, 31), (std::array<int, 3>{255, 128, 64}));
  // The sliver at clip (-1, -1): the negative viewport puts it at the bottom left.
  EXPECT_EQ(pixel(0, 31), (std::array<int, 3>{0, 0, 255}));
}

// $SKIP gaps, masks that name every component, and a second output buffer (slot 1:), from a
// vertex shader handed to ConstructGSWithSO (no geometry stage) in fx_5_0's form with no
// rasterized stream.
TEST_F(StreamOutputTest, GapsMasksAndASecondBufferFromAVertexShader) {
  fxkit::Effect effect = device_->load(write_effect("so_layout.fx", R"(
struct Out { float4 pos : POSITION; float3 n : NORMAL; float2 uv : TEXCOORD1; };
Out VS(uint id : SV_VertexID) {
  Out o;
  o.pos = float4(id, 1, 2, 3);
  o.n = float3(10 + id, 20, 30);
  o.uv = float2(-float(id), 0.5);
  return o;
}
technique11 Layout {
  pass Capture {
    SetGeometryShader(ConstructGSWithSO(CompileShader(vs_5_0, VS()),
                      "POSITION.xyzw; $SKIP.xy; 1:NORMAL.xyz; 1:$SKIP; 1:TEXCOORD1", NULL, NULL, NULL, -1));
    SetPixelShader(NULL);
  }
}
)"));
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  fxkit::Technique technique = effect.technique("Layout");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  EXPECT_EQ(technique.stream_output_buffer(0, 0).stride, 24u);  // 16 + a gap of 8
  EXPECT_EQ(technique.stream_output_buffer(0, 1).stride, 36u);  // 12 + a gap of 16 + 8
  const std::vector<float> slot0 = capture(technique, 0, 0);
  ASSERT_FALSE(slot0.empty());
  EXPECT_EQ(byte_count(slot0), 6u * 24u);
  const std::vector<float> slot1 = capture(technique, 0, 1);
  ASSERT_FALSE(slot1.empty());
  EXPECT_EQ(byte_count(slot1), 6u * 36u);
  for (uint32_t v = 0; v < 6; ++v) {
    const float* a = &slot0[1 + v * 6];
    EXPECT_EQ((std::array<float, 4>{a[0], a[1], a[2], a[3]}), (std::array<float, 4>{float(v), 1, 2, 3})) << v;
    const float* b = &slot1[1 + v * 9];
    EXPECT_EQ((std::array<float, 3>{b[0], b[1], b[2]}), (std::array<float, 3>{10.0f + v, 20, 30})) << v;
    EXPECT_EQ((std::array<float, 2>{b[7], b[8]}), (std::array<float, 2>{-float(v), 0.5f})) << v;
  }
}

// Vulkan captures whole output variables: an output the shader does not write is a located
// error of the effect; a mask narrower than its output and a rasterized stream past 0 compile,
// as fxc compiles them, with a located warning, and cannot run; a declaration naming every
// component (or none) captures.
TEST_F(StreamOutputTest, DeclarationsVulkanCannotCaptureAreErrorsAtTheirPlace) {
  constexpr const char* kShader = R"(
struct Out { float4 pos : POSITION; float3 n : NORMAL; };
Out VS(uint id : SV_VertexID) { Out o; o.pos = float4(id, 0, 0, 1); o.n = float3(0, 1, 0); return o; }
)";
  fxkit::Effect refused = device_->load(write_effect("so_refused.fx", std::string(kShader) + R"(
technique11 Narrow { pass P { SetGeometryShader(ConstructGSWithSO(CompileShader(vs_5_0, VS()), "NORMAL.xy")); } }
technique11 Missing { pass P { SetGeometryShader(ConstructGSWithSO(CompileShader(vs_5_0, VS()), "TANGENT.xyz")); } }
technique11 Stream2 {
  pass P { SetGeometryShader(ConstructGSWithSO(CompileShader(vs_5_0, VS()), "POSITION", NULL, NULL, NULL, 2)); }
}
)"));
  EXPECT_FALSE(refused.ok());
  const std::string messages = text(refused.messages());
  EXPECT_NE(messages.find("so_refused.fx:5:97: warning: 'NORMAL' is captured whole"), std::string::npos) << messages;
  EXPECT_NE(messages.find("so_refused.fx:6:98: error: the vertex shader writes no output 'TANGENT'"), std::string::npos)
      << messages;
  EXPECT_NE(messages.find("[unsupported-stream-output-decl]"), std::string::npos) << messages;
  EXPECT_NE(messages.find("[unsupported-stream-output-mask]"), std::string::npos) << messages;
  // A rasterized stream past 0 compiles, as fxc compiles it, and cannot run.
  EXPECT_NE(messages.find("so_refused.fx:8:30: warning: rasterized stream 2"), std::string::npos) << messages;

  fxkit::Effect whole = device_->load(write_effect("so_whole.fx", std::string(kShader) + R"(
technique11 Whole { pass P { SetGeometryShader(ConstructGSWithSO(CompileShader(vs_5_0, VS()), "NORMAL; POSITION.")); } }
technique11 Stream1 {
  pass P { SetGeometryShader(ConstructGSWithSO(CompileShader(vs_5_0, VS()), "POSITION", "1:NORMAL", NULL, NULL, 0)); }
}
)"));
  ASSERT_TRUE(whole.ok()) << text(whole.messages());
  const std::string stream1 = whole.technique("Stream1").reason();
  EXPECT_NE(stream1.find("stream 1's declaration: the shader writes stream 0 only"), std::string::npos) << stream1;
  fxkit::Technique technique = whole.technique("Whole");
  ASSERT_TRUE(technique.valid()) << technique.reason();
  EXPECT_EQ(technique.stream_output_buffer(0).stride, 28u) << "NORMAL unmasked is its 3 components";
}

// An engine's device created without VK_EXT_transform_feedback: the technique is refused
// with the reason (technique validation, which select runs, gives the same one at
// ConstructGSWithSO: TechniqueValidation.StreamOutputNeedsTransformFeedback).
TEST_F(StreamOutputTest, ADeviceWithoutTransformFeedbackRefusesTheTechnique) {
  VkPhysicalDeviceFeatures core{};
  core.geometryShader = VK_TRUE;
  VkPhysicalDeviceVulkan13Features v13{};
  v13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  v13.dynamicRendering = VK_TRUE;
  v13.maintenance4 = VK_TRUE;
  VkDeviceCreateInfo created{};
  created.pNext = &v13;
  created.pEnabledFeatures = &core;
  const auto [device, queue] = create_engine_device(ctx(), created);
  ASSERT_TRUE(device);
  {
    std::vector<fxkit::Message> errors;
    auto wrapped = fxkit::Device::create(
        {ctx().instance(), ctx().physical_device(), device, queue, ctx().queue_family(), &created}, options(), errors);
    ASSERT_TRUE(wrapped) << text(errors);
    // A technique the device draws, so the effect loads.
    fxkit::Effect effect = wrapped->load(write_effect("so_without_xfb.fx", std::string(kParticles) + R"(
float4 Flat(float4 p : POSITION) : SV_Position { return p; }
float4 White() : SV_Target { return 1; }
technique10 Plain { pass P { SetVertexShader(CompileShader(vs_4_0, Flat())); SetPixelShader(CompileShader(ps_4_0, White())); } }
)"));
    ASSERT_TRUE(effect.ok()) << text(effect.messages());
    fxkit::Technique technique = effect.technique("Particles");
    EXPECT_FALSE(technique.valid());
    EXPECT_NE(technique.reason().find("VK_EXT_transform_feedback"), std::string::npos) << technique.reason();
    EXPECT_NE(technique.reason().find("pass 'Simulate'"), std::string::npos) << technique.reason();
    EXPECT_FALSE(technique.stream_output_pass(0));
  }
  vkDestroyDevice(device, nullptr);
}

}  // namespace
}  // namespace fx::vk::testing
