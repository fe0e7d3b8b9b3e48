// What the public handles point at: fxkit's internals behind fxkit::Device and fxkit::Effect.
// Private to runtime/api.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fx/binding/effect_binding.h"
#include "fx/binding/effect_textures.h"
#include "fx/diagnostic.h"
#include "fx/reload/effect_library.h"
#include "fx/reload/vulkan_reload_backend.h"
#include "fx/source_manager.h"
#include "fx/vulkan/buffer.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/frame_resources.h"
#include "fxkit/device.h"

namespace fxkit::detail {

struct EffectState;

// Diagnostics as public messages (located through `sources` when given).
Message to_message(const fx::Diagnostic& d, const fx::SourceManager* sources);
std::vector<Message> to_messages(const std::vector<fx::Diagnostic>& ds, const fx::SourceManager* sources);
// A message about no place in a file.
Message to_message(fx::Severity severity, std::string code, std::string text);

// Annotations as public values, and one by name (nullptr when none).
Annotation to_public(const fx::Annotation& a);
const Annotation* find_annotation(const std::vector<Annotation>& annotations, std::string_view name);

// Why technique `t` of `version` cannot be drawn ("" when it can).
std::string technique_reason(const fx::EffectVersion& version, uint32_t t);

// The index of the technique `name` in `version` ("" = the effect's selection; kNoIndex
// when there is none).
uint32_t technique_index(const EffectState& s, const fx::EffectVersion& version, const std::string& name);

// The live version's binding with the application's resources bound, and the index `t` of
// the technique `name` (kept in the Technique's fields `serial`, `index`, `passes` while the
// version stays); null: none.
fx::vk::EffectBinding* live_binding(EffectState& s, const std::string& name, uint64_t& serial, uint32_t& index,
                                    uint32_t& passes, uint32_t& t);

// The pass-state facts of a Target (winding, Y convention, attachments).
fx::vk::RenderingFormats rendering_formats(const Formats& formats);
fx::vk::PassTargetInfo pass_target(const Target& target);

struct DeviceState {
  std::optional<fx::vk::Context> ctx;
  Target target;
  fx::vk::RenderingFormats formats;
  std::optional<fx::vk::FrameResources> frames;
  std::unique_ptr<fx::vk::EffectTextureCache> textures;
  std::unique_ptr<fx::vk::ReloadBackend> backend;
  std::unique_ptr<fx::EffectLibrary> library;
  fx::vk::Buffer default_attributes;                       // (0, 0, 0, 1) for Target::default_attribute_binding
  std::vector<std::weak_ptr<struct EffectState>> effects;  // loaded through this device
  std::vector<Message> warnings;                           // Device::warnings()

  // After load() and every poll(): each effect's `store` is its live version's.
  void refresh_stores();
};

// Technique::run_script's render targets and quad, for one version, technique and frame
// size (technique_script.cpp).
struct ScriptRun;

struct EffectState {
  fx::EffectHandle handle;
  const DeviceState* device = nullptr;  // the device it was loaded through; null once destroyed
  std::shared_ptr<ScriptRun> script;    // made by the first run_script, remade as it changes
  // The live version's parameter values (null when none): the setters' one indirection,
  // refreshed by the device where versions change (load, begin_frame, destruction).
  fx::ParameterStore* store = nullptr;
  fxkit::detail::DrawState* draw = nullptr;  // store's per-object state: Effect::set_matrix's inline path
  fx::vk::RenderingFormats formats;
  VkBuffer default_attributes = VK_NULL_HANDLE;    // bound at default_binding by begin()
  fx::vk::EffectTextureCache* textures = nullptr;  // the device's; null once it is destroyed
  uint32_t default_binding = 0;
  // The binding begin() started recording with (its version kept alive until end()), and
  // the same as Technique::apply's inline call.
  fx::vk::EffectBinding* recording = nullptr;
  PassApply pass_apply{&fx::vk::EffectBinding::apply_layout0, nullptr, &sink};
  std::shared_ptr<const fx::EffectVersion> recording_version;
  fx::vk::EffectBinding* capturing = nullptr;  // begin_capture()'s, until end_capture()
  // The binding of the version of serial `binding_serial` (0: none looked up yet).
  fx::vk::EffectBinding* binding = nullptr;
  uint64_t binding_serial = 0;
  // The application's images for texture parameters, bound to every version that goes live.
  struct AppTexture {
    std::string name;
    VkImageView view = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    fx::vk::ImageKind kind = fx::vk::ImageKind::image2d;
  };
  std::vector<AppTexture> app_textures;
  // The application's storage buffers and images (set_buffer, set_storage_image), by name.
  struct AppStorage {
    std::string name;
    VkBuffer buffer = VK_NULL_HANDLE;  // a storage buffer's range, or
    VkDeviceSize offset = 0, range = 0;
    VkImageView view = VK_NULL_HANDLE;    // a storage image's view, or
    VkBufferView texel = VK_NULL_HANDLE;  // a texel buffer's view
  };
  std::vector<AppStorage> app_storage;
  uint64_t textures_serial = 0;   // the version app_textures were bound to
  uint64_t scene_checked = 0;     // the version set_scene() last checked for unbound transforms
  fx::DiagnosticSink sink;        // problems of set/apply calls, moved to `problems`
  std::vector<Message> problems;  // the newest kRecentProblems of them
  static constexpr size_t kRecentProblems = 32;
  // The last refused set() of each parameter: true until the parameter is set (or reset)
  // or another version goes live, so it leaves messages() then.
  struct RefusedSet {
    uint32_t param = 0;
    Message message;
  };
  std::vector<RefusedSet> refused_sets;
  uint64_t refused_serial = 0;  // the version refused_sets were refused by

  // Moves what `sink` collected into `problems`.
  void keep_problems();
  // Binds app_textures and app_storage to `binding` (of `version`); false if one names no
  // texture parameter or storage resource.
  bool bind_app_textures(const fx::EffectVersion& version, fx::vk::EffectBinding& binding);
};

}  // namespace fxkit::detail
