// `fxkit check PATH...` over folders, as a CI job or pre-commit hook runs it: recursive
// search with globs, included files checked through their includers, output in file order
// whatever the jobs, stable shards, and the result cache.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "effect_folder.h"
#include "fxkit_cli.h"

namespace {

using fx::testing::run_fxkit;
namespace fs = std::filesystem;

// Effects that include each other, one of them broken through its header.
struct ShaderFolder : fx::testing::EffectFolder {
  explicit ShaderFolder(const std::string& name) : EffectFolder("folder_" + name) {
    write("common/lighting.fxh", "float4 Ambient = {0.1, 0.1, 0.1, 1};\n");
    write("broken.fxh", "float4 Tint : COLOR;\ntechnique T { pass P { ZEnable = Maybe; } }\n");
    write("a_clean.fx", "#include \"common/lighting.fxh\"\ntechnique T { pass P { ZEnable = TRUE; } }\n");
    write("b_shared.fx", "float4 Shared;\n");  // a library other effects include: not a root
    write("c_broken.fx", "#include \"b_shared.fx\"\n#include \"broken.fxh\"\n");
    write("sub/d_warns.fx", "technique T { pass P { ZEnable = TRUE; ZEnable = FALSE; } }\n");
    write("sub/e_other.fxfx", "this is not an effect\n");
  }
};

TEST(CheckFolder, FindsEffectsRecursivelyAndLeavesIncludedOnesToTheirIncluders) {
  ShaderFolder f("roots");
  auto r = run_fxkit("check --syntax-only --jobs 2 " + f.path(), true);
  EXPECT_EQ(r.status, 1) << r.err;
  // Errors in the header, through its includer, with the include note.
  EXPECT_NE(r.err.find(f.path("broken.fxh") + ":2:34: error:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(f.path("c_broken.fx") + ":2:1: note: included from here"), std::string::npos) << r.err;
  // File order: c_broken.fx's error before sub/d_warns.fx's warning.
  EXPECT_LT(r.err.find("broken.fxh"), r.err.find("d_warns.fx")) << r.err;
  EXPECT_NE(r.err.find("checked 3 files in "), std::string::npos) << r.err;  // a, c, d; not b (included)
  EXPECT_NE(r.err.find(": 1 clean, 1 warning, 1 error"), std::string::npos) << r.err;

  // Named explicitly, an included file is a root too; globs pick other names.
  auto named = run_fxkit("check --syntax-only " + f.path() + " " + f.path("b_shared.fx"), true);
  EXPECT_NE(named.err.find("checked 4 files"), std::string::npos) << named.err;
  auto globs = run_fxkit(
      "check --syntax-only --json --include-glob '*.fx' --exclude-glob 'c_*' --exclude-glob 'sub/*' " + f.path());
  EXPECT_EQ(globs.status, 0);
  // b_shared.fx's only includer is excluded, so nothing checks it through an includer: a root.
  nlohmann::json picked = nlohmann::json::parse(globs.out);
  ASSERT_EQ(picked["files"], 2) << globs.out;
  EXPECT_EQ(picked["effects"][0]["file"], f.path("a_clean.fx")) << globs.out;
  EXPECT_EQ(picked["effects"][1]["file"], f.path("b_shared.fx")) << globs.out;
  auto other = run_fxkit("check --syntax-only --json --include-glob '*.fxfx' " + f.path());
  EXPECT_EQ(nlohmann::json::parse(other.out)["effects"][0]["file"], f.path("sub/e_other.fxfx")) << other.out;
}

TEST(CheckFolder, OutputIsTheSameWhateverTheJobs) {
  ShaderFolder f("jobs");
  for (int i = 0; i < 12; ++i)
    f.write("many/e" + std::to_string(i) + ".fx",
            "technique T { pass P { ZEnable = Bad" + std::to_string(i) + "; } }\n");
  auto one = run_fxkit("check --syntax-only --jobs 1 " + f.path(), true);
  auto four = run_fxkit("check --syntax-only --jobs 4 " + f.path(), true);
  EXPECT_EQ(one.status, 1);
  auto body = [](const std::string& err) { return err.substr(0, err.rfind("checked ")); };
  EXPECT_EQ(body(one.err), body(four.err));
  EXPECT_LT(one.err.find("e10.fx"), one.err.find("e2.fx"));  // by path, as sorted
}

TEST(CheckFolder, ShardsSplitTheFilesStably) {
  ShaderFolder f("shards");
  for (int i = 0; i < 20; ++i) f.write("s/e" + std::to_string(i) + ".fx", "technique T { pass P { } }\n");
  auto count = [](const std::string& err) {
    size_t at = err.find("checked ");
    return at == std::string::npos ? size_t(-1) : std::stoul(err.substr(at + 8));
  };
  size_t total = 0;
  for (const char* shard : {"1/3", "2/3", "3/3"}) {
    auto r = run_fxkit(std::string("check --syntax-only --shard ") + shard + " " + f.path("s"), true);
    EXPECT_EQ(r.status, 0) << r.err;
    total += count(r.err);
    // The same shard again checks the same files.
    auto files = [&] {
      auto j = nlohmann::json::parse(
          run_fxkit(std::string("check --syntax-only --json --shard ") + shard + " " + f.path("s")).out);
      std::vector<std::string> out;
      for (const auto& e : j["effects"]) out.push_back(e["file"]);
      return out;
    };
    std::vector<std::string> once = files();
    EXPECT_EQ(once.size(), count(r.err));
    EXPECT_EQ(once, files());
  }
  EXPECT_EQ(total, 20u);
  // A shard, or a folder, that holds one clean file still says what it checked (a named
  // file alone is silent). The files' shards depend on their paths, which differ per run.
  ShaderFolder one("one");
  one.write("only/a.fx", "technique T { pass P { } }\n");
  EXPECT_EQ(count(run_fxkit("check --syntax-only " + one.path("only"), true).err), 1u);
  EXPECT_EQ(count(run_fxkit("check --syntax-only " + one.path("only/a.fx"), true).err), size_t(-1));
  size_t in_shards = 0;
  for (const char* shard : {"1/2", "2/2"}) {
    const size_t c =
        count(run_fxkit(std::string("check --syntax-only --shard ") + shard + " " + one.path("only"), true).err);
    EXPECT_NE(c, size_t(-1)) << shard << ": no summary";
    if (c != size_t(-1)) in_shards += c;
  }
  EXPECT_EQ(in_shards, 1u);
  EXPECT_EQ(run_fxkit("check --shard 0/3 " + f.path("s")).status, 2);
  EXPECT_EQ(run_fxkit("check --shard 4/3 " + f.path("s")).status, 2);
  EXPECT_EQ(run_fxkit("check --shard x " + f.path("s")).status, 2);
}

// A CI job pointed at the wrong folder, or with globs matching nothing, must not pass green.
TEST(CheckFolder, AFolderWithNoEffectsFailsUnlessAllowed) {
  fx::testing::EffectFolder f("empty");
  f.write("empty/readme.txt", "no effects here\n");
  auto r = run_fxkit("check --syntax-only " + f.path("empty"), true);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("no effect files found in " + f.path("empty")), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--allow-empty"), std::string::npos) << r.err;
  auto globs = run_fxkit("check --syntax-only --include-glob '*.hlsl' " + f.path("empty"), true);
  EXPECT_EQ(globs.status, 2) << globs.err;
  EXPECT_NE(globs.err.find("include globs: *.hlsl"), std::string::npos) << globs.err;
  auto allowed = run_fxkit("check --syntax-only --allow-empty " + f.path("empty"), true);
  EXPECT_EQ(allowed.status, 0) << allowed.err;
  EXPECT_NE(allowed.err.find("checked 0 files"), std::string::npos) << allowed.err;
}

TEST(CheckFolder, CacheServesUnchangedFilesAndSeesEditedIncludes) {
#ifndef FXKIT_CLI_COMPILES
  GTEST_SKIP() << "--cache needs the runtime build";
#endif
  ShaderFolder f("cache");
  std::string cache = f.path(".cache");
  auto first = run_fxkit("check --cache " + cache + " --exclude-glob '.cache/*' " + f.path(), true);
  EXPECT_EQ(first.status, 1);
  EXPECT_EQ(first.err.find("from the cache"), std::string::npos) << first.err;
  auto second = run_fxkit("check --cache " + cache + " --exclude-glob '.cache/*' " + f.path(), true);
  EXPECT_EQ(second.status, 1);
  EXPECT_NE(second.err.find("(3 from the cache)"), std::string::npos) << second.err;
  auto body = [](const std::string& err) { return err.substr(0, err.rfind("checked ")); };
  EXPECT_EQ(body(first.err), body(second.err));
  // Fixing the header is seen through its includer; the other two stay cached.
  f.write("broken.fxh", "float4 Tint : COLOR;\ntechnique T { pass P { ZEnable = TRUE; } }\n");
  auto fixed = run_fxkit("check --cache " + cache + " --exclude-glob '.cache/*' " + f.path(), true);
  EXPECT_EQ(fixed.status, 0) << fixed.err;
  EXPECT_NE(fixed.err.find("(2 from the cache)"), std::string::npos) << fixed.err;
  // Other options are other results.
  auto werror = run_fxkit("check --werror --cache " + cache + " --exclude-glob '.cache/*' " + f.path(), true);
  EXPECT_EQ(werror.status, 1) << werror.err;
  EXPECT_EQ(werror.err.find("from the cache"), std::string::npos) << werror.err;
  // A limit of 0 MB leaves nothing behind.
  run_fxkit("check --cache-limit-mb 0 --cache " + cache + " --exclude-glob '.cache/*' " + f.path());
  size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(cache)) files += e.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 0u);
}

}  // namespace
