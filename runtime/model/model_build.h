// Internal interface between the model builder, the state resolver and the pass summary.
#pragma once
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "fx/model/effect_model.h"

namespace fx::model_detail {

struct ResolveContext {
  EffectModel& model;
  DiagnosticSink& diags;
  ConstantScope scope;  // static consts and, for state values, other parameters' defaults
  std::unordered_map<std::string, const ast::Expr*> shader_variables;  // name -> initializer
  std::unordered_map<std::string, bool> glsl_blocks;                   // names declared
  // fx_5_0 interface and class type names: a compile-time argument naming a variable of one
  // is a class instance the compiler binds (class linkage), not a constant.
  std::unordered_set<std::string> class_linkage_types;
};

// Resolves one assignment of `block` against the state table. Shader bindings of pass
// states go to `shaders` (replacing an earlier one of the same stage); fixed-function
// states are also listed in `unsupported`. Unknown states were reported by the checker
// and are skipped (returns false).
bool resolve_state(const ast::StateAssignment& a, StateBlock block, ResolveContext& ctx, ResolvedState& out,
                   std::vector<ShaderBinding>* shaders, std::vector<UnsupportedState>* unsupported);

// A sampler description from D3D9 sampler_state states or a D3D10 SamplerState object's.
SamplerDesc describe_sampler(const std::vector<ResolvedState>& states, bool d3d10_object, uint32_t& texture);

// The Vulkan-facing state of a pass (D3D9 defaults, then the pass's states in order).
PassStateSummary summarize_pass(const std::vector<ResolvedState>& states, const EffectModel& model);

}  // namespace fx::model_detail
