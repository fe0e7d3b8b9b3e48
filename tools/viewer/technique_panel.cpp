// TechniquePanel: Effect::techniques() and Effect::select() as ImGui controls.
#include "technique_panel.h"

#include <imgui.h>

#include <cstdio>
#include <limits>
#include <string>
#include <vector>

void TechniquePanel::pin(const fxkit::Effect& effect, fxkit::Technique& technique, const std::string& name) {
  pinned_ = name == "auto" ? "" : name;
  technique = pinned_.empty() ? effect.select(criteria_) : effect.technique(pinned_);
}

namespace {

// The technique's distance band as selection prints it (TechniqueInfo::distance_band), with
// the Hysteresis margin when given; "" when it has none (docs/selection.md).
std::string distance_band(const fxkit::TechniqueInfo& t) {
  if (t.distance_band.empty()) return {};
  std::string out = t.distance_band;
  if (const fxkit::Annotation* h = t.annotation("Hysteresis")) {
    char margin[48];
    std::snprintf(margin, sizeof margin, ", hysteresis %g", h->number());
    out += margin;
  }
  return out;
}

}  // namespace

void TechniquePanel::draw(const fxkit::Effect& effect, fxkit::Technique& technique, float camera_distance) {
  bool changed = false;
  ImGui::TextUnformatted("Selection criteria");
  const std::vector<std::string> profiles = fxkit::caps_profiles();
  const std::string shown = caps_ == 0 ? "this device" : profiles[size_t(caps_ - 1)];
  if (ImGui::BeginCombo("caps", shown.c_str())) {
    for (int i = 0; i <= int(profiles.size()); ++i)
      if (ImGui::Selectable(i == 0 ? "this device" : profiles[size_t(i - 1)].c_str(), caps_ == i)) {
        changed |= caps_ != i;
        caps_ = i;
      }
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("select as that generation would, among what this device draws");
  criteria_.caps = caps_ == 0 ? "" : profiles[size_t(caps_ - 1)];
  changed |= ImGui::Checkbox("from the camera", &distance_from_camera_);
  ImGui::SameLine();
  if (distance_from_camera_) {
    changed |= criteria_.distance != camera_distance;
    criteria_.distance = camera_distance;
    ImGui::Text("distance %.2f", criteria_.distance);
  } else {
    changed |= ImGui::DragFloat("distance", &criteria_.distance, 0.1f, 0.f, 1000.f);
  }
  changed |= ImGui::InputText("scheme", scheme_, sizeof scheme_);
  changed |= ImGui::Checkbox("##budget", &budget_on_);
  ImGui::SameLine();
  changed |= ImGui::DragFloat("budget ms", &budget_ms_, 0.01f, 0.f, 100.f);
  changed |= ImGui::Checkbox("##error", &error_on_);
  ImGui::SameLine();
  changed |= ImGui::DragFloat("max error", &max_error_, 0.05f, 0.f, 255.f);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("in 8-bit levels (docs/selection.md)");
  criteria_.scheme = scheme_;
  criteria_.cost_budget_ms = budget_on_ ? budget_ms_ : std::numeric_limits<float>::infinity();
  criteria_.max_error = error_on_ ? max_error_ : std::numeric_limits<float>::infinity();

  ImGui::Separator();
  if (ImGui::RadioButton("auto (selection)", pinned_.empty())) pin(effect, technique, ""), changed = false;
  const std::string chosen = technique.name();
  for (const fxkit::TechniqueInfo& t : effect.techniques()) {
    ImGui::PushID(t.name.c_str());
    if (ImGui::RadioButton("##pin", pinned_ == t.name)) pin(effect, technique, t.name), changed = false;
    ImGui::SameLine();
    const ImVec4 colour = t.name == chosen ? ImVec4(0.4f, 1.f, 0.4f, 1.f)
                          : t.drawable     ? ImVec4(0.9f, 0.9f, 0.9f, 1.f)
                                           : ImVec4(1.f, 0.45f, 0.45f, 1.f);
    ImGui::TextColored(colour, "%s%s (%u pass%s)", t.name == chosen ? "> " : "", t.name.c_str(), t.passes,
                       t.passes == 1 ? "" : "es");
    if (!t.drawable) ImGui::TextWrapped("    %s", t.reason.c_str());
    if (!t.caps_reason.empty()) ImGui::TextWrapped("    %s", t.caps_reason.c_str());
    if (const std::string band = distance_band(t); !band.empty()) ImGui::Text("    distance %s", band.c_str());
    // Measured cost and error where the effect carries them (generated/costs.fxh).
    const fxkit::Annotation* error = t.annotation("MaxError");
    const fxkit::Annotation* cost = t.annotation("CostNsPerPixel");
    if (cost) ImGui::Text("    cost %.3f ns/pixel", cost->number());
    if (error) ImGui::Text("    error %.2f levels (8-bit)", error->number());
    else if (cost) ImGui::TextUnformatted("    error not measured");
    ImGui::PopID();
  }
  if (changed && pinned_.empty()) technique = effect.select(criteria_);
}
