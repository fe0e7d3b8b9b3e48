#include "fx/compile/shader_compiler.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/SPIRV/SpvTools.h>
#include <spirv-tools/libspirv.h>

#include "effect_shader_text.h"
#include "fx/compile/compile_workers.h"
#include "fx/compile/spirv_cache.h"
#include "glslang_reflect.h"
#include "spirv_legalize.h"
#include "spirv_words.h"

namespace fx {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

std::atomic<bool> glslang_process_started{false};

// glslang's process-wide tables: built once, on the first compile that needs glslang,
// released at exit. Compiles running in worker threads only need each call to own its
// TShader and TProgram (released when the compile returns).
void ensure_glslang_process() {
  static std::once_flag once;
  std::call_once(once, [] {
    glslang::InitializeProcess();
    glslang_process_started = true;
    std::atexit([] { glslang::FinalizeProcess(); });
  });
}

EShLanguage glslang_stage(ShaderStage s) {
  switch (s) {
    case ShaderStage::vertex: return EShLangVertex;
    case ShaderStage::tess_control: return EShLangTessControl;
    case ShaderStage::tess_evaluation: return EShLangTessEvaluation;
    case ShaderStage::geometry: return EShLangGeometry;
    case ShaderStage::fragment: return EShLangFragment;
    case ShaderStage::compute: return EShLangCompute;
  }
  return EShLangVertex;
}

std::string preamble_for(const TranslationUnit& unit) {
  std::string out;
  for (const ShaderDefine& d : unit.defines) out += "#define " + d.name + " " + d.value + "\n";
  return out;
}

// Makes D3D semantics mean in Vulkan what they meant in Direct3D: a vertex shader's
// SV_Position output is the clip position even as an `inout` parameter (glslang gives it a
// location), and so is a D3D9 vertex shader's POSITION; a D3D9 pixel shader's POSITION input
// is the pixel's position (the vertex shader's output struct is often the pixel shader's
// input, and fxc drops the input when unused); pixel shader outputs COLORn / SV_TargetN go
// to colour attachment n whatever order they were declared in.
void apply_d3d_semantics(CompiledShader& out, const ShaderProfile& profile, ShaderStage stage) {
  ShaderReflection& r = out.reflection;
  std::optional<uint32_t> promoted;
  if (stage == ShaderStage::vertex) {
    promoted = profile.dx9() ? spirv::promote_position(out.spirv, spirv::Interface::output,
                                                       {"POSITION", "POSITION0", "SV_POSITION"})
                             : spirv::promote_position(out.spirv, spirv::Interface::output, {"SV_POSITION"});
    if (promoted) std::erase_if(r.outputs, [&](const InterfaceVariable& v) { return v.location == *promoted; });
  } else if (stage == ShaderStage::fragment && profile.dx9()) {
    promoted = spirv::promote_position(out.spirv, spirv::Interface::input, {"POSITION", "POSITION0"});
    if (promoted) std::erase_if(r.inputs, [&](const InterfaceVariable& v) { return v.location == *promoted; });
  }
  if (stage != ShaderStage::fragment) return;
  std::map<uint32_t, uint32_t> remap;
  for (InterfaceVariable& v : r.outputs) {
    std::string_view s = v.semantic;
    std::string_view digits = s.substr(0, 5) == "COLOR"       ? s.substr(5)
                              : s.substr(0, 9) == "SV_TARGET" ? s.substr(9)
                                                              : "-";
    if (digits == "-") continue;
    uint32_t index = digits.empty() ? 0 : static_cast<uint32_t>(digits[0] - '0');
    if (digits.size() > 1 || (!digits.empty() && (digits[0] < '0' || digits[0] > '7'))) continue;
    remap[v.location] = index;
    v.location = index;
  }
  spirv::remap_locations(out.spirv, spirv::Interface::output, remap);
  std::sort(r.outputs.begin(), r.outputs.end(),
            [](const InterfaceVariable& a, const InterfaceVariable& b) { return a.location < b.location; });
}

// Whether HLSL source calls a D3D9 sampler intrinsic (tex1D, tex2Dlod, texCUBEbias, ...).
// Code written for D3D9 is often compiled with an SM4 profile (`ps_4_0_level_9_1`, fxc's
// backwards-compatibility mode): glslang reads its sampler2D as a combined image sampler only
// in DX9 compatibility mode, and otherwise writes SPIR-V that samples a bare image. That mode
// also makes a plain `sampler` combined, which breaks D3D10 `Texture.Sample(sampler, uv)`, so
// it is chosen only for code that needs it.
bool uses_d3d9_sampler_intrinsics(std::string_view hlsl) {
  for (size_t at = hlsl.find("tex"); at != std::string_view::npos; at = hlsl.find("tex", at + 3)) {
    if (at > 0 && detail::is_word_char(hlsl[at - 1])) continue;
    std::string_view rest = hlsl.substr(at + 3);
    size_t dim = rest.rfind("CUBE", 0) == 0                                               ? 4
                 : rest.size() >= 2 && rest[0] >= '1' && rest[0] <= '3' && rest[1] == 'D' ? 2
                                                                                          : 0;
    if (dim == 0) continue;
    size_t end = dim;
    while (end < rest.size() && detail::is_word_char(rest[end])) ++end;  // lod, bias, proj, grad
    while (end < rest.size() && (rest[end] == ' ' || rest[end] == '\t')) ++end;
    if (end < rest.size() && rest[end] == '(') return true;
  }
  return false;
}

// Whether SPIR-V is valid for its Vulkan target, checked as glslang's SpirvToolsValidate
// does. The validator's friendly names (every id mapped to a name before it starts, a third
// of its time) are worked out only to word an error for `log`.
bool spirv_valid(const std::vector<uint32_t>& spirv, spv_target_env env, const glslang::TIntermediate& intermediate,
                 spv::SpvBuildLogger* log) {
  auto validate = [&](bool friendly_names, spv_diagnostic* diagnostic) {
    spv_context context = spvContextCreate(env);
    spv_validator_options options = spvValidatorOptionsCreate();
    // HLSL packing (EShMsgHlslOffsets) is relaxed block layout, implied from Vulkan 1.1 on.
    spvValidatorOptionsSetRelaxBlockLayout(options, intermediate.usingHlslOffsets());
    spvValidatorOptionsSetScalarBlockLayout(options, intermediate.usingScalarBlockLayout());
    spvValidatorOptionsSetWorkgroupScalarBlockLayout(options, intermediate.usingScalarBlockLayout());
    spvValidatorOptionsSetFriendlyNames(options, friendly_names);
    spv_const_binary_t binary = {spirv.data(), spirv.size()};
    spv_result_t result = spvValidateWithOptions(context, options, &binary, diagnostic);
    spvValidatorOptionsDestroy(options);
    spvContextDestroy(context);
    return result == SPV_SUCCESS;
  };
  if (validate(false, nullptr)) return true;
  if (log) {
    spv_diagnostic diagnostic = nullptr;
    validate(true, &diagnostic);
    log->error("SPIRV-Tools Validation Errors");
    if (diagnostic) log->error(diagnostic->error);
    spvDiagnosticDestroy(diagnostic);
  }
  return false;
}

// Appends what SPIRV-Tools said about the module to an info log, one line per problem:
// its validator writes a header line, then each error (which may go on over lines) and the
// instruction at fault, indented, which all go into the error's own line. True when there
// was an error.
bool append_spirv_log(const std::string& log, const std::string& entry, std::string& info_log) {
  bool any_error = false;
  std::string pending;  // the last error, waiting for its instruction
  auto flush = [&] {
    if (!pending.empty()) info_log += "ERROR: " + pending + "\n";
    pending.clear();
  };
  for (size_t pos = 0; pos < log.size();) {
    size_t nl = log.find('\n', pos);
    std::string line = log.substr(pos, nl == std::string::npos ? std::string::npos : nl - pos);
    pos = nl == std::string::npos ? log.size() : nl + 1;
    if (line.empty() || line == "error: SPIRV-Tools Validation Errors") continue;
    if (line.rfind("error: ", 0) == 0) {
      flush();
      any_error = true;
      pending = "the SPIR-V glslang made for '" + entry + "' is invalid for Vulkan: " + line.substr(7);
    } else if (!pending.empty() && line.rfind("  ", 0) == 0) {  // the instruction, indented
      pending += " (at `" + line.substr(line.find_first_not_of(' ')) + "`)";
      flush();
    } else if (!pending.empty()) {  // the message goes on
      pending += " " + line;
    } else {
      info_log += "WARNING: SPIR-V " + line + "\n";
    }
  }
  flush();
  return any_error;
}

CompiledShader rejected(std::string text) {
  CompiledShader r;
  r.info_log = "ERROR: " + text + "\n";
  r.messages.push_back({Severity::error, {}, 0, 0, std::move(text), {}});
  return r;
}

}  // namespace

ShaderCompiler::ShaderCompiler(CompileOptions options, SpirvCache* cache, CompileWorkers* workers)
    : options_(options), cache_(cache), workers_(workers) {}

bool ShaderCompiler::glslang_started() { return glslang_process_started.load(); }

std::string ShaderCompiler::glslang_version() {
  glslang::Version v = glslang::GetVersion();
  return "glslang " + std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.patch) +
         v.flavor;
}

CompiledShader ShaderCompiler::compile(const TranslationUnit& unit) const {
  Clock::time_point start = Clock::now();
  std::optional<ShaderProfile> profile = parse_profile(unit.profile);
  if (!profile) return rejected("unknown shader profile '" + unit.profile + "'");
  if (profile->language != unit.language)
    return rejected("profile '" + unit.profile + "' is for " + to_string(profile->language) + " but the shader is " +
                    to_string(unit.language));
  if (profile->stage && *profile->stage != unit.stage)
    return rejected("profile '" + unit.profile + "' is a " + to_string(*profile->stage) + " profile, used for a " +
                    to_string(unit.stage) + " shader");
  if (unit.language == ShaderLanguage::glsl && unit.entry_point != "main")
    return rejected("GLSL shaders are entered through main(), not '" + unit.entry_point + "'");

  SpirvCacheKey key;
  if (cache_) {
    key = spirv_cache_key(unit, options_);
    if (std::optional<CompiledShader> hit = cache_->find(key)) {
      hit->from_cache = true;
      hit->parse_ms = hit->link_ms = 0;
      hit->total_ms = ms_since(start);
      return std::move(*hit);
    }
  }
  CompiledShader result;
  if (workers_) {
    ++glslang_runs_;
    result = workers_->compile(unit, options_);
  } else {
    result = run_glslang(unit, *profile);
  }
  if (cache_ && result.ok) cache_->store(key, result);
  result.total_ms = ms_since(start);
  return result;
}

CompiledShader ShaderCompiler::run_glslang(const TranslationUnit& unit, const ShaderProfile& profile) const {
  ensure_glslang_process();
  ++glslang_runs_;
  CompiledShader out;
  out.entry_point = unit.entry_point;
  out.reflection.stage = unit.stage;
  out.reflection.entry_point = unit.entry_point;

  const bool hlsl = unit.language == ShaderLanguage::hlsl;
  const EShLanguage stage = glslang_stage(unit.stage);
  const bool vulkan_1_0 = options_.target == VulkanTarget::vulkan_1_0;
  glslang::EShTargetClientVersion client = options_.target == VulkanTarget::vulkan_1_0   ? glslang::EShTargetVulkan_1_0
                                           : options_.target == VulkanTarget::vulkan_1_1 ? glslang::EShTargetVulkan_1_1
                                           : options_.target == VulkanTarget::vulkan_1_2 ? glslang::EShTargetVulkan_1_2
                                                                                         : glslang::EShTargetVulkan_1_3;

  auto shader = std::make_unique<glslang::TShader>(stage);
  const char* text = unit.source.c_str();
  const int length = static_cast<int>(unit.source.size());
  const char* name = unit.name.c_str();
  shader->setStringsWithLengthsAndNames(&text, &length, &name, 1);
  std::string preamble = preamble_for(unit);
  if (!preamble.empty()) shader->setPreamble(preamble.c_str());
  // The SPIR-V entry keeps the source name (VS, PS, Wood...): pipelines pass it as pName,
  // and disassembly and RenderDoc show the author's names.
  shader->setEntryPoint(unit.entry_point.c_str());
  shader->setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
  shader->setEnvClient(glslang::EShClientVulkan, client);
  shader->setEnvTarget(glslang::EShTargetSpv, vulkan_1_0 ? glslang::EShTargetSpv_1_0 : glslang::EShTargetSpv_1_3);
  shader->setAutoMapBindings(true);
  shader->setAutoMapLocations(true);
  if (hlsl) {
    // D3D registers are counted per class (t0, s0, b0 and u0 are four slots), a Vulkan set
    // has one binding space: each class starts at its own base so `register(t0)` and
    // `register(s0)` never share a binding. link_program renumbers them densely afterwards.
    for (auto [resource, base] : {std::pair{glslang::EResTexture, 0u},
                                  {glslang::EResSampler, 128u},
                                  {glslang::EResUbo, 256u},
                                  {glslang::EResImage, 384u},
                                  {glslang::EResUav, 384u},
                                  {glslang::EResSsbo, 512u}})
      shader->setShiftBinding(resource, base);
    shader->setHlslIoMapping(true);
    // Semantics (POSITION, TEXCOORD0) reach reflection through UserSemantic decorations.
    shader->setEnvTargetHlslFunctionality1();
  }

  int messages = EShMsgSpvRules | EShMsgVulkanRules | EShMsgCascadingErrors;
  if (hlsl) messages |= EShMsgReadHlsl | EShMsgHlslOffsets | EShMsgHlslLegalization;
  if (hlsl && (profile.dx9() || uses_d3d9_sampler_intrinsics(unit.source))) messages |= EShMsgHlslDX9Compatible;
  if (options_.debug_info) messages |= EShMsgDebugInfo;
  const EShMessages flags = static_cast<EShMessages>(messages);
  // GLSL sources carry their own #version; 450 is the fallback when they do not.
  const int default_version = hlsl ? 100 : profile.major * 100 + profile.minor * 10;

  Clock::time_point t0 = Clock::now();
  bool parsed = shader->parse(GetDefaultResources(), default_version, false, flags);
  out.parse_ms = ms_since(t0);
  out.info_log = shader->getInfoLog();
  if (!parsed) {
    out.messages = parse_info_log(out.info_log);
    return out;
  }

  Clock::time_point t1 = Clock::now();
  auto program = std::make_unique<glslang::TProgram>();
  bool spirv_error = false;
  program->addShader(shader.get());
  bool linked = program->link(flags) && program->mapIO();
  out.info_log += program->getInfoLog();
  if (linked && program->getIntermediate(stage)) {
    glslang::SpvOptions spv;
    spv.generateDebugInfo = options_.debug_info;
    spv.disableOptimizer = true;
    spv.validate = false;  // run below, after fxkit's own passes
    const glslang::TIntermediate& intermediate = *program->getIntermediate(stage);
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(intermediate, out.spirv, &logger, &spv);
    if (hlsl) spirv::scalar_any_all(out.spirv);
    const spv_target_env env = glslang::MapToSpirvToolsEnv(intermediate.getSpv(), &logger);
    // HLSL may need spirv-opt's legalization (opaque types copied into locals or passed to
    // functions, as D3D9 code does with samplers), which costs ten times the rest of the
    // compile. Most shaders are valid without it: they skip it when neither glslang, nor a
    // scan for opaque values in memory, nor the validator finds a reason for it.
    bool validated = false;
    if (hlsl && options_.validate && !intermediate.needsLegalization() && !spirv::opaque_values_in_memory(out.spirv) &&
        !spirv::variable_image_offsets(out.spirv))
      validated = spirv_valid(out.spirv, env, intermediate, nullptr);
    out.legalized = !validated;
    if (hlsl && !validated) {
      spv.disableOptimizer = false;
      glslang::SpirvToolsTransform(intermediate, out.spirv, &logger, &spv);
      if (spirv::variable_image_offsets(out.spirv)) spirv::unroll_and_fold(out.spirv, env);
    }
    // glslang can emit invalid SPIR-V for code it accepts (a derivative in a vertex shader):
    // SPIRV-Tools' validator turns that into an error instead of a driver crash.
    if (options_.validate && !validated && !out.spirv.empty()) spirv_valid(out.spirv, env, intermediate, &logger);
    spirv_error = append_spirv_log(logger.getAllMessages(), unit.entry_point, out.info_log);
    program->buildReflection(kReflectionOptions);
    ShaderReflection reflection = reflect_program(*program, stage, out.spirv);
    reflection.stage = unit.stage;
    reflection.entry_point = unit.entry_point;
    out.reflection = std::move(reflection);
    if (hlsl) apply_d3d_semantics(out, profile, unit.stage);
    if (hlsl && !options_.keep_hlsl_semantics) spirv::strip_hlsl_semantics(out.spirv);
  }
  out.link_ms = ms_since(t1);
  out.messages = parse_info_log(out.info_log);
  out.ok = linked && !spirv_error && !out.spirv.empty();
  if (options_.warnings_as_errors)
    for (ShaderMessage& m : out.messages)
      if (m.severity == Severity::warning) m.severity = Severity::error, out.ok = false;
  if (!out.ok) out.spirv.clear();
  return out;
}

CompiledShader compile_and_report(const ShaderCompiler& compiler, const TranslationUnit& unit,
                                  const ShaderLocationResolver& resolve, DiagnosticSink& sink) {
  CompiledShader result = compiler.compile(unit);
  report_messages(result.messages, resolve, sink);
  return result;
}

}  // namespace fx
