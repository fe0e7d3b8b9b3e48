// LightControl: a light direction (azimuth, elevation) written into the effect's light
// direction parameters once the user turns it on: those with the DIRECTION (or
// LIGHTDIRECTION) semantic get the direction the light travels, as SAS means it; those
// without a semantic named like the DirectX SDK's (g_LightDir, g_vLightDir, LightDir) get
// the direction towards the light, as those samples use it.
#pragma once
#include <fxkit/fxkit.h>

class LightControl {
 public:
  void draw();
  void apply(fxkit::Effect& effect) const;

 private:
  bool on_ = false;
  float azimuth_ = 30.f, elevation_ = 50.f;  // degrees; the light's position seen from the origin
};
