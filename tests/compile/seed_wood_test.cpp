// The seed's pre-release HLSL wood shader, compiled through the compatibility prelude, and
// the compile timings reported in docs/shader-compilation.md.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "compile_test_util.h"
#include "fx/compile/hlsl_compat.h"
#include "fx/compile/spirv_cache.h"

namespace fx {
namespace {

// The wood effect as the seed document lists it (tests/parser/data/wood.fx: verbatim, its two
// code fences joined), so the test needs only this checkout.
constexpr const char* kWood = FXKIT_SOURCE_DIR "/tests/parser/data/wood.fx";

// The wood effect's code: from "float ringscale" to the end of Wood(). Returns (first line
// number, text).
std::pair<uint32_t, std::string> wood_body() {
  std::ifstream in(kWood);
  std::string line, body;
  uint32_t number = 0, first = 0;
  bool inside = false, in_wood = false;
  while (std::getline(in, line)) {
    ++number;
    if (!inside && line.rfind("float ringscale", 0) == 0) inside = true, first = number;
    if (!inside) continue;
    body += line;
    body += '\n';
    in_wood = in_wood || line.rfind("PS_OUTPUT Wood", 0) == 0;
    if (in_wood && line == "};") break;  // Wood() ends with "};" (structs do too)
  }
  return {first, body};
}

TranslationUnit wood_unit(const std::string& body, uint32_t first_line) {
  TranslationUnit u;
  u.source = std::string(pre_release_hlsl_prelude()) + "#line " + std::to_string(first_line) + " \"wood.fx\"\n" + body;
  u.stage = ShaderStage::fragment;
  u.entry_point = "Wood";
  u.profile = "ps_2_0";
  return u;
}

TEST(SeedWood, AsWrittenReportsWhatCannotBeMapped) {
  auto [first, body] = wood_body();
  ASSERT_GT(first, 0u) << "wood effect not found at " << kWood;
  // The prelude cannot repair source errors: the missing semicolon after diffuse()'s return
  // and reading .a of the vec3 COLOR0 input. glslang reports them at the file's own lines.
  CompiledShader r = ShaderCompiler().compile(wood_unit(body, first));
  EXPECT_FALSE(r.ok);
  std::string log = test::messages_of(r);
  EXPECT_NE(log.find("wood.fx:47:0: ';' : Expected"), std::string::npos) << log;
  // What the prelude maps only approximately is reported by the scan.
  std::vector<CompatIssue> issues = pre_release_hlsl_issues(body);
  std::vector<std::string> names;
  for (const CompatIssue& i : issues) names.push_back(i.name);
  EXPECT_EQ(names, (std::vector<std::string>{"volumetexture", "smoothstep", "sample1d"}));
}

TEST(SeedWood, CompilesOnceTheTwoSourceErrorsAreFixed) {
  auto [first, body] = wood_body();
  ASSERT_GT(first, 0u);
  auto fix = [&body = body](const std::string& from, const std::string& to) {
    size_t at = body.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    body.replace(at, from.size(), to);
  };
  fix("dot(N, L)\n", "dot(N, L);\n");
  fix("vec3 Color      : COLOR0;", "vec4 Color      : COLOR0;");
  CompiledShader r = ShaderCompiler().compile(wood_unit(body, first));
  ASSERT_TRUE(r.ok) << r.info_log;
  EXPECT_EQ(test::spirv_val(r.spirv), "");
  // The volume texture became one combined 3D sampler; the effect parameters a $Global block.
  ASSERT_EQ(r.reflection.images.size(), 1u);
  EXPECT_EQ(r.reflection.images[0].name, "noise");
  EXPECT_EQ(r.reflection.images[0].dim, ImageDim::dim_3d);
  ASSERT_EQ(r.reflection.uniform_blocks.size(), 1u);
  EXPECT_EQ(r.reflection.uniform_blocks[0].name, "$Global");
}

double median_ms(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

TEST(CompileTiming, FirstLaterAndCachedCompiles) {
  // Run first in its own process for a true "first" figure: ctest runs each test alone.
  SpirvCache cache;
  ShaderCompiler plain;
  ShaderCompiler cached({}, &cache);
  TranslationUnit vs = test::unit(test::kD3D9Effect, ShaderStage::vertex, "VS", "vs_2_0");
  TranslationUnit ps = test::unit(test::kD3D9Effect, ShaderStage::fragment, "PS", "ps_2_0");
  double first = plain.compile(vs).total_ms + plain.compile(ps).total_ms;
  std::vector<double> later, hits;
  for (int i = 0; i < 20; ++i) later.push_back(plain.compile(vs).total_ms + plain.compile(ps).total_ms);
  cached.compile(vs), cached.compile(ps);
  for (int i = 0; i < 200; ++i) hits.push_back(cached.compile(vs).total_ms + cached.compile(ps).total_ms);
  ShaderCompiler unvalidated({.validate = false});
  std::vector<double> fast;
  for (int i = 0; i < 20; ++i) fast.push_back(unvalidated.compile(vs).total_ms + unvalidated.compile(ps).total_ms);
  std::printf(
      "[timing] D3D9 VS+PS pair: first %.2f ms (includes glslang's built-in tables), later median "
      "%.3f ms (%.3f ms without SPIR-V validation), cache hit median %.4f ms (%.0fx faster than a compile)\n",
      first, median_ms(later), median_ms(fast), median_ms(hits), median_ms(later) / std::max(1e-6, median_ms(hits)));
  EXPECT_LT(median_ms(hits), median_ms(later));
  EXPECT_EQ(cached.glslang_runs(), 2u);
}

}  // namespace
}  // namespace fx
