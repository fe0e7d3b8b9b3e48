// DXSAS scripts: a technique's or pass's `string Script = "...";` annotation (DXSAS 0.86 /
// 1.0, as FX Composer, EffectEdit and MikuMikuEffect write them) parsed into a plan of
// located, checked steps, and the STANDARDSGLOBAL parameter's ScriptClass / ScriptOrder /
// ScriptOutput. docs/dxsas.md lists the commands and what each unsupported one reports.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "fx/no_index.h"
#include "fx/source_location.h"

namespace fx {

struct EffectModel;
class DiagnosticSink;

enum class ScriptCommand {
  render_color_target,          // RenderColorTarget[0-3]=texture (empty: the frame's own target)
  render_depth_stencil_target,  // RenderDepthStencilTarget=texture (empty: the frame's own)
  clear_set_color,              // ClearSetColor=float4 parameter
  clear_set_depth,              // ClearSetDepth=float parameter
  clear_set_stencil,            // ClearSetStencil=int or float parameter
  clear,                        // Clear=Color | Depth | Stencil
  pass,                         // Pass=name (technique scripts)
  draw,                         // Draw=Geometry | Buffer (pass scripts)
  script_external,              // ScriptExternal=[name] (technique scripts): the host's scene
  loop_by_count,                // LoopByCount=int or float parameter
  loop_by_type,                 // LoopByType=type (Light, ...): runs once in a preview
  loop_get_index,               // LoopGetIndex=int or float parameter, inside a loop
  loop_end,                     // LoopEnd=
};

enum class ScriptClear { color, depth, stencil };
enum class ScriptDraw { geometry, buffer };

// One command of a script.
struct ScriptStep {
  ScriptCommand command = ScriptCommand::draw;
  uint32_t slot = 0;              // RenderColorTarget0..3
  uint32_t parameter = kNoIndex;  // the parameter it names (a target, a clear value, a loop count or index)
  uint32_t pass = kNoIndex;       // Pass=: the pass's index in its technique
  ScriptClear clear = ScriptClear::color;
  ScriptDraw draw = ScriptDraw::geometry;
  std::string value;  // as written after '='
  SourceRange range;  // the command inside the annotation's string (the annotation when unmappable)
};

// A technique's or pass's Script. A pass without one draws the geometry (`Draw=Geometry;`).
struct ScriptPlan {
  std::vector<ScriptStep> steps;
  SourceRange range;  // the Script annotation
};

// The effect's STANDARDSGLOBAL parameter (`float Script : STANDARDSGLOBAL < ... >`), lower-cased.
struct ScriptGlobal {
  uint32_t parameter = kNoIndex;  // kNoIndex when the effect has none
  std::string script_class;       // object, scene, sceneorobject ("" = object)
  std::string script_order;       // standard, preprocess, postprocess ("" = standard)
  std::string script_output;      // color
};

// Parses and checks every Script annotation of `model`'s techniques and passes into
// TechniqueInfo::script / PassInfo::script, and the STANDARDSGLOBAL parameter into
// model.script_global. Problems are warnings (D3DX ignores annotations; the effect still
// runs without its script): "script-syntax", "script-unknown-command", "script-unknown-name",
// "script-wrong-type", "script-misplaced", "script-loop-unbalanced".
void plan_scripts(EffectModel& model, DiagnosticSink& diags);

}  // namespace fx
