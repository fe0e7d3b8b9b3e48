// The SPIR-V cache: hits skip glslang, keys cover every input, disk entries are validated.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "compile_test_util.h"
#include "fx/compile/spirv_cache.h"

namespace fx {
namespace {

std::filesystem::path fresh_dir(const char* name) {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fxkit_cache_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(SpirvCacheKey, CoversEveryInput) {
  TranslationUnit u = test::unit(test::kD3D9Effect, ShaderStage::fragment, "PS", "ps_2_0");
  CompileOptions o;
  SpirvCacheKey base = spirv_cache_key(u, o);
  EXPECT_EQ(base, spirv_cache_key(u, o));
  EXPECT_EQ(base.hex().size(), 32u);
  auto differs = [&](auto change) {
    TranslationUnit u2 = u;
    CompileOptions o2 = o;
    change(u2, o2);
    return !(spirv_cache_key(u2, o2) == base);
  };
  EXPECT_TRUE(differs([](TranslationUnit& x, CompileOptions&) { x.source += " "; }));
  EXPECT_TRUE(differs([](TranslationUnit& x, CompileOptions&) { x.stage = ShaderStage::vertex; }));
  EXPECT_TRUE(differs([](TranslationUnit& x, CompileOptions&) { x.entry_point = "VS"; }));
  EXPECT_TRUE(differs([](TranslationUnit& x, CompileOptions&) { x.profile = "ps_3_0"; }));
  EXPECT_TRUE(differs([](TranslationUnit& x, CompileOptions&) { x.language = ShaderLanguage::glsl; }));
  EXPECT_TRUE(differs([](TranslationUnit& x, CompileOptions&) { x.defines.push_back({"A", "1"}); }));
  EXPECT_TRUE(differs([](TranslationUnit&, CompileOptions& x) { x.target = VulkanTarget::vulkan_1_0; }));
  EXPECT_TRUE(differs([](TranslationUnit&, CompileOptions& x) { x.debug_info = true; }));
}

TEST(SpirvCache, SecondCompileDoesNotRunGlslang) {
  SpirvCache cache;
  ShaderCompiler compiler({}, &cache);
  TranslationUnit u = test::unit(test::kD3D9Effect, ShaderStage::vertex, "VS", "vs_2_0");
  CompiledShader first = compiler.compile(u);
  ASSERT_TRUE(first.ok) << first.info_log;
  EXPECT_FALSE(first.from_cache);
  CompiledShader second = compiler.compile(u);
  EXPECT_EQ(compiler.glslang_runs(), 1u);
  EXPECT_TRUE(second.from_cache);
  EXPECT_EQ(second.spirv, first.spirv);
  EXPECT_EQ(second.reflection.inputs.size(), first.reflection.inputs.size());
  EXPECT_EQ(cache.stats().memory_hits, 1u);
  u.source += "\n// edited\n";
  EXPECT_FALSE(compiler.compile(u).from_cache);
  EXPECT_EQ(compiler.glslang_runs(), 2u);
}

TEST(SpirvCache, FailedCompilesAreNotCached) {
  SpirvCache cache;
  ShaderCompiler compiler({}, &cache);
  TranslationUnit u = test::unit("float4 PS() : SV_Target { return x; }", ShaderStage::fragment, "PS", "ps_4_0");
  compiler.compile(u);
  compiler.compile(u);
  EXPECT_EQ(compiler.glslang_runs(), 2u);
  EXPECT_EQ(cache.stats().stores, 0u);
}

TEST(SpirvCache, DiskEntriesSurviveAProcessAndRoundTripReflection) {
  std::filesystem::path dir = fresh_dir("disk");
  TranslationUnit u = test::unit(test::kD3D10Effect, ShaderStage::vertex, "VS", "vs_4_0");
  CompiledShader original;
  {
    SpirvCache cache(dir);
    ShaderCompiler compiler({}, &cache);
    original = compiler.compile(u);
    ASSERT_TRUE(original.ok);
  }
  SpirvCache cache(dir);  // a new process, as far as the cache knows
  ShaderCompiler compiler({}, &cache);
  CompiledShader loaded = compiler.compile(u);
  EXPECT_TRUE(loaded.from_cache);
  EXPECT_EQ(compiler.glslang_runs(), 0u);
  EXPECT_EQ(cache.stats().disk_hits, 1u);
  EXPECT_EQ(loaded.spirv, original.spirv);
  EXPECT_EQ(loaded.entry_point, "VS");
  ASSERT_EQ(loaded.reflection.uniform_blocks.size(), original.reflection.uniform_blocks.size());
  for (size_t i = 0; i < loaded.reflection.uniform_blocks.size(); ++i) {
    const UniformBlock& a = loaded.reflection.uniform_blocks[i];
    const UniformBlock& b = original.reflection.uniform_blocks[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.size, b.size);
    ASSERT_EQ(a.members.size(), b.members.size());
    for (size_t m = 0; m < a.members.size(); ++m) {
      EXPECT_EQ(a.members[m].offset, b.members[m].offset);
      EXPECT_EQ(a.members[m].matrix_layout, b.members[m].matrix_layout);
    }
  }
  ASSERT_EQ(loaded.reflection.inputs.size(), 2u);
  EXPECT_EQ(loaded.reflection.inputs[1].semantic, "TEXCOORD0");
  std::filesystem::remove_all(dir);
}

// What a texture read returns (Texture2D<uint>, <int>, <float4>) is reflected and kept in
// the disk entry: the binding needs it to give integer textures integer views.
TEST(SpirvCache, TheSampledTypeOfTexturesRoundTrips) {
  std::filesystem::path dir = fresh_dir("sampled");
  const char* source = R"(Texture2D<uint> Counts; Texture2D<int2> Offsets; Texture2D Colour;
float4 PS(float4 p : SV_Position) : SV_Target {
  return Colour.Load(int3(0, 0, 0)) + float(Counts.Load(int3(0, 0, 0)) + Offsets.Load(int3(0, 0, 0)).y);
}
)";
  TranslationUnit u = test::unit(source, ShaderStage::fragment, "PS", "ps_5_0");
  auto kinds = [](const CompiledShader& s) {
    std::map<std::string, ScalarKind> out;
    for (const ImageBinding& i : s.reflection.images) out[i.name] = i.sampled;
    return out;
  };
  const std::map<std::string, ScalarKind> expected = {
      {"Counts", ScalarKind::uint32}, {"Offsets", ScalarKind::int32}, {"Colour", ScalarKind::float32}};
  {
    SpirvCache cache(dir);
    ShaderCompiler compiler({}, &cache);
    CompiledShader original = compiler.compile(u);
    ASSERT_TRUE(original.ok) << original.info_log;
    EXPECT_EQ(kinds(original), expected);
  }
  SpirvCache cache(dir);
  ShaderCompiler compiler({}, &cache);
  CompiledShader loaded = compiler.compile(u);
  EXPECT_TRUE(loaded.from_cache);
  EXPECT_EQ(kinds(loaded), expected);
  std::filesystem::remove_all(dir);
}

TEST(SpirvCache, CorruptOrTruncatedFilesAreRejectedAndReplaced) {
  std::filesystem::path dir = fresh_dir("corrupt");
  TranslationUnit u = test::unit(test::kD3D9Effect, ShaderStage::fragment, "PS", "ps_2_0");
  std::filesystem::path file = dir / (spirv_cache_key(u, {}).hex() + ".spvc");
  {
    SpirvCache cache(dir);
    ShaderCompiler({}, &cache).compile(u);
  }
  ASSERT_TRUE(std::filesystem::exists(file));
  auto size = std::filesystem::file_size(file);
  for (int damage = 0; damage < 3; ++damage) {
    {
      std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
      if (damage == 0) {
        f.seekp(0);
        f.put('X');
      }  // magic
      if (damage == 1) {
        f.seekp(static_cast<std::streamoff>(size) - 3);
        f.put('!');
      }  // payload byte
    }
    if (damage == 2) std::filesystem::resize_file(file, size / 2);  // truncated
    SpirvCache cache(dir);
    ShaderCompiler compiler({}, &cache);
    CompiledShader r = compiler.compile(u);
    EXPECT_TRUE(r.ok);
    EXPECT_FALSE(r.from_cache) << damage;
    EXPECT_EQ(cache.stats().disk_rejects, 1u) << damage;
    EXPECT_EQ(compiler.glslang_runs(), 1u);
    EXPECT_EQ(std::filesystem::file_size(file), size);  // rewritten whole
  }
  std::filesystem::remove_all(dir);
}

TEST(SpirvCache, MemoryStaysWithinItsBudgetDroppingTheLeastRecentlyUsed) {
  auto shader = [](uint32_t words) {
    CompiledShader s;
    s.ok = true;
    s.spirv.assign(words, 0x07230203u);
    return s;
  };
  const size_t one = shader(4096).spirv.size() * 4;  // 16 KiB of words, plus bookkeeping
  SpirvCache cache({}, 3 * one + 3 * (sizeof(CompiledShader) + 1024));
  auto key = [](uint64_t i) { return SpirvCacheKey{i, ~i}; };
  for (uint64_t i = 0; i < 3; ++i) cache.store(key(i), shader(4096));
  EXPECT_EQ(cache.stats().evictions, 0u);
  ASSERT_TRUE(cache.find(key(0)));  // 0 is now the most recently used: 1 goes next
  cache.store(key(3), shader(4096));
  EXPECT_EQ(cache.stats().evictions, 1u);
  EXPECT_LE(cache.stats().memory_bytes, 3 * one + 3 * (sizeof(CompiledShader) + 1024));
  EXPECT_TRUE(cache.find(key(0)));
  EXPECT_FALSE(cache.find(key(1)));
  EXPECT_TRUE(cache.find(key(2)));
  EXPECT_TRUE(cache.find(key(3)));
  // An entry larger than the whole budget is not kept in memory at all.
  cache.store(key(9), shader(4 * 4096));
  EXPECT_FALSE(cache.find(key(9)));
  cache.clear_memory();
  EXPECT_EQ(cache.stats().memory_bytes, 0u);
}

TEST(SpirvCache, UnwritableDirectoryStillCachesInMemory) {
  SpirvCache cache("/proc/fxkit-cannot-write-here");
  ShaderCompiler compiler({}, &cache);
  TranslationUnit u = test::unit(test::kD3D9Effect, ShaderStage::fragment, "PS", "ps_2_0");
  EXPECT_TRUE(compiler.compile(u).ok);
  EXPECT_TRUE(compiler.compile(u).from_cache);
  EXPECT_EQ(cache.stats().disk_write_errors, 1u);
}

}  // namespace
}  // namespace fx
