// ReloadBackend: a binding per effect version, made and warmed on the reload worker.
#include "fx/reload/vulkan_reload_backend.h"

#include <chrono>
#include <filesystem>

#include "fx/binding/effect_preview.h"
#include "fx/reload/reload_transaction.h"

namespace fx::vk {

std::shared_ptr<BackendEffect> ReloadBackend::prepare(const EffectVersion& version, DiagnosticSink& diags,
                                                      BackendTimings& timings) {
  if (!version.model || !version.programs || !version.params) {
    diags.error("vk-reload-incomplete", {}, version.path + ": the version has no compiled programs to bind");
    return nullptr;
  }
  const auto start = std::chrono::steady_clock::now();
  EffectBindingDesc desc = desc_.binding;
  desc.effect_dir = std::filesystem::path(version.path).parent_path();
  auto binding = EffectBinding::create(*ctx_, *version.model, *version.programs, *version.params, *textures_, *frames_,
                                       desc, diags);
  if (!binding) return nullptr;
  if (binding->first_ok_technique() == kNoIndex) {
    std::string why;
    for (uint32_t t = 0; t < binding->technique_count(); ++t)
      why += "\n  " + version.model->techniques[t].name + ": " + binding->technique_reason(t);
    diags.error("vk-no-drawable-technique", {}, version.path + ": no technique can be drawn:" + why);
    return nullptr;
  }
  if (desc_.vertex_layout) {
    // Layout 0 is the app's geometry; pipelines of every drawable technique are made now
    // so the first frame after the swap does not stall on pipeline creation.
    std::vector<InterfaceVariable> inputs;  // of every drawable technique
    for (uint32_t t = 0; t < binding->technique_count(); ++t)
      if (binding->technique_ok(t)) {
        auto more = technique_vertex_inputs(*version.model, *version.programs, t);
        inputs.insert(inputs.end(), more.begin(), more.end());
      }
    binding->add_vertex_layout(desc_.vertex_layout(inputs));
    for (uint32_t t = 0; t < binding->technique_count(); ++t)
      if (binding->technique_ok(t) && !binding->warm(t, desc_.formats, 0, diags)) return nullptr;
  }
  timings.pipeline_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return std::make_shared<ReloadBackendEffect>(std::move(binding));
}

EffectBinding* ReloadBackend::binding(const EffectVersion& version) {
  auto* effect = dynamic_cast<ReloadBackendEffect*>(version.gpu.get());
  return effect ? &effect->binding() : nullptr;
}

}  // namespace fx::vk
