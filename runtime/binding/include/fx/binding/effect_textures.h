// fx::vk::EffectTextureCache: the textures effect parameters name, shared by every effect
// binding (and every reloaded version) of one device: procedural tables baked once per
// (generator, parameters), image files (DDS, PNG, ...) decoded once per (path, size, mtime), and neutral
// stand-ins for files that are missing. CPU data is resolved on any thread (reload workers
// bake while the app renders); GPU images are created only on the render thread, because
// uploads use the context's queue, which Vulkan does not let two threads share.
#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>

#include "fx/binding/texture_stand_in.h"
#include "fx/compile/shader_reflection.h"
#include "fx/dds.h"
#include "fx/image.h"
#include "fx/model/effect_model.h"
#include "fx/shading/table.h"
#include "fx/vulkan/texture.h"

namespace fx::vk {

// The CPU contents of one effect texture: an 8-bit image or a baked table.
struct EffectTextureData {
  std::string key;                      // identity in the cache
  std::optional<fx::Image> image;       // PNG (and other stb) files and stand-ins
  std::optional<fx::DdsTexture> dds;    // DDS files
  std::optional<shading::Table> table;  // procedural generators
  bool stand_in = false;                // a stand-in for a missing file (texture_stand_in.h)
  ImageDim dim = ImageDim::dim_2d;      // stand-ins take the shape the shader samples
  bool arrayed = false;                 // ... as an array view (Texture2DArray)
  bool depth = false;                   // a depth stand-in, for sampling with depth comparison
  bool multisampled = false;            // a multisampled stand-in, for Texture2DMS(Array)
};

class EffectTextureCache {
 public:
  explicit EffectTextureCache(const Context& ctx) : ctx_(&ctx) {}
  EffectTextureCache(const EffectTextureCache&) = delete;
  EffectTextureCache& operator=(const EffectTextureCache&) = delete;

  // The data for `texture` of `model` (thread-safe). A generator is baked (failures are
  // errors from the generator registry); a ResourceName is looked for beside the effect
  // (`effect_dir`), then in `more_dirs` (the -I folders), and read as DDS or what stb reads.
  // A file that is missing, unreadable or of another shape than the shader samples gets a
  // stand-in (texture_stand_in(), with preview_stand_ins()) and the warning
  // "vk-texture-file-missing" at the annotation; a texture with
  // neither (set by the application) gets the stand-in silently. Null only when a
  // generator fails.
  // `dim` and `arrayed` are how the shader samples it (stand-ins are made in that shape: 1D,
  // 2D, 3D or cube, as an array view for Texture2DArray and its kin): a view of another
  // shape is invalid, and lavapipe crashes on a 2D view bound to a 1D sampler.
  std::shared_ptr<const EffectTextureData> resolve(const EffectModel& model, const TextureInfo& texture,
                                                   const std::filesystem::path& effect_dir, ImageDim dim, bool arrayed,
                                                   DiagnosticSink& sink,
                                                   std::span<const std::filesystem::path> more_dirs = {});
  // A depth texture of 1.0 in the shape the shader samples, for an image sampled with depth
  // comparison (Vulkan compares only against depth formats): a shadow map nothing is in front of.
  std::shared_ptr<const EffectTextureData> depth_stand_in(ImageDim dim, bool arrayed);
  // A white multisampled 2D texture (an array view when `arrayed`) for a Texture2DMS the
  // shader reads with Load(coord, sample): no file can fill one, the application renders it
  // and binds it with set_texture().
  std::shared_ptr<const EffectTextureData> multisampled_stand_in(bool arrayed);
  // Zeros for a Texture2D<int> or <uint> (`sampled` int32 or uint32) read with Load: its view
  // must be of an integer format, which no colour file or stand-in is.
  std::shared_ptr<const EffectTextureData> integer_stand_in(ScalarKind sampled, ImageDim dim, bool arrayed);

  // Stand-ins that show what a shader does (a colour test pattern, a ramp of depths, an
  // environment: texture_stand_in.h) instead of neutral ones, for previews. Set before the
  // first resolve(); off by default.
  void set_preview_stand_ins(bool on) { preview_stand_ins_ = on; }
  bool preview_stand_ins() const { return preview_stand_ins_; }

  // The GPU texture for `data`, uploaded on first use. Render thread only.
  const Texture* gpu(const EffectTextureData& data, DiagnosticSink& sink);

  // GPU textures alive (for leak checks) and CPU entries held.
  size_t gpu_count() const { return gpu_.size(); }
  // Drops everything (render thread; the device must be done with the textures).
  void clear();

 private:
  // The entry for `key`, or null (thread-safe).
  std::shared_ptr<const EffectTextureData> cached(const std::string& key) const;
  // Inserts `data` under its key; an entry another thread inserted first wins (thread-safe).
  std::shared_ptr<const EffectTextureData> keep(EffectTextureData data);

  const Context* ctx_;
  mutable std::mutex mutex_;  // guards cpu_
  std::map<std::string, std::shared_ptr<const EffectTextureData>> cpu_;
  std::map<std::string, Texture> gpu_;
  bool preview_stand_ins_ = false;
};

}  // namespace fx::vk
