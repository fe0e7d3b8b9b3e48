// Stand-in values for a preview of an effect nobody set up: parameters the shaders read,
// which the file gives no default and the scene did not bind, get a value that draws
// something (identity bone palettes, visible colours, a light, at least one light). Used by
// `fxkit render`, `fxkit watch` and fxkit::Effect::set_preview_defaults (the viewer); an
// engine sets its own values instead.
#pragma once
#include <string>
#include <vector>

#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"

namespace fx::vk {

// How set_preview_defaults gave a parameter its value.
struct PreviewDefault {
  std::string parameter;
  // "identity bone palette", "identity object-space transform", "visible colour",
  // "light direction", "direction to the light", "light position", "light count"
  std::string rule;
};

// For every parameter in `read` (the names the shaders read; see parameters_read) with no
// default in the file and an all-zero value, declared without `static`, by its name:
// "bone", "skin" or "palette" in a float3x4 / float4x3 / float4x4 (or an array of them) gives
// identity matrices (skinning in its rest pose); "color", "colour", "diffuse", "albedo" or
// "tint" in a float3 / float4 or an array of them (but not "ambient", "emissive", "specular"
// or "fog", which are zero in many a real scene) gives 0.8 grey, alpha 1; "light" and "dir"
// in a float3 / float4 or an array of them (or the semantic DIRECTION / LIGHTDIRECTION) gives
// a light from above, front and right, normalised (w = 0): pointing from the light into the
// scene, as SAS means DIRECTION, for that semantic, an SAS Object annotation or "direction"
// spelled out (XNA), else towards the light, as the DirectX SDK's g_LightDir does;
// the semantic POSITION / LIGHTPOSITION on a light (an `Object` annotation, or "light" in
// the name) gives (2, 3, 4), w = 1; "light" and "count" or "num" in an int gives 1.
// Returns what it set, in declaration order.
std::vector<PreviewDefault> set_preview_defaults(ParameterStore& params, const EffectModel& model,
                                                 const std::vector<std::string>& read);

}  // namespace fx::vk
