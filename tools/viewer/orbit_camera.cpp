// OrbitCamera: yaw and pitch around the origin, right-handed, +Y up, Vulkan depth 0..1.
#include "orbit_camera.h"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

OrbitCamera::OrbitCamera(float radius) : radius_(std::max(radius, 1e-3f)) {
  const fxkit::Scene framed = fxkit::Scene::framing(radius_, 1.0f);
  const glm::vec3 eye(framed.eye[0], framed.eye[1], framed.eye[2]);
  distance_ = glm::length(eye);
  pitch_ = std::asin(eye.y / distance_);
}

void OrbitCamera::turn(float dx, float dy) {
  yaw_ -= dx * 0.01f;
  pitch_ = std::clamp(pitch_ + dy * 0.01f, -1.5f, 1.5f);
}

void OrbitCamera::zoom(float steps) {
  distance_ = std::clamp(distance_ * std::pow(0.9f, steps), radius_ * 1.05f, radius_ * 50.f);
}

fxkit::Scene OrbitCamera::scene(float aspect, float time) const {
  fxkit::Scene s;
  const glm::vec3 eye =
      distance_ * glm::vec3(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * std::cos(yaw_));
  const glm::mat4 view = glm::lookAtRH(eye, glm::vec3(0.f), glm::vec3(0.f, 1.f, 0.f));
  const glm::mat4 projection =
      glm::perspectiveRH_ZO(glm::radians(40.f), aspect, distance_ * 0.02f, distance_ + radius_ * 4.f);
  std::copy_n(glm::value_ptr(view), 16, s.view);
  std::copy_n(glm::value_ptr(projection), 16, s.projection);
  s.eye[0] = eye.x, s.eye[1] = eye.y, s.eye[2] = eye.z;
  s.time = time;
  return s;
}
