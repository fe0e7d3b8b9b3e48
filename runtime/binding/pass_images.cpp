// resolve_pass_images: a pass's samplers created and its images fed from textures or stand-ins.
#include "pass_images.h"

#include <algorithm>

#include "fx/emulation/stage_texture.h"

namespace fx::vk {
namespace {

// The model sampler (and the texture it reads) behind a program image named `name`; a
// generated shader's stage sampler (fx_stage<n>) reads the pass's texture stage n.
void resolve_image(const EffectModel& model, const PassInfo& pass, std::string_view name,
                   const fx::SamplerDesc** sampler, uint32_t* texture_param, fx::SamplerDesc& stage_sampler) {
  *sampler = nullptr;
  *texture_param = kNoIndex;
  if (std::optional<uint32_t> stage = emulation::stage_of_sampler(name)) {
    emulation::StageTexture t = emulation::stage_texture(pass, *stage);
    stage_sampler = t.sampler;
    *sampler = &stage_sampler;
    *texture_param = t.texture;
    return;
  }
  for (const SamplerInfo& s : model.samplers) {
    if (s.name != name) continue;
    *sampler = &s.desc;
    *texture_param = s.texture;
    return;
  }
  // GLSL combined samplers and D3D10 Texture2D objects are named after the texture.
  uint32_t p = model.find_parameter(name);
  if (p != kNoIndex && model.texture_of(p)) *texture_param = p;
}

// A storage image's stand-in format and shape (EffectStorage's, bound in bind_textures()).
ImageSlot storage_slot(const EffectModel& model, const ProgramImage& image) {
  ImageSlot slot;
  slot.name = image.name;
  slot.kind = image.kind;
  const uint32_t param = model.find_parameter(image.name);
  if (param != kNoIndex) slot.storage_format = storage_image_format(model.parameters[param].type.element);
  slot.storage_shape = storage_image_shape(image.dim, image.arrayed, image.count);
  return slot;
}

// The texture data an image samples: a depth stand-in for a comparing sampler, a
// multisampled stand-in, or the effect's texture (or a stand-in for one it does not name).
std::shared_ptr<const EffectTextureData> image_data(const ImageSources& from, const PassInfo& pass,
                                                    const ProgramImage& image, uint32_t texture_param,
                                                    bool first_mention, ImageNotes& notes, DiagnosticSink& sink) {
  EffectTextureCache& textures = from.textures;
  if (image.shadow) {
    // Vulkan compares only against depth formats: whatever the effect names (a colour
    // file, nothing), a depth stand-in is bound until set_texture() gives a depth view.
    if (first_mention)
      sink.warning("vk-texture-depth-stand-in", pass.range,
                   "pass '" + pass.name + "': '" + image.name +
                       "' is sampled with depth comparison, which needs a depth texture; a depth of 1.0 "
                       "(nothing in shadow) stands in" +
                       (texture_param != kNoIndex ? " until set_texture() binds a depth view" : ""));
    return textures.depth_stand_in(image.dim, image.arrayed);
  }
  // No file fills a multisampled image: a white one stands in until set_texture() binds
  // the application's multisampled view.
  if (image.multisampled) return textures.multisampled_stand_in(image.arrayed);
  // Texture2D<int> and <uint> need an integer view: zeros until set_texture() binds one.
  if (image.sampled != ScalarKind::float32) return textures.integer_stand_in(image.sampled, image.dim, image.arrayed);
  const TextureInfo* tex = texture_param != kNoIndex ? from.model.texture_of(texture_param) : nullptr;
  if (!tex) {
    sink.warning("vk-texture-unresolved", pass.range,
                 "pass '" + pass.name + "': '" + image.name + "' names no texture parameter; a " +
                     stand_in_name(texture_stand_in(nullptr, image.dim, textures.preview_stand_ins())) +
                     " stands in until set_texture()");
    return textures.resolve(from.model, TextureInfo{}, from.desc.effect_dir, image.dim, image.arrayed, sink);
  }
  const bool first = std::find(notes.resolved.begin(), notes.resolved.end(), texture_param) == notes.resolved.end();
  DiagnosticSink repeat;  // the same warning for every pass sampling the texture is noise
  auto data = textures.resolve(from.model, *tex, from.desc.effect_dir, image.dim, image.arrayed, first ? sink : repeat,
                               from.desc.texture_dirs);
  if (first) notes.resolved.push_back(texture_param);
  return data;
}

}  // namespace

bool resolve_pass_images(const ImageSources& from, const PassInfo& pass, const ShaderProgram& shader, ImageNotes& notes,
                         std::vector<ImageSlot>& out, std::string& reason, DiagnosticSink& sink) {
  DiagnosticSink ignored;  // not reported: to_sampler_key's approximations (border colour, MirrorOnce)
  for (const ProgramImage& image : shader.images()) {
    if (image.kind == DescriptorKind::storage_image) {
      out.push_back(storage_slot(from.model, image));
      continue;
    }
    ImageSlot slot;
    slot.name = image.name;
    slot.kind = image.kind;
    const fx::SamplerDesc* sampler_desc = nullptr;
    fx::SamplerDesc stage_sampler;
    resolve_image(from.model, pass, image.name, &sampler_desc, &slot.texture_param, stage_sampler);
    const bool first_mention = notes.told.insert(image.name).second;
    if (image.count > 1 && first_mention)
      sink.warning("vk-image-array-first", pass.range,
                   "pass '" + pass.name + "': '" + image.name + "' is an array of " + std::to_string(image.count) +
                       "; every element samples its first element's texture and sampler state");
    if (image.kind != DescriptorKind::sampled_image) {
      SamplerKey key = sampler_desc ? to_sampler_key(*sampler_desc, ignored) : SamplerKey{};
      // A shader that compares (SampleCmp, a shadow sampler) needs a comparing sampler, as
      // D3D requires a SamplerComparisonState; one declared without ComparisonFunc compares
      // with LessEqual.
      if (image.shadow) key.compare_enable = 1;
      slot.sampler = from.samplers.get(key, sink);
      if (!slot.sampler) return false;
    }
    if (image.kind != DescriptorKind::sampler) {
      slot.data = image_data(from, pass, image, slot.texture_param, first_mention, notes, sink);
      if (!slot.data) {
        reason = "pass '" + pass.name + "': texture '" + image.name + "' could not be made";
        return false;
      }
      // A texture shader's texture replaces the stand-in (slot.data) when its fill runs.
      if (slot.texture_param != kNoIndex && !image.shadow && !image.multisampled &&
          image.sampled == ScalarKind::float32)
        slot.fill = from.fills.add(from.model, slot.texture_param, image.dim, image.arrayed, from.programs, sink);
    }
    out.push_back(std::move(slot));
  }
  return true;
}

}  // namespace fx::vk
