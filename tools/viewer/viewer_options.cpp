// fxkit-view's arguments, parsed by hand: the sample depends on fxkit and its window only.
#include "viewer_options.h"

#include <cstdio>
#include <cstdlib>

const char* const kViewerUsage =
    "usage: fxkit-view FILE.fx [--mesh sphere|torus|teapot|quad|F.obj] [--technique NAME]\n"
    "                  [--load-params F.json] [--save-params F.json] [--size WxH]\n"
    "                  [--frames N] [--screenshot F.png] [--script F] [--validate]\n"
    "  --frames N       quit after N frames (0: when the window closes)\n"
    "  --screenshot F   write the last frame's scene (without the UI) as a PNG\n"
    "  --save-params F  write the parameter values as JSON on exit\n"
    "  --script F       run F's commands between frames (frames N, set NAME V,..., technique T|auto,\n"
    "                   wait-reload [S], screenshot F.png, quit); the run ends with the script\n"
    "  --validate       Vulkan validation layer on; any message fails the run\n";

bool parse_viewer_options(int argc, char** argv, ViewerOptions& o, std::string& error) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc) return error = a + " wants a value", false;
      out = argv[++i];
      return true;
    };
    std::string v;
    if (a == "--mesh") {
      if (!value(o.mesh)) return false;
    } else if (a == "--technique") {
      if (!value(o.technique)) return false;
    } else if (a == "--save-params") {
      if (!value(o.save_params)) return false;
    } else if (a == "--load-params") {
      if (!value(o.load_params)) return false;
    } else if (a == "--screenshot") {
      if (!value(o.screenshot)) return false;
    } else if (a == "--script") {
      if (!value(o.script)) return false;
    } else if (a == "--frames") {
      if (!value(v)) return false;
      o.frames = std::atoi(v.c_str());
      if (o.frames < 0) return error = "--frames wants N >= 0", false;
    } else if (a == "--size") {
      if (!value(v) || std::sscanf(v.c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width <= 0 || o.height <= 0)
        return error = "--size wants WxH", false;
    } else if (a == "--validate") {
      o.validate = true;
    } else if (a == "-h" || a == "--help") {
      return error = "", false;
    } else if (!a.empty() && a[0] != '-' && o.file.empty()) {
      o.file = a;
    } else {
      return error = "unknown argument " + a, false;
    }
  }
  if (o.file.empty()) return error = "which effect? (FILE.fx)", false;
  if (!o.screenshot.empty() && o.frames == 0) return error = "--screenshot wants --frames N", false;
  return true;
}
