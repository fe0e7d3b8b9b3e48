// fx::vk::TextureFills: the textures of one effect binding that D3DX texture shaders fill
// (fx/model/texture_shader.h). Each fill's compute program is made with the binding (any
// thread); it runs once on the GPU when the binding first binds its textures (render thread,
// a blocking one-shot submission, as texture uploads), reading the effect's globals as the
// parameter store holds them then, as D3DX evaluates a texture shader at the effect's values
// when it fills. A reloaded version is a new binding: its textures are filled anew.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "fx/binding/shader_program.h"
#include "fx/compile/effect_programs.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"
#include "fx/vulkan/texture.h"

namespace fx::vk {

class TextureFills {
 public:
  // `ctx` and `params` must outlive this.
  TextureFills(const Context& ctx, ParameterStore& params);
  TextureFills(const TextureFills&) = delete;
  TextureFills& operator=(const TextureFills&) = delete;
  ~TextureFills();

  // The fill of texture parameter `texture` of `model`, which a shader samples as `dim`
  // (`arrayed`): its index, or kNoIndex when the texture has no texture shader or its fill
  // cannot run. Why not is the warning "vk-texture-shader-failed" at the function annotation
  // (once per texture; the compiler's errors, located in the function, follow as warnings):
  // a function that does not compile as a compute shader, one that reads textures or
  // samplers, a texture filled in another shape than the shader samples. The texture's
  // stand-in stays bound then.
  uint32_t add(const EffectModel& model, uint32_t texture, ImageDim dim, bool arrayed, EffectPrograms& programs,
               DiagnosticSink& sink);
  // The texture of fill `fill`, filled on the first call (render thread); null when the
  // fill failed ("vk-texture-shader-failed", once).
  const Texture* texture(uint32_t fill, DiagnosticSink& sink);

 private:
  struct Fill;
  // Fills `fill.texture`; false (nothing filled) when a Vulkan object could not be made.
  bool run(Fill& fill, DiagnosticSink& sink);

  const Context* ctx_;
  ParameterStore* params_;
  std::vector<std::unique_ptr<Fill>> fills_;
  std::vector<std::pair<uint32_t, uint32_t>> added_;  // texture parameter -> add()'s answer
};

}  // namespace fx::vk
