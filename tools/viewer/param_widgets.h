// ParamWidget: how a parameter is shown, read from its annotations: SAS / D3DX (UIName,
// UIWidget, UIMin, UIMax, UIStep, SasUiControl, SasUiLabel, SasUiVisible, SasUiMin,
// SasUiMax) and ReShade's (ui_type, ui_min, ui_max, ui_step, ui_label, ui_tooltip,
// ui_category); other string annotations become help text. draw_param (param_draw.cpp)
// draws it with ImGui.
#pragma once
#include <fxkit/fxkit.h>

#include <string>

struct ParamWidget {
  enum class Kind { hidden, slider, drag, spinner, color, checkbox, readonly, texture_file };
  Kind kind = Kind::drag;
  std::string label;
  std::string help;                        // tooltip: ui_tooltip, then string annotations ("UIHelp: ...")
  std::string category;                    // ui_category ("" : the effect's own group)
  float min = 0.f, max = 1.f, step = 0.f;  // step 0: continuous
  bool has_range = false;
};

// The widget `param`'s annotations ask for. A texture gets a file field (its ResourceName,
// loaded with Effect::set_texture_file). Strings, scene transforms (a standard semantic or a
// name Effect::set_scene binds), matrices and arrays are read-only; UIWidget "None",
// SasUiVisible false and statics (values no application sets) are hidden.
ParamWidget widget_for(const fxkit::ParamInfo& param);

// Draws `param` as `widget` and writes a changed value into `effect`; true when it did.
bool draw_param(fxkit::Effect& effect, const fxkit::ParamInfo& param, const ParamWidget& widget);
