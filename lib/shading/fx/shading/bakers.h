// Typed table bakers for the seeds' lookup textures. Each has an options struct, a
// validator (empty string = valid) and a lookup that mirrors the shader's fetch.
// An invalid options struct bakes an empty Table (width 0); it never aborts.
#pragma once
#include <string>

#include "fx/shading/lut.h"
#include "fx/shading/noise.h"
#include "fx/shading/strand.h"
#include "fx/shading/table.h"
#include "fx/shading/ward.h"

namespace fx::shading {

// Strand table: N x N RGBA, u axis = L.T, v axis = V.T; rgb = diffuse, a = specular^n.
struct StrandTableOptions {
  int size = 256;
  double exponent = 32;
  LutMapping mapping = LutMapping::texel_centre;
  LutIndex index = LutIndex::cosine;
  TableFormat format = TableFormat::unorm8;
};
std::string validate(const StrandTableOptions& o);
Table bake_strand_table(const StrandTableOptions& o);
// One fetch at domain coordinates (lu, vu) (see lut_u_from_vectors), as the shader does it.
StrandTerms<float> lookup_strand_table(const Table& t, const StrandTableOptions& o, float lu, float vu);

// The per-pixel lighting seed's LightEval table: W x H RGBA, rgb = pow(v, exponent),
// a = u, indexed by (N.L, N.H) in [0, 1] each.
struct PowTableOptions {
  int width = 256, height = 256;
  double exponent = 100;
  LutMapping mapping = LutMapping::naive;  // what D3DXFillTexture does
  TableFormat format = TableFormat::unorm8;
};
std::string validate(const PowTableOptions& o);
Table bake_pow_table(const PowTableOptions& o);
// pow(x, exponent) looked up along v (x in [0, 1]).
float lookup_pow_table(const Table& t, const PowTableOptions& o, float x);

// The (L.N, H.N) table: N x N RGBA, u axis = H.N, v axis = L.N (both cosines in [-1, 1]);
// rgb = saturate(L.N), a = the lobe of H.N.
struct HalfAngleTableOptions {
  int size = 128;
  HalfAngleLobe lobe = HalfAngleLobe::blinn_phong;
  double shape = 32;  // exponent n (Blinn-Phong) or slope m (Gaussian)
  LutMapping mapping = LutMapping::texel_centre;
  TableFormat format = TableFormat::unorm8;
};
std::string validate(const HalfAngleTableOptions& o);
Table bake_ln_hn_table(const HalfAngleTableOptions& o);
HalfAngleTerms<float> lookup_ln_hn_table(const Table& t, const HalfAngleTableOptions& o, float ln, float hn);

// Tileable noise volume: W x H x D, 1-4 channels. One tile spans exactly spec.period
// lattice cells, so wrap addressing is seamless. float32 stores the signed noise;
// unorm8 stores 0.5 n + 0.5 (the shader expands with *2-1, the seeds' _bx2).
struct NoiseTableOptions {
  int width = 32, height = 32, depth = 32;
  int channels = 3;
  NoiseSpec noise;
  TableFormat format = TableFormat::unorm8;
};
std::string validate(const NoiseTableOptions& o);
Table bake_noise_table(const NoiseTableOptions& o);

// 1D hemisphere table over u = 0.5 N.A + 0.5: r = cosine-weighted sky fraction,
// g = the seed's "actual integral" (for A/B comparison in an effect).
struct HemisphereTableOptions {
  int width = 256;
  TableFormat format = TableFormat::unorm8;
};
std::string validate(const HemisphereTableOptions& o);
Table bake_hemisphere_table(const HemisphereTableOptions& o);

}  // namespace fx::shading
