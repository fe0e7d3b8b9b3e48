// Standard semantics: matrices handed to the store in D3DX row-vector form.
#include "fx/binding/effect_scene.h"

#include <algorithm>
#include <cctype>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "fx/ascii_case.h"

namespace fx::vk {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// A column-vector matrix G (used as G * v) is HLSL's M in mul(v, M) transposed; glm's
// column-major memory of G is exactly M's rows, so it goes in as fxkit::MatrixOrder::row_major.
bool set_matrix(ParameterStore& params, Param p, const Type& type, const glm::mat4& g) {
  const float* m = glm::value_ptr(g);  // m[r * 4 + c] == M[r][c]
  if (type.rows == 4 && type.cols == 4) return bool(params.set_matrix(p, std::span<const float>(m, 16)));
  std::vector<float> sub;
  for (int r = 0; r < type.rows; ++r)
    for (int c = 0; c < type.cols; ++c) sub.push_back(m[r * 4 + c]);
  return bool(params.set_matrix(p, sub));
}

// Names real effects give scene parameters they declare without a semantic, lower case.
// Sources: the DirectX SDK samples (g_m*, g_v*, g_f*), FX Composer and NVIDIA's shader
// library (*Xf), RenderMonkey (mat*), and engine conventions (MVP, ModelView; XNA's and
// MonoGame's SpriteEffect MatrixTransform, which maps the drawn geometry to clip space).
struct NamedSemantic {
  const char* name;
  const char* semantic;
};
constexpr NamedSemantic kSceneNames[] = {
    {"g_mworldviewprojection", "WORLDVIEWPROJECTION"},
    {"g_mworldviewproj", "WORLDVIEWPROJECTION"},
    {"g_mwvp", "WORLDVIEWPROJECTION"},
    {"g_worldviewproj", "WORLDVIEWPROJECTION"},
    {"g_worldviewprojection", "WORLDVIEWPROJECTION"},
    {"worldviewprojection", "WORLDVIEWPROJECTION"},
    {"worldviewproj", "WORLDVIEWPROJECTION"},
    {"matworldviewproj", "WORLDVIEWPROJECTION"},
    {"matworldviewprojection", "WORLDVIEWPROJECTION"},
    {"matwvp", "WORLDVIEWPROJECTION"},
    {"mwvp", "WORLDVIEWPROJECTION"},
    {"wvp", "WORLDVIEWPROJECTION"},
    {"gwvp", "WORLDVIEWPROJECTION"},
    {"wvpxf", "WORLDVIEWPROJECTION"},
    {"modelviewprojection", "WORLDVIEWPROJECTION"},
    {"modelviewproj", "WORLDVIEWPROJECTION"},
    {"mvp", "WORLDVIEWPROJECTION"},
    {"g_mworld", "WORLD"},
    {"g_world", "WORLD"},
    {"world", "WORLD"},
    {"matworld", "WORLD"},
    {"mworld", "WORLD"},
    {"gworld", "WORLD"},
    {"worldxf", "WORLD"},
    {"model", "WORLD"},
    {"objecttoworld", "WORLD"},
    {"g_mview", "VIEW"},
    {"g_view", "VIEW"},
    {"view", "VIEW"},
    {"matview", "VIEW"},
    {"mview", "VIEW"},
    {"gview", "VIEW"},
    {"viewxf", "VIEW"},
    {"g_mprojection", "PROJECTION"},
    {"g_mproj", "PROJECTION"},
    {"g_projection", "PROJECTION"},
    {"g_proj", "PROJECTION"},
    {"projection", "PROJECTION"},
    {"proj", "PROJECTION"},
    {"matprojection", "PROJECTION"},
    {"matproj", "PROJECTION"},
    {"mproj", "PROJECTION"},
    {"projxf", "PROJECTION"},
    {"g_mworldview", "WORLDVIEW"},
    {"g_worldview", "WORLDVIEW"},
    {"worldview", "WORLDVIEW"},
    {"matworldview", "WORLDVIEW"},
    {"mworldview", "WORLDVIEW"},
    {"modelview", "WORLDVIEW"},
    {"wvxf", "WORLDVIEW"},
    {"g_mviewprojection", "VIEWPROJECTION"},
    {"g_mviewproj", "VIEWPROJECTION"},
    {"g_viewproj", "VIEWPROJECTION"},
    {"g_viewprojection", "VIEWPROJECTION"},
    {"viewprojection", "VIEWPROJECTION"},
    {"viewproj", "VIEWPROJECTION"},
    {"matviewproj", "VIEWPROJECTION"},
    {"matviewprojection", "VIEWPROJECTION"},
    {"mviewproj", "VIEWPROJECTION"},
    {"vpxf", "VIEWPROJECTION"},
    {"g_mworldinverse", "WORLDINVERSE"},
    {"worldinverse", "WORLDINVERSE"},
    {"worldi", "WORLDINVERSE"},
    {"g_mworldinversetranspose", "WORLDINVERSETRANSPOSE"},
    {"g_mworldit", "WORLDINVERSETRANSPOSE"},
    {"worldinversetranspose", "WORLDINVERSETRANSPOSE"},
    {"worldit", "WORLDINVERSETRANSPOSE"},
    {"matworldit", "WORLDINVERSETRANSPOSE"},
    {"worlditxf", "WORLDINVERSETRANSPOSE"},
    {"g_mviewprojectioninverse", "VIEWPROJECTIONINVERSE"},
    {"viewprojectioninverse", "VIEWPROJECTIONINVERSE"},
    {"viewprojinverse", "VIEWPROJECTIONINVERSE"},
    {"invviewproj", "VIEWPROJECTIONINVERSE"},
    {"inverseviewprojection", "VIEWPROJECTIONINVERSE"},
    {"matrixtransform", "WORLDVIEWPROJECTION"},
    {"g_mviewinverse", "VIEWINVERSE"},
    {"viewinverse", "VIEWINVERSE"},
    {"viewi", "VIEWINVERSE"},
    {"viewixf", "VIEWINVERSE"},
    {"matviewinverse", "VIEWINVERSE"},
    {"g_veyept", "CAMERAPOSITION"},
    {"g_veyepos", "CAMERAPOSITION"},
    {"g_veye", "CAMERAPOSITION"},
    {"g_eyepos", "CAMERAPOSITION"},
    {"g_eyeposition", "CAMERAPOSITION"},
    {"eyept", "CAMERAPOSITION"},
    {"eyepos", "CAMERAPOSITION"},
    {"eyeposition", "CAMERAPOSITION"},
    {"veyepos", "CAMERAPOSITION"},
    {"camerapos", "CAMERAPOSITION"},
    {"cameraposition", "CAMERAPOSITION"},
    {"g_camerapos", "CAMERAPOSITION"},
    {"viewpos", "CAMERAPOSITION"},
    {"viewposition", "CAMERAPOSITION"},
    {"g_ftime", "TIME"},
    {"g_time", "TIME"},
    {"ftime", "TIME"},
    {"time", "TIME"},
    {"g_felapsedtime", "ELAPSEDTIME"},
    {"elapsedtime", "ELAPSEDTIME"},
    {"g_vviewportsize", "VIEWPORTPIXELSIZE"},
    {"viewportsize", "VIEWPORTPIXELSIZE"},
    {"screensize", "VIEWPORTPIXELSIZE"},
};

// The transforms set_standard_semantics computes, and the abbreviations effects write for
// them (NVIDIA's and 3ds Max's WORLDVIEWPROJ, VIEWPROJ).
constexpr NamedSemantic kTransformBases[] = {{"WORLDVIEWPROJECTION", "WORLDVIEWPROJECTION"},
                                             {"WORLDVIEWPROJ", "WORLDVIEWPROJECTION"},
                                             {"VIEWPROJECTION", "VIEWPROJECTION"},
                                             {"VIEWPROJ", "VIEWPROJECTION"},
                                             {"WORLDVIEW", "WORLDVIEW"},
                                             {"PROJECTION", "PROJECTION"},
                                             {"PROJ", "PROJECTION"},
                                             {"WORLD", "WORLD"},
                                             {"VIEW", "VIEW"}};
// Their derived forms' spellings, longest first: WORLDI, VIEWINV, WORLDIT, VIEWIT.
constexpr NamedSemantic kTransformSuffixes[] = {{"INVERSETRANSPOSE", "INVERSETRANSPOSE"},
                                                {"INVTRANSPOSE", "INVERSETRANSPOSE"},
                                                {"INVTRANS", "INVERSETRANSPOSE"},
                                                {"TRANSPOSE", "TRANSPOSE"},
                                                {"INVERSE", "INVERSE"},
                                                {"INV", "INVERSE"},
                                                {"IT", "INVERSETRANSPOSE"},
                                                {"I", "INVERSE"},
                                                {"", ""}};

// What names put around a transform's name: g_m, g_f4x4, m, mat ... and ...Matrix, ...Xf.
constexpr std::string_view kNamePrefixes[] = {"gm4x4", "gf4x4", "gmat", "gm", "g", "m4x4", "f4x4", "mat", "m", ""};
constexpr std::string_view kNameSuffixes[] = {"matrix", "mtx", "mat", "xf", ""};

// Every semantic a transform can have (the storage of semantic_by_name's answers).
const std::vector<std::string>& transform_semantics() {
  static const std::vector<std::string> all = [] {
    std::vector<std::string> out;
    for (std::string_view base : {"WORLD", "VIEW", "PROJECTION", "WORLDVIEW", "VIEWPROJECTION", "WORLDVIEWPROJECTION"})
      for (std::string_view suffix : {"", "INVERSE", "TRANSPOSE", "INVERSETRANSPOSE"})
        out.push_back(std::string(base) + std::string(suffix));
    return out;
  }();
  return all;
}

// The space a name of one means: 0 object (model, local, mesh), 1 world, 2 view (camera,
// eye), 3 clip (projection, NDC); -1 for none.
int space_of(std::string_view word) {
  for (std::string_view w : {"object", "obj", "model", "local", "mesh"})
    if (word == w) return 0;
  if (word == "world") return 1;
  for (std::string_view w : {"view", "camera", "cam", "eye"})
    if (word == w) return 2;
  for (std::string_view w : {"clip", "ndc", "projection", "proj"})
    if (word == w) return 3;
  return -1;
}

// `WorldToCamera`, `ObjectToWorld`, `CameraToWorld`: the transform from one space to another
// (the products of WORLD, VIEW, PROJECTION, or their inverses going back); "" for a name of
// another form or one space to itself.
std::string space_transform(std::string_view core) {
  constexpr const char* kForward[4][4] = {{"", "WORLD", "WORLDVIEW", "WORLDVIEWPROJECTION"},
                                          {"", "", "VIEW", "VIEWPROJECTION"},
                                          {"", "", "", "PROJECTION"},
                                          {"", "", "", ""}};
  for (size_t at = core.find("to"); at != std::string_view::npos; at = core.find("to", at + 1)) {
    const int from = space_of(core.substr(0, at)), to = space_of(core.substr(at + 2));
    if (from < 0 || to < 0 || from == to) continue;
    return from < to ? kForward[from][to] : std::string(kForward[to][from]) + "INVERSE";
  }
  return {};
}

}  // namespace

std::string standard_semantic(std::string_view semantic) {
  const std::string s = upper(semantic);
  for (const NamedSemantic& suffix : kTransformSuffixes) {
    const std::string_view end = suffix.name;
    if (s.size() <= end.size() || !std::string_view(s).ends_with(end)) continue;
    const std::string_view base = std::string_view(s).substr(0, s.size() - end.size());
    for (const NamedSemantic& b : kTransformBases)
      if (base == b.name) return std::string(b.semantic) + suffix.semantic;
  }
  return s;
}

std::string_view semantic_by_name(std::string_view name) {
  const std::string n = ascii_lower(name);
  for (const NamedSemantic& e : kSceneNames)
    if (n == e.name) return e.semantic;
  // The same transforms with other decorations: g_mInvView, WorldViewProjMatrix, g_f4x4World.
  std::string bare;
  for (char c : n)
    if (c != '_') bare.push_back(c);
  // `WorldMatrixInverseTranspose`: the word Matrix inside the name too.
  if (size_t at = bare.find("matrix"); at != std::string::npos && at > 0 && at + 6 < bare.size()) bare.erase(at, 6);
  for (std::string_view prefix : kNamePrefixes)
    for (std::string_view suffix : kNameSuffixes) {
      if (bare.size() <= prefix.size() + suffix.size() || !bare.starts_with(prefix) || !bare.ends_with(suffix))
        continue;
      std::string core = bare.substr(prefix.size(), bare.size() - prefix.size() - suffix.size());
      for (std::string_view inverse : {"inverse", "inv"})  // InvView: the inverse in front
        if (core.starts_with(inverse) && core.size() > inverse.size()) core = core.substr(inverse.size()) + "inverse";
      for (const NamedSemantic& e : kSceneNames)
        if (core == e.name) return e.semantic;
      std::string semantic = standard_semantic(core);
      if (const std::string between = space_transform(core); !between.empty()) semantic = between;
      for (const std::string& t : transform_semantics())
        if (semantic == t) return t;
    }
  return {};
}

SceneView frame_bounds(const MeshBounds& bounds, float aspect) {
  SceneView s;
  const float fov = glm::radians(40.0f);
  const float radius = std::max(bounds.radius, 1e-3f);
  // Distance at which the sphere spans 85% of the narrower field of view.
  const float half = std::min(fov, 2.0f * std::atan(std::tan(fov * 0.5f) * aspect)) * 0.5f;
  const float distance = radius / std::sin(half) / 0.85f;
  const glm::vec3 center = bounds.center();
  const glm::vec3 dir = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  s.eye = center + dir * distance;
  s.view = glm::lookAtRH(s.eye, center, glm::vec3(0.0f, 1.0f, 0.0f));
  s.projection = glm::perspectiveRH_ZO(fov, aspect, distance * 0.05f, distance + radius * 4.0f);
  return s;
}

uint32_t set_standard_semantics(ParameterStore& params, const EffectModel& model, const SceneView& scene,
                                std::vector<SceneBinding>* bound) {
  const glm::mat4 wv = scene.view * scene.world, vp = scene.projection * scene.view;
  const glm::mat4 wvp = scene.projection * wv;
  struct Named {
    const char* name;
    glm::mat4 m;
  };
  const Named bases[] = {{"WORLD", scene.world}, {"VIEW", scene.view},   {"PROJECTION", scene.projection},
                         {"WORLDVIEW", wv},      {"VIEWPROJECTION", vp}, {"WORLDVIEWPROJECTION", wvp}};
  uint32_t set = 0;
  for (const Parameter& param : model.parameters) {
    const bool by_name = param.semantic.empty();
    const std::string sem = by_name ? std::string(semantic_by_name(param.name)) : standard_semantic(param.semantic);
    if (sem.empty() || (by_name && param.is_static())) continue;
    Param p = params.find(param.name);
    const Type* type = params.type(p);
    if (!type) continue;
    const uint32_t before = set;
    if (type->cls == TypeClass::matrix) {
      for (const Named& b : bases) {
        const std::string base = b.name;
        glm::mat4 m;
        if (sem == base) m = b.m;
        else if (sem == base + "INVERSE") m = glm::inverse(b.m);
        else if (sem == base + "TRANSPOSE") m = glm::transpose(b.m);
        else if (sem == base + "INVERSETRANSPOSE") m = glm::transpose(glm::inverse(b.m));
        else continue;
        set += set_matrix(params, p, *type, m) ? 1 : 0;
        break;
      }
    } else if (sem == "CAMERAPOSITION" || sem == "EYEPOSITION" || sem == "VIEWPOSITION") {
      const float v[4] = {scene.eye.x, scene.eye.y, scene.eye.z, 1.0f};
      const uint32_t n = std::min(type->component_count(), 4u);
      if (type->base == BaseType::float32 && n >= 3) set += params.set(p, std::span<const float>(v, n)) ? 1 : 0;
    } else if (sem == "TIME" || sem == "ELAPSEDTIME") {
      if (type->component_count() == 1 && type->base == BaseType::float32)
        set += params.set(p, sem == "TIME" ? scene.time : scene.elapsed) ? 1 : 0;
    } else if (sem == "VIEWPORTPIXELSIZE" && scene.viewport_size.x > 0 && scene.viewport_size.y > 0) {
      const glm::vec2 size = scene.viewport_size;
      const float v[4] = {size.x, size.y, 1.0f / size.x, 1.0f / size.y};
      const uint32_t n = type->component_count();
      if (type->base == BaseType::float32 && (n == 2 || n == 4))
        set += params.set(p, std::span<const float>(v, n)) ? 1 : 0;
    }
    if (bound && set != before) bound->push_back({param.name, sem, by_name});
  }
  return set;
}

std::vector<std::string> parameters_read(EffectPrograms& programs, uint32_t technique) {
  std::vector<std::string> out;
  for (const EffectPass& pass : programs.units().passes()) {
    if ((technique != kNoIndex && pass.technique_index != technique) || !programs.is_compiled(pass)) continue;
    const PassProgram& program = programs.program(pass);  // compiled already: a lookup
    for (const StageProgram& stage : program.stages)
      for (const UniformBlock& block : stage.shader.reflection.uniform_blocks)
        for (const BlockMember& m : block.members) {
          std::string name = m.name.substr(0, m.name.find_first_of(".["));
          if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(std::move(name));
        }
  }
  return out;
}

std::vector<std::string> zero_transforms(const ParameterStore& params, const EffectModel& model,
                                         const std::vector<std::string>& read) {
  std::vector<std::string> out;
  for (const Parameter& param : model.parameters) {
    if (param.is_static() || std::find(read.begin(), read.end(), param.name) == read.end()) continue;
    const Param p = params.find(param.name);
    const Type* type = params.type(p);
    if (!type || type->cls != TypeClass::matrix || type->base != BaseType::float32) continue;
    std::vector<float> value(type->component_count());
    if (!params.get(p, value)) continue;
    if (std::all_of(value.begin(), value.end(), [](float v) { return v == 0.0f; })) out.push_back(param.name);
  }
  return out;
}

}  // namespace fx::vk
