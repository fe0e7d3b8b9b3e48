// The glslang translation units of a parsed effect: one per pass stage. HLSL stages get the
// part of the effect's shader code their entry reaches (functions, structs, globals,
// cbuffers) with the effect-only syntax left out and #line directives into the .fx files; GLSL stages get their named
// blocks joined. Compile-time arguments (`compile ps_2_0 PS(true, 3)`) become a wrapper entry point.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "fx/ast.h"
#include "fx/compile/stream_output.h"
#include "fx/compile/translation_unit.h"
#include "fx/diagnostic.h"
#include "fx/source_manager.h"

namespace fx {

// How a pass stage is written in the effect.
enum class StageSourceKind : uint8_t {
  hlsl,            // `compile vs_2_0 VS()`, `CompileShader(vs_4_0, VS())`, a shader variable
  glsl,            // `VertexShader = Block;` or `= { Common, Block };`
  assembly,        // `asm { }` / `decl { } asm { }`: shader model 1 assembly, translated to HLSL
  fixed_function,  // a D3D9 pass with no vertex or pixel shader: generated HLSL (fixed_function.h)
  invalid,         // the stage names something that does not exist (reported as a diagnostic)
};
const char* to_string(StageSourceKind kind);

// One stage of one pass, as the effect names it.
struct StageUnit {
  ShaderStage stage = ShaderStage::vertex;
  StageSourceKind kind = StageSourceKind::hlsl;
  std::string profile;                   // as written: "vs_2_0", "ps_2_a", "ps_4_0"; GLSL "450"
  std::string function;                  // HLSL: the effect's function ("PS")
  std::vector<std::string> glsl_blocks;  // GLSL: the blocks, in order
  std::vector<std::string> arguments;    // compile-time arguments, spelled as HLSL
  std::string entry_point;               // the unit's entry: "PS", "PS__fx_args" or "main"
  std::string unsupported;               // why no unit is built (invalid)
  // Assembly and fixed-function stages: the generated HLSL (fx/emulation/assembly.h,
  // fx/emulation/fixed_function.h) and what emulates it ("ps.1.1 assembly translated to
  // HLSL"); `profile` is the assembly's ("ps_1_1"), "fixed_function" for generated stages.
  std::string translated;
  std::string emulation;
  SourceRange range;  // the state assignment naming the shader
  // ConstructGSWithSO's declarations: the stage's output stream is captured (stream_output.h).
  std::optional<StreamOutputDecl> stream_output;
  // A shader array indexed in the pass (`VertexShader = (VSArray[VSIndices[ShaderIndex]]);`,
  // as the XNA stock effects choose their shader permutations): every element in order, and
  // which one the index selects with the parameters' initial values. The stage's own fields
  // are that element's, so the pass compiles and draws it.
  std::vector<StageUnit> choices;
  size_t choice = 0;
  std::string selector;  // the index expression, spelled
};

// One pass of one technique with the stages it names, in pipeline order.
struct EffectPass {
  std::string group;                             // fxgroup name, empty outside groups
  std::string technique;                         // name; "technique<i>" when unnamed
  std::string pass;                              // name; "pass<j>" when unnamed
  uint32_t technique_index = 0, pass_index = 0;  // technique index counts all techniques
  std::vector<StageUnit> stages;
  // Why the pass cannot run as written beyond its stages: fixed-function vertex or pixel
  // processing beside an HLSL stage (beside assembly, or with no shader at all, it is
  // generated as a stage of kind fixed_function).
  std::vector<std::string> unsupported;
  SourceRange range;

  const StageUnit* find(ShaderStage stage) const;
};

// Options for building units.
struct EffectUnitOptions {
  // Models ps.1.x register range and precision in translated assembly pixel shaders
  // (AssemblyOptions::hardware_precision) for every technique; a technique or pass turns it
  // on for itself with the annotation `bool Ps1xPrecision = true;`.
  bool ps1x_precision = false;
};

// The translation units of one effect. The shared HLSL text is built once, in the
// constructor; units are cheap to make on demand. Holds no reference to `effect` or `sm`
// after construction.
class EffectUnits {
 public:
  // Problems that are errors in the effect (an unknown shader function or GLSL block, too
  // many compile-time arguments) are reported into `sink` and mark the stage invalid.
  EffectUnits(const ast::Effect& effect, const SourceManager& sm, DiagnosticSink& sink, EffectUnitOptions options = {});

  // Every pass of every technique (fxgroups included), in source order.
  const std::vector<EffectPass>& passes() const { return passes_; }
  // The pass named `technique`/`pass`, or nullptr.
  const EffectPass* find(std::string_view technique, std::string_view pass) const;

  // The unit for one stage; nullopt when the stage is not compiled (see stage.unsupported).
  std::optional<TranslationUnit> unit(const StageUnit& stage) const;

  // The effect's whole shader code (prelude and #line included). An HLSL stage's unit holds
  // only what its entry point reaches (`hlsl_code_for`).
  const std::string& hlsl_code() const { return hlsl_; }
  // The declarations `entry` reaches, in source order, each after its own #line: the entry,
  // every overload of every name it calls, the structs, typedefs, globals, static consts,
  // cbuffers (whole) and samplers/textures their tokens name, and so on through what those
  // name (a global initializer's calls, a struct's methods). `#pragma` lines are always kept.
  // A function only another stage calls may not compile for this one at all (a geometry
  // shader's stream Append, a derivative in a vertex shader), and its errors are not this
  // stage's.
  std::string hlsl_code_for(std::string_view entry) const;
  // A compute unit: what `function` reaches (as hlsl_code_for) followed by `entry_text`, a
  // generated entry point named `entry` that calls it (a texture shader's fill,
  // fx/compile/texture_fill_unit.h), with the definition of tx_1_0's noise() when the code
  // calls it (glslang has none). nullopt when the effect defines no function `function` or
  // its front end failed.
  std::optional<TranslationUnit> compute_unit(std::string_view function, std::string_view entry,
                                              std::string_view entry_text) const;
  // The functions no stage of any pass reaches, and what they reach, compiled once per
  // effect as a fragment unit of their own so their errors are still reported (fxc rejects
  // an effect for an error in any function); nullptr when every function is reached (or the
  // effect has no HLSL stage). Functions with a stream or patch parameter or an interface
  // are not in it (they compile only as their stage's entry), nor texture shaders (a
  // texture's `string function`) and what only they reach (they compile in their fill unit). EffectPrograms compiles it
  // with the first pass that has an HLSL stage; its errors fail every such pass.
  const StageUnit* uncalled_check() const { return check_ ? &*check_ : nullptr; }
  // The names the effect declares at file scope (variables, functions, types, cbuffer
  // members), for "did you mean" on an unknown name in shader code.
  const std::vector<std::string>& symbols() const { return symbols_; }

 private:
  struct GlslBlockText {
    std::string name;
    std::string version;  // the block's #version directive line, "" if none
    std::string body;     // with #line directives, the #version line left out
  };
  std::string hlsl_;
  // Each top-level declaration as a range of hlsl_ (starting with its own #line), with the
  // names it declares and the identifiers its tokens name.
  struct DeclText {
    std::vector<std::string> names;  // a function's or type's name; every declarator; cbuffer members
    size_t begin = 0, end = 0;
    std::vector<std::string> refs;  // identifiers in its tokens (calls, types, globals)
    bool function = false;
    bool always = false;          // a #pragma: in every unit
    bool stage_only = false;      // has a stream or patch parameter (geometry, hull, domain)
    std::string dynamic_linkage;  // the interface (instance) it uses, "" for none
    // A function: where in hlsl_ its body starts, for the initializations of the statics an
    // entry point reaches (0: none, the effect lowers no static).
    size_t prologue = 0;
    // A static global whose initializer calls a function: its initialization, run at the
    // start of each entry point that reaches it (effect_unit_initializers.cpp).
    std::string initialization;
  };
  std::vector<DeclText> decls_;
  // Indices into decls_ by declared name (every overload), so reach costs what it visits
  // (looked up by string_view: no allocation per name).
  struct NameHash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  std::unordered_map<std::string, std::vector<uint32_t>, NameHash, std::equal_to<>> decls_by_name_;
  std::vector<uint32_t> always_;  // the #pragma lines
  // The declarations the roots reach, with the #pragma lines: indices into decls_, in source
  // order. Costs what it reaches, not the effect's size.
  std::vector<uint32_t> reached_from(const std::vector<std::string_view>& roots) const;
  // The text of the reached declarations; the functions named `entry` start with the
  // initializations of the lowered statics they reach, declared before them.
  std::string code_for(const std::vector<uint32_t>& reached, std::string_view entry = {}) const;
  // The initializations of the lowered statics among `reached` declared before `before`.
  std::string initializations(const std::vector<uint32_t>& reached, uint32_t before) const;
  std::optional<StageUnit> check_;     // uncalled_check()
  std::vector<std::string> uncalled_;  // the functions it checks
  std::vector<std::string> symbols_;
  std::vector<EffectPass> passes_;
  std::vector<GlslBlockText> glsl_blocks_;
  // Wrapper entry points by (function, arguments), keyed by the stage's entry text.
  struct Wrapper {
    std::string function;
    std::vector<std::string> arguments;
    std::string text;
  };
  std::vector<Wrapper> wrappers_;
  EffectUnitOptions options_;
  std::string name_;               // the effect's file name (unit names)
  bool front_end_failed_ = false;  // no unit reaches glslang

  friend class EffectUnitBuilder;
};

// Spells an effect expression as text: compile-time arguments, state values for tools.
std::string spell_expression(const ast::Expr& e);

}  // namespace fx
