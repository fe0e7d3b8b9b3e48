// fx::vk::PassResources: the values one pass's program reads: CPU copies of its uniform
// blocks (with dirty tracking) and the textures and samplers bound to its descriptors.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>
#include <vector>

#include "fx/binding/descriptor_arena.h"
#include "fx/binding/shader_program.h"
#include "fx/vulkan/texture.h"

namespace fx::vk {

// A uniform block id (ParameterStore::bind_layout) no other block of the process has, so two
// bindings of one store (a dynamic-state and a static one, a pass and a texture shader)
// never overwrite each other's block layouts.
uint32_t unique_uniform_block_id();

class PassResources {
 public:
  // Blocks start zero-filled and dirty; images unbound. `program` must outlive this.
  explicit PassResources(const ShaderProgram& program);

  // Copies `bytes` into the member called `name` ("light.dir" for struct members) of any
  // uniform block; the block becomes dirty only if the bytes differ. False (and
  // "vk-uniform-unknown" / "vk-uniform-size") when there is no such member or `bytes`
  // exceeds it.
  bool set_uniform(std::string_view name, const void* data, uint32_t bytes, DiagnosticSink& sink);
  // Copies raw bytes into block `block` at `offset` (dirty only if changed).
  bool set_block_bytes(std::string_view block, uint32_t offset, const void* data, uint32_t bytes, DiagnosticSink& sink);
  // The same for block `index` of program.uniform_blocks(): callers that resolved the name
  // once skip the per-call lookup. "vk-uniform-unknown" for an index past the last block.
  bool set_block_bytes(uint32_t index, uint32_t offset, const void* data, uint32_t bytes, DiagnosticSink& sink);
  // Binds a texture (and, for a combined image sampler, its sampler) to the descriptor called
  // `name`; for a separate sampler descriptor pass a null-view texture and the sampler; for a
  // storage image, a texture in VK_IMAGE_LAYOUT_GENERAL and no sampler.
  // False and "vk-resource-unknown" if the program has no such image or sampler.
  bool bind(std::string_view name, const Texture& texture, VkSampler sampler, DiagnosticSink& sink);
  bool bind_sampler(std::string_view name, VkSampler sampler, DiagnosticSink& sink);
  // Binds `range` bytes of `buffer` from `offset` to the storage buffer called `name`.
  // False and "vk-resource-unknown" if the program has no such storage buffer.
  bool bind_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range,
                   DiagnosticSink& sink);
  // Binds `view` to the texel buffer called `name`. False and "vk-resource-unknown" if the
  // program has no such texel buffer.
  bool bind_texel_buffer(std::string_view name, VkBufferView view, DiagnosticSink& sink);

  const ShaderProgram& program() const { return *program_; }
  // Descriptor sets (DescriptorMode::sets) kept in `arena` across frames, one per frame in
  // flight, written again only when the images change: without it each frame allocates and
  // writes a set from FrameResources. `arena` must outlive this. The kept sets serve the
  // first FrameResources that records them; a recorder on another one takes sets of its
  // frames instead.
  void keep_sets_in(DescriptorArena& arena) { arena_ = &arena; }
  // The next apply writes the descriptor set again even where every bound handle is equal:
  // an image view destroyed and made again may come back with the same handle.
  void rewrite_sets() {
    images_changed_ = true;
    ++images_version_;
  }

 private:
  friend class PassRecorder;
  struct Block {
    std::vector<uint8_t> data;
    bool dirty = true;
    uint64_t uploaded_frame = 0;  // FrameResources::frame() of the last upload
    uint32_t offset = 0;          // ring offset of the last upload
  };
  struct Bound {
    VkImageView view = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    VkSampler sampler = VK_NULL_HANDLE;
  };
  const ShaderProgram* program_;
  std::vector<Block> blocks_;                    // parallel to program.uniform_blocks()
  std::vector<Bound> images_;                    // parallel to program.images()
  std::vector<VkDescriptorBufferInfo> buffers_;  // parallel to program.storage_buffers()
  std::vector<VkBufferView> texel_views_;        // parallel to program.texel_buffers()
  bool images_changed_ = true;                   // descriptor set contents must be rewritten
  uint64_t images_version_ = 1;                  // bumped with every change of images_
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  uint64_t set_frame_ = 0;
  // keep_sets_in's sets, by frame % frames in flight: what each was written with and the
  // last frame that bound it.
  struct KeptSet {
    VkDescriptorSet set = VK_NULL_HANDLE;
    uint64_t images_version = 0;
    uint64_t frame = 0;
  };
  DescriptorArena* arena_ = nullptr;
  std::vector<KeptSet> kept_;
  uint64_t kept_for_ = 0;  // FrameResources::id() of the frames the kept sets serve (0: none yet)
};

}  // namespace fx::vk
