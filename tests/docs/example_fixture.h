// What the compiled examples share: the validated Context of the Vulkan suites, and a
// scratch working directory per test holding a link to the repository's effects/, so
// examples name "effects/..." as an application would and what they write (PNGs, SPIR-V
// caches) lands in the scratch folder.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

#include "../vulkan/vulkan_fixture.h"

namespace fx::docs {

class ExampleTest : public fx::vk::testing::VulkanTest {
 protected:
  void SetUp() override {
    VulkanTest::SetUp();
    namespace fs = std::filesystem;
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    scratch_ = fs::temp_directory_path() / ("fxkit-docs-" + std::to_string(getpid()) + "-" + test->name());
    fs::remove_all(scratch_);
    fs::create_directories(scratch_);
    fs::create_directory_symlink(fs::path(FXKIT_SOURCE_DIR) / "effects", scratch_ / "effects");
    previous_ = fs::current_path();
    fs::current_path(scratch_);
  }
  void TearDown() override {
    std::filesystem::current_path(previous_);
    std::filesystem::remove_all(scratch_);  // removes the link, not the effects
    VulkanTest::TearDown();
  }

 private:
  std::filesystem::path scratch_, previous_;
};

}  // namespace fx::docs
