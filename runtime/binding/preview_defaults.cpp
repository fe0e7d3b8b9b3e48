// Stand-in values for parameters a preview would otherwise leave zero.
#include "fx/binding/preview_defaults.h"

#include <algorithm>
#include <cmath>

#include "fx/ascii_case.h"

namespace fx::vk {
namespace {

bool holds(const std::string& lower_name, std::initializer_list<const char*> words) {
  return std::any_of(words.begin(), words.end(),
                     [&](const char* w) { return lower_name.find(w) != std::string::npos; });
}

// Identity matrices for every element of a rows x cols matrix (array), host row-major.
std::vector<float> identities(const Type& type) {
  std::vector<float> v(type.component_count(), 0.0f);
  const uint32_t per = uint32_t(type.rows) * type.cols;
  for (uint32_t e = 0; e < type.element_count(); ++e)
    for (uint32_t d = 0; d < std::min(type.rows, type.cols); ++d) v[e * per + d * type.cols + d] = 1.0f;
  return v;
}

// Whether a name is a transform from object space to object space under two of its names
// (`LocalToModel`, `MeshToObject`): a part's placement in its model, the identity in a preview.
bool within_object_space(const std::string& lower_name) {
  std::string bare;
  for (char c : lower_name)
    if (c != '_') bare.push_back(c);
  constexpr std::string_view kObject[] = {"local", "model", "object", "mesh"};
  auto object = [&](std::string_view w) {
    return std::find(std::begin(kObject), std::end(kObject), w) != std::end(kObject);
  };
  for (size_t at = bare.find("to"); at != std::string::npos; at = bare.find("to", at + 1))
    if (object(std::string_view(bare).substr(0, at)) && object(std::string_view(bare).substr(at + 2))) return true;
  return false;
}

// The light stand-in, normalised: above, in front and to the right of the object.
std::vector<float> towards_the_light() {
  const float s = 1.0f / std::sqrt(0.25f + 1.0f + 1.0f);
  return {0.5f * s, 1.0f * s, 1.0f * s, 0.0f};
}

// Which way a light direction parameter points, by its semantic, annotations and name:
// SAS's DIRECTION (and a parameter with SAS's Object annotation) and XNA's spelled-out
// `...Direction` point from the light into the scene; the DirectX SDK's abbreviated
// `g_LightDir`, `g_vLightDir`, `vLightDir` (no semantic) and any `...ToLight...` point
// towards the light. Empty when the parameter is no light direction.
std::string light_direction_rule(const Parameter& param, const std::string& lower_name) {
  const std::string semantic = ascii_lower(param.semantic);
  if (semantic == "direction" || semantic == "lightdirection") return "light direction";
  if (!holds(lower_name, {"light"}) || !holds(lower_name, {"dir"})) return {};
  if (holds(lower_name, {"tolight", "to_light"})) return "direction to the light";
  if (find_annotation(param.annotations, "Object") || holds(lower_name, {"direction"})) return "light direction";
  return "direction to the light";
}

// The value a rule gives one element of `param`, or empty when none applies. Colours and
// light directions are float3 / float4 vectors or arrays of them (one light per element).
std::vector<float> stand_in(const Parameter& param, const Type& type, std::string& rule) {
  const std::string n = ascii_lower(param.name);
  const bool float_vectors =
      type.base == BaseType::float32 && type.cls == TypeClass::vector && (type.cols == 3 || type.cols == 4);
  const bool float_vector = float_vectors && !type.is_array();
  if (type.cls == TypeClass::matrix && type.base == BaseType::float32 && type.rows >= 3 && type.cols >= 3 &&
      holds(n, {"bone", "skin", "palette"}))
    return rule = "identity bone palette", identities(type);
  if (type.cls == TypeClass::matrix && type.base == BaseType::float32 && type.rows >= 3 && type.cols >= 3 &&
      within_object_space(n))
    return rule = "identity object-space transform", identities(type);
  if (float_vectors && holds(n, {"color", "colour", "diffuse", "albedo", "tint"}) &&
      !holds(n, {"ambient", "emissive", "specular", "fog"})) {
    rule = "visible colour";
    return {0.8f, 0.8f, 0.8f, 1.0f};
  }
  const std::string semantic = ascii_lower(param.semantic);
  const bool names_light = holds(n, {"light"}) || find_annotation(param.annotations, "Object") != nullptr;
  if (float_vector && (semantic == "position" || semantic == "lightposition") && names_light) {
    rule = "light position";
    return {2.0f, 3.0f, 4.0f, 1.0f};
  }
  if (float_vectors) {
    rule = light_direction_rule(param, n);
    std::vector<float> to_light = towards_the_light();
    if (rule == "direction to the light") return to_light;
    if (rule == "light direction") return {-to_light[0], -to_light[1], -to_light[2], 0.0f};
  }
  return {};
}

}  // namespace

std::vector<PreviewDefault> set_preview_defaults(ParameterStore& params, const EffectModel& model,
                                                 const std::vector<std::string>& read) {
  std::vector<PreviewDefault> out;
  for (const Parameter& param : model.parameters) {
    if (param.default_value || param.is_static() || std::find(read.begin(), read.end(), param.name) == read.end())
      continue;
    const Param p = params.find(param.name);
    const Type* type = params.type(p);
    if (!type || !type->is_numeric()) continue;
    const std::string n = ascii_lower(param.name);
    if (type->base == BaseType::int32 && type->component_count() == 1 && holds(n, {"light"}) &&
        holds(n, {"count", "num"})) {
      int32_t count = 0;
      if (params.get(p, std::span<int32_t>(&count, 1)) && count == 0 && params.set(p, int32_t(1)))
        out.push_back({param.name, "light count"});
      continue;
    }
    if (type->base != BaseType::float32) continue;
    std::vector<float> value(type->component_count());
    if (!params.get(p, value) || std::any_of(value.begin(), value.end(), [](float v) { return v != 0.0f; })) continue;
    std::string rule;
    std::vector<float> element = stand_in(param, *type, rule);
    if (element.empty()) continue;
    std::vector<float> v;
    if (type->cls == TypeClass::matrix) v = std::move(element);  // already every element
    else
      for (uint32_t e = 0; e < type->element_count(); ++e)
        v.insert(v.end(), element.begin(), element.begin() + type->cols);
    v.resize(type->component_count());
    const bool set =
        type->cls == TypeClass::matrix ? bool(params.set_matrix(p, v)) : bool(params.set(p, std::span<const float>(v)));
    if (set) out.push_back({param.name, rule});
  }
  return out;
}

}  // namespace fx::vk
