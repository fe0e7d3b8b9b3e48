// Standard parameter semantics (SAS / D3DX conventions) filled from a simple scene: an
// object transform, a camera framing a mesh, and the time. Used by `fxkit render`, `fxkit
// watch` and the rendering tests so that any effect written against WORLDVIEWPROJECTION,
// VIEWINVERSE, CAMERAPOSITION, ... renders without per-effect setup.
#pragma once
#include <glm/glm.hpp>

#include "fx/mesh.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"

namespace fx::vk {

// A right-handed scene, +Y up, column vectors (clip = projection * view * world * p), Vulkan
// clip depth 0..1 and clip +Y up (render with a negative viewport height).
struct SceneView {
  glm::mat4 world{1.0f}, view{1.0f}, projection{1.0f};
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  float time = 0.0f;  // seconds
};

// A camera looking at `bounds` from the front and a little above (so tops and fronts both
// show), far enough that the bounding sphere fills about 85% of the shorter image side.
SceneView frame_bounds(const MeshBounds& bounds, float aspect);

// Sets every parameter whose semantic is a standard one: WORLD, VIEW, PROJECTION, their
// products (WORLDVIEW, VIEWPROJECTION, WORLDVIEWPROJECTION), inverses and transposes
// (…INVERSE, …TRANSPOSE, …INVERSETRANSPOSE), CAMERAPOSITION / EYEPOSITION /
// VIEWPOSITION (float3 or float4 with w = 1), TIME. Other parameters keep their values
// (light directions and colours keep their effect defaults). Returns how many were set.
uint32_t set_standard_semantics(ParameterStore& params, const EffectModel& model, const SceneView& scene);

}  // namespace fx::vk
