// Re-spells effect tokens as shader source for glslang: #line directives whenever the
// presumed file or line jumps, newlines and spaces that keep lines and columns where cheap,
// so glslang's messages point into the .fx files (through includes and macros).
// Private to runtime/compile.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "fx/source_manager.h"
#include "fx/token.h"

namespace fx::detail {

class ShaderTextWriter {
 public:
  // GLSL needs GL_GOOGLE_cpp_style_line_directive for `#line N "file"`: the caller writes it.
  explicit ShaderTextWriter(const SourceManager& sm) : sm_(sm) {}

  // Appends a token at its presumed position, spelled as written or as `spelling`.
  void token(const Token& t, std::string_view spelling = {});
  // Appends a line of generated text (no position): the next token re-syncs with #line.
  void line(std::string_view text);
  // Appends text on the current line; used for generated fragments between tokens.
  void text(std::string_view text);
  // Starts a new line if the current one has text.
  void end_line();
  // Forgets the position so the next token writes a #line.
  void desync() { file_.clear(); }

  std::string& out() { return out_; }

 private:
  void sync(std::string_view file, uint32_t line);

  const SourceManager& sm_;
  std::string out_;
  std::string file_;     // presumed file of the current output line ("" = unknown)
  uint32_t line_ = 0;    // presumed line of the current output line
  uint32_t column_ = 1;  // 1-based column where the next character goes
  char last_ = '\n';
};

// A character of an HLSL/GLSL identifier or number: letters, digits, '_'.
bool is_word_char(char c);

// Escapes a file name for a `#line N "name"` directive.
std::string line_directive(uint32_t line, std::string_view file);

// Words glslang's HLSL front end reserves that fxc takes as names when they are not used as
// modifiers (`float point = 1;`, but `point V input[1]`): a geometry primitive, an
// interpolation or precision modifier. Given an identifier and whether an identifier follows
// it (a type: the modifier use), the spelling for glslang ("point__fx"), or "" to keep it.
std::string glslang_safe_name(std::string_view word, bool identifier_follows);
// The spelling glslang gets for token `i` of `toks` (`last` ends its declaration): a
// reserved name renamed, C's `unsigned int` as uint, "" to keep the token as written.
std::string glslang_spelling(const std::vector<Token>& toks, uint32_t i, uint32_t last);
// The name as the effect wrote it, for reflection: "light.point__fx" -> "light.point".
std::string effect_name(std::string_view glslang_name);

}  // namespace fx::detail
