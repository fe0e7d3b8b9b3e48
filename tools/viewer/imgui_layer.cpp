// ImGuiLayer: the render pass, descriptor pool and font upload ImGui's Vulkan backend needs.
#include "imgui_layer.h"
#include "vk_struct.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <vector>

std::unique_ptr<ImGuiLayer> ImGuiLayer::create(VulkanWindow& window) {
  std::unique_ptr<ImGuiLayer> ui(new ImGuiLayer(window));
  VkDevice device = window.device();
  VkAttachmentDescription color{};
  color.format = window.color_format();
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  // The scene's colour writes (dynamic rendering, or the screenshot copy) come first.
  VkSubpassDependency dep{};
  dep.srcSubpass = VK_SUBPASS_EXTERNAL;
  dep.dstSubpass = 0;
  dep.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dep.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dep.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dep.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo rp = vk_struct<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
  rp.attachmentCount = 1;
  rp.pAttachments = &color;
  rp.subpassCount = 1;
  rp.pSubpasses = &subpass;
  rp.dependencyCount = 1;
  rp.pDependencies = &dep;
  if (vkCreateRenderPass(device, &rp, nullptr, &ui->render_pass_) != VK_SUCCESS) return nullptr;
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16}};
  VkDescriptorPoolCreateInfo pool =
      vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pool.maxSets = 16;
  pool.poolSizeCount = 1;
  pool.pPoolSizes = sizes;
  if (vkCreateDescriptorPool(device, &pool, nullptr, &ui->pool_) != VK_SUCCESS) return nullptr;

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's effects
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForVulkan(window.glfw(), true);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = window.instance();
  info.PhysicalDevice = window.physical_device();
  info.Device = device;
  info.QueueFamily = window.queue_family();
  info.Queue = window.queue();
  info.DescriptorPool = ui->pool_;
  info.MinImageCount = 2;
  info.ImageCount = std::max(2u, window.image_count());
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  ImGui_ImplVulkan_Init(&info, ui->render_pass_);

  // The font atlas, uploaded once through a one-time command buffer.
  VkCommandPool cmd_pool = VK_NULL_HANDLE;
  VkCommandPoolCreateInfo pci = vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
  pci.queueFamilyIndex = window.queue_family();
  vkCreateCommandPool(device, &pci, nullptr, &cmd_pool);
  VkCommandBufferAllocateInfo alloc =
      vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
  alloc.commandPool = cmd_pool;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  vkAllocateCommandBuffers(device, &alloc, &cmd);
  VkCommandBufferBeginInfo begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(cmd, &begin);
  ImGui_ImplVulkan_CreateFontsTexture(cmd);
  vkEndCommandBuffer(cmd);
  VkSubmitInfo submit = vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  vkQueueSubmit(window.queue(), 1, &submit, VK_NULL_HANDLE);
  vkQueueWaitIdle(window.queue());
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  vkDestroyCommandPool(device, cmd_pool, nullptr);
  return ui;
}

ImGuiLayer::~ImGuiLayer() {
  VkDevice device = window_.device();
  vkDeviceWaitIdle(device);
  if (ImGui::GetCurrentContext()) {
    if (frame_started_) ImGui::EndFrame();
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
  if (render_pass_) vkDestroyRenderPass(device, render_pass_, nullptr);
}

void ImGuiLayer::make_framebuffers(VkExtent2D extent) {
  VkDevice device = window_.device();
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  framebuffers_.clear();
  for (uint32_t i = 0; i < window_.image_count(); ++i) {
    VkImageView view = window_.image_view(i);
    VkFramebufferCreateInfo fb = vk_struct<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    fb.renderPass = render_pass_;
    fb.attachmentCount = 1;
    fb.pAttachments = &view;
    fb.width = extent.width, fb.height = extent.height, fb.layers = 1;
    vkCreateFramebuffer(device, &fb, nullptr, &framebuffers_.emplace_back());
  }
  generation_ = window_.swapchain_generation();
}

void ImGuiLayer::new_frame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  frame_started_ = true;
}

void ImGuiLayer::record(const WindowFrame& frame) {
  ImGui::Render();
  frame_started_ = false;
  if (generation_ != window_.swapchain_generation()) make_framebuffers(frame.extent);
  VkRenderPassBeginInfo begin = vk_struct<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
  begin.renderPass = render_pass_;
  begin.framebuffer = framebuffers_.at(frame.image);
  begin.renderArea = {{0, 0}, frame.extent};
  vkCmdBeginRenderPass(frame.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), frame.cmd);
  vkCmdEndRenderPass(frame.cmd);
}
