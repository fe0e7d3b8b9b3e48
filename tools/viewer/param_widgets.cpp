// ParamWidget: annotations to widgets, and the ImGui calls that draw them.
#include "param_widgets.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The first of `names` that is a string annotation, lower-cased; "" when none.
std::string text_of(const fxkit::ParamInfo& p, std::initializer_list<const char*> names, bool fold = true) {
  for (const char* n : names)
    if (const fxkit::Annotation* a = p.annotation(n); a && a->kind == fxkit::Annotation::Kind::string)
      return fold ? lower(a->text) : a->text;
  return {};
}

const fxkit::Annotation* number_of(const fxkit::ParamInfo& p, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (const fxkit::Annotation* a = p.annotation(n); a && a->kind != fxkit::Annotation::Kind::string) return a;
  return nullptr;
}

// Annotations the widget itself reads; every other string annotation is help text.
bool is_ui_annotation(const std::string& name) {
  static const char* const kRead[] = {
      "UIName",      "UIWidget", "UIMin",        "UIMax",        "UIStep", "SasUiControl", "SasUiLabel", "SasUiVisible",
      "SasUiMin",    "SasUiMax", "ui_type",      "ui_min",       "ui_max", "ui_step",      "ui_label",   "ui_tooltip",
      "ui_category", "ui_items", "ResourceName", "ResourceType", "Object", "Space"};
  return std::any_of(std::begin(kRead), std::end(kRead), [&](const char* n) { return name == n; });
}

// Names Effect::set_scene binds (docs/parameters.md): shown, not edited.
bool is_scene_bound(const fxkit::ParamInfo& p) {
  static const char* const kScene[] = {
      "world",          "view",        "projection",   "worldview", "viewprojection", "worldviewprojection",
      "cameraposition", "eyeposition", "viewposition", "time"};
  std::string sem = lower(p.semantic);
  for (const char* suffix : {"inversetranspose", "inverse", "transpose"})
    if (sem.size() > std::string(suffix).size() && sem.ends_with(suffix))
      sem.resize(sem.size() - std::string(suffix).size());
  return std::any_of(std::begin(kScene), std::end(kScene), [&](const char* n) { return sem == n; });
}

}  // namespace

ParamWidget widget_for(const fxkit::ParamInfo& p) {
  ParamWidget w;
  w.label = text_of(p, {"ui_label", "SasUiLabel", "UIName"}, false);
  if (w.label.empty()) w.label = p.name;
  w.category = text_of(p, {"ui_category"}, false);
  w.help = text_of(p, {"ui_tooltip"}, false);
  for (const fxkit::Annotation& a : p.annotations)
    if (a.kind == fxkit::Annotation::Kind::string && !is_ui_annotation(a.name))
      w.help += (w.help.empty() ? "" : "\n") + a.name + ": " + a.text;

  const fxkit::Annotation* visible = number_of(p, {"SasUiVisible", "UIVisible"});
  const std::string widget = text_of(p, {"ui_type", "UIWidget", "SasUiControl"});
  if (widget == "none" || (visible && visible->number() == 0.f)) return w.kind = ParamWidget::Kind::hidden, w;
  if (p.kind == fxkit::ParamKind::texture && p.elements == 0) return w.kind = ParamWidget::Kind::texture_file, w;
  if (p.kind != fxkit::ParamKind::numeric || !p.settable || p.rows > 1 || p.elements > 0 || is_scene_bound(p))
    return w.kind = ParamWidget::Kind::readonly, w;

  const fxkit::Annotation* min = number_of(p, {"ui_min", "UIMin", "SasUiMin"});
  const fxkit::Annotation* max = number_of(p, {"ui_max", "UIMax", "SasUiMax"});
  const fxkit::Annotation* step = number_of(p, {"ui_step", "UIStep"});
  if (min && max) w.min = min->number(), w.max = max->number(), w.has_range = w.max > w.min;
  if (step) w.step = step->number();
  if (p.scalar == fxkit::ScalarKind::boolean) w.kind = ParamWidget::Kind::checkbox;
  else if (widget == "color" || widget == "colorpicker" || widget == "colour") w.kind = ParamWidget::Kind::color;
  else if (widget == "slider") w.kind = w.has_range ? ParamWidget::Kind::slider : ParamWidget::Kind::drag;
  else if (widget == "spinner" || widget == "input") w.kind = ParamWidget::Kind::spinner;
  else if (widget == "drag") w.kind = ParamWidget::Kind::drag;
  else if (widget.empty() && (p.columns == 3 || p.columns == 4) && lower(p.name).find("col") != std::string::npos)
    w.kind = ParamWidget::Kind::color;  // an unannotated "...Color" float3/float4
  else w.kind = w.has_range ? ParamWidget::Kind::slider : ParamWidget::Kind::drag;
  if (w.kind == ParamWidget::Kind::color && p.columns < 3) w.kind = ParamWidget::Kind::drag;
  return w;
}

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
    const bool entered =
        ImGui::InputText("##file", it->second.data(), it->second.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("load") || entered) changed = effect.set_texture_file(p.name, it->second.data());
  } else if (w.kind == ParamWidget::Kind::readonly) {
    std::string what = p.type + (p.semantic.empty() ? "" : " : " + p.semantic);
    if (!p.resource_name.empty()) what += " = \"" + p.resource_name + "\"";
    if (!p.default_text.empty()) what += " = \"" + p.default_text + "\"";
    ImGui::TextDisabled("%s  (%s)", w.label.c_str(), what.c_str());
  } else if (p.scalar == fxkit::ScalarKind::float32) {
    float v[4] = {};
    effect.get(p.handle, std::span<float>(v, p.components));
    const float speed = w.step > 0 ? w.step : (w.has_range ? (w.max - w.min) / 200.f : 0.01f);
    switch (w.kind) {
      case ParamWidget::Kind::color:
        changed = n == 3 ? ImGui::ColorEdit3(w.label.c_str(), v, ImGuiColorEditFlags_Float)
                         : ImGui::ColorEdit4(w.label.c_str(), v, ImGuiColorEditFlags_Float);
        break;
      case ParamWidget::Kind::slider:
        changed = ImGui::SliderScalarN(w.label.c_str(), ImGuiDataType_Float, v, n, &w.min, &w.max);
        break;
      case ParamWidget::Kind::spinner:
        changed = ImGui::InputScalarN(w.label.c_str(), ImGuiDataType_Float, v, n, w.step > 0 ? &w.step : nullptr);
        break;
      default:
        changed = ImGui::DragScalarN(w.label.c_str(), ImGuiDataType_Float, v, n, speed, w.has_range ? &w.min : nullptr,
                                     w.has_range ? &w.max : nullptr);
    }
    if (changed) effect.set(p.handle, std::span<const float>(v, p.components));
  } else {
    int32_t v[4] = {};
    effect.get(p.handle, std::span<int32_t>(v, p.components));
    const int32_t lo = int32_t(w.min), hi = int32_t(w.max), step = std::max(1, int32_t(w.step));
    if (w.kind == ParamWidget::Kind::checkbox) {
      bool b = v[0] != 0;
      if ((changed = ImGui::Checkbox(w.label.c_str(), &b))) v[0] = b;
    } else if (w.kind == ParamWidget::Kind::slider) {
      changed = ImGui::SliderScalarN(w.label.c_str(), ImGuiDataType_S32, v, n, &lo, &hi);
    } else {
      changed = ImGui::InputScalarN(w.label.c_str(), ImGuiDataType_S32, v, n, &step);
    }
    if (changed) effect.set(p.handle, std::span<const int32_t>(v, p.components));
  }
  if (!w.help.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", w.help.c_str());
  ImGui::PopID();
  return changed;
}
