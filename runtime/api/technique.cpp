// fxkit::Technique: resolves to a technique index of the live version at begin() (by name,
// or the effect's selection) and records through that version's EffectBinding.
#include "api_state.h"
#include "fx/reload/reload_transaction.h"

namespace fxkit {
namespace {

uint32_t pass_count_of(const fx::EffectVersion& version, uint32_t t) {
  const auto& techniques = version.model->techniques;
  return t < techniques.size() ? uint32_t(techniques[t].passes.size()) : 0;
}

// A named technique's index and pass count in `version`, kept in the Technique's fields
// (`serial`, `index`, `passes`): looked up only when the version is another.
void remember(const detail::EffectState& s, const fx::EffectVersion& version, const std::string& name, uint64_t& serial,
              uint32_t& index, uint32_t& passes) {
  if (serial == version.serial) return;
  index = detail::technique_index(s, version, name);
  passes = pass_count_of(version, index);
  serial = version.serial;
}

}  // namespace

namespace detail {

uint32_t technique_index(const EffectState& s, const fx::EffectVersion& version, const std::string& name) {
  if (name.empty()) return s.handle.technique();
  const auto& techniques = version.model->techniques;
  for (uint32_t t = 0; t < techniques.size(); ++t)
    if (techniques[t].name == name) return t;
  return fx::kNoIndex;
}

fx::vk::EffectBinding* live_binding(EffectState& s, const std::string& name, uint64_t& serial, uint32_t& index,
                                    uint32_t& passes, uint32_t& t) {
  auto version = s.handle.version();
  fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  if (!binding) return nullptr;
  if (!name.empty()) remember(s, *version, name, serial, index, passes);
  t = name.empty() ? s.handle.technique() : index;
  if (s.textures_serial != version->serial) s.bind_app_textures(*version, *binding);
  return binding;
}

std::string technique_reason(const fx::EffectVersion& version, uint32_t t) {
  if (!version.techniques->valid(t)) {
    std::string why;
    for (const std::string& r : version.techniques->reasons(t)) why += (why.empty() ? "" : "; ") + r;
    return why.empty() ? "rejected by validation" : why;
  }
  const fx::vk::EffectBinding* binding = fx::vk::ReloadBackend::binding(version);
  return binding ? binding->technique_reason(t) : "no GPU objects were made for this version";
}

bool EffectState::bind_app_textures(const fx::EffectVersion& version, fx::vk::EffectBinding& binding) {
  bool ok = true;
  for (const AppTexture& t : app_textures) ok &= binding.set_texture(t.name, t.view, t.layout, t.kind, sink);
  for (const AppStorage& r : app_storage)
    ok &= r.view    ? binding.set_storage_image(r.name, r.view, sink)
          : r.texel ? binding.set_texel_buffer(r.name, r.texel, sink)
                    : binding.set_buffer(r.name, r.buffer, r.offset, r.range, sink);
  textures_serial = version.serial;
  keep_problems();
  return ok;
}

}  // namespace detail

bool Technique::valid() const { return reason().empty(); }

std::string Technique::name() const {
  if (!name_.empty() || !effect_) return name_;
  return effect_->handle.technique_name();
}

uint32_t Technique::pass_count() const {
  if (!effect_) return 0;
  // A named technique of the version begin() or the last call resolved: no lookup.
  if (!name_.empty() && resolved_serial_ != 0 && resolved_serial_ == effect_->handle.serial()) return passes_;
  auto version = effect_->handle.version();
  if (!version) return 0;
  if (name_.empty()) return pass_count_of(*version, effect_->handle.technique());
  remember(*effect_, *version, name_, resolved_serial_, resolved_, passes_);
  return passes_;
}

std::string Technique::reason() const {
  auto version = effect_ ? effect_->handle.version() : nullptr;
  if (!version) return "the effect has no good version";
  const uint32_t t = detail::technique_index(*effect_, *version, name_);
  if (t >= version->model->techniques.size())
    return name_.empty() ? "selection chose no technique" : "the effect has no technique '" + name_ + "'";
  return detail::technique_reason(*version, t);
}

bool Technique::begin(VkCommandBuffer cmd, const VkViewport& viewport, const VkRect2D& scissor) {
  if (!effect_) return false;
  detail::EffectState& s = *effect_;
  s.recording = nullptr;
  s.pass_apply.binding = nullptr;
  s.recording_version = s.handle.version();
  if (!s.recording_version) return false;
  const fx::EffectVersion& version = *s.recording_version;
  if (s.binding_serial != version.serial) {
    s.binding = fx::vk::ReloadBackend::binding(version);
    s.binding_serial = version.serial;
  }
  fx::vk::EffectBinding* binding = s.binding;
  uint32_t t;
  if (name_.empty()) {
    t = s.handle.technique();
  } else {
    remember(s, version, name_, resolved_serial_, resolved_, passes_);
    t = resolved_;
  }
  if (!binding || t >= binding->technique_count()) return false;
  if (s.textures_serial != version.serial) s.bind_app_textures(version, *binding);
  const bool ok = binding->begin(cmd, t, s.formats, viewport, scissor, s.sink);
  if (ok && s.default_attributes) {
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, s.default_binding, 1, &s.default_attributes, &offset);
  }
  if (!s.sink.diagnostics().empty()) s.keep_problems();
  if (ok) s.recording = binding, s.pass_apply.binding = binding;
  return ok;
}

bool Technique::compute_pass(uint32_t pass) const {
  auto version = effect_ ? effect_->handle.version() : nullptr;
  const fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  return binding && binding->compute_pass(detail::technique_index(*effect_, *version, name_), pass);
}

bool Technique::draw_pass(uint32_t pass) const {
  auto version = effect_ ? effect_->handle.version() : nullptr;
  const fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  return binding && binding->draw_pass(detail::technique_index(*effect_, *version, name_), pass);
}

bool Technique::dispatch(VkCommandBuffer cmd, uint32_t pass, uint32_t x, uint32_t y, uint32_t z) {
  uint32_t t = 0;
  fx::vk::EffectBinding* binding =
      effect_ ? detail::live_binding(*effect_, name_, resolved_serial_, resolved_, passes_, t) : nullptr;
  if (!binding) return false;
  const bool ok = binding->dispatch(cmd, t, pass, {x, y, z}, effect_->sink);
  if (!effect_->sink.diagnostics().empty()) effect_->keep_problems();
  return ok;
}

bool Technique::dispatch_compute_passes(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
  uint32_t t = 0;
  fx::vk::EffectBinding* binding =
      effect_ ? detail::live_binding(*effect_, name_, resolved_serial_, resolved_, passes_, t) : nullptr;
  if (!binding) return false;
  const bool ok = binding->dispatch_compute_passes(cmd, t, width, height, effect_->sink);
  if (!effect_->sink.diagnostics().empty()) effect_->keep_problems();
  return ok;
}

bool Technique::stream_output_pass(uint32_t pass) const {
  auto version = effect_ ? effect_->handle.version() : nullptr;
  const fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  return binding && binding->stream_output_pass(detail::technique_index(*effect_, *version, name_), pass);
}

bool Technique::begin_capture(VkCommandBuffer cmd, uint32_t pass) {
  uint32_t t = 0;
  fx::vk::EffectBinding* binding =
      effect_ ? detail::live_binding(*effect_, name_, resolved_serial_, resolved_, passes_, t) : nullptr;
  if (!binding) return false;
  const bool ok = binding->begin_capture(cmd, t, pass, 0, effect_->sink);
  if (ok && effect_->default_attributes) {
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, effect_->default_binding, 1, &effect_->default_attributes, &offset);
  }
  if (ok) effect_->capturing = binding;
  if (!effect_->sink.diagnostics().empty()) effect_->keep_problems();
  return ok;
}

void Technique::end_capture() {
  if (!effect_ || !effect_->capturing) return;
  effect_->capturing->end_capture();
  effect_->capturing = nullptr;
}

bool Technique::draw_stream_output(VkCommandBuffer cmd, uint32_t pass, uint32_t stream_output_pass) {
  if (!effect_ || !effect_->recording) return false;
  const bool ok = effect_->recording->draw_stream_output(cmd, pass, stream_output_pass, effect_->sink);
  if (!effect_->sink.diagnostics().empty()) effect_->keep_problems();
  return ok;
}

StreamOutputBuffer Technique::stream_output_buffer(uint32_t pass, uint32_t slot) const {
  auto version = effect_ ? effect_->handle.version() : nullptr;
  const fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  if (!binding) return {};
  auto b = binding->stream_output_buffer(detail::technique_index(*effect_, *version, name_), pass, slot);
  return b ? StreamOutputBuffer{b->buffer, b->counter, b->size, b->stride} : StreamOutputBuffer{};
}

void Technique::end() {
  if (!effect_) return;
  if (effect_->recording) effect_->recording->end();
  if (!effect_->sink.diagnostics().empty()) effect_->keep_problems();
  effect_->recording = nullptr;
  effect_->pass_apply.binding = nullptr;
  effect_->recording_version.reset();
}

}  // namespace fxkit
