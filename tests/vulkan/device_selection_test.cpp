// Device ranking, explicit requests and the FXKIT_DEVICE environment variable.
#include "fx/vulkan/device_selection.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "fx/vulkan/context.h"
#include "vulkan_fixture.h"

namespace fx::vk {
namespace {

using testing::describe;

DeviceCandidate gpu(std::string name, VkPhysicalDeviceType type, uint32_t version = VK_API_VERSION_1_3,
                    bool graphics = true) {
  return {std::move(name), type, version, graphics};
}

const std::vector<DeviceCandidate> kMachine = {
    gpu("llvmpipe (LLVM 15.0.6, 256 bits)", VK_PHYSICAL_DEVICE_TYPE_CPU),
    gpu("Intel(R) UHD Graphics 630", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU),
    gpu("NVIDIA GeForce RTX 3070", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU),
    gpu("Old Radeon", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_1),
};

TEST(SelectDevice, PrefersDiscreteThenIntegratedThenCpu) {
  DiagnosticSink sink;
  EXPECT_EQ(select_device(kMachine, "", sink), 2u);
  std::vector<DeviceCandidate> no_discrete(kMachine.begin(), kMachine.begin() + 2);
  EXPECT_EQ(select_device(no_discrete, "", sink), 1u);
  std::vector<DeviceCandidate> cpu_only(kMachine.begin(), kMachine.begin() + 1);
  EXPECT_EQ(select_device(cpu_only, "", sink), 0u);
  EXPECT_FALSE(sink.has_errors()) << describe(sink);
}

TEST(SelectDevice, SkipsDevicesWithoutVulkan13OrGraphics) {
  DiagnosticSink sink;
  std::vector<DeviceCandidate> devices = {
      gpu("Old Radeon", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_2),
      gpu("Compute card", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, VK_API_VERSION_1_3, false),
      gpu("llvmpipe", VK_PHYSICAL_DEVICE_TYPE_CPU)};
  EXPECT_EQ(select_device(devices, "", sink), 2u);
  devices.pop_back();
  EXPECT_FALSE(select_device(devices, "", sink));
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-no-suitable-device");
  EXPECT_NE(sink.diagnostics()[0].message.find("Compute card"), std::string::npos);
}

TEST(SelectDevice, RequestByIndexOrCaseInsensitiveNameSubstring) {
  DiagnosticSink sink;
  EXPECT_EQ(select_device(kMachine, "0", sink), 0u);
  EXPECT_EQ(select_device(kMachine, "1", sink), 1u);
  EXPECT_EQ(select_device(kMachine, "LLVMPIPE", sink), 0u);
  EXPECT_EQ(select_device(kMachine, "uhd", sink), 1u);
  EXPECT_FALSE(sink.has_errors()) << describe(sink);
}

TEST(SelectDevice, UnknownOrUnusableRequestIsAnErrorListingDevices) {
  DiagnosticSink sink;
  EXPECT_FALSE(select_device(kMachine, "7", sink));
  EXPECT_FALSE(select_device(kMachine, "Voodoo", sink));
  EXPECT_FALSE(select_device(kMachine, "Old Radeon", sink));
  ASSERT_EQ(sink.error_count(), 3u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-device-not-found");
  EXPECT_NE(sink.diagnostics()[1].message.find("2: NVIDIA GeForce RTX 3070 (discrete GPU"), std::string::npos)
      << sink.diagnostics()[1].message;
  EXPECT_EQ(sink.diagnostics()[2].id, "vk-no-suitable-device");
}

// Sets an environment variable for one scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(DeviceRequest, OptionWinsOverEnvironment) {
  ScopedEnv env(kDeviceEnvVar, "from-env");
  EXPECT_EQ(device_request("from-option"), "from-option");
  EXPECT_EQ(device_request(""), "from-env");
}

class DeviceEnvTest : public testing::VulkanTest {};

// The real devices of this machine, forced through FXKIT_DEVICE by index and by name.
TEST_F(DeviceEnvTest, EnvironmentVariableForcesDeviceByIndexAndName) {
  const std::string name = ctx().info().name;
  const std::string index = std::to_string(ctx().info().index);
  for (const std::string& request : {index, name.substr(0, std::min<size_t>(name.size(), 6))}) {
    ScopedEnv env(kDeviceEnvVar, request.c_str());
    DiagnosticSink sink;
    ContextOptions options;
    options.validation = true;
    auto forced = Context::headless(options, sink);
    ASSERT_TRUE(forced) << request << "\n" << describe(sink);
    EXPECT_EQ(forced->info().name.substr(0, 6), name.substr(0, 6)) << request;
    EXPECT_EQ(forced->validation_error_count(), 0u) << testing::describe_messages(*forced);
  }
  ScopedEnv env(kDeviceEnvVar, "no-such-device-anywhere");
  DiagnosticSink sink;
  EXPECT_FALSE(Context::headless({}, sink));
  ASSERT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].id, "vk-device-not-found");
}

}  // namespace
}  // namespace fx::vk
