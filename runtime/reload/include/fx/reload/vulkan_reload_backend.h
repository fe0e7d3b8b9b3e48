// fx::vk::ReloadBackend: the EffectBackend of EffectLibrary for Vulkan. Each effect version
// the reload worker builds gets its own EffectBinding (programs, pipelines, samplers;
// textures from the shared cache), made on the worker thread with its pipelines warmed for
// the application's attachment formats, so poll() only swaps pointers. The library destroys
// a replaced version's binding after its frames retired.
//
//   fx::vk::ReloadBackend backend(ctx, textures, frames,
//                                 {.formats = formats, .binding = desc, .vertex_layout = layout_for});
//   fx::EffectLibrary lib({.backend = &backend});
//   fx::EffectHandle handle = lib.load("effects/wood.fx");
//   fx::vk::EffectBinding* b = fx::vk::ReloadBackend::binding(*handle.version());
//
// The whole loop (parameters, selection, drawing, poll): docs/hot-reload.md.
#pragma once
#include <functional>
#include <memory>
#include <span>

#include "fx/binding/effect_binding.h"
#include "fx/reload/effect_backend.h"

namespace fx::vk {

// What every version is bound for.
struct ReloadBackendDesc {
  RenderingFormats formats;   // the attachments the app renders to
  EffectBindingDesc binding;  // effect_dir is replaced by each version's folder
  // The application's vertex layout for a technique's vertex shader inputs (registered as
  // layout id 0 of every binding); unset: no warm-up, pipelines are made at first apply.
  std::function<VertexLayout(std::span<const InterfaceVariable>)> vertex_layout;
};

// The GPU half of one effect version.
class ReloadBackendEffect : public BackendEffect {
 public:
  explicit ReloadBackendEffect(std::unique_ptr<EffectBinding> binding) : binding_(std::move(binding)) {}
  EffectBinding& binding() { return *binding_; }

 private:
  std::unique_ptr<EffectBinding> binding_;
};

class ReloadBackend : public EffectBackend {
 public:
  // Everything referenced must outlive the backend and the library using it.
  ReloadBackend(const Context& ctx, EffectTextureCache& textures, FrameResources& frames, ReloadBackendDesc desc)
      : ctx_(&ctx), textures_(&textures), frames_(&frames), desc_(std::move(desc)) {}

  // Binds `version`; rejects it (nullptr, errors in `diags`) when no technique can be
  // drawn or a pipeline of a drawable technique cannot be made.
  std::shared_ptr<BackendEffect> prepare(const EffectVersion& version, DiagnosticSink& diags,
                                         BackendTimings& timings) override;

  // The binding of a version prepared by a ReloadBackend (nullptr for another backend's).
  static EffectBinding* binding(const EffectVersion& version);

 private:
  const Context* ctx_;
  EffectTextureCache* textures_;
  FrameResources* frames_;
  ReloadBackendDesc desc_;
};

}  // namespace fx::vk
