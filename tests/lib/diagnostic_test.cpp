#include "fx/diagnostic.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fx/diagnostic_render.h"

namespace fx {
namespace {

TEST(Diagnostic, TextHasPositionIdSourceLineAndCaret) {
  SourceManager sm;
  BufferId f = sm.add_buffer("e.fx", "pass p0 {\n  CullMod = None;\n}\n");
  DiagnosticSink sink;
  SourceLocation at = sm.location(f, 12);
  sink.error("unknown-state", {at, at.offset(7)}, "unknown state 'CullMod'")
      .fixits.push_back({{at, at.offset(7)}, "CullMode"});
  EXPECT_EQ(render_text(sink.diagnostics(), sm),
            "e.fx:2:3: error: unknown state 'CullMod' [unknown-state]\n"
            "  CullMod = None;\n"
            "  ^~~~~~~\n"
            "e.fx:2:3: note: fix-it: replace with 'CullMode'\n");
}

TEST(Diagnostic, ADiagnosticAboutNoPlaceStartsWithItsSeverity) {
  SourceManager sm;
  DiagnosticSink sink;
  sink.error("vk-feature-missing", {}, "the device has no dynamic rendering");
  EXPECT_EQ(render_text(sink.diagnostics(), sm), "error: the device has no dynamic rendering [vk-feature-missing]\n");
}

TEST(Diagnostic, IncludeAndMacroNotes) {
  SourceManager sm;
  BufferId main = sm.add_buffer("main.fx", "#define BAD oops\n#include \"a.fxh\"\n");
  BufferId inc = sm.add_buffer("a.fxh", "BAD;\n", sm.location(main, 17));
  SourceLocation use = sm.location(inc, 0);
  SourceLocation exp = sm.add_expansion({"BAD", sm.location(main, 12), {use, use.offset(3)}}, 4);
  DiagnosticSink sink;
  sink.error("syntax", {exp, exp.offset(4)}, "expected declaration");
  std::string text = render_text(sink.diagnostics(), sm);
  EXPECT_NE(text.find("a.fxh:1:1: error: expected declaration [syntax]"), std::string::npos) << text;
  EXPECT_NE(text.find("main.fx:1:13: note: spelled in the definition of macro 'BAD'"), std::string::npos) << text;
  EXPECT_NE(text.find("a.fxh:1:1: note: in expansion of macro 'BAD'"), std::string::npos) << text;
  EXPECT_NE(text.find("main.fx:2:1: note: included from here"), std::string::npos) << text;

  nlohmann::json j = render_json(sink.diagnostics(), sm);
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["file"], "a.fxh");
  EXPECT_EQ(j[0]["line"], 1);
  EXPECT_EQ(j[0]["severity"], "error");
  EXPECT_EQ(j[0]["id"], "syntax");
  ASSERT_EQ(j[0]["notes"].size(), 3u);
  EXPECT_EQ(j[0]["notes"][0]["line"], 1);  // the definition
  EXPECT_EQ(j[0]["notes"][0]["column"], 13);
  EXPECT_EQ(j[0]["notes"][2]["file"], "main.fx");
  EXPECT_EQ(j[0]["notes"][2]["line"], 2);
}

// A fix-it for a token a macro produced edits the macro's definition, where the token is
// written, not the invocation; one for a token the preprocessor made (a paste) is left out,
// since no file holds its characters.
TEST(Diagnostic, FixItsInMacroExpansionsEditTheDefinition) {
  SourceManager sm;
  BufferId main = sm.add_buffer("main.fx", "#define S CullMod = None;\npass { S }\n");
  SourceLocation use = sm.location(main, 33);  // `S` on line 2
  SourceLocation exp = sm.add_expansion({"S", sm.location(main, 10), {use, use.offset(1)}}, 15);
  SourceLocation pasted = sm.add_scratch("CullMod", use);
  DiagnosticSink sink;
  Diagnostic& d = sink.error("unknown-state", {exp, exp.offset(7)}, "unknown state 'CullMod'");
  d.fixits.push_back({{exp, exp.offset(7)}, "CullMode"});
  Diagnostic& p = sink.error("unknown-state", {pasted, pasted.offset(7)}, "unknown state 'CullMod'");
  p.fixits.push_back({{pasted, pasted.offset(7)}, "CullMode"});
  const std::string text = render_text(sink.diagnostics()[0], sm);
  EXPECT_NE(text.find("main.fx:2:8: error: unknown state 'CullMod' [unknown-state]"), std::string::npos) << text;
  EXPECT_NE(text.find("main.fx:1:11: note: fix-it: replace with 'CullMode'"), std::string::npos) << text;
  EXPECT_EQ(text.find("main.fx:2:8: note: fix-it"), std::string::npos) << text;
  nlohmann::json j = render_json(sink.diagnostics(), sm);
  ASSERT_EQ(j[0]["fixits"].size(), 1u);
  EXPECT_EQ(j[0]["fixits"][0]["line"], 1);
  EXPECT_EQ(j[0]["fixits"][0]["column"], 11);
  EXPECT_EQ(j[0]["fixits"][0]["end"]["column"], 18);  // CullMod spans columns 11-17
  EXPECT_EQ(j[0]["fixits"][0]["replacement"], "CullMode");
  EXPECT_EQ(j[1]["fixits"].size(), 0u);
  EXPECT_EQ(render_text(sink.diagnostics()[1], sm).find("fix-it"), std::string::npos);
}

TEST(Diagnostic, WerrorAndErrorLimit) {
  DiagnosticSink sink;
  sink.set_warnings_as_errors(true);
  sink.warning("w", {}, "a warning");
  EXPECT_EQ(sink.error_count(), 1u);
  EXPECT_EQ(sink.diagnostics()[0].severity, Severity::error);
  sink.set_error_limit(2);
  sink.error("e", {}, "1");
  sink.error("e", {}, "2");
  EXPECT_EQ(sink.diagnostics().size(), 2u);
  EXPECT_EQ(sink.error_count(), 3u);
}

TEST(Diagnostic, ClosestMatchIsCaseInsensitive) {
  EXPECT_EQ(closest_match("cullmod", {"CullMode", "FillMode", "ZEnable"}), "CullMode");
  EXPECT_EQ(closest_match("Zzzzzzz", {"CullMode", "FillMode"}), "");
}

// Two letters typed in the wrong order are one slip, as one letter left out is.
TEST(Diagnostic, ClosestMatchCountsASwapOfNeighboursAsOneEdit) {
  EXPECT_EQ(closest_match("Clmp", {"Clamp", "Wrap", "Mirror", "Border"}), "Clamp");
  EXPECT_EQ(closest_match("Clmap", {"Clamp", "Wrap", "Mirror", "Border"}), "Clamp");
  EXPECT_EQ(closest_match("Lienar", {"Linear", "Point", "Anisotropic"}), "Linear");
  EXPECT_EQ(closest_match("ZEnalbe", {"ZEnable", "ZFunc", "ZWriteEnable"}), "ZEnable");
  EXPECT_EQ(closest_match("Wrpa", {"Clamp", "Mirror"}), "") << "nothing near";
}

}  // namespace
}  // namespace fx
