// What the public API tells an application about its effect (Effect::messages, Reload): a
// broken edit reported as `fxkit check` reports it (once per distinct error, with the source
// line, caret and did-you-mean), and a refused set() that leaves the messages once it is no
// longer true.
#include <gtest/gtest.h>

#include <fstream>

#include "../vulkan/effect_test_util.h"
#include "effect_check.h"
#include "fx/compile/shader_compiler.h"
#include "fxkit/fxkit.h"
#include "patience.h"

namespace fx::vk::testing {
namespace {

// Five techniques whose pixel shaders call one function; `light` is the name it reads.
std::string shared_function_effect(const std::string& light) {
  std::string text = R"(float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
float3 LightDirection = {0.3, -0.8, -0.5};
float4 Tint = {0.9, 0.6, 0.3, 1.0};
float4 Shade(float3 n) { return Tint * saturate(dot(n, -)" +
                     light + R"()); }
float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProjection); }
float4 PS() : COLOR0 { return Shade(float3(0, 0, 1)); }
)";
  for (int t = 0; t < 5; ++t)
    text += "technique t" + std::to_string(t) +
            " { pass p0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
  return text;
}

std::string text(const std::vector<fxkit::Message>& messages) {
  std::string s;
  for (const auto& m : messages) s += m.rendered;
  return s;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// What `fxkit check FILE` prints for the file's diagnostics.
std::string checked_text(const std::string& path) {
  fx::ShaderCompiler compiler;
  fx::tools::EffectCheckSettings settings;
  settings.compiler = &compiler;
  return fx::tools::check_effect(path, settings).text;
}

class ApiMessagesTest : public VulkanTest {
 protected:
  void SetUp() override {
    VulkanTest::SetUp();
    fxkit::DeviceOptions o;
    o.target = {.formats = {.color = {VK_FORMAT_R8G8B8A8_UNORM}, .depth = VK_FORMAT_D32_SFLOAT},
                .vertex_layout = fxkit::Mesh::vertex_layout(),
                .front_faces = fxkit::Winding::counter_clockwise,
                .y_flip = fxkit::YFlip::negative_viewport};
    device_ = fxkit::Device::create(
        {ctx().instance(), ctx().physical_device(), ctx().device(), ctx().queue(), ctx().queue_family()}, o, errors_);
    ASSERT_TRUE(device_) << text(errors_);
  }
  void TearDown() override {
    device_.reset();
    VulkanTest::TearDown();
  }
  // Writes `content` over `path` and runs frames until begin_frame() reports the reload.
  std::vector<fxkit::Reload> rewrite_and_reload(const std::string& path, const std::string& content) {
    std::ofstream(path, std::ios::trunc) << content;
    std::vector<fxkit::Reload> reloads;
    const auto give_up = std::chrono::steady_clock::now() + fx::testing::patience();
    while (reloads.empty() && std::chrono::steady_clock::now() < give_up) {
      device_->wait_for_reload(std::chrono::milliseconds(100));
      reloads = device_->begin_frame();
    }
    return reloads;
  }
  std::unique_ptr<fxkit::Device> device_;
  std::vector<fxkit::Message> errors_;
};

TEST_F(ApiMessagesTest, ABrokenEditIsReportedOnceWithCaretAndDidYouMeanAsCheckReportsIt) {
  const std::string path = write_effect("api_messages_shared.fx", shared_function_effect("LightDirection"));
  fxkit::Effect effect = device_->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());

  const std::vector<fxkit::Reload> reloads = rewrite_and_reload(path, shared_function_effect("LightDirecton"));
  ASSERT_EQ(reloads.size(), 1u);
  ASSERT_EQ(reloads[0].kind, fxkit::Reload::Kind::failed) << reloads[0].str();
  const std::string reported = text(reloads[0].messages);
  EXPECT_EQ(count(reported, ": error: "), 1u) << reported;
  EXPECT_NE(reported.find("did you mean 'LightDirection'?"), std::string::npos) << reported;
  EXPECT_NE(reported.find("\nfloat4 Shade(float3 n)"), std::string::npos) << "the source line\n" << reported;
  EXPECT_NE(reported.find("^"), std::string::npos) << "a caret\n" << reported;
  // The semantic model reports it before glslang compiles any pass, so once, with where the
  // name it suggests is declared (as check reports it and the editor shows it).
  EXPECT_NE(reported.find("note: 'LightDirection' is declared here"), std::string::npos) << reported;

  const std::string check = checked_text(path);
  EXPECT_EQ(reported, check) << "Reload:\n" << reported << "fxkit check:\n" << check;
  EXPECT_NE(reloads[0].str().find(check), std::string::npos) << reloads[0].str();
  EXPECT_EQ(text(effect.messages()), check) << "messages() of the failed reload";

  // A first load that fails says the same.
  const std::string broken = write_effect("api_messages_broken.fx", shared_function_effect("LightDirecton"));
  fxkit::Effect never = device_->load(broken);
  EXPECT_FALSE(never.ok());
  EXPECT_EQ(text(never.messages()), checked_text(broken));
}

TEST_F(ApiMessagesTest, ARefusedSetLeavesTheMessagesWhenTheParameterIsSetOrTheEffectReloads) {
  const std::string path = write_effect("api_messages_set.fx", shared_function_effect("LightDirection"));
  fxkit::Effect effect = device_->load(path);
  ASSERT_TRUE(effect.ok()) << text(effect.messages());
  auto refusals = [&effect] { return count(text(effect.messages()), "[parameter-set]"); };
  const fxkit::Param tint = effect.param("Tint");

  EXPECT_FALSE(effect.set(tint, 1.0f)) << "a float for a float4";
  EXPECT_EQ(refusals(), 1u);
  device_->begin_frame();
  EXPECT_EQ(refusals(), 1u) << "still true: the value is not the application's";
  EXPECT_FALSE(effect.set(tint, 2.0f));
  EXPECT_EQ(refusals(), 1u) << "one parameter, one reason: the latest";
  EXPECT_TRUE(effect.set(tint, {0.1f, 0.2f, 0.3f, 1.0f}));
  EXPECT_EQ(refusals(), 0u) << text(effect.messages());

  EXPECT_FALSE(effect.set(tint, 1.0f));
  EXPECT_EQ(refusals(), 1u);
  const std::vector<fxkit::Reload> reloads =
      rewrite_and_reload(path, shared_function_effect("LightDirection") + "float Extra = 1;\n");
  ASSERT_EQ(reloads.size(), 1u);
  EXPECT_EQ(reloads[0].kind, fxkit::Reload::Kind::reloaded) << reloads[0].str();
  EXPECT_EQ(refusals(), 0u) << "a refusal of the replaced version\n" << text(effect.messages());
}

}  // namespace
}  // namespace fx::vk::testing
