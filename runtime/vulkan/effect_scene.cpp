// Standard semantics: matrices handed to the store in D3DX row-vector form.
#include "fx/vulkan/effect_scene.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace fx::vk {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// A column-vector matrix G (used as G * v) is HLSL's M in mul(v, M) transposed; glm's
// column-major memory of G is exactly M's rows, so it goes in as HostMatrixOrder::row_major.
bool set_matrix(ParameterStore& params, Param p, const Type& type, const glm::mat4& g) {
  const float* m = glm::value_ptr(g);  // m[r * 4 + c] == M[r][c]
  if (type.rows == 4 && type.cols == 4) return bool(params.set_matrix(p, std::span<const float>(m, 16)));
  std::vector<float> sub;
  for (int r = 0; r < type.rows; ++r)
    for (int c = 0; c < type.cols; ++c) sub.push_back(m[r * 4 + c]);
  return bool(params.set_matrix(p, sub));
}

}  // namespace

SceneView frame_bounds(const MeshBounds& bounds, float aspect) {
  SceneView s;
  const float fov = glm::radians(40.0f);
  const float radius = std::max(bounds.radius, 1e-3f);
  // Distance at which the sphere spans 85% of the narrower field of view.
  const float half = std::min(fov, 2.0f * std::atan(std::tan(fov * 0.5f) * aspect)) * 0.5f;
  const float distance = radius / std::sin(half) / 0.85f;
  const glm::vec3 center = bounds.center();
  const glm::vec3 dir = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  s.eye = center + dir * distance;
  s.view = glm::lookAtRH(s.eye, center, glm::vec3(0.0f, 1.0f, 0.0f));
  s.projection = glm::perspectiveRH_ZO(fov, aspect, distance * 0.05f, distance + radius * 4.0f);
  return s;
}

uint32_t set_standard_semantics(ParameterStore& params, const EffectModel& model, const SceneView& scene) {
  const glm::mat4 wv = scene.view * scene.world, vp = scene.projection * scene.view;
  const glm::mat4 wvp = scene.projection * wv;
  struct Named {
    const char* name;
    glm::mat4 m;
  };
  const Named bases[] = {{"WORLD", scene.world}, {"VIEW", scene.view}, {"PROJECTION", scene.projection},
                         {"WORLDVIEW", wv}, {"VIEWPROJECTION", vp}, {"WORLDVIEWPROJECTION", wvp}};
  uint32_t set = 0;
  for (const Parameter& param : model.parameters) {
    if (param.semantic.empty()) continue;
    const std::string sem = upper(param.semantic);
    Param p = params.find(param.name);
    const Type* type = params.type(p);
    if (!type) continue;
    if (type->cls == TypeClass::matrix) {
      for (const Named& b : bases) {
        const std::string base = b.name;
        glm::mat4 m;
        if (sem == base) m = b.m;
        else if (sem == base + "INVERSE") m = glm::inverse(b.m);
        else if (sem == base + "TRANSPOSE") m = glm::transpose(b.m);
        else if (sem == base + "INVERSETRANSPOSE") m = glm::transpose(glm::inverse(b.m));
        else continue;
        set += set_matrix(params, p, *type, m) ? 1 : 0;
        break;
      }
    } else if (sem == "CAMERAPOSITION" || sem == "EYEPOSITION" || sem == "VIEWPOSITION") {
      const float v[4] = {scene.eye.x, scene.eye.y, scene.eye.z, 1.0f};
      const uint32_t n = std::min(type->component_count(), 4u);
      if (type->base == BaseType::float32 && n >= 3) set += params.set(p, std::span<const float>(v, n)) ? 1 : 0;
    } else if (sem == "TIME") {
      if (type->component_count() == 1 && type->base == BaseType::float32) set += params.set(p, scene.time) ? 1 : 0;
    }
  }
  return set;
}

}  // namespace fx::vk
