// OrbitCamera: a camera circling the mesh (left drag turns, wheel zooms), as fxkit::Scene.
#pragma once
#include <fxkit/fxkit.h>

class OrbitCamera {
 public:
  // Starts where Scene::framing puts the camera for a sphere of `radius`.
  explicit OrbitCamera(float radius);
  void turn(float dx_pixels, float dy_pixels);
  void zoom(float wheel_steps);
  fxkit::Scene scene(float aspect, float time) const;
  // From the camera to the centre of the mesh, in world units (selection's distance).
  float distance() const { return distance_; }

 private:
  float radius_, distance_, yaw_ = 0.f, pitch_;
};
