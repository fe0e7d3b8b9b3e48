// fxkit::Device: a Context (wrapped or headless), the frame resources, the texture cache, a
// ReloadBackend bound for the application's Target and an EffectLibrary on top.
#include <vulkan/vulkan.h>

#include "api_state.h"
#include "fx/binding/context_caps.h"
#include "fx/vulkan/one_shot.h"

namespace fxkit {
namespace detail {
namespace {

// The target's problems, one message each ("target-incomplete").
std::vector<Message> check_target(const Target& t) {
  std::vector<Message> out;
  auto error = [&out](std::string text) {
    out.push_back(to_message(fx::Severity::error, "target-incomplete", std::move(text)));
  };
  if (t.front_faces == Winding::unset)
    error(
        "Target::front_faces is unset: say whether the meshes' front faces are clockwise (Direct3D) or "
        "counter_clockwise (OpenGL, glTF)");
  if (t.y_flip == YFlip::unset)
    error("Target::y_flip is unset: say whether the viewport height is negative or the projection flips Y");
  if (t.formats.color.size() > fx::vk::kMaxColorAttachments)
    error("Target::formats has " + std::to_string(t.formats.color.size()) + " colour formats; at most " +
          std::to_string(fx::vk::kMaxColorAttachments) + " are supported");
  if (t.formats.color.empty() && t.formats.depth == VK_FORMAT_UNDEFINED)
    error("Target::formats has neither a colour nor a depth format");
  return out;
}

}  // namespace

fx::vk::RenderingFormats rendering_formats(const Formats& formats) {
  fx::vk::RenderingFormats f;
  f.color_count = uint32_t(std::min<size_t>(formats.color.size(), fx::vk::kMaxColorAttachments));
  for (uint32_t i = 0; i < f.color_count; ++i) f.color[i] = formats.color[i];
  f.depth = formats.depth;
  f.stencil = formats.stencil;
  return f;
}

fx::vk::PassTargetInfo pass_target(const Target& target) {
  fx::vk::PassTargetInfo info;
  info.color_attachment_count = uint32_t(target.formats.color.size());
  info.samples = target.formats.samples;
  info.depth_bits = fx::vk::depth_bits(target.formats.depth);
  info.negative_viewport_height = target.y_flip == YFlip::negative_viewport;
  info.mesh_front_face =
      target.front_faces == Winding::counter_clockwise ? fx::FrontFace::counter_clockwise : fx::FrontFace::clockwise;
  return info;
}

void DeviceState::refresh_stores() {
  std::erase_if(effects, [](const std::weak_ptr<EffectState>& e) { return e.expired(); });
  for (const std::weak_ptr<EffectState>& weak : effects)
    if (auto e = weak.lock()) {
      e->store = e->handle.params();
      e->draw = e->store ? e->store->draw_state() : nullptr;
    }
}

}  // namespace detail

namespace {

std::unique_ptr<detail::DeviceState> make_state(fx::vk::Context ctx, const DeviceOptions& options,
                                                std::vector<Message>& errors) {
  auto s = std::make_unique<detail::DeviceState>();
  s->ctx.emplace(std::move(ctx));
  const fx::vk::Context& c = *s->ctx;
  if (!c.features().dynamic_rendering) {
    errors.push_back(detail::to_message(
        fx::Severity::error, "vk-feature-missing",
        "the device was not created with dynamic rendering (Vulkan 1.3 dynamicRendering), which fxkit records with"));
    return nullptr;
  }
  s->target = options.target;
  s->formats = detail::rendering_formats(options.target.formats);
  fx::DiagnosticSink sink;
  fx::vk::FrameResourcesDesc frames;
  frames.frames_in_flight = std::max(1u, options.frames_in_flight);
  frames.uniform_bytes_per_frame = options.uniform_bytes_per_frame;
  frames.sets_per_frame = options.descriptor_sets_per_frame;
  s->frames = fx::vk::FrameResources::create(c, frames, sink);
  if (!s->frames) {
    auto more = detail::to_messages(sink.diagnostics(), nullptr);
    errors.insert(errors.end(), more.begin(), more.end());
    return nullptr;
  }
  s->textures = std::make_unique<fx::vk::EffectTextureCache>(c);
  fx::vk::ReloadBackendDesc desc;
  desc.formats = s->formats;
  desc.binding.target = detail::pass_target(options.target);
  if (!options.dynamic_state) desc.binding.dynamic = fx::vk::DynamicStateSet::none();
  if (options.target.extent.width && options.target.extent.height)
    desc.binding.storage_image_extent = options.target.extent;
  const uint32_t defaults = options.target.default_attribute_binding;
  desc.vertex_layout = [layout = options.target.vertex_layout, defaults](std::span<const fx::InterfaceVariable> in) {
    return defaults == Target::kNoBinding ? layout : fx::vk::with_default_attributes(layout, in, defaults);
  };
  if (defaults != Target::kNoBinding) {
    const fx::vk::DefaultAttributeData constant;
    auto buffer = fx::vk::Buffer::create(
        c,
        {sizeof constant, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, fx::vk::MemoryUsage::upload, "fxkit default attributes"},
        sink);
    if (!buffer || !buffer->write(&constant, sizeof constant)) {
      auto more = detail::to_messages(sink.diagnostics(), nullptr);
      errors.insert(errors.end(), more.begin(), more.end());
      return nullptr;
    }
    s->default_attributes = std::move(*buffer);
  }
  s->backend = std::make_unique<fx::vk::ReloadBackend>(c, *s->textures, *s->frames, std::move(desc));
  fx::EffectLibraryOptions lib;
  lib.include_dirs = options.include_dirs;
  lib.defines = options.defines;
  lib.watch = options.watch;
  lib.backend = s->backend.get();
  lib.caps = fx::vk::context_caps(c);  // the device as created: the shader features it enabled
  lib.spirv_cache_dir = options.cache_dir;
  lib.compile_threads = options.compile_threads;
  lib.frames_in_flight = std::max(1u, options.frames_in_flight);
  if (options.compile_in_workers)
    lib.compile_workers =
        fx::CompileWorkerOptions{.executable = options.compile_worker, .workers = options.compile_threads};
  s->library = std::make_unique<fx::EffectLibrary>(std::move(lib));
  if (const std::string& why = s->library->compile_workers_error(); !why.empty())
    s->warnings.push_back(detail::to_message(fx::Severity::warning, "compile-workers-unavailable",
                                             "shaders compile in this process: " + why));
  return s;
}

}  // namespace

Device::Device(std::unique_ptr<detail::DeviceState> state) : state_(std::move(state)) {}

Device::~Device() {
  if (!state_) return;
  state_->ctx->wait_idle();
  for (const std::weak_ptr<detail::EffectState>& e : state_->effects)
    if (auto effect = e.lock()) effect->script.reset(), effect->device = nullptr;  // before the versions they draw
  state_->library.reset();
  state_
      ->refresh_stores();  // handles are inert now: no store  // versions and their bindings before what they draw with
  state_->backend.reset();
  for (const std::weak_ptr<detail::EffectState>& e : state_->effects)
    if (auto effect = e.lock()) effect->textures = nullptr;
  state_->textures.reset();
  state_->frames.reset();
  state_->default_attributes = {};
}

std::unique_ptr<Device> Device::create(const VulkanHandles& vulkan, const DeviceOptions& options,
                                       std::vector<Message>& errors) {
  auto problems = detail::check_target(options.target);
  errors.insert(errors.end(), problems.begin(), problems.end());
  if (!problems.empty()) return nullptr;
  std::optional<fx::vk::DeviceFeatures> enabled;
  if (vulkan.created_with) enabled = fx::vk::enabled_features(vulkan.physical_device, *vulkan.created_with);
  auto ctx = fx::vk::Context::wrap(vulkan.instance, vulkan.physical_device, vulkan.device, vulkan.queue,
                                   vulkan.queue_family, enabled);
  auto state = make_state(std::move(ctx), options, errors);
  return state ? std::unique_ptr<Device>(new Device(std::move(state))) : nullptr;
}

std::unique_ptr<Device> Device::headless(const DeviceOptions& options, const HeadlessOptions& headless,
                                         std::vector<Message>& errors) {
  auto problems = detail::check_target(options.target);
  errors.insert(errors.end(), problems.begin(), problems.end());
  if (!problems.empty()) return nullptr;
  fx::DiagnosticSink sink;
  fx::vk::ContextOptions context;
  context.validation = headless.validation;
  context.device = headless.device;
  auto ctx = fx::vk::Context::headless(context, sink);
  if (!ctx) {
    auto more = detail::to_messages(sink.diagnostics(), nullptr);
    errors.insert(errors.end(), more.begin(), more.end());
    return nullptr;
  }
  auto state = make_state(std::move(*ctx), options, errors);
  return state ? std::unique_ptr<Device>(new Device(std::move(state))) : nullptr;
}

Effect Device::load(const std::string& path) {
  Effect e;
  e.state_ = std::make_shared<detail::EffectState>();
  e.draw_ = &e.state_->draw;
  e.state_->handle = state_->library->load(path);
  e.state_->formats = state_->formats;
  e.state_->default_attributes = state_->default_attributes.handle();
  e.state_->default_binding = state_->target.default_attribute_binding;
  e.state_->textures = state_->textures.get();
  e.state_->device = state_.get();
  state_->effects.push_back(e.state_);
  state_->refresh_stores();
  return e;
}

std::vector<Reload> Device::begin_frame() {
  state_->frames->begin_frame();
  std::vector<Reload> out;
  const std::vector<fx::ReloadEvent> events = state_->library->poll(state_->frames->frame());
  state_->refresh_stores();
  for (const fx::ReloadEvent& ev : events) {
    Reload r;
    r.kind = ev.kind == fx::ReloadEventKind::reloaded ? Reload::Kind::reloaded
             : ev.kind == fx::ReloadEventKind::failed ? Reload::Kind::failed
                                                      : Reload::Kind::deleted;
    r.file = ev.file;
    r.messages = detail::to_messages(ev.diagnostics, ev.sources.get());
    r.technique = ev.technique;
    out.push_back(std::move(r));
  }
  return out;
}

uint64_t Device::frame() const { return state_->frames->frame(); }
uint64_t Device::uniform_bytes_written() const { return state_->frames->uniform_bytes_uploaded(); }

bool Device::submit(const std::function<void(VkCommandBuffer)>& record) {
  fx::DiagnosticSink sink;
  return fx::vk::submit_and_wait(*state_->ctx, record, sink);
}

bool Device::wait_for_reload(std::chrono::milliseconds timeout) { return state_->library->wait(timeout); }

VkDevice Device::vk_device() const { return state_->ctx->device(); }
VkPhysicalDevice Device::vk_physical_device() const { return state_->ctx->physical_device(); }
const Target& Device::target() const { return state_->target; }
const std::string& Device::device_name() const { return state_->ctx->info().name; }

const std::vector<Message>& Device::warnings() const { return state_->warnings; }

std::vector<Message> Device::take_validation_messages() {
  std::vector<Message> out;
  for (const fx::vk::ValidationMessage& v : state_->ctx->validation_messages()) {
    out.push_back(detail::to_message(v.severity, v.id_name.empty() ? "vk-validation" : v.id_name, v.text));
  }
  state_->ctx->clear_validation_messages();
  return out;
}

std::string Reload::str() const {
  std::string s = kind == Kind::reloaded ? "reloaded " : kind == Kind::failed ? "failed " : "deleted ";
  s += file;
  if (!technique.empty()) s += " (technique " + technique + ")";
  if (!defaults_changed.empty()) {
    s += "; defaults changed:";
    for (const std::string& p : defaults_changed) s += " " + p;
  }
  s += "\n";
  for (const Message& m : messages) s += m.rendered;
  return s;
}

}  // namespace fxkit
