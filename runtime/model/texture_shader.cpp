// texture_shader: a texture's `function` annotation checked against the effect's functions,
// with the shape and size the texture is filled in (fx/model/texture_shader.h).
#include "fx/model/texture_shader.h"

#include <cmath>

#include "fx/ascii_case.h"
#include "fx/model/effect_model.h"

namespace fx {
namespace {

// Annotation names are matched ignoring case, as the DirectX SDK's effect viewers read them
// (`string function`, `int Width`).
const Annotation* annotation(const Parameter& p, std::string_view name) {
  for (const Annotation& a : p.annotations)
    if (iequals(a.name, name)) return &a;
  return nullptr;
}

const char* shape_name(TextureShape shape) {
  switch (shape) {
    case TextureShape::tex3d: return "3D";
    case TextureShape::cube: return "cube";
    default: return "2D";
  }
}

uint32_t dimensions(TextureShape shape) { return shape == TextureShape::tex2d ? 2 : 3; }

// The shape the texture is filled in: its type, else its `type` (or `TextureType`) annotation,
// else the sampler that reads it, else 2D. False, with `why`, for a shape D3DX cannot fill.
bool fill_shape(const EffectModel& model, const Parameter& texture, TextureShape& shape, std::string& why) {
  switch (texture.type.texture) {
    case TextureShape::tex2d:
    case TextureShape::tex3d:
    case TextureShape::cube: shape = texture.type.texture; return true;
    case TextureShape::any: break;
    default: why = "a texture shader fills 2D, 3D and cube textures, not a " + texture.type.to_string(); return false;
  }
  const Annotation* type = annotation(texture, "type");
  if (!type || !type->value.is_string()) type = annotation(texture, "TextureType");
  if (type && type->value.is_string()) {
    const std::string& t = type->value.text;
    if (iequals(t, "2D")) shape = TextureShape::tex2d;
    else if (iequals(t, "3D") || iequals(t, "volume")) shape = TextureShape::tex3d;
    else if (iequals(t, "cube")) shape = TextureShape::cube;
    else {
      why = "its " + type->name + " annotation \"" + t + "\" is none of 2D, 3D, volume, cube";
      return false;
    }
    return true;
  }
  const uint32_t index = model.find_parameter(texture.name);
  shape = TextureShape::tex2d;
  for (const SamplerInfo& s : model.samplers) {
    if (s.texture != index || s.parameter >= model.parameters.size()) continue;
    const SamplerShape sampled = model.parameters[s.parameter].type.sampler;
    if (sampled == SamplerShape::s3d) shape = TextureShape::tex3d;
    if (sampled == SamplerShape::cube) shape = TextureShape::cube;
    if (sampled == SamplerShape::s3d || sampled == SamplerShape::cube || sampled == SamplerShape::s2d) break;
  }
  return true;
}

// One edge from an annotation value: a whole number in 1..kTextureShaderMaxEdge.
bool edge(double v, uint32_t& out) {
  if (!(v >= 1 && v <= kTextureShaderMaxEdge) || std::floor(v) != v) return false;
  out = static_cast<uint32_t>(v);
  return true;
}

// The size: `width`, `height`, `depth` annotations, else a `Dimensions` vector (Engine-Nine's
// form), else kTextureShaderDefaultSize per edge. False, with `why`, for a size fxkit refuses.
bool fill_size(const Parameter& texture, TextureShader& out, std::string& why) {
  double size[3] = {kTextureShaderDefaultSize, kTextureShaderDefaultSize, kTextureShaderDefaultSize};
  if (const Annotation* d = annotation(texture, "Dimensions"); d && d->value.is_numeric())
    for (size_t i = 0; i < 3 && i < d->value.components.size(); ++i) size[i] = d->value.components[i];
  const char* names[3] = {"width", "height", "depth"};
  for (int i = 0; i < 3; ++i)
    if (const Annotation* a = annotation(texture, names[i]); a && a->value.is_numeric()) size[i] = a->value.number();
  if (out.shape == TextureShape::cube) size[1] = size[0];
  if (out.shape != TextureShape::tex3d) size[2] = 1;
  uint32_t* edges[3] = {&out.width, &out.height, &out.depth};
  for (int i = 0; i < 3; ++i)
    if (!edge(size[i], *edges[i])) {
      why = std::string("its ") + names[i] + " must be a whole number from 1 to " +
            std::to_string(kTextureShaderMaxEdge) + ", not " + std::to_string(size[i]);
      return false;
    }
  const uint64_t texels = uint64_t(out.width) * out.height * out.depth * (out.shape == TextureShape::cube ? 6 : 1);
  if (texels > kTextureShaderMaxTexels) {
    why = "its " + std::to_string(texels) + " texels are more than fxkit fills (" +
          std::to_string(kTextureShaderMaxTexels) + ")";
    return false;
  }
  return true;
}

// A float (or half) scalar or vector of `components`, 0 when the type is something else.
uint32_t float_components(const EffectModel& model, const ast::TypeRef& ref) {
  const Type t = model.types.lookup(ref.name);
  if ((t.cls != TypeClass::scalar && t.cls != TypeClass::vector) || t.is_array()) return 0;
  if (t.base != BaseType::float32 && t.base != BaseType::half) return 0;
  return t.cols;
}

// The arguments `f` takes for a texture of `shape`; false, with `why`, when it cannot fill one.
bool fill_arguments(const EffectModel& model, const ast::Function& f, TextureShape shape,
                    std::vector<TexelArgument>& out, std::string& why) {
  const std::string name(f.name);
  if (float_components(model, f.return_type) != 4) {
    why = "'" + name + "' returns " + std::string(f.return_type.name) + "; a texture shader returns a float4 colour";
    return false;
  }
  bool position = false, size = false;
  for (const ast::Variable& p : f.params) {
    const std::string pname(p.name);
    const uint32_t n = float_components(model, p.type);
    const bool is_position = iequals(p.semantic, "POSITION") || iequals(p.semantic, "POSITION0");
    const bool is_size = iequals(p.semantic, "PSIZE") || iequals(p.semantic, "PSIZE0");
    if ((!is_position && !is_size) || (p.storage & (ast::kOut | ast::kUniform)) || !p.array_dims.empty() || !n) {
      why = "its parameter '" + pname +
            "' is not a float input with the semantic POSITION or PSIZE, the only inputs of a texture shader";
      return false;
    }
    if ((is_position && position) || (is_size && size)) {
      why = "it takes " + std::string(p.semantic) + " twice";
      return false;
    }
    if (is_position && n < dimensions(shape)) {
      why = "its POSITION parameter '" + pname + "' has " + std::to_string(n) + " component" + (n == 1 ? "" : "s") +
            "; a " + shape_name(shape) + " texture's texels have " + std::to_string(dimensions(shape));
      return false;
    }
    position = position || is_position;
    size = size || is_size;
    out.push_back({is_position ? TexelInput::position : TexelInput::texel_size, static_cast<uint8_t>(n)});
  }
  if (!position) {
    why = "'" + name + "' has no POSITION parameter for the texel's position";
    return false;
  }
  return true;
}

}  // namespace

std::optional<TextureShader> texture_shader(const EffectModel& model, const Parameter& texture, DiagnosticSink& diags) {
  const Annotation* function = annotation(texture, "function");
  if (!function || !function->value.is_string()) return std::nullopt;
  TextureShader out;
  out.function = function->value.text;
  out.range = function->value_range;
  if (const Annotation* target = annotation(texture, "target"); target && target->value.is_string())
    out.target = target->value.text;
  const std::string what = "texture shader '" + out.function + "' of '" + texture.name + "'";
  std::string why;
  if (!fill_shape(model, texture, out.shape, why) || !fill_size(texture, out, why)) {
    diags.error("bad-texture-function", out.range, what + " cannot fill it: " + why);
    return std::nullopt;
  }
  bool found = false;
  if (model.ast)
    for (const ast::Decl& d : model.ast->decls) {
      if (d.kind != ast::DeclKind::function || !d.function || d.function->name != out.function) continue;
      found = true;
      std::vector<TexelArgument> arguments;
      if (fill_arguments(model, *d.function, out.shape, arguments, why)) {  // the first overload that fits
        out.arguments = std::move(arguments);
        return out;
      }
    }
  if (found) {
    diags.error("bad-texture-function", out.range,
                what + " cannot fill a " + shape_name(out.shape) + " texture: " + why);
    return std::nullopt;
  }
  Diagnostic& d = diags.error("unknown-texture-function", out.range,
                              "texture '" + texture.name + "' names no function '" + out.function + "'");
  std::vector<std::string_view> names(model.functions.begin(), model.functions.end());
  if (std::string guess = closest_match(out.function, names); !guess.empty())
    d.message += "; did you mean '" + guess + "'?";
  return std::nullopt;
}

}  // namespace fx
