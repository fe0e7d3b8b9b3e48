// TechniquePanel: every technique of the effect, drawable or not with the reason, the
// selection criteria as controls, and the technique selection chose highlighted; a click
// pins a technique by name, "auto" goes back to selection.
#pragma once
#include <fxkit/fxkit.h>

#include <string>

class TechniquePanel {
 public:
  // Draws the panel; when the criteria or the pinned technique change, `technique` becomes
  // the new choice.
  void draw(const fxkit::Effect& effect, fxkit::Technique& technique);
  // Pins `name` ("" or "auto": selection).
  void pin(const fxkit::Effect& effect, fxkit::Technique& technique, const std::string& name);

 private:
  fxkit::Criteria criteria_;
  bool budget_on_ = false, error_on_ = false;
  float budget_ms_ = 1.f, max_error_ = 2.f;
  char scheme_[64] = "";
  std::string pinned_;  // "" : selection
};
