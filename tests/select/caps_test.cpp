// DeviceCaps: shipped profiles, JSON round trips, vulkaninfo reports, a live device,
// and requirement parsing with its reason texts.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "fx/select/caps_requirement.h"
#include "fx/select/caps_sources.h"

namespace {

nlohmann::json read_fixture(const std::string& name) {
  std::ifstream in(std::string(FXKIT_SOURCE_DIR) + "/tests/select/fixtures/" + name);
  EXPECT_TRUE(in.good()) << name;
  return nlohmann::json::parse(in, nullptr, false);
}

fx::DeviceCaps profile(const char* name) {
  fx::DiagnosticSink sink;
  auto caps = fx::load_caps_profile(name, sink);
  EXPECT_TRUE(caps.has_value()) << name;
  EXPECT_FALSE(sink.has_errors()) << (sink.diagnostics().empty() ? "" : sink.diagnostics()[0].message);
  return caps.value_or(fx::DeviceCaps{});
}

TEST(CapsProfiles, EveryShippedProfileLoadsAndRoundTrips) {
  std::vector<std::string> names = fx::caps_profile_names();
  ASSERT_EQ(names, (std::vector<std::string>{"dx6", "dx7", "dx8", "dx8_1", "dx9", "dx9c", "modern"}));
  for (const auto& n : names) {
    fx::DeviceCaps caps = profile(n.c_str());
    EXPECT_EQ(caps.name, n);
    EXPECT_FALSE(caps.description.empty());
    nlohmann::json j = caps;
    EXPECT_EQ(j.get<fx::DeviceCaps>(), caps) << n;
    EXPECT_EQ(nlohmann::json(j.get<fx::DeviceCaps>()), j) << n;
  }
}

TEST(CapsProfiles, NamesAreCaseInsensitiveAndUnknownOnesSuggest) {
  EXPECT_EQ(profile("DX7").name, "dx7");
  fx::DiagnosticSink sink;
  EXPECT_FALSE(fx::load_caps_profile("dx77", sink).has_value());
  ASSERT_EQ(sink.diagnostics().size(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "unknown-caps-profile");
  EXPECT_NE(sink.diagnostics()[0].message.find("did you mean 'dx7'"), std::string::npos)
      << sink.diagnostics()[0].message;
}

TEST(CapsProfiles, GenerationsFollowTheSeed) {
  fx::DeviceCaps dx6 = profile("dx6"), dx7 = profile("dx7"), dx8 = profile("dx8"), dx81 = profile("dx8_1"),
                 dx9 = profile("dx9"), modern = profile("modern");
  // "almost all can do subtractive blending, and some can do dot product blending"
  EXPECT_TRUE(dx6.features.subtract);
  EXPECT_FALSE(dx6.features.dot3);
  EXPECT_TRUE(dx7.features.dot3 && dx7.features.subtract);
  EXPECT_FALSE(fx::supports(dx7, "ps_1_1"));
  EXPECT_TRUE(fx::supports(dx8, "ps.1.1"));
  EXPECT_FALSE(fx::supports(dx8, "ps_1_4"));
  EXPECT_TRUE(fx::supports(dx81, "PS_1_4"));  // the strand seed's four lights per pass
  EXPECT_TRUE(fx::supports(dx9, "ps_2_0"));
  EXPECT_FALSE(fx::supports(dx9, "ps_3_0"));
  EXPECT_TRUE(fx::supports(profile("dx9c"), "ps_3_0"));
  EXPECT_EQ(dx6.generation, fx::CapsGeneration::dx6);
  EXPECT_EQ(dx81.generation, fx::CapsGeneration::dx8);
  // A modern device compiles HLSL SM2-5 through glslang, but has no SM1 and no stages.
  for (const char* p : {"vs_2_0", "ps_2_0", "ps_3_0", "ps_4_0", "ps_5_0", "glsl_450"})
    EXPECT_TRUE(fx::supports(modern, p)) << p;
  for (const char* p : {"vs_1_1", "ps_1_1", "ps_1_4", "glsl_110"}) EXPECT_FALSE(fx::supports(modern, p)) << p;
  EXPECT_FALSE(modern.features.fixed_function_stages);
  EXPECT_FALSE(modern.features.dot3);
  EXPECT_EQ(modern.generation, fx::CapsGeneration::vulkan);
}

TEST(CapsJson, WrongTypesAreReportedNotThrown) {
  nlohmann::json j = {{"name", 7},
                      {"generation", "dx12"},
                      {"shader_profiles", {"ps_2_0", 3}},
                      {"limits", {{"samplers", -1}, {"texture_size", 2048}, {"warp", 2}}},
                      {"features", {{"dot3", "yes"}, {"cube_maps", true}}},
                      {"colour", "red"}};
  fx::DiagnosticSink sink;
  EXPECT_FALSE(fx::caps_from_json(j, sink).has_value());
  EXPECT_EQ(sink.error_count(), 7u);
  for (const auto& d : sink.diagnostics()) EXPECT_EQ(d.id, "caps-json");
  // The ADL form keeps what it could read.
  fx::DeviceCaps caps = j.get<fx::DeviceCaps>();
  EXPECT_EQ(caps.limits.texture_size, 2048u);
  EXPECT_TRUE(caps.features.cube_maps);
  EXPECT_EQ(caps.shader_profiles, std::vector<std::string>{"ps_2_0"});
  EXPECT_NO_THROW((void)nlohmann::json::array().get<fx::DeviceCaps>());
}

TEST(CapsVulkaninfo, ReadsTheRealReportFormat) {
  nlohmann::json report = read_fixture("vulkaninfo_lavapipe.json");
  ASSERT_FALSE(report.is_discarded());
  fx::DiagnosticSink sink;
  auto caps = fx::caps_from_vulkaninfo_json(report, sink);
  ASSERT_TRUE(caps.has_value());
  EXPECT_FALSE(sink.has_errors());
  EXPECT_EQ(caps->name, "llvmpipe (LLVM 15.0.6, 256 bits)");
  EXPECT_EQ(caps->generation, fx::CapsGeneration::vulkan);
  EXPECT_TRUE(caps->vulkan.present);
  EXPECT_EQ(caps->vulkan.device_type, "cpu");
  EXPECT_EQ(VK_API_VERSION_MINOR(caps->vulkan.api_version), 3u);
  EXPECT_TRUE(fx::supports(*caps, "ps_5_0"));
  EXPECT_TRUE(fx::supports(*caps, "gs_5_0"));  // geometryShader: true in the report
  EXPECT_TRUE(fx::supports(*caps, "ps_1_4"));  // shader model 1 assembly, translated to HLSL
  EXPECT_EQ(caps->limits.texture_size, 16384u);
  EXPECT_EQ(caps->limits.render_targets, 8u);
  EXPECT_EQ(caps->limits.interpolators, 32u);  // 128 components / 4
  EXPECT_EQ(caps->limits.samplers, 32u);
  EXPECT_EQ(caps->limits.uniform_bytes, 65536u);
  EXPECT_TRUE(caps->features.anisotropic_filtering);
  EXPECT_TRUE(caps->features.float_textures);
  EXPECT_TRUE(caps->features.fixed_function_stages);  // generated texture stages
  EXPECT_FALSE(caps->features.alpha_test);
  const fx::FormatSupport* half4 = fx::find_format(*caps, "VK_FORMAT_R16G16B16A16_SFLOAT");
  ASSERT_NE(half4, nullptr);
  EXPECT_TRUE(half4->sampled && half4->color_attachment && half4->blend);
  const fx::FormatSupport* depth = fx::find_format(*caps, "D32_SFLOAT");
  ASSERT_NE(depth, nullptr);
  EXPECT_TRUE(depth->depth_stencil);
  EXPECT_FALSE(depth->color_attachment);
  EXPECT_TRUE(std::binary_search(caps->vulkan.extensions.begin(), caps->vulkan.extensions.end(),
                                 "VK_EXT_extended_dynamic_state3"));
  EXPECT_TRUE(std::binary_search(caps->vulkan.features.begin(), caps->vulkan.features.end(), "dynamicRendering"));
  EXPECT_FALSE(std::binary_search(caps->vulkan.features.begin(), caps->vulkan.features.end(),
                                  "depthBounds"));  // false in the report
  nlohmann::json j = *caps;
  EXPECT_EQ(j.get<fx::DeviceCaps>(), *caps);
}

TEST(CapsVulkaninfo, MalformedReportsAreDiagnosed) {
  fx::DiagnosticSink sink;
  EXPECT_FALSE(fx::caps_from_vulkaninfo_json(nlohmann::json::array(), sink).has_value());
  EXPECT_FALSE(fx::caps_from_vulkaninfo_json({{"capabilities", {{"device", 1}}}}, sink).has_value());
  EXPECT_FALSE(
      fx::caps_from_vulkaninfo_json({{"capabilities", {{"device", {{"properties", {{"x", 1}}}}}}}}, sink).has_value());
  EXPECT_EQ(sink.error_count(), 3u);
  for (const auto& d : sink.diagnostics()) EXPECT_EQ(d.id, "caps-vulkaninfo");
}

// A live device: whichever the loader offers (CI forces lavapipe via VK_ICD_FILENAMES).
class LiveDevice : public ::testing::Test {
 protected:
  void SetUp() override {
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pApplicationInfo = &app;
    if (vkCreateInstance(&info, nullptr, &instance_) != VK_SUCCESS) GTEST_SKIP() << "no Vulkan instance";
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance_, &count, nullptr);
    devices_.resize(count);
    vkEnumeratePhysicalDevices(instance_, &count, devices_.data());
    if (devices_.empty()) GTEST_SKIP() << "no Vulkan device";
  }
  void TearDown() override {
    if (instance_) vkDestroyInstance(instance_, nullptr);
  }
  VkInstance instance_ = VK_NULL_HANDLE;
  std::vector<VkPhysicalDevice> devices_;
};

TEST_F(LiveDevice, CapsMatchWhatVulkanGuarantees) {
  for (VkPhysicalDevice d : devices_) {
    fx::DeviceCaps caps = fx::caps_from_physical_device(d);
    SCOPED_TRACE(caps.name);
    EXPECT_FALSE(caps.name.empty());
    EXPECT_TRUE(caps.vulkan.present);
    EXPECT_EQ(caps.generation, fx::CapsGeneration::vulkan);
    EXPECT_TRUE(fx::supports(caps, "vs_2_0") && fx::supports(caps, "ps_5_0"));
    // Emulated: assembly translated to HLSL, texture stages generated (fx/emulation).
    EXPECT_TRUE(fx::supports(caps, "ps_1_1"));
    EXPECT_TRUE(caps.features.fixed_function_stages);
    // Vulkan 1.0 minimum limits.
    EXPECT_GE(caps.limits.texture_size, 4096u);
    EXPECT_GE(caps.limits.render_targets, 4u);
    EXPECT_GE(caps.limits.uniform_bytes, 16384u);
    EXPECT_GE(caps.limits.samplers, 16u);
    EXPECT_GE(caps.limits.interpolators, 15u);
    EXPECT_TRUE(caps.features.cube_maps);
    EXPECT_EQ(caps.vulkan.formats.size(), 25u);
    const fx::FormatSupport* rgba8 = fx::find_format(caps, "R8G8B8A8_UNORM");
    ASSERT_NE(rgba8, nullptr);
    EXPECT_TRUE(rgba8->sampled && rgba8->color_attachment && rgba8->blend);  // mandatory
    nlohmann::json j = caps;
    EXPECT_EQ(j.get<fx::DeviceCaps>(), caps);
  }
}

TEST_F(LiveDevice, AgreesWithVulkaninfoForTheSameDevice) {
  auto from_report = fx::caps_from_vulkaninfo_json(read_fixture("vulkaninfo_lavapipe.json"));
  ASSERT_TRUE(from_report.has_value());
  bool compared = false;
  for (VkPhysicalDevice d : devices_) {
    fx::DeviceCaps live = fx::caps_from_physical_device(d);
    if (live.name != from_report->name) continue;
    compared = true;
    EXPECT_EQ(live.shader_profiles, from_report->shader_profiles);
    EXPECT_EQ(live.limits, from_report->limits);
    EXPECT_EQ(live.features, from_report->features);
    EXPECT_EQ(live.vulkan.features, from_report->vulkan.features);
    EXPECT_EQ(live.vulkan.formats, from_report->vulkan.formats);
  }
  if (!compared) GTEST_SKIP() << "the fixture's device is not present";
}

TEST(CapsRequirements, ParseEveryKind) {
  std::vector<std::string> errors;
  auto reqs = fx::parse_caps_requirements(
      "ps.1.4, dot3 textures>=4 mrt>=2 vk:samplerAnisotropy ext:VK_KHR_push_descriptor "
      "format:VK_FORMAT_R16G16B16A16_SFLOAT/blend format:D32_SFLOAT glsl_450",
      &errors);
  EXPECT_TRUE(errors.empty());
  std::vector<std::string> spelled;
  for (const auto& r : reqs) spelled.push_back(r.spelling());
  EXPECT_EQ(spelled,
            (std::vector<std::string>{"ps_1_4", "dot3", "simultaneous_textures>=4", "render_targets>=2",
                                      "vk:samplerAnisotropy", "ext:VK_KHR_push_descriptor",
                                      "format:R16G16B16A16_SFLOAT/blend", "format:D32_SFLOAT/sampled", "glsl_450"}));
  fx::parse_caps_requirements("dott3 textures>=four warp>=2 format:R8_UNORM/eat", &errors);
  ASSERT_EQ(errors.size(), 4u);
  EXPECT_EQ(errors[0], "unknown requirement 'dott3'");
  EXPECT_EQ(errors[1], "'four' is not a whole number in 'textures>=four'");
  EXPECT_EQ(errors[2], "unknown limit 'warp'");
  EXPECT_EQ(errors[3], "unknown format usage 'eat'");
}

TEST(CapsRequirements, UnmetReasonsNameTheDevice) {
  fx::DeviceCaps dx7 = profile("dx7"), modern = profile("modern");
  EXPECT_EQ(fx::unmet_reason(dx7, fx::CapsRequirement::profile("ps_2_0")), "ps_2_0 not supported on dx7");
  EXPECT_EQ(fx::unmet_reason(dx7, fx::CapsRequirement::limit("textures", 4)),
            "needs 4 simultaneous_textures, dx7 has 2");
  EXPECT_EQ(fx::unmet_reason(dx7, fx::CapsRequirement::feature("dot3")), std::nullopt);
  EXPECT_EQ(fx::unmet_reason(modern, fx::CapsRequirement::feature("dot3")), "dot3 not supported on modern");
  std::string error;
  auto ext = fx::parse_caps_requirement("ext:VK_KHR_push_descriptor", &error);
  ASSERT_TRUE(ext);
  EXPECT_EQ(fx::unmet_reason(dx7, *ext), "extension VK_KHR_push_descriptor not supported on dx7");
  auto fmt = fx::parse_caps_requirement("format:R32G32B32A32_SFLOAT/filter_linear", &error);
  ASSERT_TRUE(fmt);
  EXPECT_EQ(fx::unmet_reason(modern, *fmt), "format R32G32B32A32_SFLOAT not usable for filter_linear on modern");
  auto lavapipe = fx::caps_from_vulkaninfo_json(read_fixture("vulkaninfo_lavapipe.json"));
  ASSERT_TRUE(lavapipe);
  EXPECT_EQ(fx::unmet_reason(*lavapipe, *ext), std::nullopt);
  auto depth_bounds = fx::parse_caps_requirement("vk:depthBounds", &error);
  ASSERT_TRUE(depth_bounds);
  EXPECT_EQ(fx::unmet_reason(*lavapipe, *depth_bounds),
            "Vulkan feature depthBounds not supported on llvmpipe (LLVM 15.0.6, 256 bits)");
}

}  // namespace
