// fx::vk::StandIn: what stands in for a texture no file fills, chosen by the parameter's name,
// semantic and shape, and the texels of the preview stand-ins (a colour test pattern, a ramp
// of depths, an environment) that show what a shader does with its input.
#pragma once
#include "fx/compile/shader_reflection.h"
#include "fx/dds.h"
#include "fx/model/effect_model.h"

namespace fx::vk {

// Neutral stand-ins (white, flat_normal, depth, multisampled) are one texel that leaves the
// shading it feeds as if the texture were absent; preview ones (test_pattern, depth_ramp,
// environment) vary, so that a filter, a lookup or a reflection of them shows.
// signed_zero and unsigned_zero: for Texture2D<int> and <uint>, which need an integer view;
// zero is what Direct3D 11 reads from an unbound shader resource view.
enum class StandIn {
  white,
  flat_normal,
  depth,
  multisampled,
  test_pattern,
  depth_ramp,
  environment,
  signed_zero,
  unsigned_zero
};

// The stand-in for texture parameter `param` (null: no parameter) sampled as `dim`: a flat
// normal for a normal or bump map (semantic NORMALMAP or NORMAL, or "normal" or "bump" in its
// name, UIName or ResourceName); white for a shadow map ("shadow" in them). Otherwise, with
// `preview`, a ramp of depths for a depth input ("depth" in them or its semantic), an environment for a
// cube map and a colour test pattern for the rest; without, white.
StandIn texture_stand_in(const Parameter* param, ImageDim dim, bool preview);

// "colour test pattern", "flat normal", ... (for messages and --verbose).
const char* stand_in_name(StandIn kind);

// The texels of a preview stand-in in the shape `dim` (1D: 64 texels; 2D: 64x64; 3D:
// 16x16x16; cube: six 32x32 faces), RGBA8, one mip level, one layer (one cube) that an array
// view shows as an array of one. The test pattern has saturated hues from left to right,
// darkening from top to bottom, and a dark grid line every 16 texels (the 8th, 24th, ...; none
// through the centre); its 3D slices fade towards white with depth. The depth ramp is grey from
// 0 at the top left corner to 1 at the bottom right. The environment is a blue sky above a warm
// horizon and a brown ground, tinted by the compass direction so that a turned reflection shows.
// The integer kinds are one texel (six for a cube) of four 32-bit zeros. Empty for a neutral kind.
fx::DdsTexture stand_in_texels(StandIn kind, ImageDim dim);

}  // namespace fx::vk
