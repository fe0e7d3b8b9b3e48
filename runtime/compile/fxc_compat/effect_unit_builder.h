// Builds fx::EffectUnits from a parsed effect: the HLSL text (effect_unit_hlsl.cpp), the
// GLSL blocks and the passes (effect_unit_passes.cpp), and which functions each entry reaches
// (effect_units.cpp). Private to runtime/compile.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "class_linkage.h"
#include "effect_shader_text.h"
#include "fx/ast.h"
#include "fx/compile/effect_units.h"
#include "fx/emulation/fixed_function.h"
#include "fx/model/effect_model.h"
#include "fx/source_manager.h"

namespace fx {
namespace detail {

// The pipeline stage a pass state sets (the state table's rows: D3D9 assignments, D3D10/11
// calls, the GLSL and nvFX spellings), in the compiler's names.
std::optional<ShaderStage> stage_of_state(std::string_view name);

// Effect-only variable types: glslang has no such HLSL types (D3D9 texture objects,
// strings, shader objects). D3D10's `Texture2D` is real HLSL and stays.
bool is_effect_only_type(std::string_view type);

// Types that are resources rather than constants (samplers, textures, buffers): their
// `register(s0)`/`register(t0)` becomes a binding, which glslang keeps per kind.
bool is_shader_object_type(std::string_view type);

// Spells a constant expression as HLSL (compile-time arguments). False for what cannot be
// a compile-time argument (compile expressions, state blocks, asm).
bool spell(const ast::Expr* e, std::string& out);

// HLSL tokens joined with single spaces where the source had space: a one-line spelling,
// with the names glslang reserves renamed as in the unit's text.
std::string join_tokens(const std::vector<Token>& toks, ast::TokenSpan span);

// "ps_2_a"/"ps_2_b" -> "ps_2_x" (glslang has one SM2 extended profile); lower case.
std::string normalize_profile(std::string_view profile);

}  // namespace detail

// Builds EffectUnits from the AST: the shared HLSL text, the GLSL blocks and the passes.
class EffectUnitBuilder {
 public:
  EffectUnitBuilder(EffectUnits& units, const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& sink)
      : u_(units), effect_(effect), toks_(effect.tokens), sm_(sm), sink_(sink) {}

  void build();

 private:
  // Calls `visit(StageUnit&)` for every stage of every pass and each of its choices, in
  // pass order.
  template <class Visit>
  void for_each_stage(Visit&& visit) {
    for (EffectPass& pass : u_.passes_)
      for (StageUnit& stage : pass.stages) {
        visit(stage);
        for (StageUnit& choice : stage.choices) visit(choice);
      }
  }

  // A stage whose code calls through an interface that no class instance implements has
  // nothing to dispatch to: the stage says so, at the pass state (class_linkage.h).
  void mark_dynamic_linkage();

  // glslang crashes on a geometry shader whose per-vertex input array carries
  // SV_ClipDistance or SV_CullDistance (KhronosGroup/glslang#2392). The plain case, as D3D10's
  // FixedFuncEMU passes its vertex struct on, is rewritten (clip_distance_inputs.h); a stage
  // whose distances sit deeper says why instead of being compiled.
  void mark_clip_distance_inputs();
  std::unordered_set<const ast::Function*> clip_distance_rewritten_;
  // Whether a variable of this type (a struct's members, nested ones too) carries a clip or
  // cull distance semantic.
  bool carries_clip_distance(const ast::Variable& v, int depth) const;

  // Functions that no HLSL stage of any pass reaches go into the effect's check unit
  // (EffectUnits::uncalled_check), unless they cannot compile in any (stream or patch
  // parameters, interfaces).
  void mark_uncalled_functions();

  void index_declarations();

  // `uniform` on a parameter means something only to an entry point: a helper's, or an
  // entry's that a wrapper calls with its compile-time arguments, is left out, since glslang
  // then skips the argument's conversion (`2` for a uniform float stays an int constant:
  // invalid SPIR-V). Functions some pass compiles without arguments keep it.
  void respell_helper_uniforms();

  void emit_hlsl();

  // fx_5_0 dynamic linkage: glslang has no interfaces, so an interface declaration becomes
  // its dispatchers' prototypes, and a class the struct with methods it otherwise is
  // (`class C : I {` -> `struct C {`) followed by its method wrappers (class_linkage.h).
  void emit_structure(detail::ShaderTextWriter& w, const ast::Struct& s);
  // A method defined outside its class, as a function of an instance of `cls`, a class that
  // reaches it (class_linkage.h, method_function_name).
  struct MethodFunction {
    const ast::Struct* cls;
    const ast::Function* method;
  };
  // Every such function of the effect, in the order their methods are defined.
  std::vector<MethodFunction> method_functions() const;
  void emit_method_function(detail::ShaderTextWriter& w, const MethodFunction& f);
  // When a method of `cls` starts at token `i` (its definition, or its prototype in the
  // class): writes it if `methods` (what the class being written reaches) has it, and returns
  // the index of its last token; nullopt when none starts there.
  std::optional<uint32_t> emit_method_at(detail::ShaderTextWriter& w, const ast::Struct& cls, uint32_t i,
                                         const std::vector<const ast::Function*>& methods);
  // The body of `base`, a class the class being written derives from: its members, and the
  // methods of `methods` it defines.
  void emit_inherited(detail::ShaderTextWriter& w, const ast::Struct& base,
                      const std::vector<const ast::Function*>& methods);

  // The first interface or interface variable a function's tokens name that no class
  // instance implements ("" for none): its calls have nothing to dispatch to.
  std::string dynamic_linkage_in(ast::TokenSpan span) const;

  // --- effect_unit_initializers.cpp ---
  // Global initializers that call a function of the effect (glslang crashes on them): a
  // static's is run at the start of the entry point, as fxc runs it; a parameter's is left
  // out (its default is the model's). Found before emit_hlsl.
  void find_lowered_globals();
  // Whether a declaration's initializers call a function of the effect, or name a static
  // already lowered (it must run after that one's initialization).
  bool initializer_calls(ast::TokenSpan span) const;
  // Writes a lowered static's declaration without `const` and initializers; returns its
  // initialization, for the prologue of the entry points that reach it.
  std::string emit_lowered_static(detail::ShaderTextWriter& w, ast::TokenSpan span);
  std::unordered_set<uint32_t> lowered_statics_;       // declarations' first tokens
  std::unordered_set<uint32_t> dropped_initializers_;  // parameters' declarations
  std::unordered_set<std::string> lowered_names_;

  // A function as a declaration range of the text (see emit_hlsl), with what it names.
  void emit_function(detail::ShaderTextWriter& w, const ast::Function& f);

  // A function's tokens, with fxc's assignments to constructors of l-values written as a
  // temporary and one assignment per part (`{ float4 t = v; a = t.xy; b = t.zw; }`).
  void emit_function_tokens(detail::ShaderTextWriter& w, ast::TokenSpan span);

  // The identifiers a span names, each once: calls, types, globals (and locals, members and
  // intrinsics, which name no declaration of the effect or reach a little more than needed).
  std::vector<std::string> identifiers_in(ast::TokenSpan span) const;

  // Writes the token at `i` as HLSL: a name glslang reserves is renamed (reflection maps
  // it back).
  void put_hlsl(detail::ShaderTextWriter& w, uint32_t i, uint32_t last);

  void emit_tokens(detail::ShaderTextWriter& w, ast::TokenSpan span);

  // The index of the `>` closing an annotation opened at `open`, or 0 when the `<` is not an
  // annotation (a template argument such as Texture2D<float4> never contains a ';').
  uint32_t annotation_end(uint32_t open, uint32_t last) const;

  // The index of the token closing the bracket at `open` (or `last` if unbalanced).
  uint32_t matching_close(uint32_t open, uint32_t last) const;

  // The index of the `)` closing a `: register(...)` that starts at the `:` at `colon`, or
  // 0 when no register binding starts there.
  uint32_t register_end(uint32_t colon, uint32_t last) const;

  // A global or cbuffer declaration without its effect-only parts: annotations,
  // `= sampler_state { }` initializers and cbuffer member initializers (which glslang
  // ignores with a warning; the effect model keeps them as defaults). With
  // `drop_constant_registers`, a global constant's `: register(c0)` / `register(vs, c0)` goes
  // too: D3D9 assigns constant registers per shader profile, so two constants may share c0
  // (one for vs, one for ps), and glslang would turn both into the same offset of one
  // $Global block, which SPIR-V validation rejects. Parameters are matched by name, so
  // glslang's own packing loses nothing.
  // With `drop_initializers`, a global's `= value` goes too. Tokens inside one of
  // `leave_out` (sorted) are not written.
  void emit_filtered(detail::ShaderTextWriter& w, ast::TokenSpan span, bool drop_constant_registers = false,
                     bool drop_initializers = false, const std::vector<ast::TokenSpan>& leave_out = {});

  // D3D10 `SamplerState s { Filter = ...; };` -> `SamplerState s;` (the states are ours).
  void emit_sampler_object(detail::ShaderTextWriter& w, const ast::StateObject& so);

  void collect_glsl();

  void collect_passes();

  void add_technique(const ast::Technique& t, const std::string& group, uint32_t index);

  // D3D9 passes without a vertex or pixel shader use the fixed-function pipeline there: its
  // stages are generated from the pass's states (fx/emulation/fixed_function.h).
  void add_fixed_function_stages(const ast::Technique& t, EffectPass& pass, bool null_pixel);
  // The effect model (built once, on the first fixed-function pass; its diagnostics are the
  // model's own to report, so they go to a scratch sink here).
  const EffectModel& model();
  std::unique_ptr<EffectModel> model_;

  const ast::Variable* shader_variable(std::string_view name) const;

  // Fills `stage` from a shader value. False when the value names no shader (NULL).
  bool resolve(const ast::Expr& e, StageUnit& stage, int depth);

  // `VSArray[VSIndices[ShaderIndex]]`: every element of a shader array becomes a choice,
  // the one the index selects with the initial parameter values the stage itself.
  bool shader_array(const ast::Expr& e, StageUnit& stage, int depth);

  // An integer expression's value with every parameter at its initial value: literals,
  // parameters and elements of parameter arrays (`VSIndices[ShaderIndex]`). nullopt when it
  // depends on anything else.
  std::optional<int64_t> initial_value(const ast::Expr& e, int depth) const;

  static bool invalid(StageUnit& stage, std::string reason);

  bool glsl(StageUnit& stage, std::vector<std::string> names);

  // The overload of `name` that takes `args` compile-time arguments (D3D picks the same way).
  const ast::Function* function(std::string_view name, size_t args) const;

  bool hlsl(StageUnit& stage, const std::string& profile, const std::string& name,
            const std::vector<const ast::Expr*>& args, SourceRange range);

  // What an HLSL pixel shader reads, from its entry's declaration, for a generated
  // fixed-function vertex stage; nullopt when it reads anything but colours, TEXCOORD0-7 and
  // fog (or its entry cannot be found).
  std::optional<FixedFunctionState::PixelShaderInputs> pixel_shader_inputs(const StageUnit& ps) const;
  // What an HLSL vertex shader writes, from its entry's declaration (return value, out and
  // inout parameters, their struct members), for a generated fixed-function pixel stage:
  // colours, TEXCOORD0-7 and fog with their components; nullopt when its entry cannot be
  // found or an output is an array. For a shader array, what every choice writes.
  std::optional<FixedFunctionState::VertexShaderOutputs> vertex_shader_outputs(const StageUnit& vs) const;
  // The HLSL entry function a stage compiles (its wrapper's function for compile-time arguments).
  const ast::Function* entry_function(const StageUnit& s) const;
  // The struct named `name` declared in the effect, or null.
  const ast::Struct* structure(std::string_view name) const;

  // Whether a pixel shader takes D3D9's VPOS or VFACE (as a parameter, or a member of an
  // input struct), which its wrapper turns into Vulkan's.
  bool has_d3d9_system_value(const ast::Function& f) const;
  // The struct `p` is passed as, when its members carry VPOS/VFACE and can be passed one by
  // one (scalars, vectors and matrices, each with a semantic); null otherwise.
  const ast::Struct* system_value_struct(const ast::Variable& p) const;

  // The struct a parameter (or a result: its type and semantic) is passed as, when a member
  // is a bool varying the wrapper carries as uint (see carrier_struct): not nested, not an
  // array but a geometry shader's input vertices; null otherwise.
  const ast::Struct* bool_varying_struct(const ast::Variable& p) const;
  // Whether an entry point takes or returns a bool with a user semantic (or a struct
  // member so): Vulkan has no bool inputs and outputs, and its wrapper carries them as uint.
  bool has_bool_varying(const ast::Function& f) const;
  // `fx_io_S`, a copy of `s` whose bool varyings are uint, with `fx_io_S_in` (to `s`) and
  // `fx_io_S_out` (from `s`), added to `helpers` once.
  std::string carrier_struct(const ast::Struct& s, std::string& helpers) const;
  // A parameter's declaration with its type written as `type`.
  std::string retyped(const ast::Variable& p, const std::string& type) const;

  // Whether a parameter takes a compile-time argument (`uniform`) or a BindInterfaces instance
  // (an interface type).
  bool takes_argument(const ast::Variable& p) const;
  // A BindInterfaces argument as the wrapper passes it to a parameter of interface `iface`:
  // an interface variable as itself (the id the application sets), a class instance as its
  // id; false (with a located error) for anything else.
  bool spell_bound_instance(const ast::Expr& e, const ast::Struct& iface, std::string& out);

  // `R F__fx_args(varying params) : SEM { return F(varying..., literal...); }`, placed at the
  // function's own line so errors in the wrapper point at the function.
  std::string wrapper(const ast::Function& f, const std::vector<std::string>& args) const;

  EffectUnits& u_;
  const ast::Effect& effect_;
  const std::vector<Token>& toks_;
  // Tokens the unit spells otherwise, by index: flat initializer lists (flat_initializer.h)
  // and the `uniform` of helper functions' parameters (respell_helper_uniforms).
  std::unordered_map<uint32_t, std::string> respelled_;
  const SourceManager& sm_;
  DiagnosticSink& sink_;
  std::vector<const ast::Function*> functions_;
  std::vector<const ast::Variable*> variables_;
  std::vector<std::string> glsl_names_;
  detail::ClassLinkage linkage_;  // fx_5_0 interfaces, classes and their instances
  // `BindInterfaces(shader, instances...)`: the instances, while its shader is resolved.
  std::vector<const ast::Expr*> bound_interfaces_;
  // The pass and technique whose states are being resolved (assembly reads their constants,
  // textures and precision annotation).
  const ast::Pass* pass_ = nullptr;
  const ast::Technique* technique_ = nullptr;
  // `asm { }`: translated to HLSL through fx/emulation/assembly.h.
  bool assembly(const ast::Expr& e, StageUnit& stage);
};

}  // namespace fx
