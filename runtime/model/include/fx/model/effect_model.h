// The semantic model of an effect: typed parameters with folded defaults and annotations,
// textures (files or procedural generators), samplers resolved to SamplerDesc, D3D10/11
// state objects, techniques and passes with states resolved against the state table,
// shader bindings, and a per-pass PassStateSummary for the Vulkan backend.
// Stable: every struct below and build_effect_model. Indices (parameter, texture,
// sampler, state object) are positions in the EffectModel vectors.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/ast.h"
#include "fx/diagnostic.h"
#include "fx/frontend.h"
#include "fx/model/dxsas_script.h"
#include "fx/model/pass_state.h"
#include "fx/model/texture_shader.h"
#include "fx/model/type.h"
#include "fx/model/value.h"
#include "fx/no_index.h"
#include "fx/shading/generator.h"
#include "fx/source_manager.h"
#include "fx/state_table.h"

namespace fx {

// A named, typed, located annotation (`float UIMin = 0;`).
struct Annotation {
  std::string name;
  Value value;
  SourceRange range;
  SourceRange value_range;  // the value's expression (a string: from its opening quote)
};

// The annotation named `name` (case-sensitive, as D3DX), or nullptr.
const Annotation* find_annotation(const std::vector<Annotation>& list, std::string_view name);

struct Parameter {
  std::string name;
  Type type;
  std::string semantic;  // as written (lookups ignore case)
  std::vector<Annotation> annotations;
  std::optional<Value> default_value;  // converted to `type`; absent when not initialised
  uint32_t storage = 0;                // ast::StorageClass bits
  bool is_shared() const { return storage & ast::kShared; }
  bool is_static() const { return storage & ast::kStatic; }
  bool is_uniform() const { return !(storage & ast::kStatic); }
  // Lands in a uniform block or a resource binding the app can set (not static, not a
  // string, shader or state object).
  bool shader_visible = false;
  std::string constant_buffer;   // enclosing cbuffer/tbuffer ("" = the global block)
  std::string register_binding;  // `: register(c0)` as written
  SourceRange range;             // the declaration
  SourceRange name_range;
  const ast::Variable* decl = nullptr;  // into the ParsedEffect the model was built from
};

// A texture parameter: a file, a procedural table, a texture shader, or set by the app.
struct TextureInfo {
  uint32_t parameter = kNoIndex;
  TextureShape shape = TextureShape::any;
  std::string resource_name;                  // `string ResourceName = "x.png"` (or Name/File)
  SourceRange resource_range;                 // the ResourceName annotation
  std::string generator;                      // `string Generator = "strand"` ("" if none)
  shading::GeneratorParams generator_params;  // every numeric/string annotation but Generator
  SourceRange generator_range;                // the Generator annotation
  std::optional<TextureShader> shader;        // `string function = "Fill"` (fx/model/texture_shader.h)
};

// A sampler: a D3D9 `sampler2D s = sampler_state {...}` parameter or a D3D10
// `SamplerState s {...}` object.
struct SamplerInfo {
  uint32_t parameter = kNoIndex;     // the sampler parameter (D3D9 form)
  uint32_t state_object = kNoIndex;  // the SamplerState object (D3D10 form)
  std::string name;
  SamplerDesc desc;
  uint32_t texture = kNoIndex;  // the texture parameter `Texture = <t>` names
  SourceRange range;
};

// Where a shader binding comes from.
enum class ShaderSource : uint8_t { hlsl_compile, glsl_blocks, asm_block, null };

// One shader a pass binds: `compile ps_2_0 PS(true, 3)`, `SetPixelShader(CompileShader(
// ps_4_0, PS()))`, `PixelShader = asm {...}`, `VertexShader = { Common, VS }` (GLSL
// blocks), a shader variable holding one of those, or NULL.
struct ShaderBinding {
  PassStage stage = PassStage::vertex;
  ShaderSource source = ShaderSource::null;
  std::string profile;                   // "vs_2_0", "ps_4_0", "glsl" for GLSL blocks
  std::string entry;                     // entry function
  std::vector<Value> args;               // folded compile-time arguments, in order
  const ast::Expr* expr = nullptr;       // the compile/asm expression (for the shader builder)
  std::vector<std::string> glsl_blocks;  // GLSL block names, in order
  ast::TokenSpan asm_code, decl_code;    // asm { } and decl { } tokens
  std::string variable;                  // the shader variable it came through ("" if inline)
  bool stream_output = false;            // given to ConstructGSWithSO: its output stream is captured
  SourceRange range;
};

// What a resolved state value is.
enum class StateValueKind : uint8_t {
  invalid,  // could not be resolved (a diagnostic was reported)
  boolean,
  integer,
  enumeration,
  floating,
  vector,
  parameter,     // `<name>` or a name of a parameter (texture, sampler, matrix, constants)
  shader,        // index into Pass::shaders
  state_object,  // index into EffectModel::state_objects
  null,
};

struct ResolvedState {
  const StateInfo* info = nullptr;  // the state table row
  uint32_t index = 0;               // `Texture[3]` -> 3 (0 when unindexed)
  bool indexed = false;
  StateValueKind kind = StateValueKind::invalid;
  int64_t integer = 0;  // boolean (0/1), integer, enumeration and flags
  double floating = 0;
  std::array<float, 4> vector{0, 0, 0, 0};  // float4 and colours (D3DCOLOR -> r,g,b,a)
  Value constant;                           // the folded value for shader_constant literals
  uint32_t target = kNoIndex;               // parameter / shader / state object index
  std::vector<Value> call_args;             // SetBlendState(b, factor, mask): factor, mask
  SourceRange range;
};

// A state Vulkan cannot express (D3D9 fixed function), kept so validation can say why.
struct UnsupportedState {
  const StateInfo* info = nullptr;
  uint32_t index = 0;
  SourceRange range;
  std::string reason;
};

struct StateObjectInfo {
  StateBlock block = StateBlock::blend_state;
  std::string name;
  std::vector<ResolvedState> states;
  std::vector<Annotation> annotations;
  uint32_t sampler = kNoIndex;  // SamplerState objects: index into samplers
  SourceRange range;
};

struct PassInfo {
  std::string name;
  std::vector<Annotation> annotations;
  std::vector<ResolvedState> states;   // in source order
  std::vector<ShaderBinding> shaders;  // one per stage set (later ones replace)
  std::vector<UnsupportedState> unsupported;
  PassStateSummary summary;
  std::optional<ScriptPlan> script;  // its DXSAS Script annotation (fx/model/dxsas_script.h)
  SourceRange range;
  // The binding for `stage`, or nullptr.
  const ShaderBinding* shader(PassStage stage) const;
  // Texture stage `stage` as the pass sets it: the sampler states indexed [stage]
  // (AddressU[1], MinFilter[1] ...) over D3D9's defaults (wrap, point, no mips), and in
  // `texture` the parameter Texture[stage] names (kNoIndex if none).
  SamplerDesc stage_sampler(uint32_t stage, uint32_t& texture) const;
};

// True for the texture-stage states a pixel shader replaces (ColorOp, ColorArg0-2, AlphaOp,
// AlphaArg0-2, ResultArg: D3D9 ignores them while one is set) or reads (BumpEnvMat00-11,
// BumpEnvLScale, BumpEnvLOffset: texbem, texbeml and bem use them).
bool pixel_shader_replaces_or_reads(const StateInfo& info);

struct TechniqueInfo {
  std::string name;
  int version = 9;    // 9, 10, 11
  std::string group;  // enclosing fxgroup ("" if none)
  std::vector<Annotation> annotations;
  std::vector<PassInfo> passes;
  std::optional<ScriptPlan> script;  // its DXSAS Script annotation (fx/model/dxsas_script.h)
  SourceRange range;
};

// What tools call the technique at `index` (declaration order, groups included): its name,
// or "technique<index>" when the effect leaves it unnamed (`technique { pass ... }` is valid D3D).
std::string technique_label(std::string_view name, uint32_t index);

struct EffectModel {
  TypeTable types;
  std::vector<Parameter> parameters;
  std::vector<TextureInfo> textures;
  std::vector<SamplerInfo> samplers;
  std::vector<StateObjectInfo> state_objects;
  std::vector<TechniqueInfo> techniques;
  std::vector<std::string> functions;    // names of shader functions, in order
  std::vector<std::string> glsl_blocks;  // names of GLSL blocks, in order
  ScriptGlobal script_global;            // the STANDARDSGLOBAL parameter (DXSAS)
  const ast::Effect* ast = nullptr;      // the tree it was built from (must outlive it)

  // Lookups by exact name; kNoIndex / nullptr when absent.
  uint32_t find_parameter(std::string_view name) const;
  uint32_t find_state_object(std::string_view name) const;
  // By name, or by the label of an unnamed technique ("technique2"; see technique_label).
  const TechniqueInfo* find_technique(std::string_view name) const;
  // What tools call technique `index` (the free technique_label below).
  std::string technique_label(uint32_t index) const;
  const TextureInfo* texture_of(uint32_t parameter) const;

  std::unordered_map<std::string, uint32_t> parameter_index;
  std::unordered_map<std::string, uint32_t> state_object_index;
};

// Builds the model. Never throws; on a partial tree it builds what it can and reports
// the rest (ids in docs/diagnostics.md, section "Effect model").
EffectModel build_effect_model(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& diags);
inline EffectModel build_effect_model(const ParsedEffect& parsed, const SourceManager& sm, DiagnosticSink& diags) {
  return build_effect_model(parsed.ast, sm, diags);
}

}  // namespace fx
