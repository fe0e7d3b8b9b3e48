// Selection and rendering agree: every technique that validation on this device calls valid
// (what `fxkit select --caps device` prints) is one the binding draws (what `fxkit render`
// runs), and every one it rejects is one the binding refuses, for every effect of effects/,
// every rule file of tests/compile/data/fxc_accepts/ and the seams of tests/vulkan/data/.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "effect_test_util.h"
#include "fx/binding/context_caps.h"
#include "fx/select/technique_validation.h"

namespace fx::vk::testing {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> effect_files() {
  std::vector<std::string> out;
  const std::string root = FXKIT_SOURCE_DIR;
  for (const char* dir : {"/effects", "/tests/compile/data/fxc_accepts", "/tests/vulkan/data"})
    for (const auto& e : fs::directory_iterator(root + dir))
      if (e.path().extension() == ".fx") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

class SelectRenderAgreement : public VulkanTest, public ::testing::WithParamInterface<std::string> {};

TEST_P(SelectRenderAgreement, ValidTechniquesAreTheDrawableOnes) {
  // An effect that does not load is refused by both alike (they load it the same way).
  DiagnosticSink load;
  FrontEndOptions options;
  options.preprocessor.include_dirs = {effects_dir()};
  if (!EffectFile::load(GetParam(), options, load)) return;
  auto r = bind_effect(ctx(), GetParam());
  ASSERT_TRUE(r);
  const DeviceCaps caps = context_caps(ctx());
  const std::vector<TechniqueValidation> validation =
      validate_techniques(*r->effect->model, caps, {.programs = r->effect->programs.get()});
  ASSERT_EQ(validation.size(), r->binding->technique_count());
  for (uint32_t t = 0; t < validation.size(); ++t) {
    std::string why;
    for (const Diagnostic& d : validation[t].reasons) why += d.message + "; ";
    EXPECT_EQ(validation[t].valid, r->binding->technique_ok(t))
        << validation[t].name << ": select says " << (validation[t].valid ? "valid" : "invalid: " + why)
        << ", render says " << (r->binding->technique_ok(t) ? "drawable" : r->binding->technique_reason(t));
  }
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = fs::path(info.param).stem().string();
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Effects, SelectRenderAgreement, ::testing::ValuesIn(effect_files()), test_name);

}  // namespace
}  // namespace fx::vk::testing
