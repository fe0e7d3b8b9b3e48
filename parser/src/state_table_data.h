// Internal: the rows and enumeration sets behind fx/state_table.h, split by API so each
// data file stays readable. Only state_table.cpp and the data files include this.
#pragma once
#include <span>

#include "fx/state_table.h"

namespace fx::state_data {

// Enumeration sets (state_table_enums.cpp).
extern const EnumSet kBoolean, kZBuffer, kFill9, kFill10, kCull9, kCull10, kBlend, kBlendOp, kCompare, kStencilOp,
    kShade, kFogMode, kMaterialSource, kVertexBlend, kPatchEdge, kDegree, kColorWrite, kWrap, kTextureOp, kTextureArg,
    kTexCoordIndex, kTextureTransform, kTextureAddress, kTextureFilter, kFilter11, kDepthWriteMask, kLightType;

// D3D9 render, texture-stage, transform, light and material states in passes
// (state_table_d3d9.cpp).
std::span<const StateInfo> d3d9_pass_states();
// D3D9 sampler states as written in `sampler_state { }`; passes accept them indexed by
// sampler stage (`AddressU[2]`), which state_table.cpp derives from these rows.
std::span<const StateInfo> d3d9_sampler_states();
// D3D10/11 state-object fields and pass calls (state_table_d3d10.cpp).
std::span<const StateInfo> d3d10_states();

// Sampler stages a D3D9 pass may index: `Texture[0..15]`, `AddressU[0..15]`.
inline constexpr uint16_t kSamplerStages = 16;

}  // namespace fx::state_data
