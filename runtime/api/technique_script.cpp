// fxkit::Technique's DXSAS scripts: a ScriptRunner per loaded version, technique and frame
// size, run into the application's frame with fxkit's quad for Draw=Buffer.
#include "api_state.h"
#include "fx/binding/script_runner.h"
#include "fx/reload/reload_transaction.h"
#include "script_quad.h"

namespace fxkit {
namespace detail {

struct ScriptRun {
  std::shared_ptr<const fx::EffectVersion> version;  // what the runner's binding belongs to
  uint32_t technique = 0;
  VkExtent2D extent{};
  std::optional<ScriptQuad> quad;
  std::unique_ptr<fx::vk::ScriptRunner> runner;  // destroyed first: it waits for the device to be idle
};

namespace {

// The run for technique `t` of `version` into a frame of `extent`: the last one while they
// stay, else one made anew (null, with the reason in s.sink, when it cannot be).
ScriptRun* script_run(EffectState& s, std::shared_ptr<const fx::EffectVersion> version, fx::vk::EffectBinding& binding,
                      uint32_t t, VkExtent2D extent) {
  ScriptRun* run = s.script.get();
  if (run && run->version == version && run->technique == t && run->extent.width == extent.width &&
      run->extent.height == extent.height)
    return run;
  s.script.reset();  // its targets are unbound from nothing: the new runner binds its own
  auto made = std::make_shared<ScriptRun>();
  made->technique = t;
  made->extent = extent;
  made->quad = ScriptQuad::create(*s.device->ctx, s.device->target, s.sink);
  if (!made->quad) return nullptr;
  made->runner = fx::vk::ScriptRunner::create(*s.device->ctx, *version->model, binding, *version->params, t,
                                              extent.width, extent.height, s.sink);
  if (!made->runner) return nullptr;
  made->version = std::move(version);
  s.script = std::move(made);
  return s.script.get();
}

Formats public_formats(const fx::vk::RenderingFormats& f) {
  return {std::vector<VkFormat>(f.color, f.color + f.color_count), f.depth, f.stencil, VK_SAMPLE_COUNT_1_BIT};
}

}  // namespace
}  // namespace detail

bool Technique::has_script() const {
  auto version = effect_ ? effect_->handle.version() : nullptr;
  if (!version) return false;
  const uint32_t t = detail::technique_index(*effect_, *version, name_);
  return t < version->model->techniques.size() && version->model->techniques[t].script.has_value();
}

bool Technique::run_script(VkCommandBuffer cmd, const ScriptFrame& frame) {
  if (!effect_ || !effect_->device) return false;
  detail::EffectState& s = *effect_;
  uint32_t t = 0;
  fx::vk::EffectBinding* binding = detail::live_binding(s, name_, resolved_serial_, resolved_, passes_, t);
  auto version = s.handle.version();
  if (!binding || !version) return false;
  const Target& target = s.device->target;
  bool ok = false;
  if (!has_script()) {
    s.sink.error("vk-script-none", {}, "technique '" + name() + "' has no DXSAS Script annotation");
  } else if (!frame.color || (target.formats.depth != VK_FORMAT_UNDEFINED && !frame.depth) ||
             target.formats.color.empty() || frame.area.extent.width == 0 || frame.area.extent.height == 0) {
    s.sink.error("vk-script-frame", {},
                 "ScriptFrame needs a colour view, a depth view when the Target has a depth format, and an area");
  } else if (detail::ScriptRun* run = detail::script_run(s, version, *binding, t, frame.area.extent)) {
    fx::vk::ScriptFrame f;
    f.attachments.color = frame.color;
    f.attachments.depth = frame.depth;
    f.attachments.color_layout = frame.color_layout;
    f.attachments.depth_layout = frame.depth_layout;
    f.attachments.formats = s.formats;
    f.attachments.formats.color_count = 1;  // the script draws into the first colour attachment
    f.attachments.area = frame.area;
    f.vertex_layout = 0;  // the Target's, as apply() draws
    f.viewport.height = target.y_flip == YFlip::negative_viewport ? -1.f : 1.f;
    auto bind_defaults = [&s](VkCommandBuffer c) {
      const VkDeviceSize offset = 0;
      if (s.default_attributes) vkCmdBindVertexBuffers(c, s.default_binding, 1, &s.default_attributes, &offset);
    };
    f.draw_geometry = [&](VkCommandBuffer c) {
      bind_defaults(c);
      if (frame.draw_geometry) frame.draw_geometry(c);
    };
    f.draw_quad = [&](VkCommandBuffer c) {
      bind_defaults(c);
      run->quad->draw(c);
    };
    if (frame.draw_scene)
      f.draw_scene = [&](VkCommandBuffer c, const fx::vk::RenderingFormats& formats, const VkRect2D& area) {
        frame.draw_scene(c, detail::public_formats(formats), area);
      };
    ok = run->runner->record(cmd, f, s.sink);
  }
  if (!s.sink.diagnostics().empty()) s.keep_problems();
  return ok;
}

std::vector<ScriptTarget> Technique::script_targets() const {
  std::vector<ScriptTarget> out;
  if (!effect_ || !effect_->script) return out;
  for (const auto& [name, target] : effect_->script->runner->targets())
    out.push_back({name, target->color().view(), target->extent(), target->color().format()});
  return out;
}

}  // namespace fxkit
