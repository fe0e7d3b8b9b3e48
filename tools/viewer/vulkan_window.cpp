// VulkanWindow: GLFW surface, Vulkan 1.3 device (dynamic rendering for fxkit), swapchain.
#define GLFW_INCLUDE_VULKAN
#include "vulkan_window.h"
#include "vk_struct.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                             VkDebugUtilsMessageTypeFlagsEXT,
                                             const VkDebugUtilsMessengerCallbackDataEXT* data, void* counter) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    ++*static_cast<uint32_t*>(counter);
    std::fprintf(stderr, "validation: %s\n", data->pMessage);
  }
  return VK_FALSE;
}

bool has_layer(const char* name) {
  uint32_t n = 0;
  vkEnumerateInstanceLayerProperties(&n, nullptr);
  std::vector<VkLayerProperties> layers(n);
  vkEnumerateInstanceLayerProperties(&n, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_extension(VkPhysicalDevice gpu, const char* name) {
  uint32_t n = 0;
  vkEnumerateDeviceExtensionProperties(gpu, nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  vkEnumerateDeviceExtensionProperties(gpu, nullptr, &n, exts.data());
  return std::any_of(exts.begin(), exts.end(), [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

}  // namespace

struct VulkanWindow::Impl {
  WindowOptions options;
  GLFWwindow* window = nullptr;
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  uint32_t validation_count = 0;
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VkPhysicalDevice gpu = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t family = 0;
  float timestamp_period = 0;
  // The device's creation, kept for VulkanHandles::created_with.
  VkPhysicalDeviceFeatures2 features =
      vk_struct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  VkPhysicalDeviceVulkan11Features features11 =
      vk_struct<VkPhysicalDeviceVulkan11Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES);
  VkPhysicalDeviceVulkan12Features features12 =
      vk_struct<VkPhysicalDeviceVulkan12Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES);
  VkPhysicalDeviceVulkan13Features features13 =
      vk_struct<VkPhysicalDeviceVulkan13Features>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  std::vector<const char*> extensions;
  VkDeviceQueueCreateInfo queue_info = vk_struct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  float priority = 1.0f;
  VkDeviceCreateInfo device_info = vk_struct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);

  VkFormat color_format = VK_FORMAT_B8G8R8A8_UNORM;
  VkColorSpaceKHR color_space = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkFormat depth_format = VK_FORMAT_D32_SFLOAT;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VkExtent2D extent{};
  std::vector<VkImage> images;
  std::vector<VkImageView> views;
  uint64_t generation = 0;
  VkImage depth = VK_NULL_HANDLE;
  VkDeviceMemory depth_memory = VK_NULL_HANDLE;
  VkImageView depth_view = VK_NULL_HANDLE;

  struct Slot {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkFence done = VK_NULL_HANDLE;
    VkSemaphore acquired = VK_NULL_HANDLE;
  };
  std::vector<Slot> slots;
  std::vector<VkSemaphore> rendered;  // per swapchain image
  uint32_t next_slot = 0;

  VkBuffer readback = VK_NULL_HANDLE;
  VkDeviceMemory readback_memory = VK_NULL_HANDLE;
  VkDeviceSize readback_size = 0;
  VkExtent2D captured{};

  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags want) const {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(gpu, &props);
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i)
      if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & want) == want) return i;
    return 0;
  }

  bool make_instance(std::string& error);
  bool make_device(std::string& error);
  bool make_swapchain(std::string& error);
  void destroy_swapchain();
  void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
               VkPipelineStageFlags2 src_stage, VkAccessFlags2 src, VkPipelineStageFlags2 dst_stage,
               VkAccessFlags2 dst);
};

bool VulkanWindow::Impl::make_instance(std::string& error) {
  uint32_t count = 0;
  const char** glfw_exts = glfwGetRequiredInstanceExtensions(&count);
  if (!glfw_exts) return error = "GLFW finds no Vulkan surface support", false;
  std::vector<const char*> exts(glfw_exts, glfw_exts + count);
  std::vector<const char*> layers;
  const bool validate = options.validation && has_layer("VK_LAYER_KHRONOS_validation");
  if (options.validation && !validate)
    std::fprintf(stderr, "fxkit-view: VK_LAYER_KHRONOS_validation is not installed\n");
  if (validate) {
    layers.push_back("VK_LAYER_KHRONOS_validation");
    exts.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkApplicationInfo app = vk_struct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
  app.pApplicationName = "fxkit-view";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo info = vk_struct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = uint32_t(exts.size());
  info.ppEnabledExtensionNames = exts.data();
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return error = "vkCreateInstance failed", false;
  if (validate) {
    VkDebugUtilsMessengerCreateInfoEXT m =
        vk_struct<VkDebugUtilsMessengerCreateInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    m.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    m.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
    m.pfnUserCallback = on_validation;
    m.pUserData = &validation_count;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create) create(instance, &m, nullptr, &messenger);
  }
  if (glfwCreateWindowSurface(instance, window, nullptr, &surface) != VK_SUCCESS)
    return error = "glfwCreateWindowSurface failed", false;
  return true;
}

bool VulkanWindow::Impl::make_device(std::string& error) {
  uint32_t n = 0;
  vkEnumeratePhysicalDevices(instance, &n, nullptr);
  std::vector<VkPhysicalDevice> gpus(n);
  vkEnumeratePhysicalDevices(instance, &n, gpus.data());
  // The first Vulkan 1.3 device with a queue that draws and presents; a discrete GPU first.
  std::stable_sort(gpus.begin(), gpus.end(), [](VkPhysicalDevice a, VkPhysicalDevice b) {
    VkPhysicalDeviceProperties pa, pb;
    vkGetPhysicalDeviceProperties(a, &pa), vkGetPhysicalDeviceProperties(b, &pb);
    return pa.deviceType == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU &&
           pb.deviceType != VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  });
  for (VkPhysicalDevice candidate : gpus) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(candidate, &props);
    if (props.apiVersion < VK_API_VERSION_1_3 || !has_extension(candidate, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) continue;
    uint32_t qn = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &qn, nullptr);
    std::vector<VkQueueFamilyProperties> families(qn);
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &qn, families.data());
    for (uint32_t f = 0; f < qn && !gpu; ++f) {
      VkBool32 present = VK_FALSE;
      vkGetPhysicalDeviceSurfaceSupportKHR(candidate, f, surface, &present);
      if ((families[f].queueFlags & VK_QUEUE_GRAPHICS_BIT) && present) {
        gpu = candidate, family = f;
        timestamp_period = families[f].timestampValidBits ? props.limits.timestampPeriod : 0.0f;
      }
    }
    if (gpu) break;
  }
  if (!gpu) return error = "no Vulkan 1.3 device can draw and present to this window", false;
  // Everything the device supports is enabled, and fxkit is told so through created_with.
  features.pNext = &features11;
  features11.pNext = &features12;
  features12.pNext = &features13;
  vkGetPhysicalDeviceFeatures2(gpu, &features);
  features.features.robustBufferAccess = VK_FALSE;  // costs speed, catches nothing fxkit needs
  if (!features13.dynamicRendering || !features13.synchronization2)
    return error = "the device lacks dynamic rendering or synchronization2", false;
  extensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  if (has_extension(gpu, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
    extensions.push_back(VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
  queue_info.queueFamilyIndex = family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  device_info.pNext = &features;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  device_info.enabledExtensionCount = uint32_t(extensions.size());
  device_info.ppEnabledExtensionNames = extensions.data();
  if (vkCreateDevice(gpu, &device_info, nullptr, &device) != VK_SUCCESS) return error = "vkCreateDevice failed", false;
  vkGetDeviceQueue(device, family, 0, &queue);
  slots.resize(options.frames_in_flight);
  for (Slot& s : slots) {
    VkCommandPoolCreateInfo pool = vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = family;
    vkCreateCommandPool(device, &pool, nullptr, &s.pool);
    VkCommandBufferAllocateInfo alloc =
        vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = s.pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    vkAllocateCommandBuffers(device, &alloc, &s.cmd);
    VkFenceCreateInfo fence = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    fence.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    vkCreateFence(device, &fence, nullptr, &s.done);
    VkSemaphoreCreateInfo sem = vk_struct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    vkCreateSemaphore(device, &sem, nullptr, &s.acquired);
  }
  return true;
}

bool VulkanWindow::Impl::make_swapchain(std::string& error) {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window, &w, &h);
  if (w == 0 || h == 0) return false;  // minimised
  VkSurfaceCapabilitiesKHR caps;
  vkGetPhysicalDeviceSurfaceCapabilitiesKHR(gpu, surface, &caps);
  uint32_t fn = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &fn, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(fn);
  vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &fn, formats.data());
  // UNORM, as fxkit's offscreen images: the effect's colours are written as they are.
  auto unorm = std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
    return f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM;
  });
  const VkSurfaceFormatKHR chosen = unorm != formats.end() ? *unorm : formats.at(0);
  if (generation > 0 && chosen.format != color_format) return error = "the surface format changed", false;
  color_format = chosen.format, color_space = chosen.colorSpace;
  extent = caps.currentExtent.width != UINT32_MAX
               ? caps.currentExtent
               : VkExtent2D{std::clamp(uint32_t(w), caps.minImageExtent.width, caps.maxImageExtent.width),
                            std::clamp(uint32_t(h), caps.minImageExtent.height, caps.maxImageExtent.height)};
  VkSwapchainCreateInfoKHR info = vk_struct<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
  info.surface = surface;
  info.minImageCount = std::max(caps.minImageCount, 2u);
  if (caps.maxImageCount) info.minImageCount = std::min(info.minImageCount + 1, caps.maxImageCount);
  info.imageFormat = color_format;
  info.imageColorSpace = color_space;
  info.imageExtent = extent;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain;
  VkSwapchainKHR made = VK_NULL_HANDLE;
  if (vkCreateSwapchainKHR(device, &info, nullptr, &made) != VK_SUCCESS)
    return error = "vkCreateSwapchainKHR failed", false;
  destroy_swapchain();
  swapchain = made;
  uint32_t n = 0;
  vkGetSwapchainImagesKHR(device, swapchain, &n, nullptr);
  images.resize(n);
  vkGetSwapchainImagesKHR(device, swapchain, &n, images.data());
  for (VkImage image : images) {
    VkImageViewCreateInfo v = vk_struct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    v.image = image;
    v.viewType = VK_IMAGE_VIEW_TYPE_2D;
    v.format = color_format;
    v.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCreateImageView(device, &v, nullptr, &views.emplace_back());
    VkSemaphoreCreateInfo sem = vk_struct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    vkCreateSemaphore(device, &sem, nullptr, &rendered.emplace_back());
  }
  VkImageCreateInfo d = vk_struct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  d.imageType = VK_IMAGE_TYPE_2D;
  d.format = depth_format;
  d.extent = {extent.width, extent.height, 1};
  d.mipLevels = d.arrayLayers = 1;
  d.samples = VK_SAMPLE_COUNT_1_BIT;
  d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  vkCreateImage(device, &d, nullptr, &depth);
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device, depth, &req);
  VkMemoryAllocateInfo alloc = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  vkAllocateMemory(device, &alloc, nullptr, &depth_memory);
  vkBindImageMemory(device, depth, depth_memory, 0);
  VkImageViewCreateInfo dv = vk_struct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  dv.image = depth;
  dv.viewType = VK_IMAGE_VIEW_TYPE_2D;
  dv.format = depth_format;
  dv.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
  vkCreateImageView(device, &dv, nullptr, &depth_view);
  ++generation;
  return true;
}

void VulkanWindow::Impl::destroy_swapchain() {
  if (!device) return;
  vkDeviceWaitIdle(device);
  for (VkImageView v : views) vkDestroyImageView(device, v, nullptr);
  for (VkSemaphore s : rendered) vkDestroySemaphore(device, s, nullptr);
  views.clear(), rendered.clear(), images.clear();
  if (depth_view) vkDestroyImageView(device, depth_view, nullptr);
  if (depth) vkDestroyImage(device, depth, nullptr);
  if (depth_memory) vkFreeMemory(device, depth_memory, nullptr);
  depth_view = VK_NULL_HANDLE, depth = VK_NULL_HANDLE, depth_memory = VK_NULL_HANDLE;
  if (swapchain) vkDestroySwapchainKHR(device, swapchain, nullptr);
  swapchain = VK_NULL_HANDLE;
}

void VulkanWindow::Impl::barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                                 VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src,
                                 VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst) {
  VkImageMemoryBarrier2 b = vk_struct<VkImageMemoryBarrier2>(VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
  b.srcStageMask = src_stage, b.srcAccessMask = src, b.dstStageMask = dst_stage, b.dstAccessMask = dst;
  b.oldLayout = from, b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {aspect, 0, 1, 0, 1};
  VkDependencyInfo dep = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

std::unique_ptr<VulkanWindow> VulkanWindow::create(const WindowOptions& options, std::string& error) {
  if (!glfwInit()) return error = "glfwInit failed (no display? run under xvfb-run)", nullptr;
  if (!glfwVulkanSupported()) return error = "GLFW finds no Vulkan loader", nullptr;
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  impl->window = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
  if (!impl->window) return error = "glfwCreateWindow failed", nullptr;
  std::unique_ptr<VulkanWindow> w(new VulkanWindow(std::move(impl)));
  Impl& s = *w->impl_;
  if (!s.make_instance(error) || !s.make_device(error)) return nullptr;
  if (!s.make_swapchain(error)) return error = error.empty() ? "the window has no size" : error, nullptr;
  return w;
}

VulkanWindow::VulkanWindow(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

VulkanWindow::~VulkanWindow() {
  Impl& s = *impl_;
  if (s.device) {
    s.destroy_swapchain();
    for (auto& slot : s.slots) {
      vkDestroyCommandPool(s.device, slot.pool, nullptr);
      vkDestroyFence(s.device, slot.done, nullptr);
      vkDestroySemaphore(s.device, slot.acquired, nullptr);
    }
    if (s.readback) vkDestroyBuffer(s.device, s.readback, nullptr);
    if (s.readback_memory) vkFreeMemory(s.device, s.readback_memory, nullptr);
    vkDestroyDevice(s.device, nullptr);
  }
  if (s.surface) vkDestroySurfaceKHR(s.instance, s.surface, nullptr);
  if (s.messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(s.instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(s.instance, s.messenger, nullptr);
  }
  if (s.instance) vkDestroyInstance(s.instance, nullptr);
  if (s.window) glfwDestroyWindow(s.window);
  glfwTerminate();
}

GLFWwindow* VulkanWindow::glfw() const { return impl_->window; }
VkInstance VulkanWindow::instance() const { return impl_->instance; }
VkPhysicalDevice VulkanWindow::physical_device() const { return impl_->gpu; }
VkDevice VulkanWindow::device() const { return impl_->device; }
VkQueue VulkanWindow::queue() const { return impl_->queue; }
uint32_t VulkanWindow::queue_family() const { return impl_->family; }
const VkDeviceCreateInfo* VulkanWindow::created_with() const { return &impl_->device_info; }
VkFormat VulkanWindow::color_format() const { return impl_->color_format; }
VkFormat VulkanWindow::depth_format() const { return impl_->depth_format; }
uint32_t VulkanWindow::image_count() const { return uint32_t(impl_->images.size()); }
VkImageView VulkanWindow::image_view(uint32_t image) const { return impl_->views.at(image); }
VkImageView VulkanWindow::depth_view() const { return impl_->depth_view; }
uint64_t VulkanWindow::swapchain_generation() const { return impl_->generation; }
float VulkanWindow::timestamp_period_ns() const { return impl_->timestamp_period; }
uint32_t VulkanWindow::validation_messages() const { return impl_->validation_count; }
void VulkanWindow::wait_idle() { vkDeviceWaitIdle(impl_->device); }

bool VulkanWindow::begin_frame(WindowFrame& frame) {
  Impl& s = *impl_;
  Impl::Slot& slot = s.slots[s.next_slot];
  vkWaitForFences(s.device, 1, &slot.done, VK_TRUE, UINT64_MAX);
  std::string error;
  if (!s.swapchain && !s.make_swapchain(error)) return false;
  VkResult acquired =
      vkAcquireNextImageKHR(s.device, s.swapchain, UINT64_MAX, slot.acquired, VK_NULL_HANDLE, &frame.image);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    if (!s.make_swapchain(error)) return false;
    acquired = vkAcquireNextImageKHR(s.device, s.swapchain, UINT64_MAX, slot.acquired, VK_NULL_HANDLE, &frame.image);
  }
  if (acquired != VK_SUCCESS && acquired != VK_SUBOPTIMAL_KHR) return false;
  vkResetFences(s.device, 1, &slot.done);
  vkResetCommandBuffer(slot.cmd, 0);
  VkCommandBufferBeginInfo begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  vkBeginCommandBuffer(slot.cmd, &begin);
  frame.cmd = slot.cmd, frame.slot = s.next_slot, frame.extent = s.extent;
  return true;
}

void VulkanWindow::begin_scene(const WindowFrame& frame, const float clear[4]) {
  Impl& s = *impl_;
  s.barrier(frame.cmd, s.images[frame.image], VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, 0,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  s.barrier(frame.cmd, s.depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
            VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT,
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
  VkRenderingAttachmentInfo color = vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  color.imageView = s.views[frame.image];
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  std::copy_n(clear, 4, color.clearValue.color.float32);
  VkRenderingAttachmentInfo depth = vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  depth.imageView = s.depth_view;
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo info = vk_struct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  info.renderArea = {{0, 0}, frame.extent};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &color;
  info.pDepthAttachment = &depth;
  vkCmdBeginRendering(frame.cmd, &info);
}

void VulkanWindow::end_scene(const WindowFrame& frame) { vkCmdEndRendering(frame.cmd); }

void VulkanWindow::capture(const WindowFrame& frame, bool with_ui) {
  Impl& s = *impl_;
  const VkDeviceSize size = VkDeviceSize(frame.extent.width) * frame.extent.height * 4;
  if (size > s.readback_size) {
    if (s.readback) vkDestroyBuffer(s.device, s.readback, nullptr), vkFreeMemory(s.device, s.readback_memory, nullptr);
    VkBufferCreateInfo b = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
    b.size = size;
    b.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    vkCreateBuffer(s.device, &b, nullptr, &s.readback);
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(s.device, s.readback, &req);
    VkMemoryAllocateInfo alloc = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        s.memory_type(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    vkAllocateMemory(s.device, &alloc, nullptr, &s.readback_memory);
    vkBindBufferMemory(s.device, s.readback, s.readback_memory, 0);
    s.readback_size = size;
  }
  VkImage image = s.images[frame.image];
  // The scene pass leaves the image a colour attachment; the UI pass leaves it for presenting.
  const VkImageLayout layout = with_ui ? VK_IMAGE_LAYOUT_PRESENT_SRC_KHR : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  s.barrier(frame.cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {frame.extent.width, frame.extent.height, 1};
  vkCmdCopyImageToBuffer(frame.cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, s.readback, 1, &region);
  if (with_ui)
    s.barrier(frame.cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
              VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);
  else
    s.barrier(frame.cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
              VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
              VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  s.captured = frame.extent;
}

bool VulkanWindow::end_frame(const WindowFrame& frame) {
  Impl& s = *impl_;
  Impl::Slot& slot = s.slots[frame.slot];
  vkEndCommandBuffer(frame.cmd);
  const VkPipelineStageFlags wait = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSubmitInfo submit = vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &slot.acquired;
  submit.pWaitDstStageMask = &wait;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &frame.cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &s.rendered[frame.image];
  if (vkQueueSubmit(s.queue, 1, &submit, slot.done) != VK_SUCCESS) return false;
  VkPresentInfoKHR present = vk_struct<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &s.rendered[frame.image];
  present.swapchainCount = 1;
  present.pSwapchains = &s.swapchain;
  present.pImageIndices = &frame.image;
  const VkResult presented = vkQueuePresentKHR(s.queue, &present);
  s.next_slot = (s.next_slot + 1) % uint32_t(s.slots.size());
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    std::string error;
    s.make_swapchain(error);
  }
  return presented == VK_SUCCESS || presented == VK_SUBOPTIMAL_KHR || presented == VK_ERROR_OUT_OF_DATE_KHR;
}

std::vector<uint8_t> VulkanWindow::read_screenshot(uint32_t& width, uint32_t& height) const {
  const Impl& s = *impl_;
  width = s.captured.width, height = s.captured.height;
  std::vector<uint8_t> rgba(size_t(width) * height * 4);
  if (rgba.empty()) return rgba;
  void* mapped = nullptr;
  vkMapMemory(s.device, s.readback_memory, 0, VK_WHOLE_SIZE, 0, &mapped);
  std::memcpy(rgba.data(), mapped, rgba.size());
  vkUnmapMemory(s.device, s.readback_memory);
  if (s.color_format == VK_FORMAT_B8G8R8A8_UNORM)
    for (size_t i = 0; i < rgba.size(); i += 4) std::swap(rgba[i], rgba[i + 2]);
  return rgba;
}
