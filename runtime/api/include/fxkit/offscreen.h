// fxkit::Offscreen: an image of the Target's formats to render into and read back, for
// tools, tests and headless samples. An engine renders into its own swapchain images.
#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fxkit/message.h"

namespace fxkit {

class Device;

class Offscreen {
 public:
  // The first colour format and the depth format of the device's Target; nullptr with
  // `errors` when the device cannot render to them.
  static std::unique_ptr<Offscreen> create(Device& device, uint32_t width, uint32_t height,
                                           std::vector<Message>& errors);
  ~Offscreen();
  Offscreen(const Offscreen&) = delete;
  Offscreen& operator=(const Offscreen&) = delete;

  // vkCmdBeginRendering on the image, cleared to `clear`.
  void begin(VkCommandBuffer cmd, std::array<float, 4> clear = {0.f, 0.f, 0.f, 1.f});
  // vkCmdEndRendering, then a copy of the colour image for read_rgba8().
  void end(VkCommandBuffer cmd);
  // The full image, with the Target's Y convention (negative height for
  // YFlip::negative_viewport), and its scissor.
  VkViewport viewport() const;
  VkRect2D scissor() const;
  uint32_t width() const;
  uint32_t height() const;

  // After the submission that recorded end() completed: RGBA8, rows top to bottom.
  std::vector<uint8_t> read_rgba8() const;
  // The same, written as a PNG; false with a message in `errors` on failure.
  bool write_png(const std::string& path, std::vector<Message>& errors) const;

 private:
  struct Impl;
  explicit Offscreen(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace fxkit
