// Speed against error of whole techniques: every technique of an effect rendered into an
// RGBA32F target over a fixed scene set and compared per pixel with the double-precision
// shading model the effect documents, evaluated on the same pixels from a G-buffer pass;
// GPU cost from timestamps around the technique's own passes (docs/accuracy.md).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "fx/diagnostic.h"
#include "fx/vulkan/context.h"

namespace fx::bench {

// One technique's figures. Errors are in 8-bit levels (|GPU - reference| x 255, the worst
// colour channel of each pixel, both clamped to [0,1] first: the colour a UNORM target
// displays) over the covered pixels of every scene; costs are medians of repeats with the
// empty technique's time subtracted.
//
// A technique with a ps.1.x assembly pixel stage gets a second row with precision_model set:
// the same technique compiled with the ps.1.x precision model (FXKIT_PS1X_PRECISION,
// docs/legacy-assembly.md). It is a measurement of the technique under a compile option, not
// a technique of its own: selection and COST_<technique> use the row without the model.
struct TechniqueAccuracy {
  std::string effect;  // file name, "hemisphere.fx"
  std::string technique;
  std::string scheme;     // the technique's Scheme annotation ("" when none)
  bool drawable = false;  // the Vulkan binding can draw it
  bool measured = false;
  std::string reason;            // why not measured
  std::string model;             // the reference model it was compared with
  std::string substitutes;       // techniques of the effect with the same value are substitutes
  std::string emulation;         // how the binding draws a legacy technique ("ps.1.1 assembly
                                 // translated to HLSL; ..."), "" for HLSL and GLSL techniques
  bool precision_model = false;  // compiled with the ps.1.x precision model
  // precision_model rows: what the model changes, |with - without| x 255 (displayed values,
  // worst channel) at the same pixels of the same scenes: the ps.1.x banding itself.
  double banding_max_lsb = 0, banding_rmse_lsb = 0;
  double max_error_lsb = 0, p99_error_lsb = 0, rmse_lsb = 0;
  size_t pixels_compared = 0;
  double ns_per_pixel = 0;   // pixel stage: full-target time minus the vertex-only time
  double ns_per_vertex = 0;  // vertex stage: time with a 1x1 scissor off the mesh
  bool timed = false;
};

struct TechniqueAccuracyOptions {
  std::string effects_dir;        // effects/ (includes resolve there)
  uint32_t error_size = 128;      // square target for the error scenes
  uint32_t timing_size = 256;     // square target for the timing scene
  uint32_t draws = 4;             // repetitions of the technique's passes per timed frame
  int repeats = 5;                // timed frames per technique (median)
  std::vector<std::string> only;  // effect file names to measure ("brdf.fx"); all when empty
};

// The scene set, for reports: meshes, object rotations, parameter sets per effect.
std::string describe_scene_set();

// Measures every technique of every *.fx file in options.effects_dir (sorted by name; only
// those named in options.only when it is not empty).
// Techniques the binding cannot draw, or of an effect or scheme without a reference model,
// come back measured = false with the reason. nullopt with diagnostics when an effect does
// not load or a render fails.
std::optional<std::vector<TechniqueAccuracy>> measure_techniques(const vk::Context& ctx,
                                                                 const TechniqueAccuracyOptions& options,
                                                                 DiagnosticSink& sink);

}  // namespace fx::bench
