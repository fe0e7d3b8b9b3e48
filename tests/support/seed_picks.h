// The technique each seed effect should run on each caps profile (distance 0, no scheme):
// the seeds' generational story of docs/effects.md. "" = nothing can run there. Shared by
// tests/effects (validity from annotations alone) and tests/select (validity from the
// compiled passes), which must agree.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace fx::testing {

struct SeedPicks {
  const char* effect;                        // under effects/
  std::map<std::string, std::string> picks;  // caps profile -> technique
};

inline const std::vector<SeedPicks>& seed_picks() {
  static const std::vector<SeedPicks> rows = {
      {"per_pixel_lighting.fx",
       {{"dx6", "emboss"},
        {"dx7", "dot3_multitexture"},
        {"dx8", "diffuse_ps11"},
        {"dx8_1", "diffuse_ps11"},
        {"dx9", "diffuse_ps20"},
        {"modern", "diffuse_ps20"}}},
      // dx8_1: the ps.1.4 listing sums four lights, so it is measured against the four-light
      // model, a substitute group declared after the one-light group strand_lut_ps11 is in
      // (docs/accuracy.md); the one-light look leads as it does on dx9 and modern.
      {"strand_aniso.fx",
       {{"dx6", ""},
        {"dx7", ""},
        {"dx8", "strand_lut_ps11"},
        {"dx8_1", "strand_lut_ps11"},
        {"dx9", "strand_bump_renormalized"},
        {"modern", "strand_bump_renormalized"}}},
      {"hemisphere.fx",
       {{"dx6", "hemisphere_vs11"},
        {"dx7", "hemisphere_vs11"},
        {"dx8", "hemisphere_ps11"},
        {"dx8_1", "hemisphere_ps11"},
        {"dx9", "hemisphere_sun"},
        {"modern", "hemisphere_sun"}}},
      {"brdf.fx", {{"dx7", ""}, {"dx8", "tec0"}, {"dx9", "brdf_ps20"}, {"modern", "brdf_ps20"}}},
      {"wood.fx", {{"dx8_1", ""}, {"dx9", "wood"}, {"modern", "wood"}}},
      {"seeds/wood_seed.fx", {{"dx8_1", ""}, {"dx9", "wood_seed"}, {"modern", "wood_seed"}}},
      {"aniso_lut_ward.fx", {{"dx8_1", ""}, {"dx9", "gaussian_per_pixel"}, {"modern", "gaussian_per_pixel"}}},
      {"aniso_highlights_glsl.fx", {{"dx9c", ""}, {"modern", "aniso_blinn_phong"}}},
  };
  return rows;
}

}  // namespace fx::testing
