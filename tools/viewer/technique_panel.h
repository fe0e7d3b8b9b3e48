// TechniquePanel: every technique of the effect, drawable or not with the reason, its
// distance band and measured cost and error; the selection criteria as controls (a caps
// profile to emulate, distance, scheme, budget, max error) and the technique selection chose
// highlighted; a click pins a technique by name, "auto" goes back to selection.
#pragma once
#include <fxkit/fxkit.h>

#include <string>

class TechniquePanel {
 public:
  // Draws the panel; when the criteria or the pinned technique change, `technique` becomes
  // the new choice. `camera_distance` drives the distance criterion while "from the camera"
  // is ticked (selection then runs again as the camera zooms, with its hysteresis).
  void draw(const fxkit::Effect& effect, fxkit::Technique& technique, float camera_distance);
  // Pins `name` ("" or "auto": selection).
  void pin(const fxkit::Effect& effect, fxkit::Technique& technique, const std::string& name);

 private:
  fxkit::Criteria criteria_;
  int caps_ = 0;  // 0: this device, else caps_profiles()[caps_ - 1]
  bool distance_from_camera_ = false;
  bool budget_on_ = false, error_on_ = false;
  float budget_ms_ = 1.f, max_error_ = 2.f;
  char scheme_[64] = "";
  std::string pinned_;  // "" : selection
};
