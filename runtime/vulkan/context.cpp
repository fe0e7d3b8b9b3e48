// Context creation (headless or wrapped), teardown and queries.
#include "fx/vulkan/context.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "device_query.h"
#include "fx/vulkan/vk_check.h"
#include "validation_log.h"

namespace fx::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  layers.resize(count);
  return std::any_of(layers.begin(), layers.end(),
                     [name](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool has_instance_extension(const char* name, const char* layer = nullptr) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
  std::vector<VkExtensionProperties> exts(count);
  vkEnumerateInstanceExtensionProperties(layer, &count, exts.data());
  exts.resize(count);
  return std::any_of(exts.begin(), exts.end(),
                     [name](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

}  // namespace

// Owns partially created handles so every early return cleans up.
struct ContextBuilder {
  Context ctx;

  std::optional<Context> fail() { return std::nullopt; }  // ctx's destructor releases handles

  bool create_instance(const ContextOptions& options, DiagnosticSink& sink) {
    uint32_t version = 0;
    if (vkEnumerateInstanceVersion(&version) != VK_SUCCESS || version < VK_API_VERSION_1_3) {
      sink.error("vk-instance-too-old", {},
                 "the Vulkan loader supports version " + std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
                     std::to_string(VK_API_VERSION_MINOR(version)) + "; fxkit needs 1.3");
      return false;
    }
    std::vector<const char*> layers, extensions;
    bool validation = false;
    if (options.validation) {
      if (!has_layer(kValidationLayer)) {
        sink.warning("vk-validation-unavailable", {},
                     std::string(kValidationLayer) + " is not installed; continuing without validation");
      } else if (!has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME) &&
                 !has_instance_extension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, kValidationLayer)) {
        sink.warning("vk-validation-unavailable", {},
                     "VK_EXT_debug_utils is unavailable; continuing without validation");
      } else {
        validation = true;
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
      }
    }
    VkInstanceCreateFlags flags = 0;
    if (has_instance_extension(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
      // Lets the loader list portability drivers (MoltenVK) too.
      extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
      flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    }

    VkApplicationInfo app = structure<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = options.application_name.c_str();
    app.pEngineName = "fxkit";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info = structure<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.flags = flags;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{};
    if (validation) {
      ctx.log_ = std::make_unique<ValidationLog>(options.on_validation_message);
      // Chained so instance creation and destruction are validated too.
      messenger_info = messenger_create_info(ctx.log_.get(), options.validation_info);
      info.pNext = &messenger_info;
    }
    if (!check(vkCreateInstance(&info, nullptr, &ctx.instance_), sink, "vkCreateInstance")) return false;
    ctx.owned_ = true;
    if (validation) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(ctx.instance_, "vkCreateDebugUtilsMessengerEXT"));
      if (!create || !check(create(ctx.instance_, &messenger_info, nullptr, &ctx.messenger_), sink,
                            "vkCreateDebugUtilsMessengerEXT"))
        return false;
    }
    return true;
  }

  std::optional<DeviceSupport> pick_device(const ContextOptions& options, DiagnosticSink& sink) {
    uint32_t count = 0;
    if (!check(vkEnumeratePhysicalDevices(ctx.instance_, &count, nullptr), sink, "vkEnumeratePhysicalDevices"))
      return std::nullopt;
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(ctx.instance_, &count, devices.data());
    devices.resize(count);
    std::vector<DeviceSupport> supports;
    std::vector<DeviceCandidate> candidates;
    for (uint32_t i = 0; i < count; ++i) {
      supports.push_back(query_device(devices[i], i));
      const DeviceSupport& s = supports.back();
      candidates.push_back({s.info.name, s.info.type, s.info.api_version, s.has_graphics_queue});
    }
    auto chosen = select_device(candidates, device_request(options.device), sink);
    if (!chosen) return std::nullopt;
    ctx.physical_device_ = devices[*chosen];
    return std::move(supports[*chosen]);
  }

  bool create_device(const ContextOptions& options, const DeviceSupport& support, DiagnosticSink& sink) {
    FeatureChain chain(support);
    for (const std::string& name : options.device_extensions) {
      if (!support.has_extension(name)) {
        sink.error("vk-extension-missing", {}, "device '" + support.info.name + "' does not support extension " + name);
        return false;
      }
      bool already =
          std::any_of(chain.extensions.begin(), chain.extensions.end(), [&](const char* e) { return name == e; });
      if (!already) chain.extensions.push_back(name.c_str());
    }
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue = structure<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queue.queueFamilyIndex = support.graphics_family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info = structure<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
    info.pNext = &chain.head;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = uint32_t(chain.extensions.size());
    info.ppEnabledExtensionNames = chain.extensions.data();
    if (!check(vkCreateDevice(ctx.physical_device_, &info, nullptr, &ctx.device_), sink, "vkCreateDevice"))
      return false;
    ctx.queue_family_ = support.graphics_family;
    vkGetDeviceQueue(ctx.device_, ctx.queue_family_, 0, &ctx.queue_);
    ctx.info_ = support.info;
    ctx.features_ = chain.enabled;
    ctx.functions_ = load_device_functions(ctx.instance_, ctx.device_, chain.enabled, ctx.messenger_ != VK_NULL_HANDLE);
    vkGetPhysicalDeviceMemoryProperties(ctx.physical_device_, &ctx.memory_);
    return true;
  }
};

std::optional<Context> Context::headless(const ContextOptions& options, DiagnosticSink& sink) {
  ContextBuilder b;
  if (!b.create_instance(options, sink)) return b.fail();
  auto support = b.pick_device(options, sink);
  if (!support) return b.fail();
  if (!b.create_device(options, *support, sink)) return b.fail();
  return std::move(b.ctx);
}

Context Context::wrap(VkInstance instance, VkPhysicalDevice physical_device, VkDevice device, VkQueue queue,
                      uint32_t queue_family, std::optional<DeviceFeatures> enabled) {
  Context ctx;
  ctx.instance_ = instance;
  ctx.physical_device_ = physical_device;
  ctx.device_ = device;
  ctx.queue_ = queue;
  ctx.queue_family_ = queue_family;
  ctx.owned_ = false;
  DeviceSupport support = query_device(physical_device, 0);
  // Recover the enumeration index so info().index means the same as for headless contexts.
  uint32_t count = 0;
  if (instance && vkEnumeratePhysicalDevices(instance, &count, nullptr) == VK_SUCCESS) {
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    for (uint32_t i = 0; i < count && i < devices.size(); ++i)
      if (devices[i] == physical_device) support.info.index = i;
  }
  ctx.info_ = support.info;
  ctx.features_ = enabled ? *enabled : support.features;
  ctx.functions_ = load_device_functions(instance, device, ctx.features_, false);
  vkGetPhysicalDeviceMemoryProperties(physical_device, &ctx.memory_);
  return ctx;
}

Context::Context(Context&& other) noexcept { *this = std::move(other); }

Context& Context::operator=(Context&& other) noexcept {
  if (this == &other) return *this;
  destroy();
  instance_ = std::exchange(other.instance_, VK_NULL_HANDLE);
  physical_device_ = std::exchange(other.physical_device_, VK_NULL_HANDLE);
  device_ = std::exchange(other.device_, VK_NULL_HANDLE);
  queue_ = std::exchange(other.queue_, VK_NULL_HANDLE);
  queue_family_ = other.queue_family_;
  owned_ = std::exchange(other.owned_, false);
  messenger_ = std::exchange(other.messenger_, VK_NULL_HANDLE);
  log_ = std::move(other.log_);
  info_ = other.info_;
  features_ = other.features_;
  functions_ = other.functions_;
  memory_ = other.memory_;
  return *this;
}

Context::~Context() { destroy(); }

void Context::destroy() {
  if (owned_) {
    if (device_) {
      vkDeviceWaitIdle(device_);
      vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
      auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
      if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
  }
  instance_ = VK_NULL_HANDLE;
  physical_device_ = VK_NULL_HANDLE;
  device_ = VK_NULL_HANDLE;
  queue_ = VK_NULL_HANDLE;
  messenger_ = VK_NULL_HANDLE;
  owned_ = false;
}

bool Context::supports_format(VkFormat format, VkFormatFeatureFlags features) const {
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(physical_device_, format, &props);
  return (props.optimalTilingFeatures & features) == features;
}

VkFormat Context::best_depth_format(bool need_stencil) const {
  const VkFormat order[] = {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT,
                            VK_FORMAT_D16_UNORM};
  for (VkFormat f : order) {
    bool has_stencil = f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D32_SFLOAT_S8_UINT;
    if (need_stencil && !has_stencil) continue;
    if (supports_format(f, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)) return f;
  }
  return VK_FORMAT_UNDEFINED;
}

bool Context::validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }

std::vector<ValidationMessage> Context::validation_messages() const {
  return log_ ? log_->messages() : std::vector<ValidationMessage>{};
}

size_t Context::validation_error_count() const { return log_ ? log_->error_count() : 0; }

size_t Context::validation_warning_count() const { return log_ ? log_->warning_count() : 0; }

void Context::clear_validation_messages() {
  if (log_) log_->clear();
}

void Context::drain_validation_into(DiagnosticSink& sink) {
  if (!log_) return;
  for (ValidationMessage& m : log_->take())
    sink.report(m.severity, "vk-validation", {}, (m.id_name.empty() ? "" : "[" + m.id_name + "] ") + m.text);
}

void Context::set_object_name(VkObjectType type, uint64_t handle, const char* name) const {
  if (!functions_.set_object_name || !device_) return;
  VkDebugUtilsObjectNameInfoEXT info =
      structure<VkDebugUtilsObjectNameInfoEXT>(VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT);
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name;
  functions_.set_object_name(device_, &info);
}

void Context::wait_idle() const {
  if (device_) vkDeviceWaitIdle(device_);
}

}  // namespace fx::vk
