// Helpers for the EffectLibrary tests: small effects on disk and bounded waits for reload
// events (EffectLibrary::wait, never a fixed sleep).
#pragma once
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "../support/patience.h"
#include "fx/reload/effect_library.h"
#include "watch_test_support.h"

namespace fx::testing {

// An effect that includes common.fxh; `tint` and `extra` vary its text.
inline std::string effect_text(const std::string& tint = "1, 0.5, 0.25, 1", const std::string& extra = "",
                               bool with_gloss = true) {
  return "#include \"common.fxh\"\n"
         "float4 Tint = {" +
         tint + "};\n" + (with_gloss ? "float Gloss <string UIName = \"Gloss\";> = 0.5;\n" : "float Gloss2 = 0.5;\n") +
         extra +
         "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
         "float4 PS() : COLOR0 { return Tint * Scale() * " +
         (with_gloss ? "Gloss" : "Gloss2") +
         "; }\n"
         "technique Main { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
}

// An effect that includes nothing.
inline std::string standalone_text(const std::string& value = "0.5") {
  return "float Level = " + value +
         ";\n"
         "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
         "float4 PS() : COLOR0 { return Level; }\n"
         "technique Solo { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";
}

inline std::string common_text(const std::string& scale = "1.0") { return "float Scale() { return " + scale + "; }\n"; }

// Library options for tests: short coalescing (saves here are single system calls).
inline EffectLibraryOptions test_options() {
  EffectLibraryOptions o;
  o.coalesce = std::chrono::milliseconds(20);
  return o;
}

// Waits until at least `count` events arrived (giving up after fx::testing::patience()).
inline std::vector<ReloadEvent> next_events(EffectLibrary& lib, size_t count = 1,
                                            std::chrono::milliseconds limit = fx::testing::patience()) {
  std::vector<ReloadEvent> out;
  auto deadline = std::chrono::steady_clock::now() + limit;
  while (out.size() < count) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    if (!lib.wait(left)) continue;
    for (ReloadEvent& e : lib.poll()) out.push_back(std::move(e));
  }
  return out;
}

}  // namespace fx::testing
