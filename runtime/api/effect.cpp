// fxkit::Effect: an EffectHandle of the device's library, with the parameter store of the live
// version behind every setter.
#include <algorithm>
#include <filesystem>

#include "api_state.h"
#include "fx/binding/effect_scene.h"
#include "fx/binding/effect_textures.h"
#include "fx/binding/preview_defaults.h"
#include "fx/compile/effect_file.h"
#include "fx/model/class_instances.h"
#include "fx/model/parameter_store.h"
#include "fx/reload/reload_transaction.h"
#include "fx/select/caps_sources.h"
#include "fx/select/selection.h"

namespace fxkit {
namespace {

// Keeps a refused set's reason for messages() while it is true: until the parameter is set
// (or reset), replacing the previous reason for it.
bool kept(detail::EffectState& s, Param p, const fx::ParamStatus& status) {
  std::erase_if(s.refused_sets, [&](const detail::EffectState::RefusedSet& r) { return r.param == p.index; });
  if (status) return true;
  s.refused_serial = s.handle.serial();
  s.refused_sets.push_back({p.index, detail::to_message(status.code == fx::ParamStatus::removed ? fx::Severity::warning
                                                                                                : fx::Severity::error,
                                                        "parameter-set", status.message)});
  return false;
}

}  // namespace

bool Effect::ok() const { return state_ && state_->handle.ok(); }

const std::string& Effect::path() const {
  static const std::string kNone;
  return state_ ? state_->handle.path() : kNone;
}

std::vector<Message> Effect::messages() const {
  if (!state_) return {};
  auto sources = state_->handle.diagnostic_sources();
  std::vector<Message> out = detail::to_messages(state_->handle.diagnostics(), sources.get());
  out.insert(out.end(), state_->problems.begin(), state_->problems.end());
  // A refused set() speaks of the version that refused it, not of one reloaded since.
  if (state_->refused_serial == state_->handle.serial())
    for (const detail::EffectState::RefusedSet& r : state_->refused_sets) out.push_back(r.message);
  return out;
}

uint64_t Effect::serial() const { return state_ ? state_->handle.serial() : 0; }

std::vector<TechniqueInfo> Effect::techniques() const {
  std::vector<TechniqueInfo> out;
  auto version = state_ ? state_->handle.version() : nullptr;
  if (!version) return out;
  const auto choice = state_->handle.choice();
  for (uint32_t t = 0; t < version->model->techniques.size(); ++t) {
    TechniqueInfo info;
    info.name = version->model->techniques[t].name;
    info.passes = uint32_t(version->model->techniques[t].passes.size());
    for (const fx::Annotation& a : version->model->techniques[t].annotations)
      info.annotations.push_back(detail::to_public(a));
    info.reason = detail::technique_reason(*version, t);
    info.drawable = info.reason.empty();
    if (version->techniques) info.distance_band = version->techniques->plan().distance_band(t);
    // The emulated profile's reasons follow the device's in the selection's choice.
    if (choice && choice != version->techniques && version->techniques) {
      const std::vector<std::string>& all = choice->reasons(t);
      for (size_t r = version->techniques->reasons(t).size(); r < all.size(); ++r)
        info.caps_reason += (info.caps_reason.empty() ? "" : "; ") + all[r];
    }
    out.push_back(std::move(info));
  }
  return out;
}

std::vector<std::string> caps_profiles() { return fx::caps_profile_names(); }

Technique Effect::technique(std::string_view name) const {
  Technique t;
  t.effect_ = state_;
  if (state_) t.pass_apply_ = &state_->pass_apply;
  t.name_ = std::string(name);
  return t;
}

Technique Effect::select(const Criteria& criteria) const {
  Technique t;
  if (!state_) return t;
  fx::SelectionCriteria c;
  c.distance = criteria.distance;
  c.screen_size = criteria.screen_size;
  c.pixels = criteria.pixels;
  c.scheme = criteria.scheme;
  c.cost_budget_ms = criteria.cost_budget_ms;
  c.max_error = criteria.max_error;
  std::optional<fx::DeviceCaps> caps;
  if (!criteria.caps.empty()) {
    fx::DiagnosticSink sink;
    caps = fx::load_caps_profile(criteria.caps, sink);
    for (const fx::Diagnostic& d : sink.diagnostics())
      state_->problems.push_back(
          detail::to_message(fx::Severity::warning, d.id, d.message + "; selecting for this device"));
  }
  state_->handle.select(c, caps ? &*caps : nullptr);
  t.effect_ = state_;
  t.pass_apply_ = &state_->pass_apply;
  return t;
}

Param Effect::param(std::string_view name_or_semantic) const {
  if (!state_) return {};
  return state_->handle.param(name_or_semantic);
}

bool Effect::set(Param p, float value) {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && kept(*state_, p, store->set(p, value));
}
bool Effect::set(Param p, int32_t value) {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && kept(*state_, p, store->set(p, value));
}
bool Effect::set_class_instance(Param interface_variable, std::string_view instance) {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  auto version = state_ ? state_->handle.version() : nullptr;
  if (!store || !version) return false;
  const std::vector<fx::Parameter>& params = version->model->parameters;
  const uint32_t index = interface_variable.index;
  if (index < params.size() && params[index].decl &&
      fx::find_interface(version->file->parsed.ast, params[index].decl->type.name)) {
    const std::vector<fx::BindableInstance> instances =
        fx::bindable_instances(version->file->parsed.ast, params[index].decl->type.name);
    auto found = std::find_if(instances.begin(), instances.end(),
                              [&](const fx::BindableInstance& b) { return b.name == instance; });
    if (found != instances.end())
      return kept(*state_, interface_variable,
                  store->set(interface_variable, static_cast<int32_t>(found - instances.begin())));
  }
  const std::string name = index < params.size() ? params[index].name : std::string("the parameter");
  return kept(
      *state_, interface_variable,
      {fx::ParamStatus::not_found,
       std::string("'").append(instance).append("' is not a class instance that '") + name + "' can be bound to"});
}
bool Effect::set(Param p, bool value) {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && kept(*state_, p, store->set(p, value));
}
bool Effect::set(Param p, std::span<const float> values) {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && kept(*state_, p, store->set(p, values));
}

bool Effect::set(Param p, std::span<const int32_t> values) {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && kept(*state_, p, store->set(p, values));
}

// set_matrix past its inline per-object path: the checked store and its status.
bool Effect::set_matrix_checked(Param p, const float* m16, MatrixOrder order) {
  detail::EffectState* s = state_.get();
  if (!s || !s->store) return false;
  const fx::ParamStatus status = s->store->set_matrix(p, std::span<const float>(m16, 16), order);
  return kept(*s, p, status);
}

bool Effect::get(Param p, std::span<float> out) const {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && store->get(p, out);
}

bool Effect::get(Param p, std::span<int32_t> out) const {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && store->get(p, out);
}

bool Effect::reset(Param p) {
  fx::ParameterStore* store = state_ ? state_->store : nullptr;
  return store && kept(*state_, p, store->reset(p));
}

uint32_t Effect::set_scene(const Scene& scene) {
  auto version = state_ ? state_->handle.version() : nullptr;
  if (!version) return 0;
  fx::vk::SceneView view;
  std::copy_n(scene.world, 16, &view.world[0][0]);
  std::copy_n(scene.view, 16, &view.view[0][0]);
  std::copy_n(scene.projection, 16, &view.projection[0][0]);
  view.eye = {scene.eye[0], scene.eye[1], scene.eye[2]};
  view.time = scene.time;
  view.elapsed = scene.elapsed;
  view.viewport_size = {scene.viewport_size[0], scene.viewport_size[1]};
  const uint32_t set = fx::vk::set_standard_semantics(*version->params, *version->model, view);
  // Once per version: transforms the shaders read that nothing bound draw nothing.
  if (state_->scene_checked != version->serial && version->programs) {
    state_->scene_checked = version->serial;
    const auto read = fx::vk::parameters_read(*version->programs, fx::kNoIndex);
    for (const std::string& name : fx::vk::zero_transforms(*version->params, *version->model, read))
      state_->sink.report(fx::Severity::warning, "scene-transform-unbound", {},
                          "'" + name +
                              "' is read by the shaders but set_scene() left it zero (no standard semantic, "
                              "and not a name docs/parameters.md lists): set it, or give it a semantic such as "
                              "WORLDVIEWPROJECTION");
    state_->keep_problems();
  }
  return set;
}

std::vector<std::string> Effect::set_preview_defaults() {
  auto version = state_ ? state_->handle.version() : nullptr;
  if (!version || !version->programs) return {};
  std::vector<std::string> names;
  const auto read = fx::vk::parameters_read(*version->programs, fx::kNoIndex);
  for (fx::vk::PreviewDefault& d : fx::vk::set_preview_defaults(*version->params, *version->model, read))
    names.push_back(std::move(d.parameter));
  return names;
}

ApplyStats Effect::stats() const {
  auto version = state_ ? state_->handle.version() : nullptr;
  const fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  return binding ? binding->stats() : ApplyStats{};
}

void Effect::reset_stats() {
  auto version = state_ ? state_->handle.version() : nullptr;
  if (fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr)
    binding->reset_stats();
}

bool Effect::set_texture(std::string_view name, VkImageView view, VkImageLayout layout, VkImageViewType type) {
  if (!state_) return false;
  const fx::vk::ImageKind kind = type == VK_IMAGE_VIEW_TYPE_3D     ? fx::vk::ImageKind::image3d
                                 : type == VK_IMAGE_VIEW_TYPE_CUBE ? fx::vk::ImageKind::cube
                                 : type == VK_IMAGE_VIEW_TYPE_1D   ? fx::vk::ImageKind::image1d
                                                                   : fx::vk::ImageKind::image2d;
  auto& textures = state_->app_textures;
  auto same = std::find_if(textures.begin(), textures.end(), [&](const auto& t) { return t.name == name; });
  if (same == textures.end()) same = textures.insert(textures.end(), {std::string(name)});
  same->view = view, same->layout = layout, same->kind = kind;
  state_->textures_serial = 0;  // bound to the live version at the next begin()
  auto version = state_->handle.version();
  fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  return binding && state_->bind_app_textures(*version, *binding);
}

// Records the application's storage resource `name` and binds it to the live version.
static bool set_storage(detail::EffectState& state, std::string_view name, VkBuffer buffer, VkDeviceSize offset,
                        VkDeviceSize range, VkImageView view, VkBufferView texel = VK_NULL_HANDLE) {
  auto& list = state.app_storage;
  auto same = std::find_if(list.begin(), list.end(), [&](const auto& r) { return r.name == name; });
  if (same == list.end()) same = list.insert(list.end(), {std::string(name)});
  same->buffer = buffer, same->offset = offset, same->range = range, same->view = view, same->texel = texel;
  state.textures_serial = 0;  // bound to the live version at the next begin() or dispatch()
  auto version = state.handle.version();
  fx::vk::EffectBinding* binding = version ? fx::vk::ReloadBackend::binding(*version) : nullptr;
  return binding && state.bind_app_textures(*version, *binding);
}

bool Effect::set_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range) {
  return state_ && set_storage(*state_, name, buffer, offset, range, VK_NULL_HANDLE);
}

bool Effect::set_storage_image(std::string_view name, VkImageView view) {
  return state_ && set_storage(*state_, name, VK_NULL_HANDLE, 0, 0, view);
}

bool Effect::set_texel_buffer(std::string_view name, VkBufferView view) {
  return state_ && set_storage(*state_, name, VK_NULL_HANDLE, 0, 0, VK_NULL_HANDLE, view);
}

bool Effect::set_texture_file(std::string_view name, const std::string& file) {
  if (!state_) return false;
  detail::EffectState& s = *state_;
  auto version = s.handle.version();
  const fx::TextureInfo* info = nullptr;
  if (version)
    for (const fx::TextureInfo& t : version->model->textures)
      if (t.parameter < version->model->parameters.size() && version->model->parameters[t.parameter].name == name)
        info = &t;
  if (!info || !s.textures) {
    std::string why(name);
    why.append(" is no texture parameter of ").append(path());
    s.sink.error("texture-unknown", {}, why);
    s.keep_problems();
    return false;
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) {
    std::string why = "cannot read texture file '" + file + "' for ";
    why.append(name);
    s.sink.error("texture-file-missing", {}, why);
    s.keep_problems();
    return false;
  }
  fx::TextureInfo from_file = *info;
  from_file.resource_name = std::filesystem::absolute(file, ec).string();
  from_file.generator.clear();
  auto data = s.textures->resolve(*version->model, from_file, {}, fx::ImageDim::dim_2d, false, s.sink);
  const fx::vk::Texture* texture = data && !data->stand_in ? s.textures->gpu(*data, s.sink) : nullptr;
  s.keep_problems();
  return texture && set_texture(name, texture->view(), texture->layout(), VK_IMAGE_VIEW_TYPE_2D);
}

}  // namespace fxkit
