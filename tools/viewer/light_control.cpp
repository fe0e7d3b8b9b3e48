// LightControl: two angles to a unit vector, and the parameters it goes to.
#include "light_control.h"

#include <imgui.h>

#include <cctype>
#include <cmath>
#include <string>

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

void LightControl::draw() {
  ImGui::Checkbox("drive light direction", &on_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Writes DIRECTION / LIGHTDIRECTION parameters and ones named g_LightDir, LightDir, ...");
  ImGui::SliderFloat("azimuth", &azimuth_, -180.f, 180.f, "%.0f deg");
  ImGui::SliderFloat("elevation", &elevation_, -90.f, 90.f, "%.0f deg");
}

void LightControl::apply(fxkit::Effect& effect) const {
  if (!on_) return;
  const float a = azimuth_ * 3.14159265f / 180.f, e = elevation_ * 3.14159265f / 180.f;
  const float to_light[3] = {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
  for (const fxkit::ParamInfo& p : effect.params()) {
    if (p.kind != fxkit::ParamKind::numeric || p.scalar != fxkit::ScalarKind::float32 || p.rows != 1 || p.elements ||
        (p.columns != 3 && p.columns != 4))
      continue;
    const std::string sem = lower(p.semantic), name = lower(p.name);
    const bool travels = sem == "direction" || sem == "lightdirection";
    const bool towards = sem.empty() && (name == "g_lightdir" || name == "g_vlightdir" || name == "lightdir" ||
                                         name == "g_lightdirection" || name == "lightdirection");
    if (!travels && !towards) continue;
    const float s = travels ? -1.f : 1.f;
    const float v[4] = {s * to_light[0], s * to_light[1], s * to_light[2], 0.f};
    effect.set(p.handle, std::span<const float>(v, p.columns));
  }
}
