// `--mesh NAME` resolution: a built-in generator or an OBJ file.
#include <algorithm>
#include <string>

#include "fx/ascii_case.h"
#include "fx/mesh.h"

namespace fx {

std::optional<Mesh> make_mesh(std::string_view name, DiagnosticSink& sink) {
  if (iequals(name, "sphere")) return sphere();
  if (iequals(name, "torus")) return torus();
  if (iequals(name, "quad")) return quad();
  if (iequals(name, "teapot")) return teapot();
  const bool obj_suffix = name.size() > 4 && iequals(name.substr(name.size() - 4), ".obj");
  const bool looks_like_path = name.find_first_of("/\\.") != std::string_view::npos;
  if (obj_suffix || looks_like_path) return load_obj(std::filesystem::path(std::string(name)), sink);

  Diagnostic& d = sink.error(
      "unknown-mesh", {},
      "unknown mesh '" + std::string(name) + "': expected sphere, torus, quad, teapot or a path to an .obj file");
  std::string guess = closest_match(name, {"sphere", "torus", "quad", "teapot"});
  if (!guess.empty()) d.message += "; did you mean '" + guess + "'?";
  return std::nullopt;
}

}  // namespace fx
