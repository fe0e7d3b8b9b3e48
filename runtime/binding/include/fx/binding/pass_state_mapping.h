// Maps the effect model's neutral pass state summary and sampler descriptions (from D3D9
// render states or D3D10/11 state objects) into PipelineState and vk::SamplerKey.
#pragma once
#include <optional>

#include "fx/model/pass_state.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/pipeline_state.h"
#include "fx/vulkan/sampler_cache.h"

namespace fx::vk {

// The render target a pass state is mapped for.
struct PassTargetInfo {
  uint32_t color_attachment_count = 1;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  // Bits of the depth buffer: D3D9 depth bias is a fraction of the depth range, Vulkan's
  // constant factor is in units of the format's minimum resolvable difference (2^-bits).
  uint32_t depth_bits = 24;
  // The two facts that decide the Vulkan front face; the effect's FrontFace is D3D's
  // (clockwise front faces for clockwise meshes in a Y-down window). Each of these that
  // differs from D3D mirrors the winding once; two mirrors cancel.
  // True when the app flips Y with a negative viewport height (D3D's window orientation);
  // false when its projection flips Y instead.
  bool negative_viewport_height = true;
  // The winding of the application's front-facing triangles: clockwise as in Direct3D, or
  // counter_clockwise as in OpenGL and fxkit's built-in meshes (fx/mesh.h).
  FrontFace mesh_front_face = FrontFace::clockwise;
};

// The pipeline state for `pass`. Returns nullopt with "vk-feature-missing" when the pass
// needs a device feature that is not enabled (wireframe/point fill without
// fillModeNonSolid, different blend per target without independentBlend). States emulated
// elsewhere (alpha test in the fragment shader, sRGB write through an sRGB view, scissor
// enable through the scissor rectangle) are not part of the pipeline state.
std::optional<PipelineState> to_pipeline_state(const PassStateSummary& pass, const PassTargetInfo& target,
                                               const DeviceFeatures& features, DiagnosticSink& sink);

// The Vulkan sampler description for a model sampler. A border colour other than
// transparent black, opaque black or opaque white is approximated by the nearest of those
// ("vk-border-color-approximated" warning); MirrorOnce becomes mirrored repeat
// ("vk-address-mode-approximated" warning).
SamplerKey to_sampler_key(const fx::SamplerDesc& sampler, DiagnosticSink& sink);

}  // namespace fx::vk
