// Anisotropic specular highlights for hair, wool and brushed metal in GLSL (seed:
// anisotropic-highlights-glsl.txt, pythonstuff). Eye and light vectors (Phong) or the half
// vector (Blinn-Phong) are projected onto the plane spanned by the strand direction T and
// the normal N before the usual highlight; looking along the strands gives the plain
// highlight, across them it fades. Gloss map channels: r = highlight brightness,
// g = sqrt(exponent / 128), b = strand angle (0 = isotropic, 3..255 = 1..180 degrees from
// the tangent). Expect (seed figures) Blinn-Phong and Phong differing at grazing angles.
// Vulkan GLSL 450: one uniform block, combined image samplers, explicit locations.
#include "generated/costs.fxh"  // COST_<technique>: measured cost/error, scripts/accuracy-report

float4x4 WorldViewProjection : WORLDVIEWPROJECTION < string UIWidget = "None"; >;
float4x4 World : WORLD < string UIWidget = "None"; >;
float4 EyePosition : CAMERAPOSITION < string UIWidget = "None"; >;
float4 LightPosition : POSITION < string UIName = "Light position"; string Object = "PointLight0"; string Space = "World"; > = {4.0, 6.0, 8.0, 1.0};
float4 LightColor : DIFFUSE < string UIName = "Light color"; string UIWidget = "Color"; > = {1.0, 1.0, 1.0, 1.0};
int toggleaniso < string UIName = "Anisotropic (runtime switch, key I)"; int UIMin = 0; int UIMax = 1; > = 1;
int togglemodel < string UIName = "Blinn-Phong (runtime switch, key M)"; int UIMin = 0; int UIMax = 1; > = 0;
// An engine binds its own hair textures here; the generators bake brown hair with strands
// along the tangent (u), fibre bumps and a gloss map in the seed's channel layout.
texture ColorMap : DIFFUSEMAP < string Generator = "color_map"; string Pattern = "streaks"; string Color0 = "0.22 0.11 0.05"; string Color1 = "0.55 0.32 0.14"; float Softness = 0.5; int Frequency = 4; int Stretch = 16; int Width = 256; int Seed = 4; string UIName = "Color"; >;
texture NormalMap : NORMALMAP < string Generator = "normal_map"; string Pattern = "streaks"; float Strength = 0.5; int Frequency = 4; int Stretch = 16; int Width = 256; int Seed = 4; string Alpha = "one"; string UIName = "Normal map"; >;
texture GlossMap < string Generator = "gloss_map"; string Pattern = "linear"; float Angle = 0; float Amount = 0.1; float Brightness = 1.0; float Variation = 0.5; float Exponent = 32; int Frequency = 4; int Stretch = 16; int Width = 256; int Seed = 4; string UIName = "Gloss (r brightness, g sqrt exponent, b strand angle)"; >;

GLSLShader Header
{
#version 450
}

// The parameters above, as the shaders see them (same names, std140).
GLSLShader Interface
{
layout(set = 0, binding = 0, std140) uniform Parameters
{
    mat4 WorldViewProjection;
    mat4 World;
    vec4 EyePosition;
    vec4 LightPosition;
    vec4 LightColor;
    int toggleaniso;
    int togglemodel;
};
layout(set = 0, binding = 1) uniform sampler2D ColorMap;
layout(set = 0, binding = 2) uniform sampler2D NormalMap;
layout(set = 0, binding = 3) uniform sampler2D GlossMap;
}

GLSLShader HighlightVS
{
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inTangent;
layout(location = 3) in vec3 inBinormal;
layout(location = 4) in vec2 inTexCoord;
layout(location = 0) out vec2 vTexCoord;
layout(location = 1) out vec3 vEye;    // tangent space, to the eye
layout(location = 2) out vec3 vLight;  // tangent space, to the light

void main()
{
    vec4 world = World * vec4(inPosition, 1.0);
    vec3 n = normalize(mat3(World) * inNormal);
    vec3 t = normalize(mat3(World) * inTangent);
    vec3 b = normalize(mat3(World) * inBinormal);
    mat3 toTangent = transpose(mat3(t, b, n));
    vEye = toTangent * (EyePosition.xyz - world.xyz);
    vLight = toTangent * (LightPosition.xyz - world.xyz);
    vTexCoord = inTexCoord;
    gl_Position = WorldViewProjection * vec4(inPosition, 1.0);
}
}

// Technique switches as compile-time constants (a technique concatenates one of each).
GLSLShader AnisoOn { const bool kAnisotropic = true; }
GLSLShader AnisoOff { const bool kAnisotropic = false; }
GLSLShader ModelPhong { const bool kBlinnPhong = false; }
GLSLShader ModelBlinnPhong { const bool kBlinnPhong = true; }
// The seed's runtime switches (uniforms toggleaniso/togglemodel, keys I and M).
// (Not #defines: fxkit's preprocessor runs over the whole file before blocks are cut.)
GLSLShader RuntimeSwitch
{
bool kAnisotropic = toggleaniso != 0;
bool kBlinnPhong = togglemodel != 0;
}

GLSLShader HighlightFS
{
layout(location = 0) in vec2 vTexCoord;
layout(location = 1) in vec3 vEye;
layout(location = 2) in vec3 vLight;
layout(location = 0) out vec4 fragColor;

const float kDegenerate = 4.76837158e-7;

// normalize(v), or `fallback` when v has no direction (normalize(0) is undefined).
vec3 normalizeOr(vec3 v, vec3 fallback)
{
    float len = length(v);
    return len > kDegenerate ? v / len : fallback;
}

// pow with pow(0, 0) = 1 and negative bases clamped (both undefined in SPIR-V).
float guardedPow(float x, float y)
{
    float s = clamp(x, 0.0, 1.0);
    return s > 0.0 ? pow(s, y) : (y == 0.0 ? 1.0 : 0.0);
}

// x without its component along the unit plane normal b, renormalized; zero when x is
// parallel to b. Mirrors fx::shading::project_to_plane.
vec3 projectToPlane(vec3 x, vec3 b)
{
    return normalizeOr(x - dot(x, b) * b, vec3(0.0));
}

void main()
{
    vec4 texColor = vec4(texture(ColorMap, vTexCoord).rgb, 1.0);
    vec3 N = normalizeOr(texture(NormalMap, vTexCoord).rgb - 0.5, vec3(0.0, 0.0, 1.0));
    vec3 gloss = texture(GlossMap, vTexCoord).rgb;  // r brightness, g exponent, b strand dir
    vec3 E = normalizeOr(vEye, N);
    vec3 L = normalizeOr(vLight, N);
    float exponent = gloss.g * gloss.g * 128.0;  // 32 at green 128, at most 128

    // Strand direction in the tangent plane: b = 0 isotropic, else 1..180 degrees.
    float angle = (gloss.b * 255.0 - 2.0) * (3.14159265 / 180.0);
    bool strands = kAnisotropic && gloss.b * 255.0 >= 2.5;
    vec3 T = vec3(cos(angle), sin(angle), 0.0);
    // The plane's normal; the seed skips normalizing it (T lies in the unbumped tangent
    // plane), with a bump map cross(N, T) is shorter than 1. T parallel to N: isotropic.
    vec3 tplane = normalizeOr(cross(N, T), vec3(0.0));
    bool project = strands && dot(tplane, tplane) > 0.0;

    float specular;
    if (kBlinnPhong)
    {
        vec3 H = normalizeOr(L + E, vec3(0.0));  // L = -E: no highlight
        if (project) H = projectToPlane(H, tplane);
        specular = guardedPow(dot(N, H), exponent);
    }
    else
    {
        if (project)
        {
            E = projectToPlane(E, tplane);
            L = projectToPlane(L, tplane);
        }
        vec3 R = reflect(-L, N);
        specular = guardedPow(dot(R, E), exponent);
    }
    float diffuse = clamp(dot(N, normalizeOr(vLight, N)), 0.0, 1.0);
    fragColor = vec4(LightColor.rgb * (texColor.rgb * diffuse + gloss.r * specular), 1.0);
}
}

technique aniso_blinn_phong
< string Requires = "glsl_450"; string Scheme = "blinn_phong"; string UIName = "Anisotropic Blinn-Phong"; COST_aniso_blinn_phong >
{
    pass p0
    {
        VertexShader = { Header, Interface, HighlightVS };
        PixelShader = { Header, Interface, AnisoOn, ModelBlinnPhong, HighlightFS };
    }
}

technique aniso_phong
< string Requires = "glsl_450"; string Scheme = "phong"; string UIName = "Anisotropic Phong (the seed's default)"; COST_aniso_phong >
{
    pass p0
    {
        VertexShader = { Header, Interface, HighlightVS };
        PixelShader = { Header, Interface, AnisoOn, ModelPhong, HighlightFS };
    }
}

technique iso_blinn_phong
< string Requires = "glsl_450"; string Scheme = "isotropic, blinn_phong"; string UIName = "Isotropic Blinn-Phong"; COST_iso_blinn_phong >
{
    pass p0
    {
        VertexShader = { Header, Interface, HighlightVS };
        PixelShader = { Header, Interface, AnisoOff, ModelBlinnPhong, HighlightFS };
    }
}

technique iso_phong
< string Requires = "glsl_450"; string Scheme = "isotropic, phong"; string UIName = "Isotropic Phong"; COST_iso_phong >
{
    pass p0
    {
        VertexShader = { Header, Interface, HighlightVS };
        PixelShader = { Header, Interface, AnisoOff, ModelPhong, HighlightFS };
    }
}

technique runtime_switch
< string Requires = "glsl_450"; string Scheme = "interactive"; string UIName = "Seed's I/M switches as uniforms"; COST_runtime_switch >
{
    pass p0
    {
        VertexShader = { Header, Interface, HighlightVS };
        PixelShader = { Header, Interface, RuntimeSwitch, HighlightFS };
    }
}
