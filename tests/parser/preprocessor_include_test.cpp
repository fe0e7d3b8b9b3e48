// #include: search order, case-insensitive fallback, #pragma once, depth limit, notes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "preprocessor_fixture.h"

namespace fx {
namespace {

using test::kHangSeconds;
using test::Pp;
using test::seconds_since;
using test::spelled;

TEST(PreprocessorIncludes, QuotedSearchesIncluderFolderFirst) {
  Pp p;
  p.options.include_dirs = {"lib"};
  p.files["fx/common.fxh"] = "local\n";
  p.files["lib/common.fxh"] = "library\n";
  p.files["lib/only.fxh"] = "only\n#include \"common.fxh\"\n";
  p.files["fx/main.fx"] = "#include \"common.fxh\"\n#include <common.fxh>\n#include \"only.fxh\"\n";
  std::vector<Token> out;
  Preprocessor pp(p.sm, p.diags, p.options);
  EXPECT_TRUE(pp.run_file("fx/main.fx", out));
  EXPECT_EQ(Pp::spell(out), "local library only library");
  EXPECT_EQ(pp.files(), (std::vector<std::string>{"fx/main.fx", "fx/common.fxh", "lib/common.fxh", "lib/only.fxh"}));
  ASSERT_EQ(pp.includes().size(), 4u);
  EXPECT_EQ(pp.includes()[3].includer, "lib/only.fxh");
  EXPECT_EQ(pp.includes()[3].included, "lib/common.fxh");
}

// fxc, like MSVC, looks for a quoted name beside the file holding the directive, then beside
// each file that included it, innermost first, then in the -I folders.
TEST(PreprocessorIncludes, QuotedSearchesTheIncludeStackInnermostFirst) {
  Pp p;
  p.options.include_dirs = {"lib"};
  p.files["fx/main.fx"] = "#include \"sub/material.fxh\"\n";
  p.files["fx/sub/material.fxh"] = "#include \"parts/light.fxh\"\n";
  p.files["fx/sub/parts/light.fxh"] = "#include \"palette.fxh\"\n#include \"root.fxh\"\n#include \"lib.fxh\"\n";
  p.files["fx/sub/palette.fxh"] = "sub_palette\n";
  p.files["fx/palette.fxh"] = "root_palette\n";
  p.files["fx/root.fxh"] = "root\n";
  p.files["lib/root.fxh"] = "lib_root\n";
  p.files["lib/lib.fxh"] = "lib\n";
  std::vector<Token> out;
  Preprocessor pp(p.sm, p.diags, p.options);
  EXPECT_TRUE(pp.run_file("fx/main.fx", out));
  EXPECT_EQ(Pp::spell(out), "sub_palette root lib");
  EXPECT_EQ(p.ids(), "");
}

TEST(PreprocessorIncludes, BackslashesMacrosAndDotDot) {
  Pp p;
  p.files["shaders/sub/light.fxh"] = "#include \"..\\util.fxh\"\nlight\n";
  p.files["shaders/util.fxh"] = "util\n";
  p.files["shaders/main.fx"] =
      "#define HDR <sub/light.fxh>\n#define Q \"util.fxh\"\n#include \"sub\\light.fxh\"\n"
      "#include Q\n#include HDR\n";
  p.options.include_dirs = {"shaders"};
  std::vector<Token> out;
  Preprocessor pp(p.sm, p.diags, p.options);
  pp.run_file("shaders/./main.fx", out);
  EXPECT_EQ(Pp::spell(out), "util light util util light");
  EXPECT_EQ(p.ids(), "");
}

TEST(PreprocessorIncludes, CaseInsensitiveFallbackWarnsWithRealName) {
  Pp p;
  p.files["Shaders/Common/Lighting.fxh"] = "lit\n";
  EXPECT_EQ(p.run("#include \"shaders\\common\\LIGHTING.FXH\"\n"), "lit");
  const Diagnostic& d = p.only();
  EXPECT_EQ(d.id, "include-case-mismatch");
  EXPECT_EQ(d.severity, Severity::warning);
  EXPECT_EQ(d.message,
            "'shaders\\common\\LIGHTING.FXH' matches 'Shaders/Common/Lighting.fxh' "
            "only when ignoring case");
  EXPECT_EQ(p.read_files[1], "Shaders/Common/Lighting.fxh");
  // Without a lister there is no fallback.
  p.options.lister = nullptr;
  p.run("#include \"shaders/common/lighting.fxh\"\n");
  EXPECT_EQ(p.ids(), "include-case-mismatch include-not-found");
}

// An engine that runs from its content root writes includes relative to it
// ("Data/Effects/Inc/x.fxh" from Data/Effects/main.fx): found nowhere else, such a path is
// looked for from the folders above the including file, nearest first, with a warning.
// Names without a folder, and "./" or "../" ones, are not.
TEST(PreprocessorIncludes, RootRelativeIncludesAreFoundFromAnAncestorFolder) {
  Pp p;
  p.files["game/Data/Effects/Inc/common.fxh"] = "common\n#include \"Data/Effects/Inc/more.fxh\"\n";
  p.files["game/Data/Effects/Inc/more.fxh"] = "more\n";
  p.files["game/Data/Effects/main.fx"] = "#include \"Data/Effects/Inc/common.fxh\"\nmain\n";
  std::vector<Token> out;
  Preprocessor pp(p.sm, p.diags, p.options);
  EXPECT_TRUE(pp.run_file("game/Data/Effects/main.fx", out));
  EXPECT_EQ(Pp::spell(out), "common more main");
  EXPECT_EQ(p.ids(), "include-from-ancestor include-from-ancestor");
  EXPECT_EQ(p.diags.diagnostics()[0].message,
            "'Data/Effects/Inc/common.fxh' is found only from the folder 'game' above the including file (as a "
            "program run there would find it); add it to the include path");
  EXPECT_EQ(pp.files()[1], "game/Data/Effects/Inc/common.fxh");

  Pp q;
  q.files["game/util.fxh"] = "util\n";
  q.files["game/Inc/x.fxh"] = "x\n";
  q.files["game/Data/Effects/main.fx"] = "#include \"util.fxh\"\n#include \"./Inc/x.fxh\"\n";
  Preprocessor qp(q.sm, q.diags, q.options);
  qp.run_file("game/Data/Effects/main.fx", out);
  EXPECT_EQ(q.ids(), "include-not-found include-not-found");
}

TEST(PreprocessorIncludes, NotFoundAndMalformed) {
  Pp p;
  p.files["lib/a.fxh"] = "a";
  p.run("#include <a.fxh>\n#include \"lib\"\n#include\n#include <a.fxh\n#include \"x\" y\n");
  EXPECT_EQ(p.ids(),
            "include-not-found include-not-found invalid-directive invalid-directive "
            "extra-tokens include-not-found");
  EXPECT_EQ(p.diags.diagnostics()[0].message, "'a.fxh' file not found");
}

// A misspelt include says where it looked and which file it probably meant.
TEST(PreprocessorIncludes, NotFoundListsTheFoldersSearchedAndANearName) {
  Pp p;
  p.options.include_dirs = {"lib", "shared"};
  p.files["fx/common/lighting.fxh"] = "lit\n";
  p.files["shared/common/shadows.fxh"] = "shadows\n";
  p.files["fx/main.fx"] = "#include \"common/lihgting.fxh\"\n#include \"common/shadwos.fxh\"\n#include \"zzz.fxh\"\n";
  std::vector<Token> out;
  Preprocessor pp(p.sm, p.diags, p.options);
  pp.run_file("fx/main.fx", out);
  ASSERT_EQ(p.ids(), "include-not-found include-not-found include-not-found");
  EXPECT_EQ(p.diags.diagnostics()[0].message,
            "'common/lihgting.fxh' file not found (searched 'fx', 'lib', 'shared'); did you mean "
            "'common/lighting.fxh'?");
  EXPECT_EQ(p.diags.diagnostics()[1].message,
            "'common/shadwos.fxh' file not found (searched 'fx', 'lib', 'shared'); did you mean "
            "'common/shadows.fxh'?");
  EXPECT_EQ(p.diags.diagnostics()[2].message, "'zzz.fxh' file not found (searched 'fx', 'lib', 'shared')");
}

TEST(PreprocessorIncludes, PragmaOnce) {
  Pp p;
  p.files["once.fxh"] = "#pragma once\nonce\n";
  p.files["twice.fxh"] = "twice\n";
  EXPECT_EQ(p.run("#include \"once.fxh\"\n#include \"./once.fxh\"\n#include \"twice.fxh\"\n"
                  "#include \"twice.fxh\"\n"),
            "once twice twice");
  EXPECT_EQ(p.edges.size(), 4u);
}

TEST(PreprocessorIncludes, ByteOrderMarkInIncludedFile) {
  Pp p;
  p.files["common.fxh"] = "\xEF\xBB\xBF#define SIZE 4\nfloat a[SIZE];\n";
  EXPECT_EQ(p.run("\xEF\xBB\xBF#include \"common.fxh\"\n"), "float a [ 4 ] ;");
  EXPECT_TRUE(p.diags.diagnostics().empty());
}

TEST(PreprocessorIncludes, DepthLimitStopsCyclesQuickly) {
  Pp p;
  p.files["a.fxh"] = "a\n#include \"b.fxh\"\n";
  p.files["b.fxh"] = "b\n#include \"a.fxh\"\n";
  auto start = std::chrono::steady_clock::now();
  p.run("#include \"a.fxh\"\nafter\n");
  EXPECT_LT(seconds_since(start), kHangSeconds);
  const Diagnostic& d = p.only();
  EXPECT_EQ(d.id, "limit-exceeded");
  EXPECT_EQ(d.message,
            "#include nested more than 200 levels deep (include cycle: 'b.fxh' "
            "includes itself)");
  EXPECT_EQ(p.tokens.size(), 200u);  // 199 files' tokens and the eof; `after` is not reached
}

TEST(PreprocessorIncludes, IncludeNotesInRenderedDiagnostics) {
  Pp p;
  p.files["inc.fxh"] = "#define P(a) a ## -\nP(+)\n#error stop\n";
  p.run("#include \"inc.fxh\"\n");
  ASSERT_EQ(p.ids(), "invalid-paste error-directive");
  EXPECT_EQ(render_text(p.diags.diagnostics(), p.sm),
            "inc.fxh:2:1: error: pasting formed '+-', an invalid preprocessing token "
            "[invalid-paste]\n"
            "P(+)\n"
            "^\n"
            "inc.fxh:1:19: note: spelled in the definition of macro 'P'\n"
            "inc.fxh:2:1: note: in expansion of macro 'P'\n"
            "main.fx:1:1: note: included from here\n"
            "inc.fxh:3:1: error: stop [error-directive]\n"
            "#error stop\n"
            "^~~~~~\n"
            "main.fx:1:1: note: included from here\n");
}

TEST(PreprocessorIncludes, RealFilesOnDisk) {
  SourceManager sm;
  DiagnosticSink diags;
  PreprocessorOptions options;
  std::string data = std::string(FXKIT_SOURCE_DIR) + "/tests/parser/data/pp";
  options.include_dirs = {data + "/include"};
  Preprocessor pp(sm, diags, options);
  std::vector<Token> out;
  EXPECT_TRUE(pp.run_file(data + "/main.fx", out)) << render_text(diags.diagnostics(), sm);
  EXPECT_EQ(Pp::spell(out), spelled("float4 Tint = float4(1, 0.5, 0.25, 1); "
                                    "float Gloss = 32; technique Main { }"));
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].id, "include-case-mismatch");
  ASSERT_EQ(pp.files().size(), 3u);
  EXPECT_EQ(pp.files()[2], data + "/include/Lighting.fxh");
}
}  // namespace
}  // namespace fx
