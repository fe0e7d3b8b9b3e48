// fxkit::detail::PassApply: what fxkit::Technique::apply calls between begin() and end(),
// the recording binding's apply as a plain function, so that the public header calls it
// inline with one call per pass (fxkit/effect.h). Internal to fxkit: use fxkit::Technique.
#pragma once
#include <cstdint>

namespace fxkit::detail {

struct PassApply {
  // `apply(binding, pass, sink)`: fx::vk::EffectBinding::apply of the begun technique's
  // binding for the application's vertex layout, problems into `sink` (fx::DiagnosticSink).
  bool (*apply)(void* binding, uint32_t pass, void* sink) = nullptr;
  void* binding = nullptr;  // null outside begin() / end(): apply() is false
  void* sink = nullptr;
};

}  // namespace fxkit::detail
