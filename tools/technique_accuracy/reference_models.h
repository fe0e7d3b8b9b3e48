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
  glm::dvec3 position{0.0};                                         // world
  glm::dvec3 tangent{1, 0, 0}, binormal{0, 1, 0}, normal{0, 0, 1};  // world, interpolated
  glm::dvec2 uv{0.0};
  std::vector<glm::dvec4> textures;  // ReferenceModel::textures, in order
  glm::dvec3 eye{0.0};               // camera position, world
};

// Named parameter values applied before a scene is rendered (the defaults otherwise).
struct ParameterSet {
  std::string name;
  std::vector<std::pair<std::string, std::vector<float>>> values;
};

// The technique a reference colour is asked for.
struct TechniqueRef {
  std::string name;
  std::string scheme;  // its Scheme annotation, "" when none
};

// Reads a float parameter (or its first n components) from the store; zeros when absent.
glm::dvec4 read_parameter(const ParameterStore& params, const std::string& name);

struct ReferenceModel {
  std::string effect;       // "hemisphere.fx"
  std::string description;  // what the model is, for reports
  // Shader expressions of `uv` and `object` (the object-space position) whose values the
  // reference reads: the effect's own samplers and helpers, so filtering and mip selection
  // match the technique's.
  std::vector<std::string> textures;
  // A GLSL effect's measurement pass is GLSL: the effect's blocks each of its stages starts
  // with (its #version and the uniform interface), and `textures` are GLSL expressions.
  // Empty: the pass is HLSL (the effect includes common.fxh).
  std::vector<std::string> glsl_blocks;
  std::vector<ParameterSet> parameter_sets;
  // Whether the model covers a technique (the ones it does not stay unmeasured).
  std::function<bool(const TechniqueRef&)> covers = [](const TechniqueRef&) { return true; };
  // The techniques that are substitutes for one another share a group (one Pareto front
  // each): "" when every technique renders the same model, else what the model depends on.
  std::function<std::string(const TechniqueRef&)> group = [](const TechniqueRef&) { return std::string(); };
  // The reference colour of one pixel for a technique the model covers.
  std::function<glm::dvec3(const PixelInputs&, const ParameterStore&, const TechniqueRef&)> shade;
};

// The models, one per effect that has one.
const std::vector<ReferenceModel>& reference_models();

}  // namespace fx::bench
