// fxkit::Effect::params: the effect model's parameters (types, defaults, annotations) in
// public form, for tools that build a parameter UI or save presets.
#include <algorithm>

#include "api_state.h"
#include "fx/compile/effect_file.h"
#include "fx/model/class_instances.h"
#include "fx/model/parameter_store.h"
#include "fx/reload/reload_transaction.h"

namespace fxkit {
namespace {

ParamKind kind_of(const fx::Type& t) {
  switch (t.cls) {
    case fx::TypeClass::scalar:
    case fx::TypeClass::vector:
    case fx::TypeClass::matrix: return ParamKind::numeric;
    case fx::TypeClass::structure: return ParamKind::structure;
    case fx::TypeClass::string: return ParamKind::string;
    case fx::TypeClass::texture: return ParamKind::texture;
    case fx::TypeClass::sampler: return ParamKind::sampler;
    case fx::TypeClass::view: return ParamKind::view;
    default: return ParamKind::other;
  }
}

ScalarKind scalar_of(fx::BaseType base) {
  switch (base) {
    case fx::BaseType::boolean: return ScalarKind::boolean;
    case fx::BaseType::int32: return ScalarKind::int32;
    case fx::BaseType::uint32: return ScalarKind::uint32;
    default: return ScalarKind::float32;
  }
}

std::string shape_of(fx::TextureShape shape) {
  switch (shape) {
    case fx::TextureShape::tex1d:
    case fx::TextureShape::tex1d_array: return "1D";
    case fx::TextureShape::tex3d: return "3D";
    case fx::TextureShape::cube:
    case fx::TextureShape::cube_array: return "CUBE";
    case fx::TextureShape::any: return "";
    default: return "2D";
  }
}

}  // namespace

namespace detail {

Annotation to_public(const fx::Annotation& a) {
  Annotation out;
  out.name = a.name;
  if (a.value.is_string()) {
    out.kind = Annotation::Kind::string;
    out.text = a.value.text;
    return out;
  }
  const fx::BaseType base = a.value.type.base;
  out.kind = base == fx::BaseType::boolean                                 ? Annotation::Kind::boolean
             : base == fx::BaseType::int32 || base == fx::BaseType::uint32 ? Annotation::Kind::ints
                                                                           : Annotation::Kind::floats;
  out.values = a.value.floats();
  return out;
}

const Annotation* find_annotation(const std::vector<Annotation>& annotations, std::string_view name) {
  auto it = std::find_if(annotations.begin(), annotations.end(), [&](const Annotation& a) { return a.name == name; });
  return it == annotations.end() ? nullptr : &*it;
}

}  // namespace detail

const Annotation* ParamInfo::annotation(std::string_view n) const { return detail::find_annotation(annotations, n); }
const Annotation* TechniqueInfo::annotation(std::string_view n) const {
  return detail::find_annotation(annotations, n);
}

std::vector<ParamInfo> Effect::params() const {
  std::vector<ParamInfo> out;
  auto version = state_ ? state_->handle.version() : nullptr;
  if (!version) return out;
  const fx::EffectModel& model = *version->model;
  for (uint32_t i = 0; i < model.parameters.size(); ++i) {
    const fx::Parameter& p = model.parameters[i];
    ParamInfo info;
    info.handle = param(p.name);
    info.name = p.name;
    info.semantic = p.semantic;
    info.type = p.type.to_string();
    const fx::Type element = p.type.without_arrays();
    info.kind = kind_of(element);
    info.scalar = scalar_of(element.base);
    info.rows = element.rows, info.columns = element.cols;
    info.elements = p.type.is_array() ? p.type.element_count() : 0;
    info.components =
        info.kind == ParamKind::numeric || info.kind == ParamKind::structure ? p.type.component_count() : 0;
    if (const fx::TextureInfo* texture = model.texture_of(i)) {
      info.texture_shape = shape_of(texture->shape);
      info.resource_name = texture->resource_name;
    }
    if (p.default_value) {
      info.has_default = true;
      if (p.default_value->is_string()) info.default_text = p.default_value->text;
      else info.default_value = p.default_value->floats();
    }
    info.settable = p.shader_visible;
    if (p.decl && fx::find_interface(version->file->parsed.ast, p.decl->type.name))
      for (fx::BindableInstance& instance : fx::bindable_instances(version->file->parsed.ast, p.decl->type.name))
        info.class_instances.push_back(std::move(instance.name));
    for (const fx::Annotation& a : p.annotations) info.annotations.push_back(detail::to_public(a));
    out.push_back(std::move(info));
  }
  return out;
}

}  // namespace fxkit
