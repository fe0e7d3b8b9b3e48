// The HLSL kernels `fxkit bench accuracy` times: each mirrors the shader code of one
// approximation in effects/*.fx, fed with per-pixel vectors derived from the position so
// no pixel is constant-folded. Ids match the error catalogue (lib/fx/shading/approximations.h)
// where a kernel stands for an entry.
#include <cmath>
#include <string>

#include "bench_accuracy.h"
#include "fx/shading/bakers.h"

namespace fx::tools {
namespace {

using fx::shading::LutIndex;
using fx::shading::LutMapping;
using fx::shading::TableFormat;

// Inputs shared by every kernel: unit L, V, T, N that vary across the screen.
const char* kPrelude = R"(
[[vk::binding(0)]] Texture2D Table;
[[vk::binding(1)]] SamplerState Sampler;
struct PSIn { float4 pos : SV_Position; float2 uv : TEXCOORD0; };
static const float PI = 3.14159265;
void inputs(float2 uv, out float3 L, out float3 V, out float3 T, out float3 N) {
  L = normalize(float3(uv.x * 2 - 1, uv.y * 2 - 1, 0.6));
  V = normalize(float3(0.7 - uv.y, uv.x - 0.3, 0.8));
  N = normalize(float3(0.2 * uv.y, 0.1 - 0.2 * uv.x, 1));
  T = normalize(float3(1, 0, 0) - N.x * N);
}
)";

std::string ps(const std::string& body) {
  return std::string(kPrelude) +
         "float4 PS(PSIn i) : SV_Target {\n  float3 L, V, T, N;\n  inputs(i.uv, L, V, T, N);\n" + body + "\n}\n";
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The texture coordinate expression of a mapping for u (as lut.h's lut_texcoord).
std::string texcoord(LutMapping m, int n, const std::string& u) {
  std::string N = number(n) + ".0";
  switch (m) {
    case LutMapping::naive: return u;
    case LutMapping::seed_wrap: return "(" + u + " - 0.5)";
    case LutMapping::texel_centre: return "((" + u + ") * (" + N + " - 1) + 0.5) / " + N;
    case LutMapping::texel_centre_wrap: return "((" + u + ") - 0.5) * ((" + N + " - 1) / " + N + ")";
  }
  return u;
}

GpuKernel strand_lut(const std::string& id, LutIndex index, TableFormat format, int size, LutMapping mapping) {
  fx::shading::StrandTableOptions o{size, 32, mapping, index, format};
  std::string u = index == LutIndex::cosine ? "  float lu = 0.5 * dot(L, T) + 0.5, vu = 0.5 * dot(V, T) + 0.5;\n"
                                            : "  float lu = 1 - atan2(length(cross(L, T)), dot(L, T)) / PI;\n"
                                              "  float vu = 1 - atan2(length(cross(V, T)), dot(V, T)) / PI;\n";
  GpuKernel k;
  k.id = id;
  k.ps = ps(u + "  float4 t = Table.Sample(Sampler, float2(" + texcoord(mapping, size, "lu") + ", " +
            texcoord(mapping, size, "vu") + "));\n  return float4(t.rgb * 0.8 + t.a, 1);");
  k.table = fx::shading::bake_strand_table(o);
  k.wrap = fx::shading::lut_address_mode(mapping) == fx::shading::AddressMode::wrap;
  return k;
}

const char* kStrandStable = R"(
  float sl = min(length(cross(L, T)), 1), sv = min(length(cross(V, T)), 1);
  float lt = clamp(dot(L, T), -1, 1), vt = clamp(dot(V, T), -1, 1);
  float r = max(sl * sv - lt * vt, 0);
  float s = r > 0 ? pow(r, 32) : 0;
  return float4(sl * 0.8 + s, sl, s, 1);)";

const char* kStrandSeed = R"(
  float lt = dot(L, T), vt = dot(V, T);
  float sl = sqrt(1 - lt * lt), sv = sqrt(1 - vt * vt);
  float s = pow(sl * sv - lt * vt, 32);
  return float4(sl * 0.8 + s, sl, s, 1);)";

// Strand specular evaluated per vertex of a grid (VS) or per pixel (PS), on the same grid.
// The grid's normal/tangent field bends across the screen like a sphere's.
const char* kGridVs = R"(
struct VSOut { float4 pos : SV_Position; float2 uv : TEXCOORD0; float3 n : TEXCOORD1; float3 t : TEXCOORD2; float4 c : COLOR0; };
static const uint CORNER[6] = {0, 1, 2, 2, 1, 3};
VSOut VS(uint id : SV_VertexID) {
  uint cell = id / 6, corner = CORNER[id % 6];
  uint cx = cell % CELLS, cy = cell / CELLS;
  float2 uv = float2(cx + (corner & 1), cy + (corner >> 1)) / CELLS;
  VSOut o;
  o.pos = float4(uv * 2 - 1, 0, 1);
  o.uv = uv;
  float2 p = uv * 2 - 1;
  o.n = float3(p * 0.7, sqrt(max(1 - dot(p * 0.7, p * 0.7), 0)));
  o.t = normalize(cross(float3(0, 0, 1), o.n) + float3(1e-4, 0, 0));
  o.c = float4(0, 0, 0, 1);
#if PER_VERTEX
  float3 L = normalize(float3(1, 1, 1)), V = normalize(float3(0.2, -0.4, 1)), T = o.t;
  float sl = min(length(cross(L, T)), 1), sv = min(length(cross(V, T)), 1);
  float r = max(sl * sv - dot(L, T) * dot(V, T), 0);
  o.c = float4(r > 0 ? pow(r, 32) : 0, sl, 0, 1);
#endif
  return o;
}
)";

const char* kGridPs = R"(
struct PSIn { float4 pos : SV_Position; float2 uv : TEXCOORD0; float3 n : TEXCOORD1; float3 t : TEXCOORD2; float4 c : COLOR0; };
// Every variant reads every interpolant (a tiny weight keeps them alive): unconsumed
// vertex outputs are a validation warning.
float4 PS(PSIn i) : SV_Target {
  float4 keep = float4(i.n + i.t, i.c.a + i.uv.x) * 1e-6;
#if PER_PIXEL
  float3 N = normalize(i.n), T = normalize(i.t - dot(i.t, N) * N);
  float3 L = normalize(float3(1, 1, 1)), V = normalize(float3(0.2, -0.4, 1));
  float sl = min(length(cross(L, T)), 1), sv = min(length(cross(V, T)), 1);
  float r = max(sl * sv - dot(L, T) * dot(V, T), 0);
  return float4(r > 0 ? pow(r, 32) : 0, sl, 0, 1) + keep;
#else
  return i.c + float4(i.uv, 0, 0) + keep;
#endif
}
)";

GpuKernel grid(const std::string& id, int cell_px, int size, const char* mode) {
  int cells = (size + cell_px - 1) / cell_px;
  std::string defs = "#define CELLS " + std::to_string(cells) + "\n#define " + mode + " 1\n";
  GpuKernel k;
  k.id = id;
  k.vs = defs + kGridVs;
  k.ps = defs + kGridPs;
  k.grid_px = cell_px;
  return k;
}

}  // namespace

std::vector<GpuKernel> accuracy_kernels(int size) {
  std::vector<GpuKernel> out;
  out.push_back(
      {"empty", "", std::string(kPrelude) + "float4 PS(PSIn i) : SV_Target { return float4(i.uv, 0, 1); }\n"});
  out.push_back({"setup", "", ps("  return float4(L + V + T + N, 1);")});
  out.push_back({"strand_analytic/stable", "", ps(kStrandStable)});
  out.push_back({"strand_analytic/seed_sqrt", "", ps(kStrandSeed)});
  const int sizes[] = {16, 32, 64, 128, 256, 512, 1024};
  for (LutIndex index : {LutIndex::cosine, LutIndex::angle})
    for (TableFormat f : {TableFormat::unorm8, TableFormat::float32})
      for (int n : sizes)
        out.push_back(strand_lut(std::string("strand_lut/") + (index == LutIndex::cosine ? "dot" : "angle") + "/" +
                                     (f == TableFormat::unorm8 ? "unorm8" : "float32") + "/s" + std::to_string(n),
                                 index, f, n, LutMapping::texel_centre));
  for (auto [m, name] : {std::pair{LutMapping::naive, "naive"}, std::pair{LutMapping::seed_wrap, "seed_wrap"},
                         std::pair{LutMapping::texel_centre_wrap, "texel_centre_wrap"}})
    out.push_back(
        strand_lut(std::string("strand_mapping/") + name + "/s256", LutIndex::cosine, TableFormat::unorm8, 256, m));
  // Specular power: the three ways of per_pixel_lighting.fx.
  const std::string nh = "  float x = saturate(dot(N, normalize(L + V)));\n";
  out.push_back({"specular/pow_native", "", ps(nh + "  return float4(pow(x, 16).xxx, 1);")});
  out.push_back({"specular/squaring_float", "",
                 ps(nh + "  float r = x * x; r = r * r; r = r * r; r = r * r;\n  return float4(r.xxx, 1);")});
  out.push_back({"specular/squaring_8bit", "",
                 ps(nh + "  float r = round(x * 255) / 255;\n"
                         "  [unroll] for (int k = 0; k < 4; ++k) r = round(r * r * 255) / 255;\n"
                         "  return float4(r.xxx, 1);")});
  for (TableFormat f : {TableFormat::unorm8, TableFormat::float32}) {
    for (int n : sizes) {
      fx::shading::PowTableOptions o{2, n, 16, LutMapping::texel_centre, f};
      GpuKernel k{
          std::string("specular/table/") + (f == TableFormat::unorm8 ? "unorm8" : "float32") + "/s" + std::to_string(n),
          "",
          ps(nh + "  return float4(Table.Sample(Sampler, float2(0.5, " + texcoord(LutMapping::texel_centre, n, "x") +
             ")).rrr, 1);")};
      k.table = fx::shading::bake_pow_table(o);
      out.push_back(std::move(k));
    }
  }
  // Hemisphere: the cosine form and the seed's form.
  out.push_back({"hemisphere/cosine_float", "",
                 ps("  float a = 0.5 + 0.5 * dot(N, L);\n  return float4(lerp(float3(0.1, 0.1, 0), float3(0.6, 0.7, "
                    "1), a), 1);")});
  out.push_back(
      {"hemisphere/seed_float", "",
       ps("  float c = dot(N, L), s = sqrt(saturate(1 - c * c));\n  float a = c >= 0 ? 1 - 0.5 * s : 0.5 * s;\n"
          "  return float4(lerp(float3(0.1, 0.1, 0), float3(0.6, 0.7, 1), a), 1);")});
  // (L.N, H.N) table and the seed's Gaussian.
  for (int n : sizes) {
    fx::shading::HalfAngleTableOptions o{n, fx::shading::HalfAngleLobe::blinn_phong, 32, LutMapping::texel_centre,
                                         TableFormat::unorm8};
    GpuKernel k{
        "ln_hn/blinn_phong/s" + std::to_string(n), "",
        ps("  float3 H = normalize(L + V);\n  float4 t = Table.Sample(Sampler, float2(" +
           texcoord(LutMapping::texel_centre, n, "0.5 * dot(N, H) + 0.5") + ", " +
           texcoord(LutMapping::texel_centre, n, "0.5 * dot(N, L) + 0.5") + "));\n  return float4(t.rgb * t.a, 1);")};
    k.table = fx::shading::bake_ln_hn_table(o);
    out.push_back(std::move(k));
  }
  out.push_back({"gaussian/float", "",
                 ps("  float3 H = normalize(L + V);\n  float u = dot(T, H) * 0.3, w = dot(N, H);\n"
                    "  float e = 4 * u / w;\n  float c = w > 0 ? exp(-e * e) : 0;\n  return float4(c.xxx, 1);")});
  // Per-vertex vs per-pixel on grids whose cells match the catalogue's sphere edges for a
  // sphere 512 pixels across (edge = 256 pi / rings pixels).
  for (int rings : {6, 12, 24, 48, 96}) {
    int cell = int(std::lround(256 * 3.14159265 / rings));
    std::string r = std::to_string(rings);
    GpuKernel base = grid("grid_empty/rings" + r, cell, size, "GRID_EMPTY");
    GpuKernel pv = grid("per_vertex/rings" + r, cell, size, "PER_VERTEX");
    GpuKernel pp = grid("per_pixel/rings" + r, cell, size, "PER_PIXEL");
    pv.baseline = pp.baseline = base.id;
    base.baseline = "empty";
    out.push_back(std::move(base));
    out.push_back(std::move(pv));
    out.push_back(std::move(pp));
  }
  return out;
}

}  // namespace fx::tools
