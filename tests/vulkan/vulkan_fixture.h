// Shared test fixture: one validated Context per test suite; every test fails if the
// validation layers reported an error while it ran.
#pragma once
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "fx/diagnostic.h"
#include "fx/vulkan/context.h"

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

class VulkanTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    DiagnosticSink sink;
    ContextOptions options;
    options.validation = true;
    context_storage() = Context::headless(options, sink);
    ASSERT_TRUE(context_storage().has_value()) << describe(sink);
  }
  static void TearDownTestSuite() { context_storage().reset(); }

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

}  // namespace fx::vk::testing
