// Every effect in tests/compile/data/fxc_accepts is one rule of the native compiler (the
// file's first comment): it checks with no error, and every stage of every pass compiles
// to SPIR-V that spirv-val accepts and links with its pass.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "compile_test_util.h"
#include "fx/compile/effect_programs.h"
#include "fx/diagnostic_render.h"
#include "fx/frontend.h"

namespace fx {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> rule_files() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(FXKIT_SOURCE_DIR) / "tests/compile/data/fxc_accepts"))
    if (e.path().extension() == ".fx") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  return files;
}

class FxcAccepts : public ::testing::TestWithParam<std::string> {};

TEST_P(FxcAccepts, ChecksCleanAndEveryStageCompilesToValidSpirv) {
  const fs::path path = fs::path(FXKIT_SOURCE_DIR) / "tests/compile/data/fxc_accepts" / GetParam();
  SourceManager sm;
  DiagnosticSink diags;
  ParsedEffect parsed = parse_effect_file(path.string(), sm, diags, {});
  EffectUnits units(parsed.ast, sm, diags);
  ASSERT_FALSE(diags.has_errors()) << render_text(diags.diagnostics(), sm);
  ASSERT_FALSE(units.passes().empty());
  ShaderCompiler compiler;
  EffectPrograms programs(units, compiler, sm);
  for (const EffectPass& pass : units.passes()) {
    const PassProgram& p = programs.program(pass);
    EXPECT_TRUE(p.unsupported.empty()) << pass.technique << "." << pass.pass << ": " << p.unsupported.front();
    EXPECT_FALSE(p.stages.empty()) << pass.technique << "." << pass.pass;
    for (const StageProgram& s : p.stages) {
      ASSERT_TRUE(s.shader.ok) << pass.technique << "." << pass.pass << " " << to_string(s.stage) << "\n"
                               << render_text(s.diagnostics, sm) << "\n"
                               << s.unit.source;
      EXPECT_EQ(test::spirv_val(s.shader.spirv), "") << pass.technique << "." << pass.pass;
      // Reflection names what the effect declares, whatever the unit renamed for glslang.
      std::vector<std::string> names;
      for (const UniformBlock& b : s.shader.reflection.uniform_blocks)
        for (const BlockMember& m : b.members) names.push_back(m.name);
      for (const ImageBinding& i : s.shader.reflection.images) names.push_back(i.name);
      for (const InterfaceVariable& v : s.shader.reflection.inputs) names.push_back(v.name);
      for (const std::string& n : names) EXPECT_EQ(n.find("__fx"), std::string::npos) << n;
      // Every resource has a binding of its own in the module (D3D counts t#, s#, b#, u# apart).
      std::map<uint32_t, std::string> owner;
      for (const auto& [name, binding] : test::spirv_bindings(s.shader.spirv)) {
        auto [it, fresh] = owner.emplace(binding, name);
        EXPECT_TRUE(fresh) << name << " and " << it->second << " share binding " << binding;
      }
    }
    EXPECT_TRUE(p.compiled) << pass.technique << "." << pass.pass << "\n" << render_text(p.diagnostics, sm);
    // The other elements of a shader array the pass indexes.
    for (const StageUnit& stage : pass.stages)
      for (const StageUnit& choice : stage.choices) {
        std::optional<StageProgram> s = programs.compile_alone(choice);
        ASSERT_TRUE(s) << choice.unsupported;
        EXPECT_TRUE(s->shader.ok) << choice.function << "\n" << render_text(s->diagnostics, sm);
      }
  }
}

INSTANTIATE_TEST_SUITE_P(Rules, FxcAccepts, ::testing::ValuesIn(rule_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = fs::path(info.param).stem().string();
                           std::replace_if(
                               name.begin(), name.end(),
                               [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
                           return name;
                         });

}  // namespace
}  // namespace fx
