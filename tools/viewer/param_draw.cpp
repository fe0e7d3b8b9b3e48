// draw_param: a ParamWidget as ImGui controls, writing changed values into the effect. The
// label goes on its own line above a full-width control (the panel's text wrap position
// wraps it), so no label is cut off at the panel's edge.
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <map>

#include "param_widgets.h"

bool draw_param(fxkit::Effect& effect, const fxkit::ParamInfo& p, const ParamWidget& w) {
  if (w.kind == ParamWidget::Kind::hidden) return false;
  ImGui::PushID(p.name.c_str());
  bool changed = false;
  const int n = int(std::min<uint32_t>(p.components, 4));
  if (w.kind == ParamWidget::Kind::texture_file) {
    // The file a texture parameter samples: its ResourceName (relative to the effect) until
    // another is typed and loaded (Effect::set_texture_file).
    static std::map<std::string, std::array<char, 512>> paths;
    auto [it, fresh] = paths.try_emplace(effect.path() + "|" + p.name);
    if (fresh && !p.resource_name.empty()) {
      const std::string shown = (std::filesystem::path(effect.path()).parent_path() / p.resource_name).string();
      std::snprintf(it->second.data(), it->second.size(), "%s", shown.c_str());
    }
    ImGui::TextUnformatted(w.label.c_str());
    ImGui::SetNextItemWidth(-ImGui::CalcTextSize("load").x - 3 * ImGui::GetStyle().FramePadding.x -
                            ImGui::GetStyle().ItemSpacing.x);
    const bool entered =
        ImGui::InputText("##file", it->second.data(), it->second.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("load") || entered) changed = effect.set_texture_file(p.name, it->second.data());
  } else if (w.kind == ParamWidget::Kind::readonly) {
    std::string what = p.type + (p.semantic.empty() ? "" : " : " + p.semantic);
    if (!p.resource_name.empty()) what += " = \"" + p.resource_name + "\"";
    if (!p.default_text.empty()) what += " = \"" + p.default_text + "\"";
    ImGui::TextDisabled("%s  (%s)", w.label.c_str(), what.c_str());
  } else if (w.kind == ParamWidget::Kind::checkbox) {
    int32_t v[4] = {};
    effect.get(p.handle, std::span<int32_t>(v, p.components));
    bool b = v[0] != 0;
    if ((changed = ImGui::Checkbox("##value", &b))) v[0] = b;
    ImGui::SameLine();
    ImGui::TextUnformatted(w.label.c_str());  // the tooltip below is the label's
    if (changed) effect.set(p.handle, std::span<const int32_t>(v, p.components));
  } else if (p.scalar == fxkit::ScalarKind::float32) {
    ImGui::TextUnformatted(w.label.c_str());
    ImGui::SetNextItemWidth(-FLT_MIN);
    float v[4] = {};
    effect.get(p.handle, std::span<float>(v, p.components));
    const float speed = w.step > 0 ? w.step : (w.has_range ? (w.max - w.min) / 200.f : 0.01f);
    switch (w.kind) {
      case ParamWidget::Kind::color:
        changed = n == 3 ? ImGui::ColorEdit3("##value", v, ImGuiColorEditFlags_Float)
                         : ImGui::ColorEdit4("##value", v, ImGuiColorEditFlags_Float);
        break;
      case ParamWidget::Kind::slider:
        changed = ImGui::SliderScalarN("##value", ImGuiDataType_Float, v, n, &w.min, &w.max);
        break;
      case ParamWidget::Kind::spinner:
        changed = ImGui::InputScalarN("##value", ImGuiDataType_Float, v, n, w.step > 0 ? &w.step : nullptr);
        break;
      default:
        changed = ImGui::DragScalarN("##value", ImGuiDataType_Float, v, n, speed, w.has_range ? &w.min : nullptr,
                                     w.has_range ? &w.max : nullptr);
    }
    if (changed) effect.set(p.handle, std::span<const float>(v, p.components));
  } else {
    ImGui::TextUnformatted(w.label.c_str());
    ImGui::SetNextItemWidth(-FLT_MIN);
    int32_t v[4] = {};
    effect.get(p.handle, std::span<int32_t>(v, p.components));
    const int32_t lo = int32_t(w.min), hi = int32_t(w.max), step = std::max(1, int32_t(w.step));
    if (w.kind == ParamWidget::Kind::slider)
      changed = ImGui::SliderScalarN("##value", ImGuiDataType_S32, v, n, &lo, &hi);
    else changed = ImGui::InputScalarN("##value", ImGuiDataType_S32, v, n, &step);
    if (changed) effect.set(p.handle, std::span<const int32_t>(v, p.components));
  }
  if (!w.help.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", w.help.c_str());
  ImGui::PopID();
  return changed;
}
