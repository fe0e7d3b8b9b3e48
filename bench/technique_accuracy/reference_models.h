// The shading models the seed effects document, in double, evaluated per pixel from the
// inputs a G-buffer pass reads back (world position, interpolated tangent frame, uv and the
// effect's own texture samples), and the parameter sets that exercise them.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "fx/model/parameter_store.h"

namespace fx::bench {

// What the G-buffer pass gives one pixel.
struct PixelInputs {
  glm::dvec3 position{0.0};                       // world
  glm::dvec3 tangent{1, 0, 0}, binormal{0, 1, 0}, normal{0, 0, 1};  // world, interpolated
  glm::dvec2 uv{0.0};
  std::vector<glm::dvec4> textures;  // ReferenceModel::textures, in order
  glm::dvec3 eye{0.0};              // camera position, world
};

// Named parameter values applied before a scene is rendered (the defaults otherwise).
struct ParameterSet {
  std::string name;
  std::vector<std::pair<std::string, std::vector<float>>> values;
};

// Reads a float parameter (or its first n components) from the store; zeros when absent.
glm::dvec4 read_parameter(const ParameterStore& params, const std::string& name);

struct ReferenceModel {
  std::string effect;      // "hemisphere.fx"
  std::string description;  // what the model is, for reports
  // HLSL expressions of `uv` whose values the reference reads (the effect's own samplers,
  // so filtering and mip selection match the technique's).
  std::vector<std::string> textures;
  std::vector<ParameterSet> parameter_sets;
  // The reference colour for a technique of `scheme`, or nullopt when the model does not
  // cover that scheme (`covers` says so up front).
  std::function<bool(const std::string& scheme)> covers;
  // The techniques that are substitutes for one another share a group (one Pareto front
  // each): the scheme when the model depends on it, "" otherwise.
  std::function<std::string(const std::string& scheme)> group = [](const std::string&) { return std::string(); };
  std::function<glm::dvec3(const PixelInputs&, const ParameterStore&, const std::string& scheme)> shade;
};

// The models, one per effect that has one.
const std::vector<ReferenceModel>& reference_models();

}  // namespace fx::bench
