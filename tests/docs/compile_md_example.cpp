// docs/preprocessor.md, docs/effect-compilation.md and docs/shader-compilation.md: the
// front end and the compiler on their own, without a device.
// The examples are the docs' text, verbatim (examples_compiled_test.cpp): not reformatted.
// clang-format off
#include "example_fixture.h"
#include "fx/compile/compile_workers.h"
#include "fx/compile/effect_file.h"
#include "fx/compile/effect_programs.h"
#include "fx/compile/effect_units.h"
#include "fx/compile/program_link.h"
#include "fx/compile/shader_compiler.h"
#include "fx/compile/shader_message.h"
#include "fx/compile/spirv_cache.h"
#include "fx/frontend.h"
#include "fx/preprocessor.h"

namespace fx::docs {
namespace {

TEST_F(ExampleTest, Preprocessing) {
  std::vector<std::string> watched;
  auto watch = [&](const std::string& f) { watched.push_back(f); };

  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  fx::Preprocessor pp(sm, diags, {.include_dirs = {"effects"},
                                  .defines = {fx::parse_define("QUALITY=2")}});
  std::vector<fx::Token> tokens;               // ends with one eof token
  bool ok = pp.run_file("effects/strand_aniso.fx", tokens);
  for (const std::string& f : pp.files()) watch(f);   // include graph: pp.includes()

  EXPECT_TRUE(ok);
  EXPECT_GE(watched.size(), 3u);  // the effect, common.fxh, generated/costs.fxh
}

TEST_F(ExampleTest, EffectCompilation) {
  fx::DiagnosticSink diags;
  fx::FrontEndOptions options;
  size_t used = 0, reported = 0;
  auto use = [&](const std::vector<fx::StageProgram>& stages, const fx::ProgramLayout&) { used = stages.size(); };
  auto report = [&](const std::string&) { ++reported; };

  auto file = fx::EffectFile::parse("effects/wood.fx", options, diags);  // the front end
  fx::SpirvCache cache(".fxkit-cache");                 // memory + optional directory
  fx::ShaderCompiler compiler({}, &cache);
  file->build_programs(diags, &compiler);              // units and lazily compiled programs
  const fx::PassProgram* p = file->programs->program("wood", "p0");  // compiles only this pass
  if (p && p->ok()) use(p->stages, p->layout);
  if (p) for (const std::string& why : p->unsupported) report(why);  // asm, fixed function

  EXPECT_EQ(used, 2u);
  EXPECT_EQ(reported, 0u);
  EXPECT_FALSE(diags.has_errors());
}

TEST_F(ExampleTest, ShaderCompilation) {
  fx::SourceManager sm;
  fx::DiagnosticSink sink;
  fx::ParsedEffect parsed = fx::parse_effect_file("effects/wood.fx", sm, sink);
  fx::EffectUnits units(parsed.ast, sm, sink);
  const fx::EffectPass& pass = units.passes().front();
  const fx::TranslationUnit vs_unit = *units.unit(*pass.find(fx::ShaderStage::vertex));
  const fx::TranslationUnit ps_unit = *units.unit(*pass.find(fx::ShaderStage::fragment));

  fx::SpirvCache cache(".fxkit-cache");                 // optional; memory only if no path
  fx::ShaderCompiler compiler({.target = fx::VulkanTarget::vulkan_1_1}, &cache);
  fx::CompiledShader vs = fx::compile_and_report(compiler, vs_unit, fx::resolver_for(sm), sink);
  fx::CompiledShader ps = fx::compile_and_report(compiler, ps_unit, fx::resolver_for(sm), sink);
  fx::ProgramLayout layout = fx::link_program({&vs, &ps}, sink);  // shared bindings, varyings

  EXPECT_FALSE(sink.has_errors());
  EXPECT_FALSE(vs.spirv.empty());
  EXPECT_FALSE(layout.bindings.empty());
}

TEST_F(ExampleTest, CompileWorkers) {
  fx::SourceManager sm;
  fx::DiagnosticSink sink;
  fx::ParsedEffect parsed = fx::parse_effect_file("effects/wood.fx", sm, sink);
  fx::EffectUnits units(parsed.ast, sm, sink);
  const fx::TranslationUnit vs_unit = *units.unit(*units.passes().front().find(fx::ShaderStage::vertex));
  fx::SpirvCache cache;

  std::string error;
  auto workers = fx::CompileWorkers::start({.workers = 2}, error);  // nullptr + error if not found
  fx::ShaderCompiler compiler({}, &cache, workers.get());          // compile() is unchanged

  ASSERT_TRUE(workers) << error;
  fx::CompiledShader vs = compiler.compile(vs_unit);
  EXPECT_TRUE(vs.ok) << vs.info_log;
  EXPECT_EQ(workers->stats().compiles, 1u);
}

}  // namespace
}  // namespace fx::docs
