#include "shader_serialize.h"

#include <nlohmann/json.hpp>

namespace fx {
namespace {

using nlohmann::json;

json type_json(const ReflectedType& t) {
  return {{"scalar", static_cast<int>(t.scalar)},
          {"rows", t.rows},
          {"columns", t.columns},
          {"struct", t.is_struct},
          {"array", t.array_size},
          {"glsl", t.glsl_name}};
}
ReflectedType type_from(const json& j) {
  ReflectedType t;
  t.scalar = static_cast<ScalarKind>(j.at("scalar").get<int>());
  t.rows = j.at("rows").get<uint8_t>();
  t.columns = j.at("columns").get<uint8_t>();
  t.is_struct = j.at("struct").get<bool>();
  t.array_size = j.at("array").get<uint32_t>();
  t.glsl_name = j.at("glsl").get<std::string>();
  return t;
}

json block_json(const UniformBlock& b) {
  json members = json::array();
  for (const BlockMember& m : b.members)
    members.push_back({{"name", m.name},
                       {"type", type_json(m.type)},
                       {"offset", m.offset},
                       {"size", m.size},
                       {"array_stride", m.array_stride},
                       {"matrix_stride", m.matrix_stride},
                       {"matrix_layout", static_cast<int>(m.matrix_layout)}});
  return {{"name", b.name}, {"set", b.set},       {"binding", b.binding},
          {"size", b.size}, {"members", members}, {"written", b.written}};
}
UniformBlock block_from(const json& j) {
  UniformBlock b;
  b.name = j.at("name").get<std::string>();
  b.set = j.at("set").get<uint32_t>();
  b.binding = j.at("binding").get<uint32_t>();
  b.size = j.at("size").get<uint32_t>();
  b.written = j.at("written").get<bool>();
  for (const json& m : j.at("members"))
    b.members.push_back({m.at("name").get<std::string>(), type_from(m.at("type")), m.at("offset").get<uint32_t>(),
                         m.at("size").get<uint32_t>(), m.at("array_stride").get<uint32_t>(),
                         m.at("matrix_stride").get<uint32_t>(),
                         static_cast<MatrixLayout>(m.at("matrix_layout").get<int>())});
  return b;
}

json blocks_json(const std::vector<UniformBlock>& blocks) {
  json a = json::array();
  for (const UniformBlock& b : blocks) a.push_back(block_json(b));
  return a;
}
std::vector<UniformBlock> blocks_from(const json& j) {
  std::vector<UniformBlock> out;
  for (const json& b : j) out.push_back(block_from(b));
  return out;
}

}  // namespace

std::string write_shader_metadata(const CompiledShader& s) {
  const ShaderReflection& r = s.reflection;
  json images = json::array();
  for (const ImageBinding& i : r.images)
    images.push_back({{"name", i.name},
                      {"kind", static_cast<int>(i.kind)},
                      {"dim", static_cast<int>(i.dim)},
                      {"arrayed", i.arrayed},
                      {"shadow", i.shadow},
                      {"set", i.set},
                      {"binding", i.binding},
                      {"array", i.array_size},
                      {"multisampled", i.multisampled},
                      {"sampled", static_cast<int>(i.sampled)}});
  auto interface = [](const std::vector<InterfaceVariable>& vars) {
    json a = json::array();
    for (const InterfaceVariable& v : vars)
      a.push_back({{"name", v.name},
                   {"location", v.location},
                   {"type", type_json(v.type)},
                   {"semantic", v.semantic},
                   {"unread", v.unread}});
    return a;
  };
  json messages = json::array();
  for (const ShaderMessage& m : s.messages) {
    messages.push_back({{"severity", static_cast<int>(m.severity)},
                        {"file", m.file},
                        {"line", m.line},
                        {"column", m.column},
                        {"text", m.text}});
    if (!m.id.empty()) messages.back()["id"] = m.id;
  }
  json j = {{"entry_point", s.entry_point},
            {"legalized", s.legalized},
            {"info_log", s.info_log},
            {"messages", messages},
            {"stage", static_cast<int>(r.stage)},
            {"uniform_blocks", blocks_json(r.uniform_blocks)},
            {"storage_blocks", blocks_json(r.storage_blocks)},
            {"push_constants", blocks_json(r.push_constants)},
            {"images", images},
            {"inputs", interface(r.inputs)},
            {"outputs", interface(r.outputs)},
            {"local_size", {r.local_size[0], r.local_size[1], r.local_size[2]}}};
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

bool read_shader_metadata(std::string_view text, CompiledShader& s) {
  json j = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) return false;
  // Schema mismatches surface as json exceptions; they must not leave the library.
  try {
    s.entry_point = j.at("entry_point").get<std::string>();
    s.legalized = j.at("legalized").get<bool>();
    s.info_log = j.at("info_log").get<std::string>();
    for (const json& m : j.at("messages"))
      s.messages.push_back({static_cast<Severity>(m.at("severity").get<int>()), m.at("file").get<std::string>(),
                            m.at("line").get<uint32_t>(), m.at("column").get<uint32_t>(),
                            m.at("text").get<std::string>(), m.value("id", std::string())});
    ShaderReflection& r = s.reflection;
    r.stage = static_cast<ShaderStage>(j.at("stage").get<int>());
    r.entry_point = s.entry_point;
    r.uniform_blocks = blocks_from(j.at("uniform_blocks"));
    r.storage_blocks = blocks_from(j.at("storage_blocks"));
    r.push_constants = blocks_from(j.at("push_constants"));
    for (const json& i : j.at("images"))
      r.images.push_back({i.at("name").get<std::string>(), static_cast<ImageBinding::Kind>(i.at("kind").get<int>()),
                          static_cast<ImageDim>(i.at("dim").get<int>()), i.at("arrayed").get<bool>(),
                          i.at("shadow").get<bool>(), i.at("set").get<uint32_t>(), i.at("binding").get<uint32_t>(),
                          i.at("array").get<uint32_t>(), i.at("multisampled").get<bool>(),
                          static_cast<ScalarKind>(i.at("sampled").get<int>())});
    for (auto [key, list] : {std::pair{"inputs", &r.inputs}, std::pair{"outputs", &r.outputs}})
      for (const json& v : j.at(key))
        list->push_back({v.at("name").get<std::string>(), v.at("location").get<uint32_t>(), type_from(v.at("type")),
                         v.at("semantic").get<std::string>(), v.value("unread", false)});
    for (int d = 0; d < 3; ++d) r.local_size[d] = j.at("local_size").at(static_cast<size_t>(d)).get<uint32_t>();
  } catch (const nlohmann::json::exception&) {
    return false;
  }
  return true;
}

}  // namespace fx
