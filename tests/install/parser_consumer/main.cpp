// Parses a two-technique effect with fxkit::parser and prints its technique count; exit 0
// when the effect parses clean and has both techniques. Uses only installed headers.
#include <cstdio>

#include "fx/diagnostic_render.h"
#include "fx/frontend.h"

int main() {
  fx::SourceManager sm;
  fx::DiagnosticSink diags;
  fx::ParsedEffect effect = fx::parse_effect_text("consumer.fx", R"(
float4 Tint = float4(1, 0.5, 0.25, 1);
float4 shade() : COLOR { return Tint; }
technique Full { pass P0 { PixelShader = compile ps_2_0 shade(); } }
technique Fallback { pass P0 { ZEnable = false; PixelShader = compile ps_2_0 shade(); } }
)",
                                                  sm, diags);
  if (!effect.ok) {
    std::fputs(fx::render_text(diags.diagnostics(), sm).c_str(), stderr);
    return 1;
  }
  int techniques = 0;
  for (const fx::ast::Decl& decl : effect.ast.decls) techniques += decl.kind == fx::ast::DeclKind::technique;
  std::printf("techniques: %d\n", techniques);
  return techniques == 2 ? 0 : 1;
}
