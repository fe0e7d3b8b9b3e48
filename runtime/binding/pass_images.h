// Private: a pass's images and samplers resolved when its binding is created: sampler
// states to cached samplers, each image to the texture that feeds it (the effect's own,
// baked or decoded now) or a stand-in, with the warnings a preview needs once.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "fx/binding/effect_binding.h"
#include "fx/binding/shader_program.h"
#include "fx/binding/texture_fills.h"

namespace fx::vk {

// One image, sampler or combined image-sampler descriptor of a pass and what feeds it.
struct ImageSlot {
  std::string name;
  DescriptorKind kind = DescriptorKind::combined_image_sampler;
  VkSampler sampler = VK_NULL_HANDLE;
  uint32_t texture_param = kNoIndex;               // the texture parameter it samples
  std::shared_ptr<const EffectTextureData> data;   // the effect's own texture
  VkFormat storage_format = VK_FORMAT_UNDEFINED;   // a storage image's stand-in format
  std::optional<StorageImageShape> storage_shape;  // ... and its shape (none: no stand-in fits)
  uint32_t fill = kNoIndex;                        // the TextureFills fill of its texture shader
};

// What the passes of one binding have said already: each texture's problems and each
// image's stand-in warnings are reported for the first pass only.
struct ImageNotes {
  std::vector<uint32_t> resolved;  // texture parameters already resolved
  std::set<std::string> told;      // images whose array / depth stand-in warning was given
};

// Where the images of a binding's passes come from.
struct ImageSources {
  const EffectModel& model;
  SamplerCache& samplers;
  EffectTextureCache& textures;
  const EffectBindingDesc& desc;
  TextureFills& fills;  // the binding's texture shaders
  EffectPrograms& programs;
};

// The slots of `shader`'s images for the pass `pass`, storage images left to EffectStorage
// (bound in EffectBinding::bind_textures). False when one cannot be made: with `reason` set
// when a texture could not be made (the technique cannot run), empty when a sampler could
// not be created (nothing can be set up).
bool resolve_pass_images(const ImageSources& from, const PassInfo& pass, const ShaderProgram& shader, ImageNotes& notes,
                         std::vector<ImageSlot>& out, std::string& reason, DiagnosticSink& sink);

}  // namespace fx::vk
