// PassResources: uniform shadows with change detection and image bindings.
#include "fx/binding/pass_resources.h"

#include <atomic>
#include <cstring>
#include <string>

namespace fx::vk {

uint32_t unique_uniform_block_id() {
  static std::atomic<uint32_t> next{0};
  return next++;
}

PassResources::PassResources(const ShaderProgram& program) : program_(&program) {
  for (const ProgramUniformBlock& b : program.uniform_blocks())
    blocks_.push_back({std::vector<uint8_t>(b.size, 0), true, 0, 0});
  images_.resize(program.images().size());
  buffers_.resize(program.storage_buffers().size());
  texel_views_.resize(program.texel_buffers().size(), VK_NULL_HANDLE);
}

static bool write_if_changed(std::vector<uint8_t>& dst, uint32_t offset, const void* data, uint32_t bytes,
                             bool& dirty) {
  if (std::memcmp(dst.data() + offset, data, bytes) == 0) return false;
  std::memcpy(dst.data() + offset, data, bytes);
  dirty = true;
  return true;
}

bool PassResources::set_uniform(std::string_view name, const void* data, uint32_t bytes, DiagnosticSink& sink) {
  const auto& blocks = program_->uniform_blocks();
  for (size_t i = 0; i < blocks.size(); ++i) {
    if (!blocks[i].reflection) continue;
    for (const BlockMember& m : blocks[i].reflection->members) {
      if (m.name != name) continue;
      if (bytes > m.size || m.offset + bytes > blocks_[i].data.size()) {
        sink.error("vk-uniform-size", {},
                   "uniform '" + std::string(name) + "' has " + std::to_string(m.size) + " bytes; " +
                       std::to_string(bytes) + " given");
        return false;
      }
      write_if_changed(blocks_[i].data, m.offset, data, bytes, blocks_[i].dirty);
      return true;
    }
  }
  sink.error("vk-uniform-unknown", {}, "the program has no uniform '" + std::string(name) + "'");
  return false;
}

bool PassResources::set_block_bytes(std::string_view block, uint32_t offset, const void* data, uint32_t bytes,
                                    DiagnosticSink& sink) {
  const auto& blocks = program_->uniform_blocks();
  for (size_t i = 0; i < blocks.size(); ++i)
    if (blocks[i].name == block) return set_block_bytes(uint32_t(i), offset, data, bytes, sink);
  sink.error("vk-uniform-unknown", {}, "the program has no uniform block '" + std::string(block) + "'");
  return false;
}

bool PassResources::set_block_bytes(uint32_t index, uint32_t offset, const void* data, uint32_t bytes,
                                    DiagnosticSink& sink) {
  if (index >= blocks_.size()) {
    sink.error("vk-uniform-unknown", {}, "the program has no uniform block #" + std::to_string(index));
    return false;
  }
  Block& b = blocks_[index];
  if (uint64_t(offset) + bytes > b.data.size()) {
    sink.error("vk-uniform-size", {},
               "write past the end of uniform block '" + program_->uniform_blocks()[index].name + "'");
    return false;
  }
  write_if_changed(b.data, offset, data, bytes, b.dirty);
  return true;
}

bool PassResources::bind(std::string_view name, const Texture& texture, VkSampler sampler, DiagnosticSink& sink) {
  const auto& images = program_->images();
  for (size_t i = 0; i < images.size(); ++i) {
    if (images[i].name != name) continue;
    Bound b{texture.view(), texture.layout(), sampler};
    Bound& cur = images_[i];
    if (cur.view != b.view || cur.layout != b.layout || cur.sampler != b.sampler) {
      cur = b;
      images_changed_ = true;
      ++images_version_;
    }
    return true;
  }
  sink.error("vk-resource-unknown", {}, "the program has no texture or sampler '" + std::string(name) + "'");
  return false;
}

bool PassResources::bind_buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize range,
                                DiagnosticSink& sink) {
  const auto& buffers = program_->storage_buffers();
  for (size_t i = 0; i < buffers.size(); ++i) {
    if (buffers[i].name != name) continue;
    VkDescriptorBufferInfo& cur = buffers_[i];
    if (cur.buffer != buffer || cur.offset != offset || cur.range != range) {
      cur = {buffer, offset, range};
      images_changed_ = true;
      ++images_version_;
    }
    return true;
  }
  sink.error("vk-resource-unknown", {}, "the program has no storage buffer '" + std::string(name) + "'");
  return false;
}

bool PassResources::bind_texel_buffer(std::string_view name, VkBufferView view, DiagnosticSink& sink) {
  const auto& texel = program_->texel_buffers();
  for (size_t i = 0; i < texel.size(); ++i) {
    if (texel[i].name != name) continue;
    if (texel_views_[i] != view) {
      texel_views_[i] = view;
      images_changed_ = true;
      ++images_version_;
    }
    return true;
  }
  sink.error("vk-resource-unknown", {}, "the program has no texel buffer '" + std::string(name) + "'");
  return false;
}

bool PassResources::bind_sampler(std::string_view name, VkSampler sampler, DiagnosticSink& sink) {
  return bind(name, Texture(), sampler, sink);
}

}  // namespace fx::vk
