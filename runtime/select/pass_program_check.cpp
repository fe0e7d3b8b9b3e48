// Compiled programs against device limits and compile success (see pass_program_check.h).
#include "pass_program_check.h"

#include <algorithm>

#include "fx/compile/effect_programs.h"
#include "fx/compile/effect_units.h"
#include "fx/compile/shader_compiler.h"
#include "fx/select/caps_requirement.h"
#include "fx/vulkan/shader_capabilities.h"

namespace fx::detail {
namespace {

// Every Vulkan device offers at least 16 vertex attributes (maxVertexInputAttributes) and
// Direct3D 8/9 vertex shaders read v0..v15; caps carry no separate limit for it.
constexpr uint32_t kVertexInputs = 16;

Diagnostic reason(std::string id, SourceRange range, std::string message) {
  Diagnostic d;
  d.id = std::move(id);
  d.severity = Severity::note;
  d.range = range;
  d.message = std::move(message);
  return d;
}

// vec4 slots a stage interface variable takes (a matrix one per column).
uint32_t slots(const InterfaceVariable& v) {
  return std::max<uint32_t>(1, v.type.array_size) * (v.type.rows > 1 ? v.type.columns : 1);
}

const EffectPass* find_pass(const EffectUnits& units, uint32_t t, std::string_view technique, uint32_t pass) {
  for (const EffectPass& p : units.passes())
    if (p.technique_index == t && p.pass_index == pass && (technique.empty() || p.technique == technique)) return &p;
  if (!technique.empty())  // units that number techniques differently from the model
    for (const EffectPass& p : units.passes())
      if (p.technique == technique && p.pass_index == pass) return &p;
  return nullptr;
}

}  // namespace

std::string unmet_limit(const DeviceCaps& caps, std::string_view limit, uint32_t need) {
  for (const CapsLimitRow& r : caps_limit_table())
    if (limit == r.name) {
      if (caps.limits.*(r.member) == 0) return {};
      return unmet_reason(caps, CapsRequirement::limit(limit, need)).value_or("");
    }
  return {};
}

PassProgramCheck check_pass_program(EffectPrograms& programs, uint32_t technique_index, std::string_view technique,
                                    uint32_t pass_index, SourceRange pass_range, const DeviceCaps& caps) {
  PassProgramCheck out;
  const EffectPass* ep = find_pass(programs.units(), technique_index, technique, pass_index);
  if (!ep) return out;
  out.found = true;
  for (const StageUnit& stage : ep->stages) {
    if (stage.kind == StageSourceKind::invalid)
      out.reasons.push_back(
          reason("shader-compile-failed", stage.range, "shader does not compile: " + stage.unsupported));
    if (stage.kind == StageSourceKind::assembly && stage.translated.empty() && !stage.unsupported.empty())
      out.reasons.push_back(reason("unsupported-shader-profile", stage.range, stage.unsupported));
  }
  bool compiled = std::any_of(ep->stages.begin(), ep->stages.end(),
                              [](const StageUnit& s) { return s.kind != StageSourceKind::invalid; });
  if (!compiled) return out;

  const PassProgram& program = programs.program(*ep);
  // What fxkit cannot draw on a Vulkan device: a combination of stages its emulation does not
  // cover. A historic caps profile (dx7, ...) describes the hardware the effect was written
  // for, where the pass ran: there it stays valid, as D3DX says.
  if (caps.generation == CapsGeneration::vulkan)
    for (const std::string& why : program.unsupported)
      out.reasons.push_back(reason("pass-not-drawable", pass_range, why));
  auto at = [&](ShaderStage s) {
    const StageUnit* ps = ep->find(s);
    return ps ? ps->range : pass_range;
  };
  bool all_ok = true;
  for (const StageProgram& sp : program.stages) {
    auto err = std::find_if(sp.diagnostics.begin(), sp.diagnostics.end(),
                            [](const Diagnostic& d) { return d.severity >= Severity::error; });
    if (err == sp.diagnostics.end() && sp.shader.ok) continue;
    all_ok = false;
    std::string what = std::string(to_string(sp.stage)) + " shader does not compile";
    if (err == sp.diagnostics.end()) {
      out.reasons.push_back(reason("shader-compile-failed", at(sp.stage), what));
      continue;
    }
    out.reasons.push_back(
        reason("shader-compile-failed", err->range.valid() ? err->range : at(sp.stage), what + ": " + err->message));
    out.reasons.back().notes.push_back({at(sp.stage).begin, "compiled for this pass here"});
  }
  for (const Diagnostic& d : program.diagnostics)
    if (d.severity >= Severity::error) {
      all_ok = false;
      out.reasons.push_back(reason("shader-compile-failed", d.range.valid() ? d.range : pass_range,
                                   "program does not link: " + d.message));
    }
  if (!all_ok) return out;
  // Stream output fxkit cannot capture on Vulkan (a second stream): the pass compiles, as fxc
  // compiles it, and cannot run.
  if (const auto& so = program.stream_output;
      caps.generation == CapsGeneration::vulkan && so && !so->unsupported.empty())
    out.reasons.push_back(reason("unsupported-stream-output", so->unsupported_range, so->unsupported));

  auto limit = [&](std::string_view name, uint32_t need, SourceRange range, const std::string& what) {
    if (std::string why = unmet_limit(caps, name, need); !why.empty())
      out.reasons.push_back(reason("shader-exceeds-limit", range, what + ": " + why));
  };
  for (const StageProgram& sp : program.stages) {
    const ShaderReflection& r = sp.shader.reflection;
    // Effects name the tessellation stages as Direct3D 11 does.
    const std::string noun = std::string(sp.stage == ShaderStage::tess_control      ? "hull"
                                         : sp.stage == ShaderStage::tess_evaluation ? "domain"
                                                                                    : to_string(sp.stage)) +
                             " shader";
    uint32_t textures = 0, samplers = 0, uniform = 0, inputs = 0;
    for (const ImageBinding& img : r.images) {
      uint32_t n = std::max<uint32_t>(1, img.array_size);
      using K = ImageBinding::Kind;
      if (img.kind == K::combined_image_sampler || img.kind == K::sampled_image) textures += n;
      if (img.kind == K::combined_image_sampler || img.kind == K::sampler) samplers += n;
      out.image_names.push_back(img.name);
    }
    for (const UniformBlock& b : r.uniform_blocks) uniform = std::max(uniform, b.size);
    for (const InterfaceVariable& v : r.inputs) inputs += slots(v);
    if (sp.stage == ShaderStage::fragment && textures) limit("simultaneous_textures", textures, at(sp.stage), noun);
    if (samplers) limit("samplers", samplers, at(sp.stage), noun);
    if (uniform) limit("uniform_bytes", uniform, at(sp.stage), noun);
    if (sp.stage == ShaderStage::fragment && inputs) limit("interpolators", inputs, at(sp.stage), noun + " inputs");
    // A module declaring a capability whose feature the device lacks is invalid to create
    // (VUID-VkShaderModuleCreateInfo-pCode-01091). Only Vulkan caps list the features.
    if (caps.vulkan.present)
      for (const ShaderCapabilityFeature* f : features_needed_by(sp.shader.spirv)) {
        const CapsRequirement feature{CapsRequirement::Kind::vulkan_feature, f->feature, 0, {}};
        if (auto why = unmet_reason(caps, feature))
          out.reasons.push_back(
              reason("shader-needs-feature", at(sp.stage),
                     noun + " uses " + f->written_as + " (SPIR-V capability " + f->capability_name + "): " + *why));
      }
    if (sp.stage == ShaderStage::vertex && inputs > kVertexInputs)
      out.reasons.push_back(reason("shader-exceeds-limit", at(sp.stage),
                                   noun + " reads " + std::to_string(inputs) + " vertex inputs, at most " +
                                       std::to_string(kVertexInputs) + " are portable"));
  }
  return out;
}

}  // namespace fx::detail
