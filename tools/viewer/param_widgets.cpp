// widget_for: a parameter's annotations to the widget that shows it (no ImGui here, so
// tests read what the viewer lists).
#include "param_widgets.h"

#include <algorithm>
#include <cctype>

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
  // A static (`static const float3 K`) is the shader's constant, not a parameter: no block
  // holds it and nothing can set it.
  if ((p.kind == fxkit::ParamKind::numeric || p.kind == fxkit::ParamKind::structure) && !p.settable)
    return w.kind = ParamWidget::Kind::hidden, w;
  if (p.kind == fxkit::ParamKind::texture && p.elements == 0) return w.kind = ParamWidget::Kind::texture_file, w;
  if (p.kind != fxkit::ParamKind::numeric || p.rows > 1 || p.elements > 0 || is_scene_bound(p))
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
