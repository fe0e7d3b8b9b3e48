// ImGuiLayer: Dear ImGui on the window (Debian's libimgui.a, with its GLFW and Vulkan 1.86
// backends). That Vulkan backend draws inside a render pass, so the UI is a render pass
// that loads the scene the effect drew with dynamic rendering and leaves the image ready
// to present.
#pragma once
#include <vulkan/vulkan.h>

#include <memory>
#include <vector>

#include "vulkan_window.h"

class ImGuiLayer {
 public:
  // nullptr when the backends cannot be set up.
  static std::unique_ptr<ImGuiLayer> create(VulkanWindow& window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Starts the UI of a frame (ImGui:: calls follow).
  void new_frame();
  // Draws the UI over the frame's image and leaves it in PRESENT_SRC.
  void record(const WindowFrame& frame);

 private:
  explicit ImGuiLayer(VulkanWindow& window) : window_(window) {}
  void make_framebuffers(VkExtent2D extent);
  VulkanWindow& window_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<VkFramebuffer> framebuffers_;
  uint64_t generation_ = 0;  // of the swapchain the framebuffers are for (0: none yet)
  bool frame_started_ = false;
};
