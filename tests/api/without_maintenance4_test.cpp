// An engine's device created without Vulkan 1.3's maintenance4, wrapped: Direct3D effects
// write vertex outputs their pixel shaders never read, which Vulkan without maintenance4
// reports once per output and pipeline (Shader-OutputNotConsumed). fxkit removes those
// outputs, so the validation layer has nothing to say.
#include <gtest/gtest.h>

#include "../vulkan/effect_test_util.h"
#include "fxkit/fxkit.h"

namespace fx::vk::testing {
namespace {

// Four varyings the pixel shader ignores, one it reads.
constexpr const char* kChattyVertexShader = R"(
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
struct V { float4 pos : POSITION; float4 colour : COLOR0; float2 uv : TEXCOORD0; float3 n : TEXCOORD1;
           float3 t : TEXCOORD2; float4 extra : TEXCOORD3; };
V VS(float4 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) {
  V o;
  o.pos = mul(p, WorldViewProjection);
  o.colour = float4(abs(n), 1);
  o.uv = uv;
  o.n = n;
  o.t = n.zxy;
  o.extra = p;
  return o;
}
float4 PS(float4 colour : COLOR0) : COLOR0 { return colour; }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
)";

size_t outputs_not_consumed(const Context& ctx) {
  size_t n = 0;
  for (const ValidationMessage& m : ctx.validation_messages())
    n += m.id_name.find("OutputNotConsumed") != std::string::npos ? 1 : 0;
  return n;
}

TEST_F(VulkanTest, AWrappedDeviceWithoutMaintenance4DrawsWithoutOutputNotConsumed) {
  // The engine's device: this physical device, dynamic rendering and nothing else.
  VkPhysicalDeviceVulkan13Features v13{};
  v13.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES;
  v13.dynamicRendering = VK_TRUE;
  VkDeviceCreateInfo created{};
  created.pNext = &v13;
  const auto [device, queue] = create_engine_device(ctx(), created);
  ASSERT_TRUE(device);

  std::string problems;
  uint8_t centre_green = 0;
  {
    fxkit::DeviceOptions o;
    o.target = {.formats = {.color = {VK_FORMAT_R8G8B8A8_UNORM}, .depth = VK_FORMAT_D32_SFLOAT},
                .vertex_layout = fxkit::Mesh::vertex_layout(),
                .front_faces = fxkit::Winding::counter_clockwise,
                .y_flip = fxkit::YFlip::negative_viewport};
    std::vector<fxkit::Message> errors;
    auto wrapped = fxkit::Device::create(
        {ctx().instance(), ctx().physical_device(), device, queue, ctx().queue_family(), &created}, o, errors);
    auto mesh = wrapped ? fxkit::Mesh::create(*wrapped, "sphere", errors) : nullptr;
    auto image = wrapped ? fxkit::Offscreen::create(*wrapped, 32, 32, errors) : nullptr;
    ASSERT_TRUE(wrapped && mesh && image) << (errors.empty() ? "" : errors[0].rendered);
    fxkit::Effect effect = wrapped->load(write_effect("without_maintenance4.fx", kChattyVertexShader));
    for (const fxkit::Message& m : effect.messages()) problems += m.rendered;
    ASSERT_TRUE(effect.ok()) << problems;
    effect.set_scene(fxkit::Scene::framing(mesh->radius(), 1.0f));
    fxkit::Technique technique = effect.technique("T");
    EXPECT_TRUE(wrapped->submit([&](VkCommandBuffer cmd) {
      wrapped->begin_frame();
      image->begin(cmd);
      if (technique.begin(cmd, image->viewport(), image->scissor()))
        for (uint32_t pass = 0; pass < technique.pass_count(); ++pass)
          if (technique.apply(pass)) mesh->draw(cmd);
      technique.end();
      image->end(cmd);
    }));
    const std::vector<uint8_t> rgba = image->read_rgba8();
    centre_green = rgba[(16 * 32 + 16) * 4 + 1];
  }
  vkDestroyDevice(device, nullptr);
  EXPECT_GT(centre_green, 0) << "the sphere is drawn with the colour the pixel shader reads";
  EXPECT_EQ(outputs_not_consumed(ctx()), 0u) << describe_messages(ctx());
}

}  // namespace
}  // namespace fx::vk::testing
