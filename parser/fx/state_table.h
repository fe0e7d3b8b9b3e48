// The one table of effect states: Direct3D 9 pass and sampler states, the Direct3D 10/11
// state-object fields and pass calls. Parsing checks, the runtime's Vulkan mapping and the
// documentation (docs/states.md) all read these rows, so adding a state is one row.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fx {

// The kind of block a state assignment appears in.
enum class StateBlock : uint8_t {
  pass,                 // technique passes (D3D9 states and D3D10/11 Set* calls)
  sampler_state,        // D3D9 `sampler_state { }` initializers
  blend_state,          // D3D10/11 `BlendState name { }`
  depth_stencil_state,  // D3D10/11 `DepthStencilState name { }`
  rasterizer_state,     // D3D10/11 `RasterizerState name { }`
  sampler_object,       // D3D10/11 `SamplerState` / `SamplerComparisonState name { }`
};
inline constexpr int kStateBlockCount = 6;
// Display name of a block: "pass", "sampler_state", "BlendState", ...
std::string_view to_string(StateBlock block);
// The block of a D3D10/11 state-object type name (case-insensitive), if it is one.
std::optional<StateBlock> state_object_block(std::string_view type_name);

// What a state's value must be.
enum class StateValueType : uint8_t {
  boolean,          // TRUE/FALSE, true/false, 0/1
  integer,          // DWORD/UINT/INT
  floating,         // float
  enumeration,      // one name of StateInfo::enums (or its integer value)
  flags,            // enum names and integers combined with `|`
  color,            // D3DCOLOR: 0xAARRGGBB, or a float4
  float4,           // float4(...) / { ... } / a vector parameter
  matrix,           // a float4x4 parameter
  texture,          // a texture parameter (`<tex>`) or NULL
  sampler,          // a sampler parameter or NULL
  shader,           // compile ..., asm { }, CompileShader(...), a shader variable, NULL
  shader_constant,  // a parameter or literal uploaded to shader constant registers
  state_object,     // a D3D10/11 state object of the matching kind (Set*State)
};
std::string_view to_string(StateValueType type);

// Which API family defines a state.
enum class StateApi : uint8_t { d3d9, d3d10, d3d11 };
std::string_view to_string(StateApi api);

// What the state means on Vulkan; the runtime's validation reads this.
enum class VulkanMeaning : uint8_t {
  maps_to_vulkan,  // a direct pipeline/sampler/descriptor equivalent exists
  emulated,        // no Vulkan state; fxkit reproduces it (alpha test -> discard, sRGB views)
  fixed_function,  // D3D9 fixed-function pipeline (texture stages, fog, lighting): unsupported
  ignored,         // no visible effect to reproduce (dither, last pixel, FVF)
};
std::string_view to_string(VulkanMeaning meaning);

// Where on Vulkan a state lands (for the runtime's pipeline key and validation).
enum class VulkanArea : uint8_t {
  none,
  shader_stage,
  shader_constants,
  resource_binding,
  input_assembly,
  rasterization,
  depth_stencil,
  color_blend,
  multisample,
  sampler,
};
std::string_view to_string(VulkanArea area);

// A pipeline stage, in D3D names: the stage a shader state or a shader object sets.
enum class PassStage : uint8_t { vertex, pixel, geometry, hull, domain, compute };
std::string_view to_string(PassStage stage);

// Where a state's value lands. The runtime applies a pass by looping over its states and
// writing each value to its row's field (runtime/model/pass_summary.cpp): no state is
// named there, so a new state that lands on an existing field is one row.
enum class StateLanding : uint8_t {
  pipeline,        // a field of the pipeline state (fx::PassStateSummary -> fx::vk::PipelineState)
  dynamic,         // dynamic state recorded with the draw (stencil reference, blend constants)
  sampler,         // a field of a sampler description (fx::SamplerDesc)
  binding,         // what a pass binds: shader code, constants, textures, samplers, state objects
  fixed_function,  // a D3D9 fixed-function stage field: parsed and validated, never applied
  unsupported,     // nothing on Vulkan; StateInfo::reason says why
};
std::string_view to_string(StateLanding landing);

// The field a state's value writes: a member of fx::PassStateSummary or fx::SamplerDesc
// (runtime/model/include/fx/model/pass_state.h), a binding, or a fixed-function stage field. Several
// rows may share one (ZEnable and DepthEnable both write depth_test).
enum class StateField : uint8_t {
  none,
  // Depth and stencil.
  depth_test,
  depth_write,
  depth_compare,
  stencil_test,
  stencil_read_mask,
  stencil_write_mask,
  stencil_front_fail,
  stencil_front_depth_fail,
  stencil_front_pass,
  stencil_front_compare,
  stencil_back_fail,
  stencil_back_depth_fail,
  stencil_back_pass,
  stencil_back_compare,
  stencil_two_sided,  // D3D9: without it the back face copies the front
  stencil_ref,
  // Rasterization.
  fill,
  cull,
  front_face_ccw,
  depth_bias_d3d9,
  depth_bias_units,
  depth_bias_clamp,
  depth_bias_slope,
  depth_clip,
  scissor,
  multisample,
  antialiased_lines,
  // Blending and output: the blend fields write TargetBlend of StateInfo::target (or the index).
  blend_enable,
  src_color,
  dst_color,
  color_op,
  src_alpha,
  dst_alpha,
  alpha_op,
  separate_alpha,  // D3D9: without it alpha blends like colour
  write_mask,
  blend_constants,
  alpha_to_coverage,
  sample_mask,
  srgb_write,
  alpha_test,
  alpha_compare,
  alpha_ref,
  state_object,  // applies a D3D10/11 state object of StateInfo::object_kind
  // Bindings.
  shader,
  shader_constants,
  texture,
  sampler,
  // Sampler descriptions.
  address_u,
  address_v,
  address_w,
  border_color,
  mag_filter,
  min_filter,
  mip_filter,
  lod_bias,
  max_mip_level,
  max_anisotropy,
  srgb_texture,
  min_lod,
  max_lod,
  compare,
  filter_bits,
  // Fixed-function texture stages (validated against the device's stages).
  stage_color_op,
  stage_alpha_op,
};
std::string_view to_string(StateField field);

// Where a field's value lands: the row's StateLanding for every field but none.
constexpr StateLanding landing_of(StateField field) {
  switch (field) {
    case StateField::none: return StateLanding::unsupported;
    case StateField::stencil_ref:
    case StateField::blend_constants: return StateLanding::dynamic;
    case StateField::state_object:
    case StateField::shader:
    case StateField::shader_constants:
    case StateField::texture:
    case StateField::sampler: return StateLanding::binding;
    case StateField::stage_color_op:
    case StateField::stage_alpha_op: return StateLanding::fixed_function;
    default: break;
  }
  return field >= StateField::address_u ? StateLanding::sampler : StateLanding::pipeline;
}

// StateInfo::target for a blend field that writes every render target when unindexed.
inline constexpr uint8_t kEveryTarget = 0xFF;

// One named value of an enumeration; several names may share a value (D3D9 and D3D10
// spellings).
struct EnumValue {
  std::string_view name;
  int64_t value;
};

// A set of enumeration values. Names match case-insensitively, ignoring underscores and
// any of the prefixes: `D3DBLEND_SRCALPHA`, `SrcAlpha`, `SRC_ALPHA` are one name.
struct EnumSet {
  std::string_view name;  // "blend", "cmp", ...
  std::span<const EnumValue> values;
  std::span<const std::string_view> prefixes;  // "D3DBLEND_", "D3D10_BLEND_", ...
};

// One row of the state table.
struct StateInfo {
  std::string_view name;  // canonical spelling; lookup is case-insensitive
  StateBlock block = StateBlock::pass;
  StateValueType type = StateValueType::integer;
  const EnumSet* enums = nullptr;  // for enumeration and flags
  uint16_t index_count = 0;        // 0: not indexable; else valid indices are [0, index_count)
  bool index_required = false;     // `VertexShaderConstant[n]`; others default to index 0
  uint8_t call_args = 0;           // D3D10/11 pass calls (`SetBlendState(b, f, m)`): arguments
  StateApi api = StateApi::d3d9;
  VulkanMeaning vulkan = VulkanMeaning::maps_to_vulkan;
  VulkanArea area = VulkanArea::none;
  std::string_view object_kind;    // state_object: the block the argument must be
  std::optional<PassStage> stage;  // shader states: the stage whose code they name
  StateLanding lands = StateLanding::unsupported;
  StateField field = StateField::none;
  // Blend fields: the render target an unindexed assignment writes (kEveryTarget: all); an
  // index names one target (clamped to index_count - 1).
  uint8_t target = kEveryTarget;
  // Pass calls: the fields their extra arguments write, in order (SetBlendState(b, factor,
  // mask): blend_constants, sample_mask).
  std::array<StateField, 2> call_fields{StateField::none, StateField::none};
  std::string_view reason;  // unsupported and fixed_function: why fxkit does not apply it
};

// Every row, grouped by block.
std::span<const StateInfo> all_states();
// The row for `name` (case-insensitive) in `block`, or nullptr. O(1): hashed lookup.
const StateInfo* find_state(std::string_view name, StateBlock block);
// The value of an enumeration name for a state with enums (see EnumSet for spellings).
// `state` is a row of the table or a copy of one: the table's sets are hashed once.
std::optional<int64_t> find_enum(const StateInfo& state, std::string_view name);
// The stage a pass state naming shader code sets, from its row (any case): VertexShader,
// PixelShader, GeometryShader, HullShader, DomainShader, ComputeShader, the D3D10/11 calls
// SetVertexShader ... SetComputeShader, and the GLSL blocks' FragmentShader with the nvFX
// spellings VertexProgram, FragmentProgram, GeometryProgram, ComputeProgram. nullopt for
// any other name.
std::optional<PassStage> shader_state_stage(std::string_view state);
// The stage a shader object type holds (`VertexShader vs = compile vs_2_0 VS();`): the
// six D3D types, any case; nullopt for other types.
std::optional<PassStage> shader_type_stage(std::string_view type);
// A stage's shader type as D3D spells it ("VertexShader") and its profile prefix ("vs").
std::string_view shader_type_name(PassStage stage);
std::string_view profile_prefix(PassStage stage);
// The state names of a block (for did-you-mean).
std::vector<std::string_view> state_names(StateBlock block);
// The value names a state accepts (for did-you-mean), in the table's spelling.
std::vector<std::string_view> enum_names(const StateInfo& state);
// docs/states.md, generated from the rows.
std::string render_state_table_markdown();

}  // namespace fx
