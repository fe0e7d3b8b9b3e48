// Standard parameter semantics (SAS / D3DX conventions) filled from a simple scene: an
// object transform, a camera framing a mesh, and the time. Used by `fxkit render`, `fxkit
// watch` and the rendering tests so that any effect written against WORLDVIEWPROJECTION,
// VIEWINVERSE, CAMERAPOSITION, ... renders without per-effect setup.
#pragma once
#include <glm/glm.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "fx/compile/effect_programs.h"
#include "fx/mesh.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"

namespace fx::vk {

// A right-handed scene, +Y up, column vectors (clip = projection * view * world * p), Vulkan
// clip depth 0..1 and clip +Y up (render with a negative viewport height).
struct SceneView {
  glm::mat4 world{1.0f}, view{1.0f}, projection{1.0f};
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  float time = 0.0f;              // seconds
  float elapsed = 1.0f / 60.0f;   // seconds since the previous frame (ELAPSEDTIME)
  glm::vec2 viewport_size{0.0f};  // pixels (VIEWPORTPIXELSIZE); 0 leaves it alone
};

// A camera looking at `bounds` from the front and a little above (so tops and fronts both
// show), far enough that the bounding sphere fills about 85% of the shorter image side.
SceneView frame_bounds(const MeshBounds& bounds, float aspect);

// How set_standard_semantics gave a parameter its value.
struct SceneBinding {
  std::string parameter;
  std::string semantic;  // the standard semantic it was given ("WORLDVIEWPROJECTION")
  bool by_name = false;  // from its name (semantic_by_name), as it has no semantic
};

// The standard semantic effects mean by a parameter declared without one, from its name
// (case-insensitive): "g_mWorldViewProjection", "WorldViewProj", "matWVP" ->
// "WORLDVIEWPROJECTION"; "" for other names. The table (docs/parameters.md, "Scene
// parameters by name") holds the names of the DirectX SDK samples, FX Composer, RenderMonkey
// and common engine conventions.
// Beyond the table, a transform's name with other decorations is known too: prefixes
// (g_m, g_f4x4, m, mat), suffixes (Matrix, Xf), Inv in front (g_mInvView -> VIEWINVERSE).
std::string_view semantic_by_name(std::string_view name);

// A semantic in the spelling set_standard_semantics reads, upper case: the abbreviations
// effects write for transforms (WORLDVIEWPROJ, VIEWPROJ, WORLDI, VIEWINV, WORLDIT) become
// WORLDVIEWPROJECTION, VIEWPROJECTION, WORLDINVERSE, VIEWINVERSE, WORLDINVERSETRANSPOSE;
// any other semantic is only upper-cased.
std::string standard_semantic(std::string_view semantic);

// Sets every parameter whose semantic is a standard one: WORLD, VIEW, PROJECTION, their
// products (WORLDVIEW, VIEWPROJECTION, WORLDVIEWPROJECTION), inverses and transposes
// (…INVERSE, …TRANSPOSE, …INVERSETRANSPOSE), CAMERAPOSITION / EYEPOSITION /
// VIEWPOSITION (float3 or float4 with w = 1), TIME, ELAPSEDTIME, VIEWPORTPIXELSIZE (float2,
// or float4 with the reciprocals in zw, when the scene has a size); and every parameter with no semantic
// whose name semantic_by_name knows, as if it had that semantic. Other parameters keep
// their values (light directions and colours keep their effect defaults). Returns how
// many were set; `bound` (when given) receives how each was.
uint32_t set_standard_semantics(ParameterStore& params, const EffectModel& model, const SceneView& scene,
                                std::vector<SceneBinding>* bound = nullptr);

// The parameters the compiled passes of `technique` read (uniform block members, by
// parameter name; kNoIndex: every pass compiled so far). Compiles nothing.
std::vector<std::string> parameters_read(EffectPrograms& programs, uint32_t technique);

// The matrix parameters among `read` (names the shaders read) whose value is all zero, in
// declaration order: transforms nothing bound, which draw nothing (every vertex lands at
// the origin). Parameters the effect declares as `static` are left out.
std::vector<std::string> zero_transforms(const ParameterStore& params, const EffectModel& model,
                                         const std::vector<std::string>& read);

}  // namespace fx::vk
