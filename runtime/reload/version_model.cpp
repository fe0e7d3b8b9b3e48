// Reload transaction, model side: the effect model, its parameter store and what technique
// selection needs to know about each technique.
#include <optional>
#include <variant>

#include "fx/compile/effect_file.h"
#include "fx/model/effect_model.h"
#include "fx/model/parameter_store.h"
#include "fx/select/annotation_value.h"
#include "version_steps.h"

namespace fx {
namespace {

std::optional<AnnotationValue> fact_value(const Value& v) {
  if (v.is_string()) return AnnotationValue(v.text);
  if (v.type.cls != TypeClass::scalar || v.components.empty()) return std::nullopt;
  switch (v.type.base) {
    case BaseType::boolean: return AnnotationValue(v.truthy());
    case BaseType::int32:
    case BaseType::uint32: return AnnotationValue(static_cast<int32_t>(v.number()));
    default: return AnnotationValue(static_cast<float>(v.number()));
  }
}

}  // namespace

bool build_version_model(EffectVersion& version, DiagnosticSink& sink, std::vector<TechniqueFacts>& facts) {
  size_t errors = sink.error_count();
  EffectFile& file = *version.file;
  const bool built = file.build_model(sink);
  version.model = std::shared_ptr<EffectModel>(version.file, file.model.get());
  if (!built) return false;
  version.params = std::shared_ptr<ParameterStore>(version.file, file.params.get());
  facts.clear();
  for (const TechniqueInfo& t : version.model->techniques) {
    TechniqueFacts f;
    f.name = t.name;
    f.range = t.range;
    for (const fx::Annotation& a : t.annotations)
      if (auto v = fact_value(a.value)) f.annotations.emplace_back(a.name, std::move(*v));
    facts.push_back(std::move(f));
  }
  return sink.error_count() == errors;
}

}  // namespace fx
