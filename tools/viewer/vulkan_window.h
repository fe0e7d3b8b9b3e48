// VulkanWindow: a GLFW window with the Vulkan objects an application owns and fxkit borrows
// (instance, device, queue), a swapchain with a depth image, frames in flight, and a
// readback of the scene for --screenshot.
#pragma once
#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

struct WindowOptions {
  std::string title = "fxkit-view";
  int width = 960, height = 640;
  bool validation = false;  // VK_LAYER_KHRONOS_validation, errors and warnings counted
  uint32_t frames_in_flight = 2;
};

// One frame being recorded: the command buffer and the swapchain image it draws into.
struct WindowFrame {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  uint32_t slot = 0;   // frame in flight
  uint32_t image = 0;  // swapchain image index
  VkExtent2D extent{};
};

class VulkanWindow {
 public:
  static std::unique_ptr<VulkanWindow> create(const WindowOptions& options, std::string& error);
  ~VulkanWindow();
  VulkanWindow(const VulkanWindow&) = delete;
  VulkanWindow& operator=(const VulkanWindow&) = delete;

  GLFWwindow* glfw() const;
  VkInstance instance() const;
  VkPhysicalDevice physical_device() const;
  VkDevice device() const;
  VkQueue queue() const;
  uint32_t queue_family() const;
  // What the device was created with (for fxkit::VulkanHandles::created_with).
  const VkDeviceCreateInfo* created_with() const;
  VkFormat color_format() const;
  VkFormat depth_format() const;
  uint32_t image_count() const;
  VkImageView image_view(uint32_t image) const;
  // The depth image's view, in DEPTH_ATTACHMENT_OPTIMAL from begin_scene on.
  VkImageView depth_view() const;
  // Bumped whenever the swapchain is made again (a resize): image views changed.
  uint64_t swapchain_generation() const;
  float timestamp_period_ns() const;  // 0: the queue has no timestamps

  // Waits for the slot's previous frame, acquires an image (remaking the swapchain when
  // it is out of date) and begins the command buffer. False when the window is minimised.
  bool begin_frame(WindowFrame& frame);
  // The scene's dynamic rendering on the frame's image, cleared, with the depth image.
  void begin_scene(const WindowFrame& frame, const float clear[4]);
  void end_scene(const WindowFrame& frame);
  // After end_scene: copies the scene into a host buffer (read_screenshot once idle).
  // `with_ui`: after the UI was recorded instead, so the copy holds the whole window.
  void capture(const WindowFrame& frame, bool with_ui = false);
  // Ends, submits and presents (the UI render pass leaves the image in PRESENT_SRC).
  bool end_frame(const WindowFrame& frame);
  void wait_idle();
  // RGBA8, rows top to bottom, of the last capture(); empty when none.
  std::vector<uint8_t> read_screenshot(uint32_t& width, uint32_t& height) const;
  // Validation errors and warnings reported so far (validation on).
  uint32_t validation_messages() const;

 private:
  struct Impl;
  explicit VulkanWindow(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};
