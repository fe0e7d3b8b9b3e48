// DeviceCaps of a Context: what technique validation may assume of the device as it was
// created, not only as its physical device could be.
#pragma once
#include "fx/select/device_caps.h"
#include "fx/vulkan/context.h"

namespace fx::vk {

// The physical device's caps (caps_from_physical_device) without the features SPIR-V
// capabilities need (fx/vulkan/shader_capabilities.h) that the device was created without:
// an application's device (Context::wrap) may not have enabled shaderClipDistance, and a
// technique writing SV_ClipDistance is then invalid on it.
DeviceCaps context_caps(const Context& ctx);

}  // namespace fx::vk
