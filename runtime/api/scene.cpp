// fxkit::Scene::framing: the preview camera of fx::vk::frame_bounds, in public form.
#include <algorithm>

#include "fx/binding/effect_scene.h"
#include "fxkit/effect.h"

namespace fxkit {

Scene Scene::framing(float radius, float aspect) {
  fx::MeshBounds bounds;
  bounds.min = glm::vec3(-radius);
  bounds.max = glm::vec3(radius);
  bounds.radius = radius;
  const fx::vk::SceneView view = fx::vk::frame_bounds(bounds, aspect);
  Scene s;
  std::copy_n(&view.world[0][0], 16, s.world);
  std::copy_n(&view.view[0][0], 16, s.view);
  std::copy_n(&view.projection[0][0], 16, s.projection);
  std::copy_n(&view.eye[0], 3, s.eye);
  s.time = view.time;
  return s;
}

}  // namespace fxkit
