// Technique validation from an effect model's passes (see technique_validation.h).
#include "fx/select/technique_validation.h"

#include <algorithm>
#include <charconv>
#include <memory>
#include <tuple>

#include "fx/ascii_case.h"
#include "fx/compile/effect_file.h"
#include "fx/model/effect_model.h"
#include "fx/select/caps_requirement.h"
#include "fx/state_table.h"
#include "pass_program_check.h"

namespace fx {
namespace {

constexpr std::string_view kTransformFeedbackExtension = "VK_EXT_transform_feedback";

std::string caps_name(const DeviceCaps& caps) { return caps.name.empty() ? "this device" : caps.name; }

// "ColorOp[0]" for indexed rows, "AlphaTestEnable" otherwise.
std::string state_name(const ResolvedState& s) {
  std::string n(s.info->name);
  if (s.info->index_count > 0) n.append("[").append(std::to_string(s.index)).append("]");
  return n;
}

const char* stage_noun(PassStage stage) {
  switch (stage) {
    case PassStage::vertex: return "vertex shader";
    case PassStage::pixel: return "pixel shader";
    case PassStage::geometry: return "geometry shader";
    case PassStage::hull: return "hull shader";
    case PassStage::domain: return "domain shader";
    case PassStage::compute: return "compute shader";
  }
  return "shader";
}

// The text of the first line of a token span: "vs" ".1.1" -> "vs.1.1".
std::string first_line(const ast::Effect& effect, ast::TokenSpan span) {
  std::string out;
  for (uint32_t i = span.first; i < span.last && i < effect.tokens.size(); ++i) {
    const Token& t = effect.tokens[i];
    if (i != span.first && t.at_line_start()) break;
    out += t.text();
  }
  return out;
}

// Collects reasons for one technique; keeps the first of equal (id, message, range).
class Rejections {
 public:
  void add(std::string id, SourceRange range, std::string message) {
    for (const Diagnostic& d : list_)
      if (d.id == id && d.message == message && d.range.begin == range.begin) return;
    Diagnostic d;
    d.id = std::move(id);
    d.severity = Severity::note;
    d.range = range;
    d.message = std::move(message);
    list_.push_back(std::move(d));
  }
  Diagnostic& last() { return list_.back(); }
  Diagnostic& at(size_t i) { return list_[i]; }
  size_t size() const { return list_.size(); }
  bool has_message(std::string_view message) const {
    return std::any_of(list_.begin(), list_.end(), [&](const Diagnostic& d) { return d.message == message; });
  }
  std::vector<Diagnostic> take() { return std::move(list_); }

 private:
  std::vector<Diagnostic> list_;
};

class TechniqueValidator {
 public:
  TechniqueValidator(const EffectModel& model, const DeviceCaps& caps, const TechniqueValidationOptions& options)
      : model_(model), caps_(caps), options_(options) {}

  TechniqueValidation run(const TechniqueInfo& technique) {
    TechniqueValidation out;
    out.name = technique.name;
    out.range = technique.range;
    out.annotations = annotations(technique);
    for (uint32_t p = 0; p < technique.passes.size(); ++p) check_pass(technique, p);
    // Nothing to draw: a binding has no pass to apply, so no device runs it.
    if (technique.passes.empty()) reasons_.add("no-passes", technique.range, "the technique has no passes");
    check_requires(technique);
    out.reasons = reasons_.take();
    out.valid = out.reasons.empty();
    out.emulation = std::move(emulation_);
    return out;
  }

 private:
  static std::vector<TechniqueAnnotation> annotations(const TechniqueInfo& technique) {
    std::vector<TechniqueAnnotation> out;
    for (const auto& a : technique.annotations) {
      const Value& v = a.value;
      if (v.is_string()) {
        out.emplace_back(a.name, v.text);
      } else if (v.components.size() == 1 && v.type.cls == TypeClass::scalar) {
        switch (v.type.base) {
          case BaseType::boolean: out.emplace_back(a.name, v.truthy()); break;
          case BaseType::int32:
          case BaseType::uint32: out.emplace_back(a.name, int32_t(v.number())); break;
          default: out.emplace_back(a.name, float(v.number())); break;
        }
      }
    }
    return out;
  }

  void require_profile(const std::string& profile, SourceRange range) {
    if (supports(caps_, profile)) return;
    profile_rejected_ = true;
    reasons_.add("unsupported-shader-profile", range,
                 unmet_reason(caps_, CapsRequirement::profile(profile)).value_or(profile + " not supported"));
  }

  // The GLSL version a list of blocks declares (`#version 450` -> 450), 0 when none.
  int glsl_version(const ShaderBinding& b) const {
    if (!model_.ast) return 0;
    for (const std::string& name : b.glsl_blocks)
      for (const auto& d : model_.ast->decls) {
        if (d.kind != ast::DeclKind::glsl_block || d.glsl_block->name != name) continue;
        const ast::TokenSpan code = d.glsl_block->code;
        for (uint32_t i = code.first; i < code.last && i < model_.ast->tokens.size(); ++i) {
          std::string_view t = model_.ast->tokens[i].text();
          if (model_.ast->tokens[i].kind != TokenKind::directive || t.find("version") == std::string_view::npos)
            continue;
          size_t digit = t.find_first_of("0123456789");
          int version = 0;
          if (digit != std::string_view::npos) std::from_chars(t.data() + digit, t.data() + t.size(), version);
          if (version) return version;
        }
      }
    return 0;
  }

  void check_shader(const ShaderBinding& b) {
    switch (b.source) {
      case ShaderSource::null: return;
      case ShaderSource::hlsl_compile: require_profile(canonical_shader_profile(b.profile), b.range); return;
      case ShaderSource::asm_block: {
        std::string version = model_.ast ? first_line(*model_.ast, b.asm_code) : std::string();
        std::string profile = canonical_shader_profile(version);
        bool looks_like_version = profile.size() >= 6 && (profile.starts_with("vs_") || profile.starts_with("ps_"));
        if (!looks_like_version) {
          profile_rejected_ = true;
          reasons_.add(
              "unsupported-shader-profile", b.range,
              std::string(stage_noun(b.stage)) + " assembly has no version token (vs.1.1, ps.1.4) on its first line");
          return;
        }
        require_profile(profile, b.range);
        if (b.stage == PassStage::pixel && profile < "ps_1_4") count_texture_registers(b);
        if (caps_.generation == CapsGeneration::vulkan)
          note_emulation("emulated: " + version + " assembly translated to HLSL");
        return;
      }
      case ShaderSource::glsl_blocks: {
        int version = glsl_version(b);
        if (version) {
          require_profile("glsl_" + std::to_string(version), b.range);
          return;
        }
        bool any = std::any_of(caps_.shader_profiles.begin(), caps_.shader_profiles.end(),
                               [](const std::string& p) { return p.starts_with("glsl_"); });
        if (!any) {
          profile_rejected_ = true;
          reasons_.add("unsupported-shader-profile", b.range, "GLSL shaders not supported on " + caps_name(caps_));
        }
        return;
      }
    }
  }

  void note_emulation(const std::string& line) {
    if (std::find(emulation_.begin(), emulation_.end(), line) == emulation_.end()) emulation_.push_back(line);
  }
  static int technique_version(const TechniqueInfo& t) { return t.version; }

  // ps.1.1-1.3 sample stage n into register tn: the highest t register is the stage count.
  void count_texture_registers(const ShaderBinding& b) {
    for (uint32_t i = b.asm_code.first; i < b.asm_code.last && i < model_.ast->tokens.size(); ++i) {
      const Token& t = model_.ast->tokens[i];
      std::string_view word = t.text();
      if (t.kind != TokenKind::identifier || word.size() < 2 || word[0] != 't') continue;
      uint32_t n = 0;
      auto [end, ec] = std::from_chars(word.data() + 1, word.data() + word.size(), n);
      if (ec != std::errc() || end != word.data() + word.size() || n >= 16) continue;
      note_texture_stage(n, b.range);
    }
  }

  void note_texture_stage(uint32_t stage, SourceRange range) {
    if (stage + 1 > textures_) {
      textures_ = stage + 1;
      textures_range_ = range;
    }
  }

  void check_fixed_function(const ResolvedState& s) {
    if (!caps_.features.fixed_function_stages) {
      // One reason per pass; the pass's other fixed-function states become its notes.
      if (fixed_function_reason_ != kNone) {
        reasons_.at(fixed_function_reason_)
            .notes.push_back({s.range.begin, "fixed-function state '" + state_name(s) + "' here too"});
        return;
      }
      reasons_.add("fixed-function-state", s.range,
                   "fixed-function state '" + state_name(s) + "' has no Vulkan equivalent (" + caps_name(caps_) +
                       " has no fixed-function texture stages)");
      fixed_function_reason_ = reasons_.size() - 1;
      return;
    }
    bool is_op = s.info->field == StateField::stage_color_op || s.info->field == StateField::stage_alpha_op;
    if (!is_op || s.kind != StateValueKind::enumeration) return;
    auto op_is = [&](std::string_view op) {
      auto v = find_enum(*s.info, op);
      return v && *v == s.integer;
    };
    if (op_is("Disable")) return;
    if (op_is("DotProduct3") && !caps_.features.dot3)
      reasons_.add("state-needs-feature", s.range,
                   "'" + state_name(s) + " = DotProduct3' needs dot3 (D3DTOP_DOTPRODUCT3), not supported on " +
                       caps_name(caps_));
    if (op_is("Subtract") && !caps_.features.subtract)
      reasons_.add(
          "state-needs-feature", s.range,
          "'" + state_name(s) + " = Subtract' needs subtract (D3DTOP_SUBTRACT), not supported on " + caps_name(caps_));
    // A blending stage past the device's stages cannot run even when it samples nothing.
    note_texture_stage(s.index, s.range);
  }

  void check_feature_state(const ResolvedState& s, StateField field, const char* feature, bool CapsFeatures::*member) {
    if (s.info->field != field || s.kind != StateValueKind::boolean || s.integer == 0) return;
    if (caps_.features.*member) return;
    reasons_.add("state-needs-feature", s.range,
                 "'" + state_name(s) + " = TRUE' needs " + feature + ", not supported on " + caps_name(caps_));
  }

  // `string Format = "float32"` on a texture parameter: the format it is created with.
  void check_texture_format(uint32_t parameter) {
    if (parameter >= model_.parameters.size()) return;
    const Parameter& p = model_.parameters[parameter];
    const Annotation* fmt = find_annotation(p.annotations, "Format");
    if (!fmt || !fmt->value.is_string()) return;
    const std::string& f = fmt->value.text;
    std::string vk_format = f;
    bool is_float = false;
    if (iequals(f, "float32")) vk_format = "R32G32B32A32_SFLOAT", is_float = true;
    else if (iequals(f, "float16")) vk_format = "R16G16B16A16_SFLOAT", is_float = true;
    else if (iequals(f, "unorm8")) vk_format = "R8G8B8A8_UNORM";
    else is_float = f.find("FLOAT") != std::string::npos || f.find("float") != std::string::npos;
    // Generated tables are fxkit's own data: on generations without float textures the
    // seed techniques read them at 8 bits (the BRDF seed's DirectX 8 cube maps), so only
    // textures the application supplies make the technique invalid.
    const TextureInfo* tex = model_.texture_of(parameter);
    bool generated = tex && !tex->generator.empty();
    if (is_float && !generated && !caps_.features.float_textures)
      reasons_.add("unsupported-format", fmt->range,
                   "texture '" + p.name + "' is " + f + ": float_textures not supported on " + caps_name(caps_));
    if (!caps_.vulkan.present) return;
    CapsRequirement req;
    req.kind = CapsRequirement::Kind::format;
    req.name = vk_format;
    req.usage = "sampled";
    if (auto why = unmet_reason(caps_, req))
      reasons_.add("unsupported-format", fmt->range, "texture '" + p.name + "': " + *why);
  }

  void check_program(const TechniqueInfo& technique, uint32_t index) {
    const uint32_t t = uint32_t(&technique - model_.techniques.data());
    detail::PassProgramCheck c =
        detail::check_pass_program(*options_.programs, t, technique.name, index, technique.passes[index].range, caps_);
    for (Diagnostic& d : c.reasons) {
      reasons_.add(d.id, d.range, d.message);
      for (auto& n : d.notes) reasons_.last().notes.push_back(n);
    }
    for (const std::string& name : c.image_names)  // the formats of the textures it samples
      for (const SamplerInfo& s : model_.samplers)
        if (s.name == name && s.texture != kNoIndex && s.texture < model_.textures.size())
          check_texture_format(model_.textures[s.texture].parameter);
  }

  void check_pass(const TechniqueInfo& technique, uint32_t index) {
    const PassInfo& pass = technique.passes[index];
    textures_ = 0;
    textures_range_ = {};
    profile_rejected_ = false;
    fixed_function_reason_ = kNone;
    for (const ShaderBinding& b : pass.shaders) check_shader(b);
    if (caps_.generation == CapsGeneration::vulkan && technique_version(technique) == 9) {
      auto has = [&](PassStage s) {
        const ShaderBinding* b = pass.shader(s);
        return b && b->source != ShaderSource::null;
      };
      if (!has(PassStage::vertex)) note_emulation("emulated: fixed-function vertex processing as generated HLSL");
      if (!has(PassStage::pixel)) note_emulation("emulated: fixed-function texture stages as generated HLSL");
    }
    check_vertex_shader(technique, pass);
    check_stream_output(pass);
    const ShaderBinding* pixel = pass.shader(PassStage::pixel);
    const bool pixel_shader = pixel && pixel->source != ShaderSource::null;
    for (const ResolvedState& s : pass.states) {
      if (!s.info) continue;
      if (pixel_shader && pixel_shader_replaces_or_reads(*s.info)) continue;  // D3D9 ignores them then
      if (s.info->vulkan == VulkanMeaning::fixed_function) {
        check_fixed_function(s);
        continue;
      }
      check_feature_state(s, StateField::alpha_test, "alpha_test (no shader emulation yet)", &CapsFeatures::alpha_test);
      check_feature_state(s, StateField::separate_alpha, "separate_alpha_blend", &CapsFeatures::separate_alpha_blend);
      check_feature_state(s, StateField::stencil_two_sided, "two_sided_stencil", &CapsFeatures::two_sided_stencil);
      const bool texture = s.info->field == StateField::texture;
      bool binds_texture = s.info->block == StateBlock::pass && (texture || s.info->field == StateField::sampler) &&
                           s.kind != StateValueKind::null && s.kind != StateValueKind::invalid;
      if (binds_texture) {
        note_texture_stage(s.index, s.range);
        if (s.kind == StateValueKind::parameter && texture) check_texture_format(s.target);
      }
    }
    if (std::string why = detail::unmet_limit(caps_, "simultaneous_textures", textures_); !why.empty())
      reasons_.add("too-many-textures", textures_range_, why);
    if (fixed_function_reason_ != kNone) {
      Diagnostic& d = reasons_.at(fixed_function_reason_);
      if (!d.notes.empty()) d.message += "; " + std::to_string(d.notes.size()) + " more in pass '" + pass.name + "'";
    }
    // Limits of a profile the device cannot run at all would only repeat the rejection.
    if (options_.programs && !profile_rejected_) check_program(technique, index);
  }

  // A Direct3D 10/11 pass that sets other stages draws only with a vertex shader, and a
  // Vulkan graphics pipeline needs one (a Direct3D 9 pass gets the fixed-function one); a
  // hull shader goes with a domain shader.
  void check_vertex_shader(const TechniqueInfo& technique, const PassInfo& pass) {
    if (technique_version(technique) < 10) return;
    auto bound = [&](PassStage s) {
      const ShaderBinding* b = pass.shader(s);
      return b && b->source != ShaderSource::null ? b : nullptr;
    };
    // Tessellation takes both stages (Direct3D 11 and Vulkan alike).
    const ShaderBinding* hull = bound(PassStage::hull);
    const ShaderBinding* domain = bound(PassStage::domain);
    if (!hull != !domain)
      reasons_.add("missing-tessellation-stage", hull ? hull->range : domain->range,
                   std::string("pass sets a ") +
                       (hull ? "hull shader but no domain shader" : "domain shader but no hull shader") +
                       "; tessellation needs both");
    if (bound(PassStage::vertex)) return;
    // ConstructGSWithSO of a vertex shader is that vertex shader with stream output: the pass
    // draws with it.
    if (const ShaderBinding* gs = bound(PassStage::geometry); gs && gs->profile.starts_with("vs_")) return;
    for (PassStage s : {PassStage::hull, PassStage::domain, PassStage::geometry, PassStage::pixel})
      if (const ShaderBinding* b = bound(s)) {
        reasons_.add("missing-vertex-shader", b->range,
                     std::string("pass sets a ") + stage_noun(s) + " but no vertex shader, which drawing needs");
        return;
      }
  }

  // ConstructGSWithSO: the stream is captured with VK_EXT_transform_feedback (its transformFeedback
  // feature enabled, its vertices drawable by byte count); a Direct3D 10/11 profile has it.
  void check_stream_output(const PassInfo& pass) {
    if (!caps_.vulkan.present) return;
    const auto& extensions = caps_.vulkan.extensions;
    if (std::find(extensions.begin(), extensions.end(), kTransformFeedbackExtension) != extensions.end()) return;
    for (const ShaderBinding& b : pass.shaders)
      if (b.stream_output && b.source != ShaderSource::null)
        reasons_.add("unsupported-stream-output", b.range,
                     "stream output (ConstructGSWithSO) needs " + std::string(kTransformFeedbackExtension) +
                         " with transform feedback draws, not enabled on " + caps_name(caps_));
  }

  // The technique's `Requires`: located at the annotation. A need the passes already
  // reported (same sentence) is not repeated.
  void check_requires(const TechniqueInfo& technique) {
    const Annotation* req = find_annotation(technique.annotations, "Requires");
    if (!req) return;
    if (!req->value.is_string()) {
      reasons_.add("bad-requires", req->range, "annotation Requires must be a string");
      return;
    }
    std::vector<std::string> errors;
    for (const CapsRequirement& r : parse_caps_requirements(req->value.text, &errors))
      if (auto why = unmet_reason(caps_, r); why && !reasons_.has_message(*why))
        reasons_.add("unmet-requirement", req->range, "Requires: " + *why);
    for (std::string& e : errors) reasons_.add("bad-requires", req->range, std::move(e));
  }

  const EffectModel& model_;
  const DeviceCaps& caps_;
  const TechniqueValidationOptions& options_;
  Rejections reasons_;
  std::vector<std::string> emulation_;
  uint32_t textures_ = 0;          // texture stages the current pass uses
  SourceRange textures_range_;     // the state or shader that uses the last one
  bool profile_rejected_ = false;  // the current pass has a shader the device cannot run
  static constexpr size_t kNone = size_t(-1);
  size_t fixed_function_reason_ = kNone;  // the current pass's fixed-function reason
};

}  // namespace

TechniqueValidation validate_technique(const EffectModel& model, const TechniqueInfo& technique, const DeviceCaps& caps,
                                       const TechniqueValidationOptions& options) {
  return TechniqueValidator(model, caps, options).run(technique);
}

std::vector<TechniqueValidation> validate_techniques(const EffectModel& model, const DeviceCaps& caps,
                                                     const TechniqueValidationOptions& options) {
  std::vector<TechniqueValidation> out;
  out.reserve(model.techniques.size());
  for (const TechniqueInfo& t : model.techniques) out.push_back(validate_technique(model, t, caps, options));
  return out;
}

std::vector<TechniqueValidation> validate_effect(EffectFile& effect, const DeviceCaps& caps, DiagnosticSink& diags,
                                                 bool compile, const ShaderCompiler* compiler) {
  if (!effect.model) effect.build_model(diags);
  if (!compile) return validate_techniques(*effect.model, caps);
  if (!effect.programs) {
    DiagnosticSink repeated;  // the model reports bad shader references; the units would repeat them
    effect.build_programs(repeated, compiler);
  }
  return validate_techniques(*effect.model, caps, {.programs = effect.programs.get()});
}

std::optional<size_t> find_next_valid(std::span<const TechniqueValidation> techniques, std::optional<size_t> after) {
  if (after && *after >= techniques.size()) return std::nullopt;
  for (size_t i = after ? *after + 1 : 0; i < techniques.size(); ++i)
    if (techniques[i].valid) return i;
  return std::nullopt;
}

std::string located_reason(const Diagnostic& reason, const SourceManager& sm) {
  PresumedLocation at = sm.presumed(reason.range.begin);
  if (!at.valid()) return reason.message;
  std::string file(at.file);
  if (auto slash = file.find_last_of("/\\"); slash != std::string::npos) file = file.substr(slash + 1);
  return file + ":" + std::to_string(at.line) + ": " + reason.message;
}

}  // namespace fx
