// vk_struct<T>(type): a zeroed Vulkan struct with its sType, without listing every member
// (which -Wmissing-field-initializers would ask of `T{type}`).
#pragma once
#include <vulkan/vulkan.h>

template <class T>
T vk_struct(VkStructureType type) {
  T t{};
  t.sType = type;
  return t;
}
