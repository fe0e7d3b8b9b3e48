// Shared by the effect rendering tests: load an effect file, bind it to a preview on a
// mesh, render one frame with the standard semantics filled in.
#pragma once
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "fx/binding/effect_preview.h"
#include "fx/compile/effect_file.h"
#include "vulkan_fixture.h"

namespace fx::vk::testing {

inline std::string effects_dir() { return std::string(FXKIT_SOURCE_DIR) + "/effects"; }

// An effect, a preview and a binding of one to the other.
struct RenderedEffect {
  std::unique_ptr<EffectFile> effect;
  std::unique_ptr<EffectPreview> preview;
  std::unique_ptr<EffectBinding> binding;
  uint32_t technique = kNoIndex;
  uint32_t layout = 0;

  // Makes technique `t` the one render() draws, with a vertex layout for its inputs.
  void use_technique(uint32_t t) {
    technique = t;
    auto inputs = technique_vertex_inputs(*effect->model, *effect->programs, t);
    layout = binding->add_vertex_layout(preview->vertex_layout(inputs));
  }

  // Renders one frame; fails the test on diagnostics that are errors.
  std::optional<fx::Image> render() {
    DiagnosticSink sink;
    set_standard_semantics(*effect->params, *effect->model, preview->scene());
    auto image = preview->render(*binding, technique, layout, sink);
    EXPECT_TRUE(image.has_value()) << describe(sink);
    return image;
  }

  // The same frame read back as floats (bind_effect with a float colour format).
  std::optional<fx::ImageF> render_floats() {
    DiagnosticSink sink;
    set_standard_semantics(*effect->params, *effect->model, preview->scene());
    auto image = preview->render_floats(*binding, technique, layout, sink);
    EXPECT_TRUE(image.has_value()) << describe(sink);
    return image;
  }
};

// Loads `path` and binds it for `mesh` at `size`; `technique` "" = the first that can run;
// `preview_stand_ins`: textures no file fills get the preview's stand-ins (texture_stand_in.h);
// `diagnostics`: where loading and binding's diagnostics go (dropped when null).
inline std::unique_ptr<RenderedEffect> bind_effect(
    Context& ctx, const std::string& path, const std::string& technique = "", const std::string& mesh = "sphere",
    uint32_t size = 96, std::optional<DynamicStateSet> dynamic = std::nullopt,
    VkFormat color = VK_FORMAT_R8G8B8A8_UNORM, bool preview_stand_ins = false, DiagnosticSink* diagnostics = nullptr) {
  auto r = std::make_unique<RenderedEffect>();
  DiagnosticSink local;
  DiagnosticSink& sink = diagnostics ? *diagnostics : local;
  FrontEndOptions options;
  options.preprocessor.include_dirs = {effects_dir()};
  r->effect = EffectFile::load(path, options, sink);
  EXPECT_TRUE(r->effect) << describe(sink);
  if (!r->effect) return nullptr;
  auto m = make_mesh(mesh, sink);
  EXPECT_TRUE(m) << describe(sink);
  EffectPreviewDesc desc;
  desc.width = desc.height = size;
  desc.color_format = color;
  r->preview = EffectPreview::create(ctx, *m, desc, sink);
  EXPECT_TRUE(r->preview) << describe(sink);
  if (!r->preview) return nullptr;
  r->preview->textures().set_preview_stand_ins(preview_stand_ins);
  EffectBindingDesc bd = r->preview->binding_desc();
  bd.effect_dir = std::filesystem::path(path).parent_path();
  bd.dynamic = dynamic;
  r->binding = EffectBinding::create(ctx, *r->effect->model, *r->effect->programs, *r->effect->params,
                                     r->preview->textures(), r->preview->frames(), bd, sink);
  EXPECT_TRUE(r->binding) << describe(sink);
  if (!r->binding) return nullptr;
  const uint32_t t = technique.empty() ? r->binding->first_ok_technique() : r->effect->find_technique(technique);
  EXPECT_NE(t, kNoIndex) << technique;
  if (t == kNoIndex) return nullptr;
  EXPECT_TRUE(r->binding->technique_ok(t)) << r->binding->technique_reason(t);
  r->use_technique(t);
  return r;
}

inline std::string golden_path(const std::string& name) {
  return std::string(FXKIT_SOURCE_DIR) + "/tests/golden/" + name + ".png";
}

// Compares with tests/golden/NAME.png (3 levels per channel: lavapipe and GPUs round
// differently); FXKIT_UPDATE_GOLDEN=1 rewrites the file instead.
inline void expect_golden(const fx::Image& image, const std::string& name) {
  DiagnosticSink sink;
  const char* update = std::getenv("FXKIT_UPDATE_GOLDEN");
  if (update && std::string(update) == "1") {
    ASSERT_TRUE(write_png(golden_path(name), image, sink)) << describe(sink);
    return;
  }
  auto golden = read_png(golden_path(name), sink, 4);
  ASSERT_TRUE(golden) << "missing golden " << golden_path(name) << " (run with FXKIT_UPDATE_GOLDEN=1)";
  ASSERT_EQ(golden->width, image.width);
  ASSERT_EQ(golden->height, image.height);
  ImageDiff diff = compare(*golden, image, 3);
  EXPECT_EQ(diff.channels_over, 0u) << name << ": max difference " << diff.max_abs << " at " << diff.first_x << ","
                                    << diff.first_y;
}

// An engine's own device on `ctx`'s physical device with one graphics queue, created from
// `created` (the caller's feature chain and features, kept for fxkit::Device::create to read).
struct EngineDevice {
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
};
inline EngineDevice create_engine_device(const Context& ctx, VkDeviceCreateInfo& created) {
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue_info.queueFamilyIndex = ctx.queue_family();
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  created.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  created.queueCreateInfoCount = 1;
  created.pQueueCreateInfos = &queue_info;
  EngineDevice d;
  if (vkCreateDevice(ctx.physical_device(), &created, nullptr, &d.device) == VK_SUCCESS)
    vkGetDeviceQueue(d.device, ctx.queue_family(), 0, &d.queue);
  created.queueCreateInfoCount = 0;  // queue_info goes out of scope
  created.pQueueCreateInfos = nullptr;
  return d;
}

// Writes `text` to a fresh file under the test temp dir and returns its path.
inline std::string write_effect(const std::string& name, const std::string& text) {
  auto dir = std::filesystem::temp_directory_path() / ("fxkit_effect_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace fx::vk::testing
