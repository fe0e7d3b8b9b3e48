// PassStateSummary / fx::SamplerDesc -> PipelineState / vk::SamplerKey. The model's enums
// share Vulkan's values (documented in fx/model/pass_state.h), so most fields cast.
#include "fx/binding/pass_state_mapping.h"

#include <algorithm>
#include <cmath>

namespace fx::vk {

std::optional<PipelineState> to_pipeline_state(const PassStateSummary& p, const PassTargetInfo& target,
                                               const DeviceFeatures& features, DiagnosticSink& sink) {
  PipelineState s;
  s.cull_mode = uint32_t(p.cull);
  FrontFace front = p.front_face;
  const bool projection_flip = !target.negative_viewport_height;
  const bool mirrored_meshes = target.mesh_front_face == FrontFace::counter_clockwise;
  if (projection_flip != mirrored_meshes)
    front = front == FrontFace::clockwise ? FrontFace::counter_clockwise : FrontFace::clockwise;
  s.front_face = uint32_t(front);
  if (p.fill != FillMode::solid && !features.fill_mode_non_solid) {
    sink.error("vk-feature-missing", {},
               "wireframe or point fill needs the fillModeNonSolid feature, which the device lacks");
    return std::nullopt;
  }
  s.polygon_mode = uint32_t(p.fill);
  // D3D10+ biases arrive in format units already; D3D9's are fractions of the depth range.
  s.depth_bias_constant =
      p.depth_bias_normalized ? float(std::ldexp(double(p.depth_bias), int(target.depth_bits))) : p.depth_bias;
  s.depth_bias_slope = p.depth_bias_slope;
  s.depth_bias_clamp = features.depth_bias_clamp ? p.depth_bias_clamp : 0.0f;
  s.depth_bias_enable = s.depth_bias_constant != 0 || s.depth_bias_slope != 0;
  // DepthClipEnable = FALSE: clamping depth instead of clipping is the Vulkan equivalent.
  s.depth_clamp = !p.depth_clip && features.depth_clamp;
  s.depth_test = p.depth_test;
  s.depth_write = p.depth_test && p.depth_write;  // D3D: no writes when the test is off
  s.depth_compare = uint32_t(p.depth_compare);
  s.stencil_test = p.stencil;
  s.front_fail = uint32_t(p.stencil_front.fail), s.front_pass = uint32_t(p.stencil_front.pass);
  s.front_depth_fail = uint32_t(p.stencil_front.depth_fail);
  s.front_compare = uint32_t(p.stencil_front.compare);
  s.back_fail = uint32_t(p.stencil_back.fail), s.back_pass = uint32_t(p.stencil_back.pass);
  s.back_depth_fail = uint32_t(p.stencil_back.depth_fail);
  s.back_compare = uint32_t(p.stencil_back.compare);
  s.front_compare_mask = s.back_compare_mask = p.stencil_read_mask & 0xFF;
  s.front_write_mask = s.back_write_mask = p.stencil_write_mask & 0xFF;
  s.front_reference = s.back_reference = p.stencil_ref & 0xFF;

  const uint32_t n = std::min(target.color_attachment_count, kMaxColorAttachments);
  s.color_attachment_count = n;
  for (uint32_t i = 0; i < n; ++i) {
    const TargetBlend& b = p.blend[i];
    if (i > 0 && !(b == p.blend[0]) && !features.independent_blend) {
      sink.error(
          "vk-feature-missing", {},
          "render target " + std::to_string(i) + " blends differently from target 0, which needs independentBlend");
      return std::nullopt;
    }
    AttachmentBlend& a = s.blend[i];
    a.blend_enable = b.enable;
    a.src_color = uint32_t(b.src_color), a.dst_color = uint32_t(b.dst_color);
    a.color_op = uint32_t(b.color_op);
    a.src_alpha = uint32_t(b.src_alpha), a.dst_alpha = uint32_t(b.dst_alpha);
    a.alpha_op = uint32_t(b.alpha_op);
    a.write_mask = b.write_mask & 0xF;
  }
  for (int c = 0; c < 4; ++c) s.blend_constants[c] = p.blend_constants[size_t(c)];
  s.set_samples(target.samples);
  s.alpha_to_coverage = p.alpha_to_coverage && target.samples != VK_SAMPLE_COUNT_1_BIT;
  s.sample_mask = p.sample_mask;
  return s;
}

SamplerKey to_sampler_key(const fx::SamplerDesc& m, DiagnosticSink& sink) {
  SamplerKey d;
  VkSamplerAddressMode* modes[3] = {&d.address_u, &d.address_v, &d.address_w};
  for (int i = 0; i < 3; ++i) {
    AddressMode3 a = m.address[size_t(i)];
    if (a == AddressMode3::mirror_clamp_to_edge) {
      sink.warning("vk-address-mode-approximated", {},
                   "MirrorOnce addressing is sampled as Mirror (samplerMirrorClampToEdge is not "
                   "required of devices)");
      a = AddressMode3::mirrored_repeat;
    }
    *modes[i] = VkSamplerAddressMode(a);
  }
  d.min_filter = VkFilter(m.min_filter);
  d.mag_filter = VkFilter(m.mag_filter);
  d.mip_filter = m.mip_filter == MipFilter::linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
  d.mip_lod_bias = m.lod_bias;
  d.max_anisotropy = m.anisotropic ? float(std::max(1u, m.max_anisotropy)) : 1.0f;
  d.min_lod = std::max(m.min_lod, float(m.max_mip_level));
  // D3D9 MipFilter = None samples the most detailed level only.
  d.max_lod = m.mip_filter == MipFilter::none ? d.min_lod : std::max(d.min_lod, m.max_lod);
  const auto& c = m.border_color;
  const bool opaque = c[3] >= 0.5f;
  const bool white = opaque && (c[0] + c[1] + c[2]) >= 1.5f;
  d.border = !opaque ? VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK
                     : (white ? VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE : VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK);
  const bool exact = (c == std::array<float, 4>{0, 0, 0, 0}) || (c == std::array<float, 4>{0, 0, 0, 1}) ||
                     (c == std::array<float, 4>{1, 1, 1, 1});
  if (!exact)
    sink.warning("vk-border-color-approximated", {},
                 "border colour (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) +
                     ", " + std::to_string(c[3]) +
                     ") is sampled as the nearest of transparent black, opaque black and opaque white");
  d.compare_enable = m.compare_enable;
  d.compare_op = VkCompareOp(m.compare);
  return d;
}

}  // namespace fx::vk
