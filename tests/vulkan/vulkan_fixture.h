// Shared test fixture: one validated Context per test suite; every test fails if the
// validation layers reported an error while it ran.
#pragma once
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <link.h>

#include <functional>
#include <optional>
#include <string>

#include "fx/diagnostic.h"
#include "fx/image.h"
#include "fx/vulkan/context.h"
#include "fx/vulkan/texture.h"

namespace fx::vk::testing {

// All recorded validation messages, one per line, for failure output.
inline std::string describe_messages(const Context& ctx) {
  std::string out;
  for (const ValidationMessage& m : ctx.validation_messages())
    out += std::string(to_string(m.severity)) + " " + m.id_name + ": " + m.text + "\n";
  return out;
}

// Diagnostics as text, for failure output.
inline std::string describe(const DiagnosticSink& sink) {
  std::string out;
  for (const Diagnostic& d : sink.diagnostics()) out += d.id + ": " + d.message + "\n";
  return out;
}

// Marks every shared object loaded so far (the ICD, the validation layer) RTLD_NODELETE.
// Drivers keep allocations reachable only from their globals; when the loader dlcloses them
// LeakSanitizer reports those as leaks. Pinned, the memory stays reachable and only real
// leaks are reported. Harmless without sanitizers.
inline void pin_loaded_libraries() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        if (info->dlpi_name && info->dlpi_name[0]) dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}

// Counts validation errors across contexts, including those reported while a context is
// destroyed (leaked objects are reported by vkDestroyDevice).
inline size_t& teardown_validation_errors() {
  static size_t count = 0;
  return count;
}

class VulkanTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    DiagnosticSink sink;
    ContextOptions options;
    options.validation = true;
    options.on_validation_message = [](const ValidationMessage& m) {
      if (m.severity == Severity::error) ++teardown_validation_errors();
    };
    context_storage() = Context::headless(options, sink);
    ASSERT_TRUE(context_storage().has_value()) << describe(sink);
    pin_loaded_libraries();
  }
  static void TearDownTestSuite() {
    size_t before = teardown_validation_errors();
    context_storage().reset();
    EXPECT_EQ(teardown_validation_errors(), before)
        << "validation errors while destroying the device (leaked Vulkan objects?)";
  }

  void SetUp() override {
    ASSERT_TRUE(context_storage().has_value());
    ASSERT_TRUE(ctx().validation_enabled()) << "validation layers are required by the tests";
    ctx().clear_validation_messages();
  }
  void TearDown() override {
    if (!context_storage()) return;
    ctx().wait_idle();
    EXPECT_EQ(ctx().validation_error_count(), 0u) << describe_messages(ctx());
    ctx().clear_validation_messages();
  }

  static Context& ctx() { return *context_storage(); }

 private:
  static std::optional<Context>& context_storage() {
    static std::optional<Context> context;
    return context;
  }
};

// A 1x1 linear texture of colour (red, green, 0, 255).
inline std::optional<Texture> solid_texture(const Context& ctx, uint8_t red, uint8_t green, DiagnosticSink& sink) {
  fx::Image image = fx::Image::blank(1, 1, 4);
  image.pixels = {red, green, 0, 255};
  return Texture::from_image(ctx, image, ColorSpace::linear, sink);
}

}  // namespace fx::vk::testing
